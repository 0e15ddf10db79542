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

vec3 sum(const std::vector<vec3>& v)
{
    vec3 s{0, 0, 0};
    for (const vec3& a : v) { s.x += a.x; s.y += a.y; s.z += a.z; }
    return s;
}

vec3 moment(const std::vector<vec3>& x, const std::vector<vec3>& F)
{
    vec3 c{0, 0, 0};
    for (const vec3& a : x) { c.x += a.x; c.y += a.y; c.z += a.z; }
    const double n = double(x.size());
    c = vec3{c.x/n, c.y/n, c.z/n};
    vec3 m{0, 0, 0};
    for (size_t k = 0; k < x.size(); ++k)
    {
        const vec3 r{x[k].x - c.x, x[k].y - c.y, x[k].z - c.z};
        const vec3 t = cross(r, F[k]);
        m.x += t.x; m.y += t.y; m.z += t.z;
    }
    return m;
}

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

// Sum F_k = 0 and sum r_k x F_k = T for a plate-like grid (J invertible)
TEST(TorqueAsSphereForces, PlateGridDeliversTorque)
{
    std::vector<vec3> x;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 3; ++j)
            x.push_back(vec3{0.3 + 0.7e-3*i, -0.1 + 0.4e-3*j, 0.05});
    // rotate the grid off the axes
    const double c = std::cos(0.3), sn = std::sin(0.3);
    for (vec3& p : x) p = vec3{c*p.x - sn*p.z, p.y, sn*p.x + c*p.z};
    const vec3 T{1.3e-8, -2.1e-8, 0.7e-8};
    std::vector<vec3> F(x.size());
    const vec3 got = torqueAsSphereForces(int(x.size()), x.data(), T, F.data());
    EXPECT_LT(mag(sum(F)), 1e-11*mag(F[0]));   // x ~ 0.3 m, r ~ 1 mm: round-off
    EXPECT_LT(dist(moment(x, F), T), 1e-12*mag(T));
    EXPECT_LT(dist(got, T), 1e-12*mag(T));
}

// A straight chain (rod): J is singular along the axis. The transverse
// torque is delivered exactly, the axial part is dropped.
TEST(TorqueAsSphereForces, RodDropsAxialPart)
{
    const vec3 e{0.6, 0.0, 0.8};
    std::vector<vec3> x;
    for (int k = 0; k < 9; ++k)
    {
        const double s = (k - 4)*0.55e-3;
        x.push_back(vec3{0.06 + s*e.x, 0.06 + s*e.y, 0.2 + s*e.z});
    }
    const vec3 Tperp{0.8e-8, 1.5e-8, -0.6e-8};   // . e = 0
    const vec3 T{Tperp.x + 2e-8*e.x, Tperp.y + 2e-8*e.y, Tperp.z + 2e-8*e.z};
    std::vector<vec3> F(x.size());
    const vec3 got = torqueAsSphereForces(int(x.size()), x.data(), T, F.data());
    EXPECT_LT(mag(sum(F)), 1e-11*mag(F[0]));   // x ~ 0.3 m, r ~ 1 mm: round-off
    EXPECT_LT(dist(moment(x, F), Tperp), 1e-10*mag(Tperp));
    EXPECT_LT(dist(got, Tperp), 1e-10*mag(Tperp));
    for (const vec3& f : F)
    {
        EXPECT_LT(std::fabs(f.x*e.x + f.y*e.y + f.z*e.z), 1e-12*mag(F[0]));
    }
}

TEST(TorqueAsSphereForces, SingleSphereGetsNothing)
{
    const vec3 x{0.1, 0.2, 0.3};
    vec3 F{1, 1, 1};
    const vec3 got = torqueAsSphereForces(1, &x, vec3{1e-8, 0, 0}, &F);
    EXPECT_EQ(mag(F), 0.0);
    EXPECT_EQ(mag(got), 0.0);
}
