// Unit tests of src/foamDEM/correlations/shapeDescriptors.{H,C} and of the
// Hoelzer-Sommerfeld drag evaluated with them.
//
// Expected values were computed by hand in a separate python3 scratch
// script (not by calling this code): spherocylinder projected area from the
// stadium shadow, cuboid projected area as the shoelace area of the convex
// hull of the 8 projected vertices, mean longitudinal projected areas from
// the closed forms (elliptic E from scipy.special.ellipe) and checked
// against brute-force averaging of the hull/stadium areas over 1e5 viewing
// directions (agreement < 1e-8 relative).
// Shapes: spherocylinder D = 1.1 mm, L = 5.5 mm; plate 5.5 x 1.1 x 0.33 mm.

#include "shapeDescriptors.H"
#include "dragCorrelations.H"
#include "relNear.h"

#include <cmath>
#include <initializer_list>

using namespace foamDEM::correlations;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double tol = 1e-9;
constexpr double mm = 1e-3;

const spherocylinder rod{1.1*mm, 5.5*mm};
const cuboid plate{5.5*mm, 1.1*mm, 0.33*mm};

// flow direction at angle theta (deg) from body x, in the x-y plane
// (spherocylinder) / x-z plane (plate)
void dirXY(double thetaDeg, double n[3])
{
    const double t = thetaDeg*kPi/180.0;
    n[0] = std::cos(t); n[1] = std::sin(t); n[2] = 0.0;
}
void dirXZ(double thetaDeg, double n[3])
{
    const double t = thetaDeg*kPi/180.0;
    n[0] = std::cos(t); n[1] = 0.0; n[2] = std::sin(t);
}

// Brute-force mean of projectedArea over nSamples viewing directions
// perpendicular to dir (independent of the closed forms in the code).
template<class Shape>
double sampledLongitudinalArea(const Shape& s, const double dir[3], int nSamples)
{
    const double m = std::sqrt(dir[0]*dir[0] + dir[1]*dir[1] + dir[2]*dir[2]);
    const double f[3] = {dir[0]/m, dir[1]/m, dir[2]/m};
    // p: any unit vector normal to f; q = f x p
    double t[3] = {1.0, 0.0, 0.0};
    if (std::fabs(f[0]) > 0.9) { t[0] = 0.0; t[1] = 1.0; }
    double p[3] =
        {f[1]*t[2] - f[2]*t[1], f[2]*t[0] - f[0]*t[2], f[0]*t[1] - f[1]*t[0]};
    const double pm = std::sqrt(p[0]*p[0] + p[1]*p[1] + p[2]*p[2]);
    for (double& x : p) x /= pm;
    const double q[3] =
        {f[1]*p[2] - f[2]*p[1], f[2]*p[0] - f[0]*p[2], f[0]*p[1] - f[1]*p[0]};
    double sum = 0.0;
    for (int k = 0; k < nSamples; ++k)
    {
        const double psi = 2.0*kPi*(k + 0.5)/nSamples;
        const double v[3] =
        {
            std::cos(psi)*p[0] + std::sin(psi)*q[0],
            std::cos(psi)*p[1] + std::sin(psi)*q[1],
            std::cos(psi)*p[2] + std::sin(psi)*q[2]
        };
        sum += projectedArea(s, v);
    }
    return sum/nSamples;
}
}


// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

TEST(ShapeDescriptors, CompleteEllipticE)
{
    EXPECT_REL(completeEllipticE(0.0), kPi/2.0, 1e-15);
    EXPECT_REL(completeEllipticE(1.0), 1.0, 1e-15);
    // scipy.special.ellipe(m = k^2 = 0.5)
    EXPECT_REL(completeEllipticE(std::sqrt(0.5)), 1.3506438810476755, 1e-14);
    // scipy.special.ellipe(0.99)
    EXPECT_REL(completeEllipticE(std::sqrt(0.99)), 1.015993545025224, 1e-14);
    EXPECT_REL(completeEllipticE(-std::sqrt(0.5)), 1.3506438810476755, 1e-14);
    EXPECT_TRUE(std::isnan(completeEllipticE(1.5)));
}


// * * * * * * * * * * * * * * * Sphere limit * * * * * * * * * * * * * * * //

TEST(ShapeDescriptors, SpherocylinderSphereLimit)
{
    const spherocylinder sphere{2e-3, 2e-3};
    EXPECT_REL(volume(sphere), kPi*8e-9/6.0, 1e-14);
    EXPECT_REL(surfaceArea(sphere), kPi*4e-6, 1e-14);
    EXPECT_REL(equivalentDiameter(sphere), 2e-3, 1e-14);
    EXPECT_REL(sphericity(sphere), 1.0, 1e-14);
    for (double th : {0.0, 30.0, 45.0, 90.0, 137.0})
    {
        double n[3];
        dirXY(th, n);
        EXPECT_REL(crosswiseSphericity(sphere, n), 1.0, 1e-14) << th;
        EXPECT_REL(lengthwiseSphericity(sphere, n), 1.0, 1e-14) << th;
    }
    const double oblique[3] = {0.3, 0.4, 0.5};
    EXPECT_REL(lengthwiseSphericity(sphere, oblique), 1.0, 1e-14);
}

TEST(ShapeDescriptors, Cube)
{
    const cuboid cube{1.0, 1.0, 1.0};
    // Phi = pi^(1/3) 6^(2/3)/6 = (pi/6)^(1/3)
    EXPECT_REL(sphericity(cube), std::cbrt(kPi/6.0), 1e-14);
    EXPECT_REL(sphericity(cube), 0.80599597700823467, 1e-14);
    const double face[3] = {0.0, 0.0, 1.0};
    const double diag[3] = {1.0, 1.0, 1.0};
    // face-on: A = 1, PhiPerp = (pi/4)(6/pi)^(2/3); A_long = 4/pi
    EXPECT_REL(crosswiseSphericity(cube, face), 1.2089939655123521, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(cube, face), 4.0/kPi, 1e-14);
    EXPECT_REL(lengthwiseSphericity(cube, face), 0.70015152468089492, tol);
    // along the body diagonal: hexagonal shadow of area sqrt(3)
    EXPECT_REL(projectedArea(cube, diag), std::sqrt(3.0), 1e-14);
    EXPECT_REL(crosswiseSphericity(cube, diag), 0.69801299143718953, tol);
    EXPECT_REL(lengthwiseSphericity(cube, diag), 0.83922573687234592, tol);
}


// * * * * * * * * * * * * * * * Spherocylinder * * * * * * * * * * * * * * //

TEST(ShapeDescriptors, SpherocylinderHandComputed)
{
    EXPECT_REL(volume(rod), 4.8783697922493502e-09, tol);
    EXPECT_REL(surfaceArea(rod), 1.9006635554218246e-05, tol);
    EXPECT_REL(equivalentDiameter(rod), 0.0021042243010496288, tol);
    EXPECT_REL(sphericity(rod), 0.73186114200459496, tol);

    double n[3];
    // 0 deg: flow along the axis (end-on); 90 deg: broadside
    dirXY(0.0, n);
    EXPECT_REL(projectedArea(rod, n), 9.5033177771091253e-07, tol);
    EXPECT_REL(crosswiseSphericity(rod, n), 3.6593057100229736, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(rod, n), 5.790331777710912e-06, tol);
    EXPECT_REL(lengthwiseSphericity(rod, n), 0.93659240868601623, tol);
    dirXY(45.0, n);
    EXPECT_REL(crosswiseSphericity(rod, n), 0.79528249287285591, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(rod, n), 5.111989322205743e-06, tol);
    EXPECT_REL(lengthwiseSphericity(rod, n), 0.79191400422593539, tol);
    dirXY(90.0, n);
    EXPECT_REL(projectedArea(rod, n), 5.790331777710912e-06, tol);
    EXPECT_REL(crosswiseSphericity(rod, n), 0.6005794890683458, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(rod, n), 4.0315714759700057e-06, tol);
    EXPECT_REL(lengthwiseSphericity(rod, n), 0.63554746678768026, tol);

    const double oblique[3] = {0.3, -0.5, 0.8};
    EXPECT_REL(crosswiseSphericity(rod, oblique), 0.62515185436147303, tol);
    EXPECT_REL(lengthwiseSphericity(rod, oblique), 0.67267665312992364, tol);
}

TEST(ShapeDescriptors, SpherocylinderAxisymmetricAndScaleFree)
{
    // rotation about the axis and the sign/length of dir do not matter
    const double a[3] = {0.6, 0.8, 0.0};
    const double b[3] = {-1.2, 0.0, 1.6};
    EXPECT_REL(crosswiseSphericity(rod, a), crosswiseSphericity(rod, b), 1e-14);
    EXPECT_REL(lengthwiseSphericity(rod, a), lengthwiseSphericity(rod, b), 1e-14);
    // descriptors are dimensionless: scale the rod by 1000
    const spherocylinder big{1.1, 5.5};
    EXPECT_REL(lengthwiseSphericity(big, a), lengthwiseSphericity(rod, a), 1e-13);
}


// * * * * * * * * * * * * * * * * * Plate  * * * * * * * * * * * * * * * * //

TEST(ShapeDescriptors, PlateHandComputed)
{
    EXPECT_REL(volume(plate), 1.9964999999999999e-09, tol);
    EXPECT_REL(surfaceArea(plate), 1.6456e-05, tol);
    EXPECT_REL(equivalentDiameter(plate), 0.0015622728930764879, tol);
    EXPECT_REL(sphericity(plate), 0.46595007805396854, tol);

    double n[3];
    // 0 deg: edgewise along the length a; 90 deg: broadside (normal to a x b)
    dirXZ(0.0, n);
    EXPECT_REL(projectedArea(plate, n), 3.6300000000000001e-07, tol);
    EXPECT_REL(crosswiseSphericity(plate, n), 5.2807675512783101, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(plate, n), 5.0070145096710276e-06, tol);
    EXPECT_REL(lengthwiseSphericity(plate, n), 0.59513419941492629, tol);
    dirXZ(45.0, n);
    EXPECT_REL(projectedArea(plate, n), 4.5346757877493289e-06, tol);
    EXPECT_REL(crosswiseSphericity(plate, n), 0.42272451457118182, tol);
    EXPECT_REL(lengthwiseSphericity(plate, n), 0.45797165900490006, tol);
    dirXZ(90.0, n);
    EXPECT_REL(projectedArea(plate, n), 6.0499999999999997e-06, tol);
    EXPECT_REL(crosswiseSphericity(plate, n), 0.31684605307669861, tol);
    EXPECT_REL(meanLongitudinalProjectedArea(plate, n), 1.3865578642165923e-06, tol);
    EXPECT_REL(lengthwiseSphericity(plate, n), 0.28019218507861016, tol);

    // edgewise across the width (along b)
    const double ey[3] = {0.0, 1.0, 0.0};
    EXPECT_REL(crosswiseSphericity(plate, ey), 1.0561535102556621, tol);
    EXPECT_REL(lengthwiseSphericity(plate, ey), 0.46242541625081907, tol);
    const double oblique[3] = {0.3, -0.5, 0.8};
    EXPECT_REL(projectedArea(plate, oblique), 5.9158573619155666e-06, tol);
    EXPECT_REL(crosswiseSphericity(plate, oblique), 0.3240305679874142, tol);
    EXPECT_REL(lengthwiseSphericity(plate, oblique), 0.40425112121579654, tol);
}


// * * * * * * * * * * * * Closed forms vs. sampling * * * * * * * * * * * * //

TEST(ShapeDescriptors, LongitudinalAreaMatchesSampledAverage)
{
    // 360 viewing directions; the error of the sampled mean is the
    // documented accuracy of a numerical evaluation (kinks of |cos|).
    for (double th : {0.0, 10.0, 45.0, 80.0, 90.0})
    {
        double n[3];
        dirXY(th, n);
        EXPECT_REL(sampledLongitudinalArea(rod, n, 360),
                   meanLongitudinalProjectedArea(rod, n), 1e-5) << th;
        dirXZ(th, n);
        EXPECT_REL(sampledLongitudinalArea(plate, n, 360),
                   meanLongitudinalProjectedArea(plate, n), 1e-4) << th;
    }
    const double oblique[3] = {0.3, -0.5, 0.8};
    EXPECT_REL(sampledLongitudinalArea(plate, oblique, 360),
               meanLongitudinalProjectedArea(plate, oblique), 1e-4);
}

TEST(ShapeDescriptors, HalfSurfaceExceedsLongitudinalArea)
{
    // S/2 - A_long > 0 for every orientation (convex bodies)
    for (double th = 0.0; th <= 90.0; th += 5.0)
    {
        double n[3];
        dirXZ(th, n);
        const cuboid thin{5.5e-3, 1.1e-3, 1e-6};
        EXPECT_GT(0.5*surfaceArea(thin) - meanLongitudinalProjectedArea(thin, n), 0.0);
        EXPECT_GT(lengthwiseSphericity(rod, n), 0.0);
    }
}


// * * * * * * * * * * * * * * * Invalid input  * * * * * * * * * * * * * * //

TEST(ShapeDescriptors, InvalidInputIsNaN)
{
    const double x[3] = {1.0, 0.0, 0.0};
    const double zeroDir[3] = {0.0, 0.0, 0.0};
    EXPECT_TRUE(std::isnan(volume(spherocylinder{1e-3, 0.5e-3})));   // L < D
    EXPECT_TRUE(std::isnan(sphericity(spherocylinder{0.0, 1e-3})));
    EXPECT_TRUE(std::isnan(sphericity(cuboid{1.0, -1.0, 1.0})));
    EXPECT_TRUE(std::isnan(crosswiseSphericity(rod, zeroDir)));
    EXPECT_TRUE(std::isnan(lengthwiseSphericity(plate, zeroDir)));
    EXPECT_TRUE(std::isnan(projectedArea(cuboid{1.0, 1.0, 0.0}, x)));
}


// * * * * * * * * * Hoelzer-Sommerfeld Cd with these shapes * * * * * * * * //

namespace
{
struct cdCase { double Re, full, simplified; };
}

TEST(ShapeDescriptors, HoelzerSommerfeldCdSpherocylinder)
{
    // edgewise: flow along the axis; broadside: flow normal to the axis
    const double edge[3] = {1.0, 0.0, 0.0};
    const double broad[3] = {0.0, 0.0, 1.0};
    const cdCase edgeCases[] =
    {
        {1.0, 30.973374443229222, 26.889071346938032},
        {10.0, 4.108707949067016, 3.7002776394378962},
        {100.0, 0.8616805817094596, 0.82083755074654763}
    };
    const cdCase broadCases[] =
    {
        {1.0, 33.826007861218677, 34.114011634891952},
        {10.0, 5.3696002750584118, 5.3984006524257406},
        {100.0, 1.963398798501051, 1.9662788362377839}
    };
    const double Phi = sphericity(rod);
    for (const cdCase& c : edgeCases)
    {
        EXPECT_REL(hoelzerSommerfeldCd(c.Re, Phi, crosswiseSphericity(rod, edge),
                   lengthwiseSphericity(rod, edge)), c.full, tol) << c.Re;
        EXPECT_REL(hoelzerSommerfeldSimplifiedCd(c.Re, Phi,
                   crosswiseSphericity(rod, edge)), c.simplified, tol) << c.Re;
    }
    for (const cdCase& c : broadCases)
    {
        EXPECT_REL(hoelzerSommerfeldCd(c.Re, Phi, crosswiseSphericity(rod, broad),
                   lengthwiseSphericity(rod, broad)), c.full, tol) << c.Re;
        EXPECT_REL(hoelzerSommerfeldSimplifiedCd(c.Re, Phi,
                   crosswiseSphericity(rod, broad)), c.simplified, tol) << c.Re;
    }
}

TEST(ShapeDescriptors, HoelzerSommerfeldCdPlate)
{
    // edgewise: flow along the length a; broadside: normal to the a x b face
    const double edge[3] = {1.0, 0.0, 0.0};
    const double broad[3] = {0.0, 0.0, 1.0};
    const cdCase edgeCases[] =
    {
        {1.0, 39.295611088843764, 32.406820999066731},
        {10.0, 5.2295933918345838, 4.5407143828568808},
        {100.0, 1.0365080858062798, 0.96762018490850965}
    };
    const cdCase broadCases[] =
    {
        {1.0, 46.646883771131975, 45.745838797283071},
        {10.0, 8.3118934642932309, 8.2217889669083402},
        {100.0, 3.6919108972819696, 3.6829004475434806}
    };
    const double Phi = sphericity(plate);
    for (const cdCase& c : edgeCases)
    {
        EXPECT_REL(hoelzerSommerfeldCd(c.Re, Phi, crosswiseSphericity(plate, edge),
                   lengthwiseSphericity(plate, edge)), c.full, tol) << c.Re;
        EXPECT_REL(hoelzerSommerfeldSimplifiedCd(c.Re, Phi,
                   crosswiseSphericity(plate, edge)), c.simplified, tol) << c.Re;
    }
    for (const cdCase& c : broadCases)
    {
        EXPECT_REL(hoelzerSommerfeldCd(c.Re, Phi, crosswiseSphericity(plate, broad),
                   lengthwiseSphericity(plate, broad)), c.full, tol) << c.Re;
        EXPECT_REL(hoelzerSommerfeldSimplifiedCd(c.Re, Phi,
                   crosswiseSphericity(plate, broad)), c.simplified, tol) << c.Re;
    }
}

// Sub-volume points (divided void fraction of shaped particles). Counts
// worked by hand: plate 5.5 x 1.1 x 0.33 mm, 40 aimed at: h = (V/40)^(1/3)
// = 0.3684 mm, 15 x 3 x 1 boxes; rod D 1.1, L 5.5 mm: V = 4.8784 mm^3,
// h = 0.4960 mm, 11 x 2 x 2 cells, every centre inside (the end cells'
// centres are 0.491 mm from the cap centres, < 0.55 mm).
namespace
{
template<class Shape>
void moments(const Shape& s, int n, double& count, double c[3], double m2[3])
{
    const std::vector<bodyPoint> pts = subVolumePoints(s, n);
    count = pts.size();
    for (int d = 0; d < 3; ++d)
    {
        c[d] = m2[d] = 0;
        for (const bodyPoint& p : pts) { c[d] += p[d]; m2[d] += p[d]*p[d]; }
        c[d] /= count;
        m2[d] /= count;
    }
}
}

TEST(ShapeDescriptors, PlateSubVolumePoints)
{
    const cuboid plate{5.5e-3, 1.1e-3, 0.33e-3};
    double n, c[3], m2[3];
    moments(plate, 40, n, c, m2);
    EXPECT_EQ(n, 45);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c[d], 0, 1e-18);
    // midpoint grid: mean x^2 = a^2/12 (1 - 1/n^2)
    EXPECT_REL(m2[0], 5.5e-3*5.5e-3/12*(1 - 1.0/225), 1e-12);
    EXPECT_REL(m2[1], 1.1e-3*1.1e-3/12*(1 - 1.0/9), 1e-12);
    EXPECT_NEAR(m2[2], 0, 1e-24);
    for (const bodyPoint& p : subVolumePoints(plate, 40))
    {
        EXPECT_LE(std::fabs(p[0]), 0.5*plate.a);
        EXPECT_LE(std::fabs(p[1]), 0.5*plate.b);
    }
}

TEST(ShapeDescriptors, SpherocylinderSubVolumePoints)
{
    const spherocylinder rod{1.1e-3, 5.5e-3};
    double n, c[3], m2[3];
    moments(rod, 40, n, c, m2);
    EXPECT_EQ(n, 44);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c[d], 0, 1e-18);
    // Fine sets approach the body's second moment along its axis:
    // cylinder pi r^2 2c^3/3 plus two hemispheres at +-c,
    // 2 (2/3 pi r^3 c^2 + 2 c pi r^4/4 + 2/15 pi r^5), over V
    const double r = 0.55e-3, cc = 0.5*(5.5e-3 - 1.1e-3);
    const double V = M_PI*r*r*2*cc + 4.0/3*M_PI*r*r*r;
    const double Ixx = M_PI*r*r*2*cc*cc*cc/3
        + 2*(2.0/3*M_PI*r*r*r*cc*cc + 2*cc*M_PI*r*r*r*r/4 + 2.0/15*M_PI*std::pow(r, 5));
    moments(rod, 20000, n, c, m2);
    EXPECT_REL(m2[0], Ixx/V, 0.01);
    // A target of one point: the centre
    const std::vector<bodyPoint> one = subVolumePoints(spherocylinder{1e-3, 1e-3}, 1);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_NEAR(one[0][0], 0, 1e-18);
}
