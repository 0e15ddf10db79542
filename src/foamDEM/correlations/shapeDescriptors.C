/*---------------------------------------------------------------------------*\
  foamDEM: CFD-DEM coupling (OpenFOAM + LIGGGHTS)
-------------------------------------------------------------------------------
File
    shapeDescriptors.C

Description
    Implementation of the shape descriptors; see shapeDescriptors.H for the
    definitions, formulas and references.

\*---------------------------------------------------------------------------*/

#include "shapeDescriptors.H"

#include <cmath>
#include <limits>

namespace foamDEM
{
namespace correlations
{

namespace
{

constexpr double pi = 3.14159265358979323846;

inline double nan()
{
    return std::numeric_limits<double>::quiet_NaN();
}

//- Normalise dir into n; false for a zero or non-finite vector.
bool unitDirection(const double dir[3], double n[3])
{
    const double mag =
        std::sqrt(dir[0]*dir[0] + dir[1]*dir[1] + dir[2]*dir[2]);
    if (!(mag > 0.0) || !std::isfinite(mag))
    {
        return false;
    }
    for (int i = 0; i < 3; ++i)
    {
        n[i] = dir[i]/mag;
    }
    return true;
}

//- sqrt(1 - x^2) for |x| <= 1 (round-off guarded)
inline double complement(double x)
{
    const double v = (1.0 - x)*(1.0 + x);
    return (v > 0.0) ? std::sqrt(v) : 0.0;
}

bool valid(const spherocylinder& s)
{
    return s.D > 0.0 && s.L >= s.D && std::isfinite(s.L);
}

bool valid(const cuboid& s)
{
    return s.a > 0.0 && s.b > 0.0 && s.c > 0.0
        && std::isfinite(s.a) && std::isfinite(s.b) && std::isfinite(s.c);
}

//- E as a function of the COMPLEMENTARY modulus kp = sqrt(1 - k^2), which
//  is the natural input here (kp = |cos(angle)|) and avoids cancellation.
//  AGM: a0 = 1, b0 = kp, c0 = k;  K = pi/(2 AGM),
//  E = K (1 - sum_{n>=0} 2^(n-1) c_n^2).
double ellipticEFromComplement(double kp)
{
    if (!(kp >= 0.0) || kp > 1.0)
    {
        return nan();
    }
    if (kp == 0.0)
    {
        return 1.0;                       // E(k = 1)
    }

    double a = 1.0;
    double b = kp;
    double sum = 0.5*(1.0 - kp)*(1.0 + kp);   // 2^-1 c0^2, c0^2 = k^2
    double pow2 = 0.5;
    for (int n = 0; n < 64; ++n)
    {
        const double c = 0.5*(a - b);
        const double aNew = 0.5*(a + b);
        b = std::sqrt(a*b);
        a = aNew;
        pow2 *= 2.0;
        sum += pow2*c*c;
        // quadratic convergence: the next c is ~c^2/(4a) <= 2.5e-19 a, so
        // every further term is below round-off (iterating on would only
        // add 2^n-amplified round-off noise)
        if (std::fabs(c) <= 1e-9*a)
        {
            break;
        }
    }
    return pi/(2.0*a)*(1.0 - sum);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

double completeEllipticE(double k)
{
    if (!(std::fabs(k) <= 1.0))
    {
        return nan();
    }
    return ellipticEFromComplement(complement(std::fabs(k)));
}


double equivalentDiameterFromVolume(double V)
{
    if (!(V >= 0.0))
    {
        return nan();
    }
    return std::cbrt(6.0*V/pi);
}


// * * * * * * * * * * * * * * * Spherocylinder * * * * * * * * * * * * * * //

double volume(const spherocylinder& s)
{
    if (!valid(s))
    {
        return nan();
    }
    const double l = s.L - s.D;
    return pi*s.D*s.D/4.0*l + pi*s.D*s.D*s.D/6.0;
}


double surfaceArea(const spherocylinder& s)
{
    if (!valid(s))
    {
        return nan();
    }
    const double l = s.L - s.D;
    return pi*s.D*l + pi*s.D*s.D;
}


double equivalentDiameter(const spherocylinder& s)
{
    return equivalentDiameterFromVolume(volume(s));
}


double sphericity(const spherocylinder& s)
{
    const double dv = equivalentDiameter(s);
    return pi*dv*dv/surfaceArea(s);
}


double projectedArea(const spherocylinder& s, const double dirBody[3])
{
    double n[3];
    if (!valid(s) || !unitDirection(dirBody, n))
    {
        return nan();
    }
    // sin(angle between flow and axis) = |n x e_x| = sqrt(n_y^2 + n_z^2)
    const double sinAlpha = std::sqrt(n[1]*n[1] + n[2]*n[2]);
    return pi*s.D*s.D/4.0 + s.D*(s.L - s.D)*sinAlpha;
}


double meanLongitudinalProjectedArea
(
    const spherocylinder& s,
    const double dirBody[3]
)
{
    double n[3];
    if (!valid(s) || !unitDirection(dirBody, n))
    {
        return nan();
    }
    // k = sin(alpha), complementary modulus k' = |cos(alpha)| = |n_x|
    const double E = ellipticEFromComplement(std::fabs(n[0]));
    return pi*s.D*s.D/4.0 + s.D*(s.L - s.D)*(2.0/pi)*E;
}


double crosswiseSphericity(const spherocylinder& s, const double dirBody[3])
{
    const double dv = equivalentDiameter(s);
    return pi*dv*dv/4.0/projectedArea(s, dirBody);
}


double lengthwiseSphericity(const spherocylinder& s, const double dirBody[3])
{
    const double dv = equivalentDiameter(s);
    return
        pi*dv*dv/4.0
       /(0.5*surfaceArea(s) - meanLongitudinalProjectedArea(s, dirBody));
}


// * * * * * * * * * * * * * * * * * Cuboid * * * * * * * * * * * * * * * * //

double volume(const cuboid& s)
{
    if (!valid(s))
    {
        return nan();
    }
    return s.a*s.b*s.c;
}


double surfaceArea(const cuboid& s)
{
    if (!valid(s))
    {
        return nan();
    }
    return 2.0*(s.a*s.b + s.b*s.c + s.a*s.c);
}


double equivalentDiameter(const cuboid& s)
{
    return equivalentDiameterFromVolume(volume(s));
}


double sphericity(const cuboid& s)
{
    const double dv = equivalentDiameter(s);
    return pi*dv*dv/surfaceArea(s);
}


double projectedArea(const cuboid& s, const double dirBody[3])
{
    double n[3];
    if (!valid(s) || !unitDirection(dirBody, n))
    {
        return nan();
    }
    return
        s.b*s.c*std::fabs(n[0])
      + s.a*s.c*std::fabs(n[1])
      + s.a*s.b*std::fabs(n[2]);
}


double meanLongitudinalProjectedArea(const cuboid& s, const double dirBody[3])
{
    double n[3];
    if (!valid(s) || !unitDirection(dirBody, n))
    {
        return nan();
    }
    return
        (2.0/pi)
       *(
            s.b*s.c*complement(n[0])
          + s.a*s.c*complement(n[1])
          + s.a*s.b*complement(n[2])
        );
}


double crosswiseSphericity(const cuboid& s, const double dirBody[3])
{
    const double dv = equivalentDiameter(s);
    return pi*dv*dv/4.0/projectedArea(s, dirBody);
}


double lengthwiseSphericity(const cuboid& s, const double dirBody[3])
{
    const double dv = equivalentDiameter(s);
    return
        pi*dv*dv/4.0
       /(0.5*surfaceArea(s) - meanLongitudinalProjectedArea(s, dirBody));
}

// * * * * * * * * * * * * *  Sub-volume points  * * * * * * * * * * * * * //

namespace
{
int cellsAlong(double edge, double h)
{
    const double n = std::round(edge/h);
    return n < 1 ? 1 : static_cast<int>(n);
}

// Centre of cell i of n equal cells over [-edge/2, edge/2]
double cellCentre(int i, int n, double edge)
{
    return (i + 0.5)*edge/n - 0.5*edge;
}
}


std::vector<bodyPoint> subVolumePoints(const cuboid& s, int nTarget)
{
    std::vector<bodyPoint> pts;
    if (!(s.a > 0 && s.b > 0 && s.c > 0) || nTarget < 1) return pts;
    const double h = std::cbrt(volume(s)/nTarget);
    const int na = cellsAlong(s.a, h), nb = cellsAlong(s.b, h),
        nc = cellsAlong(s.c, h);
    pts.reserve(static_cast<std::size_t>(na)*nb*nc);
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j)
            for (int k = 0; k < nc; ++k)
                pts.push_back(bodyPoint{{cellCentre(i, na, s.a),
                    cellCentre(j, nb, s.b), cellCentre(k, nc, s.c)}});
    return pts;
}


std::vector<bodyPoint> subVolumePoints(const spherocylinder& s, int nTarget)
{
    std::vector<bodyPoint> pts;
    if (!(s.D > 0 && s.L >= s.D) || nTarget < 1) return pts;
    const double h = std::cbrt(volume(s)/nTarget);
    const int nx = cellsAlong(s.L, h), ny = cellsAlong(s.D, h);
    const double R = 0.5*s.D, halfCore = 0.5*(s.L - s.D);
    for (int i = 0; i < nx; ++i)
    {
        const double x = cellCentre(i, nx, s.L);
        const double ax = std::fabs(x) > halfCore ? std::fabs(x) - halfCore : 0;
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < ny; ++k)
            {
                const double y = cellCentre(j, ny, s.D), z = cellCentre(k, ny, s.D);
                if (ax*ax + y*y + z*z <= R*R)
                {
                    pts.push_back(bodyPoint{{x, y, z}});
                }
            }
    }
    if (pts.empty()) pts.push_back(bodyPoint{{0, 0, 0}});
    return pts;
}

} // End namespace correlations
} // End namespace foamDEM
