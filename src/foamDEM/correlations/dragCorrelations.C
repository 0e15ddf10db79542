/*---------------------------------------------------------------------------*\
  foamDEM: CFD-DEM coupling (OpenFOAM + LIGGGHTS)
-------------------------------------------------------------------------------
File
    dragCorrelations.C

Description
    Implementation of the pure drag kernels; see dragCorrelations.H for the
    equations, conventions and references.

\*---------------------------------------------------------------------------*/

#include "dragCorrelations.H"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace foamDEM
{
namespace correlations
{

namespace
{

constexpr double pi = 3.14159265358979323846;

//- Non-negative slip magnitude (NaN-safe: NaN -> 0).
inline double slipMagnitude(double slip)
{
    const double s = std::fabs(slip);
    return (s > 0.0) ? s : 0.0;
}

//- Product Cd*Re of Schiller-Naumann (finite at Re = 0).
inline double schillerNaumannCdRe(double Re)
{
    if (Re > 1000.0)
    {
        return 0.44*Re;
    }
    return 24.0*(1.0 + 0.15*std::pow(Re, 0.687));
}

//- Common Di Felice / Rong evaluation, model A:
//  (pi/8) Cd rho d^2 slip eps^(2-chi) = (pi/8) mu d (0.63 sqrt(Re)+4.8)^2
//  eps^(1-chi), with Re = eps rho slip d/mu.
inline double diFeliceTypeCoeff
(
    double d, double mu, double eps, double Re, double chi
)
{
    const double a = 0.63*std::sqrt(Re) + 4.8;
    return 0.125*pi*mu*d*a*a*std::pow(eps, 1.0 - chi);
}

} // End anonymous namespace


double clampVoidFraction(double eps)
{
    if (!(eps > minVoidFraction))
    {
        return minVoidFraction;   // also catches NaN
    }
    return std::min(eps, 1.0);
}


double particleReynolds(double d, double rho, double mu, double eps, double slip)
{
    return clampVoidFraction(eps)*rho*slipMagnitude(slip)*d/mu;
}


double schillerNaumannCd(double Re)
{
    if (Re > 1000.0)
    {
        return 0.44;
    }
    return 24.0/Re*(1.0 + 0.15*std::pow(Re, 0.687));
}


double schillerNaumannForceCoeff(double d, double rho, double mu, double slip)
{
    const double Re0 = rho*slipMagnitude(slip)*d/mu;
    // (pi/8) Cd rho d^2 slip = (pi/8) (Cd Re0) mu d
    return 0.125*pi*schillerNaumannCdRe(Re0)*mu*d;
}


double diFeliceCd(double Re)
{
    const double a = 0.63 + 4.8/std::sqrt(Re);
    return a*a;
}


double diFeliceChi(double Re)
{
    if (!(Re > 0.0))
    {
        return 3.7;
    }
    const double x = 1.5 - std::log10(Re);
    return 3.7 - 0.65*std::exp(-0.5*x*x);
}


double diFeliceForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double Re = particleReynolds(d, rho, mu, e, slip);
    return diFeliceTypeCoeff(d, mu, e, Re, diFeliceChi(Re));
}


double kochHillForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double phi = 1.0 - e;
    const double Re = particleReynolds(d, rho, mu, e, slip);

    double F0;
    if (phi < 0.4)
    {
        // phi ln(phi) -> 0 as phi -> 0
        const double phiLnPhi = (phi > 0.0) ? phi*std::log(phi) : 0.0;
        F0 =
            (1.0 + 3.0*std::sqrt(0.5*phi) + (135.0/64.0)*phiLnPhi + 16.14*phi)
           /(1.0 + 0.681*phi - 8.48*phi*phi + 8.16*phi*phi*phi);
    }
    else
    {
        F0 = 10.0*phi/(e*e*e);
    }

    const double F3 = 0.0673 + 0.212*phi + 0.0232/std::pow(e, 5);

    // V_p beta/phi = (pi d^3/6) 18 mu eps^2 (F0 + F3 Re/2)/d^2
    return 3.0*pi*mu*d*e*e*(F0 + 0.5*F3*Re);
}


double gidaspowForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double phi = 1.0 - e;
    const double s = slipMagnitude(slip);

    if (e <= 0.8)
    {
        // Ergun: V_p/phi (150 phi^2 mu/(eps d^2) + 1.75 phi rho s/d)
        return pi*d/6.0*(150.0*phi*mu/e + 1.75*rho*s*d);
    }

    // Wen-Yu: V_p/phi (3/4) Cd eps phi rho s eps^-2.65/d
    //       = (pi/8) Cd Re mu d eps^-2.65 (Re = eps rho s d/mu)
    const double Re = e*rho*s*d/mu;
    return 0.125*pi*schillerNaumannCdRe(Re)*mu*d*std::pow(e, -2.65);
}


double beetstraForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double phi = 1.0 - e;
    const double Re = particleReynolds(d, rho, mu, e, slip);

    const double e2 = e*e;
    const double FLow = 10.0*phi/e2 + e2*(1.0 + 1.5*std::sqrt(phi));

    // 0.413 Re/(24 e^2) [1/e + 3 e phi + 8.4 Re^-0.343]
    //   / [1 + 10^(3 phi) Re^-a],  a = (1 + 4 phi)/2
    // = 0.413/(24 e^2) [Re (1/e + 3 e phi) + 8.4 Re^0.657]
    //   * Re^a/(Re^a + 10^(3 phi))          (-> 0 as Re -> 0)
    double FRe = 0.0;
    if (Re > 0.0)
    {
        const double a = 0.5*(1.0 + 4.0*phi);
        const double ReA = std::pow(Re, a);
        FRe =
            0.413/(24.0*e2)
           *(Re*(1.0/e + 3.0*e*phi) + 8.4*std::pow(Re, 0.657))
           *ReA/(ReA + std::pow(10.0, 3.0*phi));
    }

    return 3.0*pi*mu*d*e*(FLow + FRe);
}


double tennetiForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double phi = 1.0 - e;
    const double Re = particleReynolds(d, rho, mu, e, slip);

    const double e3 = e*e*e;
    const double phi3 = phi*phi*phi;

    const double F =
        (1.0 + 0.15*std::pow(Re, 0.687))/e3
      + 5.81*phi/e3
      + 0.48*std::cbrt(phi)/(e3*e)
      + phi3*Re*(0.95 + 0.61*phi3/(e*e));

    // F is the total force of the particle-resolved simulations, mean
    // pressure gradient included; the drag without it (model A, as every
    // law here) is (1 - phi) of it
    return 3.0*pi*mu*d*e*e*F;
}


double rongChi(double Re, double eps)
{
    const double e = clampVoidFraction(eps);
    const double chi0 = 2.65*(e + 1.0);
    if (!(Re > 0.0))
    {
        return chi0;
    }
    const double x = 1.5 - std::log10(Re);
    return chi0 - (5.3 - 3.5*e)*e*e*std::exp(-0.5*x*x);
}


double rongForceCoeff
(
    double d, double rho, double mu, double eps, double slip
)
{
    const double e = clampVoidFraction(eps);
    const double Re = particleReynolds(d, rho, mu, e, slip);
    return diFeliceTypeCoeff(d, mu, e, Re, rongChi(Re, e));
}


double hoelzerSommerfeldCd
(
    double Re,
    double sphericity,
    double crosswiseSphericity,
    double lengthwiseSphericity
)
{
    if
    (
        !(sphericity > 0.0)
     || !(crosswiseSphericity > 0.0)
     || !(lengthwiseSphericity > 0.0)
    )
    {
        return std::numeric_limits<double>::quiet_NaN();
    }

    // -log10(Phi) >= 0 for Phi <= 1; guard round-off above 1
    const double mLog = std::max(0.0, -std::log10(sphericity));

    return
        8.0/(Re*std::sqrt(lengthwiseSphericity))
      + 16.0/(Re*std::sqrt(sphericity))
      + 3.0/(std::sqrt(Re)*std::pow(sphericity, 0.75))
      + 0.42*std::pow(10.0, 0.4*std::pow(mLog, 0.2))/crosswiseSphericity;
}


double hoelzerSommerfeldSimplifiedCd
(
    double Re,
    double sphericity,
    double crosswiseSphericity
)
{
    return hoelzerSommerfeldCd
    (
        Re, sphericity, crosswiseSphericity, crosswiseSphericity
    );
}


double terminalVelocity
(
    const std::function<double(double slip)>& forceCoeff,
    double netWeight
)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();

    if (!(netWeight > 0.0))
    {
        return 0.0;
    }

    auto f = [&forceCoeff, netWeight](double v)
    {
        return forceCoeff(v)*v - netWeight;
    };

    // Bracket: f(0) = -netWeight < 0; first guess from the slip -> 0
    // coefficient (exact for a constant K), then doubling.
    const double K0 = forceCoeff(0.0);
    double hi = netWeight/K0;
    if (!(K0 > 0.0) || !std::isfinite(hi) || !(hi > 0.0))
    {
        hi = 1.0;
    }

    double lo = 0.0;
    double flo = -netWeight;
    double fhi = f(hi);
    for (int i = 0; fhi < 0.0; ++i)
    {
        if (i > 1100)
        {
            return nan;
        }
        lo = hi;
        flo = fhi;
        hi *= 2.0;
        fhi = f(hi);
    }
    if (!std::isfinite(fhi) || !std::isfinite(hi))
    {
        return nan;
    }
    if (fhi == 0.0)
    {
        return hi;
    }

    // Brent's method (after Brent 1973 / Numerical Recipes zbrent)
    const double relTol = 1e-12;

    double a = lo, b = hi, c = hi;
    double fa = flo, fb = fhi, fc = fhi;
    double dStep = b - a, e = dStep;

    for (int iter = 0; iter < 500; ++iter)
    {
        if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0))
        {
            c = a;
            fc = fa;
            dStep = b - a;
            e = dStep;
        }
        if (std::fabs(fc) < std::fabs(fb))
        {
            a = b;  b = c;  c = a;
            fa = fb;  fb = fc;  fc = fa;
        }

        const double tol1 =
            2.0*DBL_EPSILON*std::fabs(b) + 0.5*relTol*std::fabs(b);
        const double xm = 0.5*(c - b);

        if (std::fabs(xm) <= tol1 || fb == 0.0)
        {
            return b;
        }

        if (std::fabs(e) >= tol1 && std::fabs(fa) > std::fabs(fb))
        {
            // Inverse quadratic interpolation or secant
            const double s = fb/fa;
            double p, q;
            if (a == c)
            {
                p = 2.0*xm*s;
                q = 1.0 - s;
            }
            else
            {
                const double qq = fa/fc;
                const double r = fb/fc;
                p = s*(2.0*xm*qq*(qq - r) - (b - a)*(r - 1.0));
                q = (qq - 1.0)*(r - 1.0)*(s - 1.0);
            }
            if (p > 0.0)
            {
                q = -q;
            }
            p = std::fabs(p);
            const double min1 = 3.0*xm*q - std::fabs(tol1*q);
            const double min2 = std::fabs(e*q);
            if (2.0*p < std::min(min1, min2))
            {
                e = dStep;
                dStep = p/q;
            }
            else
            {
                dStep = xm;
                e = dStep;
            }
        }
        else
        {
            dStep = xm;
            e = dStep;
        }

        a = b;
        fa = fb;
        b += (std::fabs(dStep) > tol1) ? dStep : (xm >= 0.0 ? tol1 : -tol1);
        fb = f(b);
    }

    return b;
}


double stokesTerminalVelocity
(
    double d, double rhoP, double rho, double mu, double g
)
{
    return (rhoP - rho)*g*d*d/(18.0*mu);
}

} // End namespace correlations
} // End namespace foamDEM
