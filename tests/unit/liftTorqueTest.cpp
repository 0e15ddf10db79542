// Unit tests of src/foamDEM/correlations/liftTorqueCorrelations.{H,C}.
//
// Expected values were computed by hand in a separate python3 scratch
// script from the ORIGINAL forms (not by calling this code):
//   Saffman: radius form F = 6.46 mu a^2 U_n sqrt(kappa/nu) times Mei's f,
//            U_n = |w x omega|/|omega|, direction (w x omega) normalised;
//   Magnus:  F = 0.5 rho C_LR (pi d^2/4) |w| (Omega x w)/|Omega|, C_LR from
//            the Oesterle & Bui Dinh formula as printed;
//   torque:  T = (rho/2) (d/2)^5 C_R |Omega| Omega.
// water: rho = 1000, mu = 1e-3; air: rho = 1.2, mu = 1.8e-5 (SI).

#include "liftTorqueCorrelations.H"
#include "relNear.h"

#include <cmath>
#include <limits>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double tol = 1e-10;
constexpr double rhoW = 1000.0, muW = 1e-3;
constexpr double rhoA = 1.2, muA = 1.8e-5;

// componentwise relative comparison against |expected| (zeros must match
// to that absolute level)
::testing::AssertionResult vecNear(const vec3& a, const vec3& e, double rel)
{
    const double scale = mag(e);
    const double err = mag(vec3{a.x - e.x, a.y - e.y, a.z - e.z});
    if (std::isfinite(err) && err <= rel*scale)
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
        << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
        << e.x << ", " << e.y << ", " << e.z << "), relative error "
        << err/scale;
}

bool isZero(const vec3& a)
{
    return a.x == 0.0 && a.y == 0.0 && a.z == 0.0;
}

bool isFinite(const vec3& a)
{
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}
}


// * * * * * * * * * * * * * * * Saffman - Mei  * * * * * * * * * * * * * * //

TEST(SaffmanMei, CorrectionHandComputed)
{
    // Re_p = 1, Re_s = 1 (beta = 0.5): (1 - 0.3314 sqrt .5) e^-0.1 + 0.3314 sqrt .5
    EXPECT_REL(meiLiftCorrection(1.0, 1.0), 0.92713735950304821, tol);
    EXPECT_REL(meiLiftCorrection(22.360679774997898, 50.0), 0.41983936525287197, tol);
    // Re_p > 40 branch: 0.0524 sqrt(0.5 Re_s)
    EXPECT_REL(meiLiftCorrection(111.8033988749895, 50.0), 0.262, tol);
    EXPECT_EQ(meiLiftCorrection(0.0, 3.0), 1.0);
    EXPECT_TRUE(std::isnan(meiLiftCorrection(std::nan(""), 1.0)));
}

TEST(SaffmanMei, ForceHandComputed)
{
    // lagging particle in u = (G y, 0, 0), G = 100: omega = (0, 0, -100)
    EXPECT_TRUE(vecNear(
        saffmanMeiLift(1e-4, rhoW, muW, {0.01, 0.0, 0.0}, {0.0, 0.0, -100.0}),
        {0.0, 1.497326835597423e-09, 0.0}, tol));
    EXPECT_TRUE(vecNear(
        saffmanMeiLift(1e-3, rhoW, muW, {0.02, 0.01, 0.0}, {0.0, 0.0, -50.0}),
        {-4.7944708841966893e-08, 9.5889417683933785e-08, 0.0}, tol));
    EXPECT_TRUE(vecNear(
        saffmanMeiLift(2e-3, rhoA, muA, {0.0, 0.5, 0.3}, {200.0, 0.0, 0.0}),
        {0.0, 3.4467620235663035e-08, -5.7446033726105049e-08}, tol));
    // slip not normal to omega (Re_p > 40 branch)
    EXPECT_TRUE(vecNear(
        saffmanMeiLift(1e-3, rhoW, muW, {0.1, 0.0, 0.05}, {0.0, 30.0, 40.0}),
        {-8.9759427697039166e-08, -2.3935847385877109e-07,
          1.7951885539407833e-07}, tol));
}

TEST(SaffmanMei, SaffmanWithoutCorrection)
{
    // meiCorrection false: Saffman's radius form F = 6.46 mu a^2 U_n
    // sqrt(kappa/nu), a = 0.5 mm in water, w = (0.02, 0.01, 0), kappa = 50
    // (Re_p = 22.4, Re_s = 50, where Mei's factor is 0.42: the corrected
    // force of ForceHandComputed is 0.42 of this one)
    EXPECT_TRUE(vecNear(
        saffmanMeiLift(1e-3, rhoW, muW, {0.02, 0.01, 0.0}, {0.0, 0.0, -50.0}, false),
        {-1.1419774516162744e-07, 2.2839549032325488e-07, 0.0}, tol));
    EXPECT_TRUE(isZero(saffmanMeiLift(1e-3, rhoW, muW, {0.0, 0.0, 0.0}, {0.0, 0.0, -50.0}, false)));
}

TEST(SaffmanMei, SaffmanLimitAndDirection)
{
    // Re_p -> 0 at fixed shear: f -> 1, F -> 1.615 d^2 sqrt(rho mu G) |w|
    const double d = 1e-4, G = 10.0, w = 1e-9;
    const vec3 F = saffmanMeiLift(d, rhoW, muW, {w, 0.0, 0.0}, {0.0, 0.0, -G});
    // (Re_p = 1e-7, Re_s = 0.1: f = 1 - 2.3e-6)
    EXPECT_REL(F.y, 1.615*d*d*std::sqrt(rhoW*muW*G)*w, 1e-5);
    EXPECT_EQ(F.x, 0.0);
    EXPECT_EQ(F.z, 0.0);
    // leading particle (w along -x) goes to -y, towards the slower fluid
    const vec3 Fl = saffmanMeiLift(d, rhoW, muW, {-0.01, 0.0, 0.0}, {0.0, 0.0, -G});
    EXPECT_LT(Fl.y, 0.0);
    // lift normal to both slip and vorticity
    const vec3 w3{0.3, -0.2, 0.1}, om3{5.0, 7.0, -3.0};
    const vec3 F3 = saffmanMeiLift(d, rhoW, muW, w3, om3);
    EXPECT_NEAR((F3.x*w3.x + F3.y*w3.y + F3.z*w3.z)/(mag(F3)*mag(w3)), 0.0, 1e-14);
    EXPECT_NEAR((F3.x*om3.x + F3.y*om3.y + F3.z*om3.z)/(mag(F3)*mag(om3)), 0.0, 1e-14);
}

TEST(SaffmanMei, ZeroWithoutSlipOrShear)
{
    EXPECT_TRUE(isZero(saffmanMeiLift(1e-3, rhoW, muW, {0, 0, 0}, {0, 0, 5})));
    EXPECT_TRUE(isZero(saffmanMeiLift(1e-3, rhoW, muW, {0.1, 0, 0}, {0, 0, 0})));
    // slip parallel to vorticity: no lift
    const vec3 F = saffmanMeiLift(1e-3, rhoW, muW, {0, 0, 0.1}, {0, 0, 5});
    EXPECT_EQ(mag(F), 0.0);
    // finite for vanishing slip / shear
    EXPECT_TRUE(isFinite(saffmanMeiLift(1e-3, rhoW, muW, {1e-300, 0, 0}, {0, 0, 5})));
    EXPECT_TRUE(isFinite(saffmanMeiLift(1e-3, rhoW, muW, {0.1, 0, 0}, {0, 0, 1e-300})));
}


// * * * * * * * * * * * * * * * * * Magnus  * * * * * * * * * * * * * * * * //

TEST(Magnus, CoefficientHandComputed)
{
    EXPECT_REL(oesterleBuiDinhLiftCoeff(66.666666666666657, 6.666666666666667),
               0.22185395874058741, tol);
    EXPECT_REL(oesterleBuiDinhLiftCoeff(1.0, 0.20615528128088303),
               0.21341465212735666, tol);
    EXPECT_REL(oesterleBuiDinhLiftCoeff(421.63702135578393, 96.14803401237306),
               0.42451099289806749, tol);
}

TEST(Magnus, ForceHandComputed)
{
    // sphere spinning about +z in still air, fluid streaming along +x
    EXPECT_TRUE(vecNear(
        magnusLift(1e-3, rhoA, muA, {1.0, 0.0, 0.0}, {0, 0, 0}, {0.0, 0.0, 100.0}),
        {0.0, -1.0454621504238636e-07, 0.0}, tol));
    EXPECT_TRUE(vecNear(
        magnusLift(1e-4, rhoW, muW, {0.0, 0.01, 0.0}, {0, 0, 40.0}, {5.0, 0, 0}),
        {-8.1305448388954009e-11, 0.0, -2.0326362097238502e-11}, tol));
    EXPECT_TRUE(vecNear(
        magnusLift(2e-3, rhoA, muA, {-3.0, 1.0, 0.0}, {0, 0, -600.0}, {0, 200.0, 0}),
        {2.1054243558821595e-06, 6.3162730676464791e-06,
         -4.2108487117643191e-06}, tol));
    // all components of vorticity and spin: Omega = (2, -3, 0)
    EXPECT_TRUE(vecNear(
        magnusLift(5e-4, rhoW, muW, {0.02, -0.01, 0.03}, {6.0, -4.0, 2.0}, {1.0, 1.0, 1.0}),
        {-8.9509795351606506e-09, -5.9673196901071001e-09,
          3.9782131267380668e-09}, tol));
}

TEST(Magnus, RubinowKellerLimitAndDirection)
{
    // Re_p, Re_r -> 0: F -> (pi/8) rho d^3 (Omega x w)
    const double d = 1e-5;
    const vec3 w{1e-6, 0.0, 0.0};
    const vec3 omP{0.0, 0.0, 0.1};         // Omega = -omP
    // Re_p = Re_r = 1e-5: C_LR Re_p/Re_r = 1 - 8e-6
    const vec3 F = magnusLift(d, rhoW, muW, w, {0, 0, 0}, omP);
    const vec3 RK = {0.0, -kPi/8.0*rhoW*d*d*d*0.1*1e-6, 0.0};
    EXPECT_TRUE(vecNear(F, RK, 1e-4));
    // ball moving along +x through still fluid (w = -x) with spin +z:
    // lift along omegaP x v = +y
    const vec3 Fb = magnusLift(1e-3, rhoA, muA, {-2.0, 0, 0}, {0, 0, 0}, {0, 0, 300.0});
    EXPECT_GT(Fb.y, 0.0);
    EXPECT_EQ(Fb.x, 0.0);
    // a particle co-rotating with the fluid (omegaP = curl(u)/2) feels none
    EXPECT_TRUE(isZero(magnusLift(1e-3, rhoA, muA, {1, 0, 0}, {0, 0, 60.0}, {0, 0, 30.0})));
}

TEST(Magnus, ZeroAndFiniteLimits)
{
    EXPECT_TRUE(isZero(magnusLift(1e-3, rhoA, muA, {0, 0, 0}, {0, 0, 0}, {0, 0, 100})));
    EXPECT_TRUE(isZero(magnusLift(1e-3, rhoA, muA, {1, 0, 0}, {0, 0, 0}, {0, 0, 0})));
    // vanishing slip with finite spin: F -> 0 continuously, never NaN
    const vec3 Fs = magnusLift(1e-3, rhoA, muA, {1e-200, 0, 0}, {0, 0, 0}, {0, 0, 100});
    EXPECT_TRUE(isFinite(Fs));
    EXPECT_LT(mag(Fs), 1e-200);
    const vec3 Fo = magnusLift(1e-3, rhoA, muA, {1, 0, 0}, {0, 0, 0}, {0, 0, 1e-200});
    EXPECT_TRUE(isFinite(Fo));
    EXPECT_LT(mag(Fo), 1e-200);
}


// * * * * * * * * * * * * * * Rotational torque  * * * * * * * * * * * * * //

TEST(RotationalTorque, StokesLimit)
{
    // fluid rotating (vorticity 20 -> rotation 10 rad/s), particle at rest:
    // Re_r = 10, T = pi mu d^3 Omega
    const vec3 T = rotationalTorque(1e-3, rhoW, muW, {0, 0, 20.0}, {0, 0, 0});
    EXPECT_TRUE(vecNear(T, {0.0, 0.0, 3.141592653589793e-11}, 1e-14));
    EXPECT_REL(rotationalTorqueCoeff(10.0), 20.106192982974676, 1e-14);
    // Re_r = 32 still Stokes
    EXPECT_TRUE(vecNear(rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {0, 0, -32.0}),
                        {0.0, 0.0, 1.0053096491487338e-10}, 1e-13));
    // all components: Omega = omegaF/2 - omegaP = (2, -3, 0), Re_r = 3.6
    EXPECT_TRUE(vecNear(rotationalTorque(1e-3, rhoW, muW, {6.0, -4.0, 2.0}, {1.0, 1.0, 1.0}),
                        {6.2831853071795853e-12, -9.424777960769378e-12, 0.0}, 1e-13));
    // tiny spin: finite, linear
    const vec3 Ts = rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {1e-200, 0, 0});
    EXPECT_TRUE(isFinite(Ts));
    EXPECT_REL(Ts.x, -kPi*muW*1e-9*1e-200, 1e-12);
}

TEST(RotationalTorque, FiniteReHandComputed)
{
    EXPECT_TRUE(vecNear(rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {0, 100.0, 0}),
                        {0.0, -4.0218749999999996e-10, 0.0}, tol));
    EXPECT_TRUE(vecNear(rotationalTorque(2e-3, rhoA, muA, {0, 0, 0}, {3000.0, 0, 4000.0}),
                        {-4.0462294463174893e-09, 0.0, -5.3949725950899858e-09}, tol));
    EXPECT_TRUE(vecNear(rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {0, 0, -32.0001}),
                        {0.0, 0.0, 1.0068708156581218e-10}, tol));
    EXPECT_REL(rotationalTorqueCoeff(100.0), 2.574, tol);
    // the published branches differ by 0.15 % at Re_r = 32
    EXPECT_NEAR(rotationalTorqueCoeff(32.0 + 1e-9)/rotationalTorqueCoeff(32.0), 1.0015, 1e-4);
}

TEST(RotationalTorque, ZeroAndOpposesRelativeSpin)
{
    EXPECT_TRUE(isZero(rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {0, 0, 0})));
    EXPECT_TRUE(isZero(rotationalTorque(1e-3, rhoW, muW, {0, 0, 8.0}, {0, 0, 4.0})));
    // spinning particle in still fluid is braked
    const vec3 T = rotationalTorque(1e-3, rhoW, muW, {0, 0, 0}, {1.0, 2.0, -3.0});
    EXPECT_LT(T.x, 0.0);
    EXPECT_LT(T.y, 0.0);
    EXPECT_GT(T.z, 0.0);
}
