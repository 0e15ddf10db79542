// Unit tests of the pitching-torque kernels and of the split of a torque
// into sphere forces (src/foamDEM/correlations/liftTorqueCorrelations.H,
// items 4 and 5).
//
// Expected C_T values were computed by hand in a separate python3 scratch
// script from the printed correlation
//   C_T = (c1/Re^c2 + c3/Re^c4) sin^(c5 + c6 Re^c7) cos^(c8 + c9 Re^c10)
// (Zastawny et al. 2012), and the torque from |T| = (pi/16) C_T rho d^3 |w|^2.

#include "liftTorqueCorrelations.H"
#include "relNear.h"

#include <cmath>
#include <vector>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double deg = kPi/180.0;
constexpr double tol = 1e-12;

double dist(const vec3& a, const vec3& b)
{
    return mag(vec3{a.x - b.x, a.y - b.y, a.z - b.z});
}
}


TEST(PitchingTorque, ZastawnyProlate52HandValues)
{
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate52, 1, 45*deg), 1.2335205488194805, tol);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate52, 10, 30*deg), 0.6366159734494764, tol);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate52, 10, 45*deg), 0.7300230951023962, tol);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate52, 100, 60*deg), 0.39838062555952347, tol);
}

TEST(PitchingTorque, ZastawnyProlate54HandValues)
{
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate54, 1, 30*deg), 0.22565652454801777, tol);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate54, 10, 45*deg), 0.1727784517181961, tol);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear,
        pitchingTorqueCoeff(zastawnyProlate54, 100, 60*deg), 0.1004503468141425, tol);
}

TEST(PitchingTorque, ZeroAtAlignedAndBroadside)
{
    EXPECT_EQ(pitchingTorqueCoeff(zastawnyProlate52, 10, 0.0), 0.0);
    EXPECT_EQ(pitchingTorqueCoeff(zastawnyProlate52, 10, 0.5*kPi), 0.0);
    const vec3 w{0, 0, 0.1};
    for (bool flat : {false, true})
    {
        const vec3 along = pitchingTorque(zastawnyProlate52, 2e-3, 1000, 1e-3, w, vec3{0, 0, -2}, flat);
        const vec3 normal = pitchingTorque(zastawnyProlate52, 2e-3, 1000, 1e-3, w, vec3{1, 0, 0}, flat);
        const vec3 noSlip = pitchingTorque(zastawnyProlate52, 2e-3, 1000, 1e-3, vec3{0, 0, 0}, vec3{1, 0, 1}, flat);
        EXPECT_EQ(mag(along), 0.0);
        EXPECT_LT(mag(normal), 1e-25);
        EXPECT_EQ(mag(noSlip), 0.0);
    }
}

// Rod (d_v = 2.1042 mm) in a glycerol-water mixture (rho 1000, mu 1e-2),
// slip 0.12 m/s upward (body falling), axis 45 deg from the vertical in
// the x-z plane: Re = 25.2504, |T| = 1.5850748988892202e-08 N m.
TEST(PitchingTorque, RodAt45DegTurnsBroadside)
{
    const double s = std::sqrt(0.5);
    const vec3 w{0, 0, 0.12};
    const vec3 T = pitchingTorque(zastawnyProlate52, 2.1042e-3, 1000, 1e-2, w, vec3{s, 0, s}, false);
    EXPECT_NEAR(T.x, 0.0, 1e-24);
    EXPECT_NEAR(T.z, 0.0, 1e-24);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear, T.y, 1.5850748988892202e-08, 1e-10);
    // the axis's sign does not matter
    const vec3 T2 = pitchingTorque(zastawnyProlate52, 2.1042e-3, 1000, 1e-2, w, vec3{-s, 0, -s}, false);
    EXPECT_LT(dist(T, T2), 1e-22);
    // rotating the axis about T lowers its vertical component: d a = T x a
    const vec3 da = cross(T, vec3{s, 0, s});
    EXPECT_LT(da.z, 0.0);
}

// Flat body: the face normal turns towards the slip, same magnitude at the
// same incidence (45 deg between w and the face)
TEST(PitchingTorque, PlateNormalTurnsTowardsSlip)
{
    const double s = std::sqrt(0.5);
    const vec3 w{0, 0, 0.12};
    const vec3 n{s, 0, s};
    const vec3 T = pitchingTorque(zastawnyProlate52, 2.1042e-3, 1000, 1e-2, w, n, true);
    EXPECT_PRED_FORMAT3(foamDEMTest::relNear, T.y, -1.5850748988892202e-08, 1e-10);
    const vec3 dn = cross(T, n);
    EXPECT_GT(dn.z, 0.0);
}

