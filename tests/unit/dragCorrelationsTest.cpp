// Unit tests of src/foamDEM/correlations/dragCorrelations.{H,C}.
//
// Expected values were computed by hand (python3 scratch computation of the
// ORIGINAL published forms: Cd forms, beta forms V_p beta/phi, the
// un-rearranged Beetstra expression, ...), not by calling this code.
// Unless stated otherwise: d = 1e-3 m, water rho = 1000 kg/m^3,
// mu = 1e-3 Pa s, so Re = eps*slip*1000.

#include "dragCorrelations.H"
#include "relNear.h"

#include <cmath>
#include <limits>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double d = 1e-3;
constexpr double rho = 1000.0;
constexpr double mu = 1e-3;
constexpr double tol = 1e-10;
const double stokes = 3.0*kPi*mu*d;    // 9.4247779607693791e-06

bool finiteNonNegative(double x) { return std::isfinite(x) && x >= 0.0; }
}


// * * * * * * * * * * * * * * * particleReynolds  * * * * * * * * * * * * * //

TEST(ParticleReynolds, HandComputed)
{
    // 0.6*1000*0.05*1e-3/1e-3 = 30
    EXPECT_REL(particleReynolds(d, rho, mu, 0.6, 0.05), 30.0, 1e-14);
    // air: 1.2*15*2e-3/1.8e-5 = 2000 (eps = 1)
    EXPECT_REL(particleReynolds(2e-3, 1.2, 1.8e-5, 1.0, 15.0), 2000.0, 1e-14);
    EXPECT_EQ(particleReynolds(d, rho, mu, 0.6, 0.0), 0.0);
}

TEST(ParticleReynolds, VoidFractionIsClamped)
{
    // eps > 1 -> 1: 1*1000*0.05 = 50
    EXPECT_REL(particleReynolds(d, rho, mu, 1.5, 0.05), 50.0, 1e-14);
    // eps <= 0 -> minVoidFraction = 1e-6: 1e-6*50 = 5e-5
    EXPECT_REL(particleReynolds(d, rho, mu, 0.0, 0.05), 5e-5, 1e-12);
    EXPECT_REL(particleReynolds(d, rho, mu, -0.3, 0.05), 5e-5, 1e-12);
    EXPECT_EQ(clampVoidFraction(std::nan("")), minVoidFraction);
}


// * * * * * * * * * * * * * * * Schiller-Naumann * * * * * * * * * * * * * //

TEST(SchillerNaumann, CdHandComputed)
{
    // 24/Re (1 + 0.15 Re^0.687)
    EXPECT_REL(schillerNaumannCd(0.1), 247.40120614554289, tol);
    EXPECT_REL(schillerNaumannCd(10.0), 4.1510659404892616, tol);
    EXPECT_REL(schillerNaumannCd(500.0), 0.56266530162911343, tol);
    EXPECT_REL(schillerNaumannCd(1000.0), 0.438288140019997, tol); // <= 1000
    EXPECT_EQ(schillerNaumannCd(2000.0), 0.44);
}

TEST(SchillerNaumann, ForceCoeffHandComputed)
{
    // (pi/8) Cd rho d^2 slip, Re0 = 1000 slip
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, 1e-3),   // Re0 = 1
               1.0838494654884787e-05, tol);
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, 0.5),    // Re0 = 500
               1.1047907362674424e-04, tol);
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, 2.0),    // Re0 = 2000
               3.455751918948772e-04, tol);
    // air, d = 2e-3, slip = 15: Re0 = 2000, (pi/8) 0.44 1.2 4e-6 15
    EXPECT_REL(schillerNaumannForceCoeff(2e-3, 1.2, 1.8e-5, 15.0),
               1.2440706908215579e-05, tol);
}

TEST(SchillerNaumann, StokesLimit)
{
    // Re -> 0: K -> 3 pi mu d = 9.4247779607693791e-06
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, 0.0),
               9.4247779607693791e-06, 1e-14);
    // slip = 1e-15 -> Re0 = 1e-12, correction 0.15 Re0^0.687 = 8.5e-10
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, 1e-15), stokes, 1e-8);
    // Consistency with Cd form at small but finite Re
    const double s = 1e-7, Re0 = rho*s*d/mu;
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, s),
               kPi/8.0*schillerNaumannCd(Re0)*rho*d*d*s, 1e-12);
}


// * * * * * * * * * * * * * * * * Di Felice * * * * * * * * * * * * * * * * //

TEST(DiFelice, CdAndChiHandComputed)
{
    EXPECT_REL(diFeliceCd(0.5), 55.030063625232465, tol);
    EXPECT_REL(diFeliceCd(31.622776601683793), 2.200992160094335, tol);
    EXPECT_REL(diFeliceCd(1000.0), 0.61119455288698354, tol);

    EXPECT_REL(diFeliceChi(0.5), 3.5716041794812599, tol);
    // log10 Re = 1.5: minimum chi = 3.7 - 0.65 = 3.05
    EXPECT_REL(diFeliceChi(31.622776601683793), 3.05, tol);
    EXPECT_REL(diFeliceChi(1000.0), 3.4889758962170729, tol);
    // Re -> 0 limit
    EXPECT_EQ(diFeliceChi(0.0), 3.7);
    EXPECT_REL(diFeliceChi(1e-30), 3.7, 1e-14);
}

TEST(DiFelice, ForceCoeffHandComputed)
{
    // (pi/8) Cd rho d^2 eps^2 slip eps^-chi
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 0.5, 0.01),     // Re = 5
               7.0937733145788519e-05, tol);
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 0.8, 0.1),      // Re = 80
               6.8330782294657972e-05, tol);
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 0.4, 1e-4),     // Re = 0.04
               1.1209963066205571e-04, tol);
}

TEST(DiFelice, SingleParticleLimitAtEpsOne)
{
    // eps = 1, slip = 0.05 (Re = 50): (pi/8) Cd_DF(50) rho d^2 slip
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 1.0, 0.05),
               3.3634997624888403e-05, tol);
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 1.0, 0.05),
               kPi/8.0*diFeliceCd(50.0)*rho*d*d*0.05, 1e-12);
}

TEST(DiFelice, ZeroSlipLimit)
{
    // slip -> 0: (pi/8) mu d 4.8^2 eps^(1 - 3.7)
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 0.6, 0.0),
               3.5936351657379881e-05, tol);
    EXPECT_REL(diFeliceForceCoeff(d, rho, mu, 1.0, 0.0),     // (pi/8) mu d 23.04
               9.0477868423386043e-06, tol);
    EXPECT_TRUE(finiteNonNegative(diFeliceForceCoeff(d, rho, mu, 0.0, 0.0)));
}

TEST(DiFelice, IsModelAForm)
{
    // Model A (eps^(2-chi)) is eps times the model-B eps^(1-chi) form:
    // compare with the hand value for model B at eps = 0.5, slip = 0.01,
    // 7.0937733145788519e-05/0.5 -> must NOT be returned.
    const double K = diFeliceForceCoeff(d, rho, mu, 0.5, 0.01);
    EXPECT_GT(std::fabs(K - 7.0937733145788519e-05/0.5), 1e-6);
}


// * * * * * * * * * * * * * * * * Koch-Hill * * * * * * * * * * * * * * * * //

TEST(KochHill, ForceCoeffHandComputed)
{
    // V_p beta/phi with beta = 18 mu eps^2 phi (F0 + F3 Re/2)/d^2
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 0.45, 0.01),   // phi >= 0.4
               1.2138031262835683e-04, tol);
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 0.7, 0.05),    // phi < 0.4
               6.5317559752122866e-05, tol);
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 0.95, 0.2),    // dilute
               1.03663917855154e-04, tol);
}

TEST(KochHill, ZeroSlipLimit)
{
    // phi = 0.4: V_p 18 mu eps^2 F0/d^2, F0 = 10 phi/eps^3 -> 6.28318...e-5
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 0.6, 0.0),
               6.2831853071795883e-05, tol);
}

TEST(KochHill, DiluteLimitAtEpsOne)
{
    // eps = 1 (phi = 0): F0 = 1, F3 = 0.0673 + 0.0232 = 0.0905,
    // K = 3 pi mu d (1 + 0.0905/2 Re); Re = 200 here.
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 1.0, 0.2),
               9.4719018505732251e-05, tol);
    // slip = 0, eps = 1: exactly Stokes
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 1.0, 0.0), stokes, 1e-14);
    // continuity towards eps = 1 (hand value at eps = 1 - 1e-9)
    EXPECT_REL(kochHillForceCoeff(d, rho, mu, 1.0 - 1e-9, 0.2),
               9.4719650507158907e-05, 1e-8);
}


// * * * * * * * * * * * * * * * * Gidaspow * * * * * * * * * * * * * * * * //

TEST(Gidaspow, ErgunBranchHandComputed)
{
    // V_p/phi (150 phi^2 mu/(eps d^2) + 1.75 phi rho slip/d)
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.4, 0.01),
               1.2697270308258747e-04, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.5, 0.0),
               7.8539816339744841e-05, tol);
}

TEST(Gidaspow, WenYuBranchHandComputed)
{
    // V_p/phi 3/4 Cd eps phi rho slip eps^-2.65/d, Cd Schiller-Naumann in Re
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.9, 0.05),    // Re = 45
               3.800946570389058e-05, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.9, 2.0),     // Re = 1800: 0.44
               4.1118987980841396e-04, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.999999, 0.05),
               3.0200501333500737e-05, tol);
    // slip -> 0: 3 pi mu d eps^-2.65
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.9, 0.0),
               1.2460299388133755e-05, tol);
}

TEST(Gidaspow, DiscontinuousAtEpsPointEight)
{
    // eps = 0.8 belongs to Ergun; just above, Wen-Yu.
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.8, 0.05),
               6.5449846949787352e-05, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.8 + 1e-12, 0.05),
               4.9219877517049243e-05, 1e-9);
    // slip = 0: Ergun 1.9634954084936207e-05 vs Wen-Yu 1.7024825213131865e-05
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.8, 0.0),
               1.9634954084936207e-05, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 0.8 + 1e-12, 0.0),
               1.7024825213131865e-05, 1e-9);
}

TEST(Gidaspow, WenYuAtEpsOneEqualsSchillerNaumann)
{
    // eps = 1: (pi/8) Cd_SN rho d^2 slip; slip = 0.05 -> Re = 50
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 1.0, 0.05),
               3.0200435575117243e-05, tol);
    // By hand, (pi/8) (Cd Re) mu d with Re = 1000 slip: Re 0, Cd Re = 24
    // (3 pi mu d); Re 1, 24 x 1.15 = 27.6; Re 500, 24 (1 + 0.15 x
    // 500^0.687) = 281.33265; Re 2000, Newton's 0.44 Re = 880
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 1.0, 0.0),
               9.4247779607693791e-06, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 1.0, 1e-3),
               1.0838494654884787e-05, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 1.0, 0.5),
               1.1047907362674424e-04, tol);
    EXPECT_REL(gidaspowForceCoeff(d, rho, mu, 1.0, 2.0),
               3.4557519189487730e-04, tol);
}


// * * * * * * * * * * * * * * * * Beetstra * * * * * * * * * * * * * * * * //

TEST(Beetstra, ForceCoeffHandComputed)
{
    // 3 pi mu d eps F_B (original form, 1.5 sqrt(phi))
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.4, 0.01),    // Re = 4
               1.4463785292010545e-04, tol);
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.7, 0.1),     // Re = 70
               1.0689624250400173e-04, tol);
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.9, 1.0),     // Re = 900
               3.7074731974916491e-04, tol);
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.5, 1e-6),    // Re = 5e-4
               9.6675437685835958e-05, tol);
}

TEST(Beetstra, UsesOnePointFiveNotMisprint)
{
    // eps = 0.6, slip = 0.05: paper (1.5) 1.0087662631078197e-04,
    // misprint (1.15) would give 1.0042599338704545e-04.
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.6, 0.05),
               1.0087662631078197e-04, tol);
}

TEST(Beetstra, ZeroSlipLimit)
{
    // Re -> 0: 3 pi mu d eps (10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi)))
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 0.6, 0.0),
               6.6798889070192799e-05, tol);
    EXPECT_TRUE(finiteNonNegative(beetstraForceCoeff(d, rho, mu, 0.6, 1e-300)));
}

TEST(Beetstra, DiluteLimitAtEpsOne)
{
    // eps = 1, Re = 100:
    // 3 pi mu d (1 + 0.413*100/24 (1 + 8.4*100^-0.343)/(1 + 100^-0.5))
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 1.0, 0.1),
               4.9689775947254067e-05, tol);
    EXPECT_REL(beetstraForceCoeff(d, rho, mu, 1.0, 0.0), stokes, 1e-14);
}


// * * * * * * * * * * * * * * * * Tenneti * * * * * * * * * * * * * * * * * //

TEST(Tenneti, ForceCoeffHandComputed)
{
    // The paper's F is the total fluid-particle force (it includes the
    // mean pressure gradient's share); the model-A drag is (1 - phi) of it:
    // K = 3 pi mu d eps^2 F (hand-computed in python from the paper's form)
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 0.5, 0.02),     // Re = 10
               1.0541910206809134e-04, tol);
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 0.8, 0.1),      // Re = 80
               6.916801405035466e-05, tol);
    // slip = 0, eps = 0.7:
    // 3 pi mu d eps^2 (1/eps^3 + 5.81 phi/eps^3 + 0.48 phi^(1/3)/eps^4)
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 0.7, 0.0),
               4.311216220666117e-05, tol);
}

TEST(Tenneti, SchillerNaumannAtEpsOne)
{
    // eps = 1, Re = 100: 3 pi mu d (1 + 0.15*100^0.687)
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 1.0, 0.1),
               4.2872179693490291e-05, tol);
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 1.0, 0.1),
               schillerNaumannForceCoeff(d, rho, mu, 0.1), 1e-13);
    EXPECT_REL(tennetiForceCoeff(d, rho, mu, 1.0, 0.0), stokes, 1e-14);
}


// * * * * * * * * * * * * * * * * * Rong * * * * * * * * * * * * * * * * * //

TEST(Rong, ChiHandComputed)
{
    // 2.65 (eps+1) - (5.3 - 3.5 eps) eps^2 exp(-(1.5 - log10 Re)^2/2)
    EXPECT_REL(rongChi(31.622776601683793, 0.5), 3.0875, tol);
    EXPECT_REL(rongChi(1.0, 0.8), 4.2505560522266403, tol);
    EXPECT_REL(rongChi(500.0, 1.0), 4.4227628132197827, tol);
    EXPECT_REL(rongChi(0.0, 0.7), 4.505, 1e-14);     // Re -> 0: 2.65 (eps+1)
}

TEST(Rong, ForceCoeffHandComputed)
{
    // (pi/8) Cd_DF rho d^2 slip eps^(2 - chi_Rong)
    EXPECT_REL(rongForceCoeff(d, rho, mu, 0.5, 0.01),
               7.6170637607373106e-05, tol);
    EXPECT_REL(rongForceCoeff(d, rho, mu, 0.8, 0.1),
               7.1355792411673832e-05, tol);
    // slip -> 0: (pi/8) mu d 4.8^2 eps^(1 - 2.65 (eps+1))
    EXPECT_REL(rongForceCoeff(d, rho, mu, 0.7, 0.0),
               3.1584479930467832e-05, tol);
}

TEST(Rong, SingleParticleLimitAtEpsOne)
{
    // eps = 1: same as Di Felice single particle, (pi/8) Cd_DF(50) rho d^2 s
    EXPECT_REL(rongForceCoeff(d, rho, mu, 1.0, 0.05),
               3.3634997624888403e-05, tol);
}


// * * * * * * * * * * * * * * Hoelzer-Sommerfeld * * * * * * * * * * * * * //

TEST(HoelzerSommerfeld, SphereReducesToStandardForm)
{
    // Phi = PhiPerp = PhiPar = 1: 24/Re + 3/sqrt(Re) + 0.42
    EXPECT_REL(hoelzerSommerfeldCd(0.5, 1.0, 1.0, 1.0), 52.662640687119286, 1e-12);
    EXPECT_REL(hoelzerSommerfeldCd(10.0, 1.0, 1.0, 1.0), 3.7686832980505134, 1e-12);
    EXPECT_REL(hoelzerSommerfeldCd(1000.0, 1.0, 1.0, 1.0), 0.53886832980505139, 1e-12);
    for (double Re : {0.01, 3.0, 77.0, 2.5e4})
    {
        EXPECT_REL(hoelzerSommerfeldSimplifiedCd(Re, 1.0, 1.0),
                   24.0/Re + 3.0/std::sqrt(Re) + 0.42, 1e-12);
    }
}

TEST(HoelzerSommerfeld, NonSphericalHandComputed)
{
    // Re = 50, Phi = 0.8, PhiPerp = 0.7, PhiPar = 0.9 (log10):
    EXPECT_REL(hoelzerSommerfeldCd(50.0, 0.8, 0.7, 0.9), 2.0969245958619789, tol);
    // (natural log would give 2.2150666738571418 -> excluded by tolerance)
    // Re = 2, Phi = 0.6, PhiPerp = 0.9, PhiPar = 0.5
    EXPECT_REL(hoelzerSommerfeldCd(2.0, 0.6, 0.9, 0.5), 20.019031134422075, tol);
}

TEST(HoelzerSommerfeld, SimplifiedHandComputed)
{
    // PhiPar replaced by PhiPerp
    EXPECT_REL(hoelzerSommerfeldSimplifiedCd(50.0, 0.8, 0.7), 2.1195063648131685, tol);
    EXPECT_REL(hoelzerSommerfeldSimplifiedCd(2.0, 0.6, 0.9), 18.578547098487533, tol);
}

TEST(HoelzerSommerfeld, InvalidSphericityIsNaN)
{
    EXPECT_TRUE(std::isnan(hoelzerSommerfeldCd(10.0, 0.0, 1.0, 1.0)));
    EXPECT_TRUE(std::isnan(hoelzerSommerfeldSimplifiedCd(10.0, 0.8, -1.0)));
}


// * * * * * * * * * * * * * * Zero slip, all laws  * * * * * * * * * * * * * //

TEST(AllLaws, FiniteNonNegativeAtZeroSlip)
{
    for (double eps : {0.0, 1e-3, 0.3, 0.4, 0.6, 0.8, 0.95, 1.0})
    {
        EXPECT_TRUE(finiteNonNegative(diFeliceForceCoeff(d, rho, mu, eps, 0.0))) << eps;
        EXPECT_TRUE(finiteNonNegative(kochHillForceCoeff(d, rho, mu, eps, 0.0))) << eps;
        EXPECT_TRUE(finiteNonNegative(gidaspowForceCoeff(d, rho, mu, eps, 0.0))) << eps;
        EXPECT_TRUE(finiteNonNegative(beetstraForceCoeff(d, rho, mu, eps, 0.0))) << eps;
        EXPECT_TRUE(finiteNonNegative(tennetiForceCoeff(d, rho, mu, eps, 0.0))) << eps;
        EXPECT_TRUE(finiteNonNegative(rongForceCoeff(d, rho, mu, eps, 0.0))) << eps;
    }
    EXPECT_TRUE(finiteNonNegative(schillerNaumannForceCoeff(d, rho, mu, 0.0)));
}


// * * * * * * * * * * * * * * Terminal velocity * * * * * * * * * * * * * * //

namespace
{
// glass bead d = 1e-3, rho_p = 2500 in water, g = 9.81:
// W = (2500 - 1000) pi d^3/6 9.81
constexpr double W = 7.7047559829289682e-06;
}

TEST(TerminalVelocity, StokesConstantCoefficient)
{
    // K = 3 pi mu d constant -> v = W/(3 pi mu d) = Stokes 0.8175
    const double v = terminalVelocity([](double) { return stokes; }, W);
    EXPECT_REL(v, 0.81749999999999989, 1e-11);
    EXPECT_REL(stokesTerminalVelocity(d, 2500.0, rho, mu, 9.81),
               0.81749999999999989, 1e-14);
    // sand in air: (2650 - 1.2) 9.81 1e-8/(18 1.8e-5)
    EXPECT_REL(stokesTerminalVelocity(1e-4, 2650.0, 1.2, 1.8e-5, 9.81),
               0.80199777777777781, 1e-14);
}

TEST(TerminalVelocity, SchillerNaumannGlassBead)
{
    // independent bisection of (pi/8) Cd_SN rho d^2 v^2 = W
    const double v = terminalVelocity
    (
        [](double s) { return schillerNaumannForceCoeff(d, rho, mu, s); }, W
    );
    EXPECT_REL(v, 0.14594554921597352, 1e-11);
    EXPECT_REL(schillerNaumannForceCoeff(d, rho, mu, v)*v, W, 1e-11);
}

TEST(TerminalVelocity, DiFeliceHinderedSettling)
{
    // eps = 0.6, same bead: bisection of K_DF(0.6, v) v = W
    const double v = terminalVelocity
    (
        [](double s) { return diFeliceForceCoeff(d, rho, mu, 0.6, s); }, W
    );
    EXPECT_REL(v, 0.081014600774425294, 1e-11);
}

TEST(TerminalVelocity, NonPositiveWeightGivesZero)
{
    EXPECT_EQ(terminalVelocity([](double) { return stokes; }, 0.0), 0.0);
    EXPECT_EQ(terminalVelocity([](double) { return stokes; }, -1.0), 0.0);
}

TEST(TerminalVelocity, NoRootGivesNaN)
{
    // K(v) v never reaches W (K decays like 1/v^2)
    const double v = terminalVelocity
    (
        [](double s) { return 1.0/(1.0 + s*s); }, 10.0
    );
    EXPECT_TRUE(std::isnan(v));
}
