// Unit tests of src/foamDEM/correlations/selfInducedVelocity.{H,C}.
// Expected values are closed forms of the papers' limits, computed by hand
// (not by calling this code):
//  - Stokes, Gaussian-regularised force of standard deviation sigma read at
//    its centre: u = F sqrt(2/pi)/(6 pi mu sigma) (the regularised
//    Stokeslet's centre value: F/(6 pi mu) <1/r> over the Gaussian,
//    <1/r> = sqrt(2/pi)/sigma; Ireland & Desjardins 2017, Balachandar et
//    al. 2019 Stokes limit);
//  - Stokes, the implicit diffusion filter (1 + k^2 L^2)^-1 on the source
//    and on the read: u = F/(12 pi mu L);
//  - Oseen, slip U -> inf, Gaussian exp(-k^2 a^2): u = F/(8 pi rho U a^2)
//    (momentum flux; Balachandar et al. 2019's decay as 1/Re_sigma);
//  - I(q) = 2q(1+q^2) atan(1/q) - 2q^2: I(1) = pi - 2, I -> 4/3.

#include "selfInducedVelocity.H"
#include "relNear.h"

#include <cmath>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double rho = 1000, mu = 1e-3;
}

TEST(OseenAngularFactor, ClosedForms)
{
    EXPECT_EQ(oseenAngularFactor(0), 0.0);
    EXPECT_REL(oseenAngularFactor(1), kPi - 2, 1e-14);
    // small q: I ~ pi q - 4 q^2
    EXPECT_REL(oseenAngularFactor(1e-4), kPi*1e-4 - 4e-8, 1e-6);
    // the series branch joins the closed form at q = 50
    EXPECT_REL(oseenAngularFactor(49.999), oseenAngularFactor(50.001), 1e-6);
    EXPECT_REL(oseenAngularFactor(1e6), 4.0/3.0, 1e-12);
}

TEST(SelfInducedMobility, StokesGaussianCentreValue)
{
    // A Gaussian of std sigma read at the centre: G = exp(-k^2 sigma^2/2)
    for (double sigma : {1e-4, 1e-3, 2.5e-3})
    {
        EXPECT_REL(selfInducedMobility(rho, mu, 0, sigma/std::sqrt(2.0), 0),
                   std::sqrt(2/kPi)/(6*kPi*mu*sigma), 1e-8);
    }
}

TEST(SelfInducedMobility, StokesDiffusionFilter)
{
    const double L = 3e-3;
    EXPECT_REL(selfInducedMobility(rho, mu, 0, 0, L), 1/(12*kPi*mu*L), 1e-8);
    // a vanishing Gaussian factor changes nothing
    EXPECT_REL(selfInducedMobility(rho, mu, 0, 1e-9, L), 1/(12*kPi*mu*L), 1e-6);
}

TEST(SelfInducedMobility, OseenLimits)
{
    const double a = 1e-3;
    const double stokes = selfInducedMobility(rho, mu, 0, a, 0);
    // slow slip: Stokes (Re_a = 1e-4)
    EXPECT_REL(selfInducedMobility(rho, mu, 1e-7, a, 0), stokes, 1e-3);
    // fast slip: momentum flux, 1/(8 pi rho U a^2) (Re_a = 1e5)
    EXPECT_REL(selfInducedMobility(rho, mu, 100, a, 0),
               1/(8*kPi*rho*100*a*a), 1e-4);
    // decreasing in the slip
    double last = stokes;
    for (double U : {1e-3, 1e-2, 1e-1, 1.0})
    {
        const double m = selfInducedMobility(rho, mu, U, a, 0);
        EXPECT_LT(m, last);
        last = m;
    }
    // no kernel: a point force
    EXPECT_TRUE(std::isinf(selfInducedMobility(rho, mu, 1, 0, 0)));
}

TEST(SelfInducedMobility, SettlingSphereCell)
{
    // The tutorial's sphere at terminal velocity (U = 0.1459 m/s) in 8 mm
    // cells: a^2 = h^2/12; the asymptote 1/(8 pi rho U a^2) within 0.5 %
    // (Re_a = 337)
    const double h = 8e-3, U = 0.1459, a = h/std::sqrt(12.0);
    EXPECT_REL(selfInducedMobility(rho, mu, U, a, 0),
               1/(8*kPi*rho*U*a*a), 5e-3);
}

TEST(UndisturbedSlipFactor, Values)
{
    EXPECT_REL(undisturbedSlipFactor(100, 1e-3), 1/(1 - 0.1), 1e-14);
    EXPECT_EQ(undisturbedSlipFactor(0, 1e-3), 1.0);
    // m K limited to 0.5 by default
    EXPECT_REL(undisturbedSlipFactor(1e4, 1e-3), 2.0, 1e-14);
    EXPECT_REL(undisturbedSlipFactor(1e4, 1e-3, 0.8), 5.0, 1e-12);
}

TEST(KernelCentreValue, ClosedForms)
{
    // Gaussian exp(-k^2 a^2): a normal density of variance 2 a^2 per
    // direction, (4 pi a^2)^(-3/2) = 1/(8 pi^(3/2) a^3) at its centre
    const double a = 1e-3;
    EXPECT_REL(kernelCentreValue(a, 0), 1/(8*std::pow(kPi, 1.5)*a*a*a), 1e-8);
    // filter alone: 1/(2 pi^2) int k^2/(1 + k^2 L^2)^2 dk = 1/(8 pi L^3)
    const double L = 2e-3;
    EXPECT_REL(kernelCentreValue(0, L), 1/(8*kPi*L*L*L), 1e-14);
    // (a 1e-4 L Gaussian stretches the quadrature over 21 decades)
    EXPECT_REL(kernelCentreValue(1e-7, L), 1/(8*kPi*L*L*L), 1e-3);
    // a cell's top-hat (a^2 = h^2/12): 0.933/h^3, the cube's exact 1/h^3
    // within 7 %
    const double h = 1e-3;
    EXPECT_NEAR(kernelCentreValue(h/std::sqrt(12.0), 0)*h*h*h, 0.933, 1e-3);
    EXPECT_TRUE(std::isinf(kernelCentreValue(0, 0)));
}
