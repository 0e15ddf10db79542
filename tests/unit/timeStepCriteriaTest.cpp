// Unit tests of src/foamDEM/correlations/timeStepCriteria.{H,C}.
// Expected values were computed by hand (python3 scratch, original formulas),
// not by calling this code.

#include "timeStepCriteria.H"
#include "relNear.h"

#include <cmath>
#include <limits>

using namespace foamDEM::correlations;

namespace
{
constexpr double tol = 1e-12;
constexpr double kPi = 3.14159265358979323846;
}

TEST(RayleighTimeStep, HandComputedCases)
{
    // r = 2.5e-3, rho_p = 890, E = 1e7, nu = 0.33:
    // G = 1e7/2.66 = 3.7593985e6; pi r sqrt(890/G)/(0.1631*0.33 + 0.8766)
    EXPECT_REL(rayleighTimeStep(2.5e-3, 890.0, 1e7, 0.33),
               1.2988089283516734e-04, tol);
    // r = 1e-3, rho_p = 2500, E = 5e6, nu = 0.45
    EXPECT_REL(rayleighTimeStep(1e-3, 2500.0, 5e6, 0.45),
               1.2592517245242754e-04, tol);
    // steel: r = 5e-4, rho_p = 7800, E = 2e11, nu = 0.3
    EXPECT_REL(rayleighTimeStep(5e-4, 7800.0, 2e11, 0.3),
               5.4044108107044275e-07, tol);
}

TEST(RayleighTimeStep, UsesShearModulusNotYoungs)
{
    // Using E instead of G = E/(2(1+nu)) would be sqrt(2(1+nu)) = 1.631 x
    // smaller; make sure the shear modulus is used.
    const double withE = kPi*2.5e-3*std::sqrt(890.0/1e7)/(0.1631*0.33 + 0.8766);
    const double dt = rayleighTimeStep(2.5e-3, 890.0, 1e7, 0.33);
    EXPECT_REL(dt/withE, std::sqrt(2.0*1.33), 1e-12);
}

TEST(EffectiveYoungsModulus, HandComputedCases)
{
    // identical (1e7, 0.33): E/(2 (1 - 0.33^2)) = 1e7/1.7822
    EXPECT_REL(effectiveYoungsModulus(1e7, 0.33, 1e7, 0.33),
               5611042.5317023909, tol);
    // soft particle on steel wall: (1e7, 0.33) + (2e11, 0.3)
    EXPECT_REL(effectiveYoungsModulus(1e7, 0.33, 2e11, 0.3),
               11221512.087532284, tol);
    // glass-glass (7e10, 0.2): 7e10/(2*0.96)
    EXPECT_REL(effectiveYoungsModulus(7e10, 0.2, 7e10, 0.2),
               36458333333.333336, tol);
}

TEST(EffectiveYoungsModulus, Symmetric)
{
    EXPECT_REL(effectiveYoungsModulus(2e11, 0.3, 1e7, 0.33),
               effectiveYoungsModulus(1e7, 0.33, 2e11, 0.3), 1e-14);
}

TEST(HertzContactTime, HandComputedCases)
{
    // Two identical spheres r = 2.5e-3, rho = 890, E = 1e7, nu = 0.33:
    // m = 890*4/3*pi*r^3, m* = m/2, r* = r/2, E* = 5611042.5317023909
    const double r = 2.5e-3;
    const double m = 890.0*4.0/3.0*kPi*r*r*r;
    const double Es = 5611042.5317023909;
    // v = 1: 2.87 ((m/2)^2/((r/2) E*^2 1))^(1/5)
    EXPECT_REL(hertzContactTime(0.5*m, 0.5*r, Es, 1.0),
               3.3464930576106037e-04, 1e-12);
    // v = 0.1
    EXPECT_REL(hertzContactTime(0.5*m, 0.5*r, Es, 0.1),
               5.3038340656254225e-04, 1e-12);
    // m* = 1e-3, r* = 1e-3, E* = 1e9, v = 2: 2.87 (1e-6/(2e15))^(1/5)
    EXPECT_REL(hertzContactTime(1e-3, 1e-3, 1e9, 2.0),
               1.5764343796442783e-04, 1e-12);
}

TEST(HertzContactTime, ScalesWithVelocityToMinusOneFifth)
{
    const double t1 = hertzContactTime(1e-3, 1e-3, 1e9, 1.0);
    const double t32 = hertzContactTime(1e-3, 1e-3, 1e9, 32.0);
    EXPECT_REL(t1/t32, 2.0, 1e-12);   // 32^(1/5) = 2 (exponent 1/5, not 2)
}

TEST(HertzContactTime, ZeroVelocityIsInfinite)
{
    EXPECT_EQ(hertzContactTime(1e-3, 1e-3, 1e9, 0.0),
              std::numeric_limits<double>::infinity());
}

TEST(ParticleRelaxationTime, HandComputedCases)
{
    // d = 1e-3, rho_p = 2500, mu = 1e-3: 2500e-6/18e-3
    EXPECT_REL(particleRelaxationTime(1e-3, 2500.0, 1e-3),
               0.1388888888888889, tol);
    // d = 1e-4, rho_p = 2650, mu = 1.8e-5 (sand in air)
    EXPECT_REL(particleRelaxationTime(1e-4, 2650.0, 1.8e-5),
               0.081790123456790126, tol);
    // d = 5e-3, rho_p = 890, mu = 1e-3
    EXPECT_REL(particleRelaxationTime(5e-3, 890.0, 1e-3),
               1.2361111111111114, tol);
}
