/*---------------------------------------------------------------------------*\
  foamDEM: CFD-DEM coupling (OpenFOAM + LIGGGHTS)
-------------------------------------------------------------------------------
File
    timeStepCriteria.C

Description
    Implementation of the DEM time-scale estimates; see timeStepCriteria.H.

\*---------------------------------------------------------------------------*/

#include "timeStepCriteria.H"

#include <cmath>
#include <limits>

namespace foamDEM
{
namespace correlations
{

namespace
{
constexpr double pi = 3.14159265358979323846;
}


double rayleighTimeStep
(
    double radius, double rhoP, double youngsModulus, double poisson
)
{
    const double G = youngsModulus/(2.0*(1.0 + poisson));
    return pi*radius*std::sqrt(rhoP/G)/(0.1631*poisson + 0.8766);
}


double hertzContactTime
(
    double effectiveMass,
    double effectiveRadius,
    double effectiveYoungsModulus,
    double impactVelocity
)
{
    if (!(impactVelocity > 0.0))
    {
        return std::numeric_limits<double>::infinity();
    }
    const double E = effectiveYoungsModulus;
    return 2.87*std::pow
    (
        effectiveMass*effectiveMass/(effectiveRadius*E*E*impactVelocity),
        0.2
    );
}


double effectiveYoungsModulus(double E1, double nu1, double E2, double nu2)
{
    return 1.0/((1.0 - nu1*nu1)/E1 + (1.0 - nu2*nu2)/E2);
}


double particleRelaxationTime(double d, double rhoP, double mu)
{
    return rhoP*d*d/(18.0*mu);
}

} // End namespace correlations
} // End namespace foamDEM
