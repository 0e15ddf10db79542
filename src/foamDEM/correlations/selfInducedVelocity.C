/*---------------------------------------------------------------------------*\
  foamDEM: CFD-DEM coupling (OpenFOAM + LIGGGHTS)
-------------------------------------------------------------------------------
    The self-induced velocity of a regularised force (selfInducedVelocity.H).
\*---------------------------------------------------------------------------*/

#include "selfInducedVelocity.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
    constexpr double kPi = 3.14159265358979323846;
}


double foamDEM::correlations::oseenAngularFactor(double q)
{
    q = std::fabs(q);
    if (q > 50)
    {
        // 2 q (1 + q^2) atan(1/q) - 2 q^2 cancels; its series in 1/q^2
        const double x = 1/(q*q);
        return 4.0/3.0 - 4.0/15.0*x + 4.0/35.0*x*x - 4.0/63.0*x*x*x;
    }
    if (q == 0)
    {
        return 0;
    }
    return 2*q*(1 + q*q)*std::atan(1/q) - 2*q*q;
}


double foamDEM::correlations::selfInducedMobility
(
    double rho, double mu, double slip, double a, double L
)
{
    a = std::max(a, 0.0);
    L = std::max(L, 0.0);
    if (a <= 0 && L <= 0)
    {
        return std::numeric_limits<double>::infinity();
    }
    const double U = std::fabs(slip);
    // q = k/kOseen; U = 0 is the Stokes limit (q infinite, I = 4/3)
    const double kOseen = rho*U/mu;

    const double ell = std::max(a, L);
    const double kLo = 1e-7/ell;
    const double kHi = a > 0 ? 6.5/a : 1e5/L;

    auto f = [&](double k)
    {
        const double kL2 = k*k*L*L;
        const double G = std::exp(-k*k*a*a)/((1 + kL2)*(1 + kL2));
        const double I =
            kOseen > 0 ? oseenAngularFactor(k/kOseen) : 4.0/3.0;
        return G*I;
    };

    // Composite Simpson in t = ln k: int f dk = int f(k) k dt
    const int n = 400;
    const double t0 = std::log(kLo);
    const double dt = (std::log(kHi) - t0)/n;
    double sum = 0;
    for (int i = 0; i <= n; ++i)
    {
        const double k = std::exp(t0 + i*dt);
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w*f(k)*k;
    }
    double integral = sum*dt/3;
    // 0 < k < kLo: f is about constant there (or rises as k)
    integral += f(kLo)*kLo;

    return integral/(4*kPi*kPi*mu);
}


double foamDEM::correlations::kernelCentreValue(double a, double L)
{
    a = std::max(a, 0.0);
    L = std::max(L, 0.0);
    if (a <= 0 && L <= 0)
    {
        return std::numeric_limits<double>::infinity();
    }
    if (a <= 0)
    {
        return 1/(8*kPi*L*L*L);
    }
    // Composite Simpson in t = ln k, as selfInducedMobility
    const double ell = std::max(a, L);
    const double kLo = 1e-7/ell;
    const double kHi = 6.5/a;
    const int n = 400;
    const double t0 = std::log(kLo);
    const double dt = (std::log(kHi) - t0)/n;
    double sum = 0;
    for (int i = 0; i <= n; ++i)
    {
        const double k = std::exp(t0 + i*dt);
        const double kL2 = k*k*L*L;
        const double G = std::exp(-k*k*a*a)/((1 + kL2)*(1 + kL2));
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w*k*k*G*k;
    }
    return sum*dt/3/(2*kPi*kPi);
}


double foamDEM::correlations::undisturbedSlipFactor
(
    double m, double K, double maxMK
)
{
    const double mK = std::min(std::max(m*K, 0.0), maxMK);
    return 1/(1 - mK);
}
