// Unit tests of correlations/orientationKinematics.H: the orientation of
// shaped spheres (random start, rotation by the spin, rotation matrix)
#include "orientationKinematics.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
}

// A quarter turn about z at 2 rad/s for pi/4 s maps body x to space y
TEST(OrientationKinematics, QuarterTurnAboutZ)
{
    double q[4] = {1, 0, 0, 0};
    const double omega[3] = {0, 0, 2.0};
    rotateBySpin(q, omega, kPi/4);
    double R[3][3];
    quaternionToMatrix(q, R);
    EXPECT_NEAR(R[0][0], 0.0, 1e-15);   // body x -> (0, 1, 0)
    EXPECT_NEAR(R[1][0], 1.0, 1e-15);
    EXPECT_NEAR(R[0][1], -1.0, 1e-15);  // body y -> (-1, 0, 0)
    EXPECT_NEAR(R[2][2], 1.0, 1e-15);
}

// Rotations about one axis add; composing about different axes follows
// the space-frame order (the later spin acts on the rotated body)
TEST(OrientationKinematics, RotationsCompose)
{
    double q[4] = {1, 0, 0, 0};
    const double wx[3] = {1.0, 0, 0}, wz[3] = {0, 0, 1.0};
    rotateBySpin(q, wz, kPi/2);     // body x -> y
    rotateBySpin(q, wx, kPi/2);     // then about space x: y -> z
    double R[3][3];
    quaternionToMatrix(q, R);
    EXPECT_NEAR(R[0][0], 0.0, 1e-15);
    EXPECT_NEAR(R[1][0], 0.0, 1e-15);
    EXPECT_NEAR(R[2][0], 1.0, 1e-15);
    // many small steps at constant spin = one large step
    double a[4] = {0.5, 0.5, 0.5, 0.5}, b[4] = {0.5, 0.5, 0.5, 0.5};
    const double w[3] = {0.3, -1.2, 2.0};
    for (int k = 0; k < 1000; ++k) rotateBySpin(a, w, 1e-3);
    rotateBySpin(b, w, 1.0);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-12);
}

TEST(OrientationKinematics, ZeroSpinKeepsOrientation)
{
    double q[4] = {0.5, -0.5, 0.5, 0.5};
    const double w[3] = {0, 0, 0};
    rotateBySpin(q, w, 1.0);
    EXPECT_EQ(q[0], 0.5);
    EXPECT_EQ(q[1], -0.5);
}

// R is orthonormal and right-handed for random quaternions
TEST(OrientationKinematics, MatrixIsRotation)
{
    for (std::uint64_t key = 1; key < 50; ++key)
    {
        double q[4], R[3][3];
        randomOrientation(key, q);
        EXPECT_NEAR(q[0]*q[0] + q[1]*q[1] + q[2]*q[2] + q[3]*q[3], 1.0, 1e-14);
        quaternionToMatrix(q, R);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
            {
                double d = 0;
                for (int k = 0; k < 3; ++k) d += R[k][i]*R[k][j];
                EXPECT_NEAR(d, i == j ? 1.0 : 0.0, 1e-14);
            }
        const double det =
            R[0][0]*(R[1][1]*R[2][2] - R[1][2]*R[2][1])
          - R[0][1]*(R[1][0]*R[2][2] - R[1][2]*R[2][0])
          + R[0][2]*(R[1][0]*R[2][1] - R[1][1]*R[2][0]);
        EXPECT_NEAR(det, 1.0, 1e-14);
    }
}

// Uniform orientations: the body x axis is isotropic, so over N keys each
// space component c of it has mean 0 (sd 1/sqrt(3N)) and <c^2> = 1/3
// (sd sqrt(4/45/N)); bounds at 5 sd for N = 20000
TEST(OrientationKinematics, RandomOrientationIsIsotropic)
{
    const int N = 20000;
    double m[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
    for (int n = 0; n < N; ++n)
    {
        double q[4], R[3][3];
        randomOrientation(std::uint64_t(n) + 1, q);
        quaternionToMatrix(q, R);
        for (int i = 0; i < 3; ++i)
        {
            m[i] += R[i][0]/N;
            m2[i] += R[i][0]*R[i][0]/N;
        }
    }
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_LT(std::fabs(m[i]), 5/std::sqrt(3.0*N));
        EXPECT_LT(std::fabs(m2[i] - 1.0/3.0), 5*std::sqrt(4.0/45.0/N));
    }
    // the same key gives the same orientation
    double a[4], b[4];
    randomOrientation(12345, a);
    randomOrientation(12345, b);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]);
}
