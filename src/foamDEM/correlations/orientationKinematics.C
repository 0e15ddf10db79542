#include "orientationKinematics.H"

#include <cmath>

namespace foamDEM
{
namespace correlations
{

namespace
{

std::uint64_t splitmix64(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30))*0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27))*0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

// Uniform in [0, 1) from the top 53 bits
double uniform(std::uint64_t& state)
{
    return double(splitmix64(state) >> 11)*(1.0/9007199254740992.0);
}

void normalise(double q[4])
{
    const double n = std::sqrt(q[0]*q[0] + q[1]*q[1] + q[2]*q[2] + q[3]*q[3]);
    for (int k = 0; k < 4; ++k) q[k] /= n;
}

} // End anonymous namespace


void randomOrientation(std::uint64_t key, double q[4])
{
    const double twoPi = 6.283185307179586476925;
    std::uint64_t state = key;
    const double u1 = uniform(state);
    const double u2 = uniform(state);
    const double u3 = uniform(state);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    q[0] = a*std::sin(twoPi*u2);
    q[1] = a*std::cos(twoPi*u2);
    q[2] = b*std::sin(twoPi*u3);
    q[3] = b*std::cos(twoPi*u3);
}


void rotateBySpin(double q[4], const double omega[3], double dt)
{
    const double w = std::sqrt
    (
        omega[0]*omega[0] + omega[1]*omega[1] + omega[2]*omega[2]
    );
    const double theta = w*dt;
    if (!(theta > 0.0)) return;
    const double c = std::cos(0.5*theta), s = std::sin(0.5*theta)/w;
    const double r[4] = {c, s*omega[0], s*omega[1], s*omega[2]};
    // r q (Hamilton product)
    const double p[4] =
    {
        r[0]*q[0] - r[1]*q[1] - r[2]*q[2] - r[3]*q[3],
        r[0]*q[1] + r[1]*q[0] + r[2]*q[3] - r[3]*q[2],
        r[0]*q[2] - r[1]*q[3] + r[2]*q[0] + r[3]*q[1],
        r[0]*q[3] + r[1]*q[2] - r[2]*q[1] + r[3]*q[0]
    };
    for (int k = 0; k < 4; ++k) q[k] = p[k];
    normalise(q);
}


void quaternionToMatrix(const double q[4], double R[3][3])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0][0] = 1 - 2*(y*y + z*z); R[0][1] = 2*(x*y - w*z); R[0][2] = 2*(x*z + w*y);
    R[1][0] = 2*(x*y + w*z); R[1][1] = 1 - 2*(x*x + z*z); R[1][2] = 2*(y*z - w*x);
    R[2][0] = 2*(x*z - w*y); R[2][1] = 2*(y*z + w*x); R[2][2] = 1 - 2*(x*x + y*y);
}

} // End namespace correlations
} // End namespace foamDEM
