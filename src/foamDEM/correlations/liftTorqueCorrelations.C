/*---------------------------------------------------------------------------*\
  foamDEM: CFD-DEM coupling (OpenFOAM + LIGGGHTS)
-------------------------------------------------------------------------------
File
    liftTorqueCorrelations.C

Description
    Implementation of the lift and torque kernels; see
    liftTorqueCorrelations.H for the equations, conventions and references.

\*---------------------------------------------------------------------------*/

#include "liftTorqueCorrelations.H"

#include <cmath>
#include <limits>

namespace foamDEM
{
namespace correlations
{

namespace
{

constexpr double pi = 3.14159265358979323846;

inline vec3 scaled(const vec3& a, double s)
{
    return vec3{s*a.x, s*a.y, s*a.z};
}

inline vec3 zero()
{
    return vec3{0.0, 0.0, 0.0};
}

//- Relative spin Omega = omegaF/2 - omegaP
inline vec3 relativeSpin(const vec3& omegaF, const vec3& omegaP)
{
    return vec3
    {
        0.5*omegaF.x - omegaP.x,
        0.5*omegaF.y - omegaP.y,
        0.5*omegaF.z - omegaP.z
    };
}

} // End anonymous namespace


vec3 cross(const vec3& a, const vec3& b)
{
    return vec3
    {
        a.y*b.z - a.z*b.y,
        a.z*b.x - a.x*b.z,
        a.x*b.y - a.y*b.x
    };
}


double mag(const vec3& a)
{
    if (std::isnan(a.x) || std::isnan(a.y) || std::isnan(a.z))
    {
        return std::numeric_limits<double>::quiet_NaN();
    }
    // scaled, so that tiny (1e-200) or huge components neither underflow
    // nor overflow
    const double s =
        std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z)));
    if (s == 0.0 || !std::isfinite(s))
    {
        return s;
    }
    const double x = a.x/s, y = a.y/s, z = a.z/s;
    return s*std::sqrt(x*x + y*y + z*z);
}


// * * * * * * * * * * * * * * * Saffman - Mei  * * * * * * * * * * * * * * //

double meiLiftCorrection(double ReP, double ReS)
{
    if (std::isnan(ReP) || std::isnan(ReS))
    {
        return std::numeric_limits<double>::quiet_NaN();
    }
    if (!(ReP > 0.0))
    {
        return 1.0;                       // limit Re_p -> 0 of the first branch
    }
    const double beta = 0.5*std::fmax(ReS, 0.0)/ReP;
    if (ReP <= 40.0)
    {
        const double sb = 0.3314*std::sqrt(beta);
        return (1.0 - sb)*std::exp(-0.1*ReP) + sb;
    }
    return 0.0524*std::sqrt(beta*ReP);
}


vec3 saffmanMeiLift
(
    double d,
    double rho,
    double mu,
    const vec3& slip,
    const vec3& omegaF,
    bool meiCorrection
)
{
    const double w = mag(slip);
    const double om = mag(omegaF);
    if (!(w > 0.0) || !(om > 0.0))
    {
        return zero();
    }
    const double ReP = rho*w*d/mu;
    const double ReS = rho*om*d*d/mu;
    const double f = meiCorrection ? meiLiftCorrection(ReP, ReS) : 1.0;
    const double C = 1.615*d*d*std::sqrt(rho*mu/om)*f;
    return scaled(cross(slip, omegaF), C);
}


// * * * * * * * * * * * * * * * * * Magnus  * * * * * * * * * * * * * * * * //

double oesterleBuiDinhLiftCoeff(double ReP, double ReR)
{
    const double X = std::exp(-0.05684*std::pow(ReR, 0.4)*std::pow(ReP, 0.3));
    return 0.45 + (ReR/ReP - 0.45)*X;
}


vec3 magnusLift
(
    double d,
    double rho,
    double mu,
    const vec3& slip,
    const vec3& omegaF,
    const vec3& omegaP
)
{
    const vec3 Omega = relativeSpin(omegaF, omegaP);
    const double w = mag(slip);
    const double om = mag(Omega);
    if (!(w > 0.0) || !(om > 0.0))
    {
        return zero();
    }
    const double ReP = rho*w*d/mu;
    const double ReR = rho*om*d*d/mu;
    const double X = std::exp(-0.05684*std::pow(ReR, 0.4)*std::pow(ReP, 0.3));
    // C_LR |w| = 0.45 |w| (1 - X) + |Omega| d X  (finite for any slip)
    const double CLRw = 0.45*w*(1.0 - X) + om*d*X;
    const double C = 0.125*pi*rho*d*d*CLRw/om;
    return scaled(cross(Omega, slip), C);
}


// * * * * * * * * * * * * * * Rotational torque  * * * * * * * * * * * * * //

double rotationalTorqueCoeff(double ReR)
{
    if (ReR <= 32.0)
    {
        return 64.0*pi/ReR;
    }
    return 12.9/std::sqrt(ReR) + 128.4/ReR;
}


vec3 rotationalTorque
(
    double d,
    double rho,
    double mu,
    const vec3& omegaF,
    const vec3& omegaP
)
{
    const vec3 Omega = relativeSpin(omegaF, omegaP);
    const double om = mag(Omega);
    if (!(om > 0.0))
    {
        return zero();
    }
    const double ReR = rho*om*d*d/mu;
    if (ReR <= 32.0)
    {
        // Stokes: (rho/2)(d/2)^5 (64 pi/Re_r) |Omega| = pi mu d^3
        return scaled(Omega, pi*mu*d*d*d);
    }
    const double r = 0.5*d;
    const double C = 0.5*rho*r*r*r*r*r*rotationalTorqueCoeff(ReR)*om;
    return scaled(Omega, C);
}



// * * * * * * * * * * * * * * * Pitching torque  * * * * * * * * * * * * * //

const double zastawnyProlate52[10] =
    {2.078, 0.279, 0.372, 0.018, 0.98, 0.0, 0.0, 1.0, 0.0, 0.0};

const double zastawnyProlate54[10] =
    {0.935, 0.146, -0.469, 0.145, 0.116, 0.748, 0.041, 0.221, 0.657, 0.044};


double pitchingTorqueCoeff(const double c[10], double Re, double phi)
{
    const double s = std::fabs(std::sin(phi));
    const double co = std::fabs(std::cos(phi));
    const double ps = c[4] + c[5]*std::pow(Re, c[6]);
    const double pc = c[7] + c[8]*std::pow(Re, c[9]);
    // 0^p with p > 0 is 0; sin(pi/2) rounds to 1, cos(pi/2) to 6e-17
    const double fs = s > 0.0 ? std::pow(s, ps) : 0.0;
    const double fc = co > 1e-15 ? std::pow(co, pc) : 0.0;
    return (c[0]/std::pow(Re, c[1]) + c[2]/std::pow(Re, c[3]))*fs*fc;
}


vec3 pitchingTorque
(
    const double c[10],
    double d,
    double rho,
    double mu,
    const vec3& slip,
    const vec3& axis,
    bool flat
)
{
    const double w = mag(slip);
    const double la = mag(axis);
    if (!(w > 0.0) || !(la > 0.0))
    {
        return zero();
    }
    // axis with a.w >= 0, unit
    const double aw = slip.x*axis.x + slip.y*axis.y + slip.z*axis.z;
    const vec3 a = scaled(axis, (aw < 0.0 ? -1.0 : 1.0)/la);
    // direction: elongated w x a (a turns away from w), flat a x w
    const vec3 n = flat ? cross(a, slip) : cross(slip, a);
    const double nn = mag(n);
    if (!(nn > 0.0))
    {
        return zero();
    }
    // angle between w and the axis, in [0, pi/2]
    const double angle = std::atan2(nn, std::fabs(aw));
    const double phi = flat ? 0.5*pi - angle : angle;
    const double Re = rho*w*d/mu;
    const double T = pi/16.0*pitchingTorqueCoeff(c, Re, phi)*rho*d*d*d*w*w;
    return scaled(n, T/nn);
}


} // End namespace correlations
} // End namespace foamDEM
