"""Shape descriptors and the Hoelzer-Sommerfeld (2008) drag of spherocylinders
and plates, written in Python independently of the C++ kernels
(src/foamDEM/correlations/shapeDescriptors.H) so that the tutorials' checks
verify the C++ against a second implementation (verification, not
validation: both follow the same published formula).

Body frame: x along the length (spherocylinder axis, plate length a), y along
the plate width b, z along the plate thickness c. Definitions as in
doc/models-shapes.md:
    d_v = (6 V/pi)^(1/3), A_eq = pi d_v^2/4
    Phi     = pi d_v^2 / S
    PhiPerp = A_eq / A_proj(f)            (shadow normal to the flow f)
    PhiPar  = A_eq / (S/2 - A_long(f))    (A_long: projected area seen from
              directions m normal to f, averaged over the rotation about f)
Here A_long is a numerical average of the exact projected area over
N_LONG viewing directions (not the closed form used in C++).
"""
import math

import numpy as np

N_LONG = 20000


class Spherocylinder:
    """Diameter D, TOTAL length L (caps included), axis = body x."""

    def __init__(self, D, L):
        self.D, self.L = float(D), float(L)

    def volume(self):
        D, L = self.D, self.L
        return math.pi * D * D / 4 * (L - D) + math.pi * D ** 3 / 6

    def surface(self):
        D, L = self.D, self.L
        return math.pi * D * (L - D) + math.pi * D * D

    def projected_area(self, n):
        """Shadow on the plane normal to the unit vector n: a disc of
        diameter D swept along the projection of the cylinder axis."""
        n = np.asarray(n, float) / np.linalg.norm(n)
        sin_a = math.sqrt(max(0.0, 1 - n[0] ** 2))
        return math.pi * self.D ** 2 / 4 + self.D * (self.L - self.D) * sin_a


class Plate:
    """Cuboid a x b x c along body x, y, z."""

    def __init__(self, a, b, c):
        self.a, self.b, self.c = float(a), float(b), float(c)

    def volume(self):
        return self.a * self.b * self.c

    def surface(self):
        a, b, c = self.a, self.b, self.c
        return 2 * (a * b + b * c + a * c)

    def projected_area(self, n):
        """Convex polyhedron: half the sum over the faces of |n.normal| area."""
        n = np.asarray(n, float) / np.linalg.norm(n)
        a, b, c = self.a, self.b, self.c
        return b * c * abs(n[0]) + a * c * abs(n[1]) + a * b * abs(n[2])


class Clump:
    """A multisphere body: equal spheres of radius r at the given centres
    (body frame). Its projected area is the union of the spheres' shadows,
    discs of radius r, measured on a raster of cells of size h (default
    r/200). Its volume is not computed here (tools/shapes/foamDEMShapes
    reports the union's)."""

    def __init__(self, centres, r):
        self.centres = np.asarray(centres, float).reshape(-1, 3)
        self.r = float(r)

    def projected_area(self, n, h=None):
        h = self.r / 200 if h is None else h
        f, p, q = _normal_basis(n)
        u, v = self.centres @ p, self.centres @ q
        r = self.r
        xs = np.arange(u.min() - r, u.max() + r + h, h) + 0.5 * h
        ys = np.arange(v.min() - r, v.max() + r + h, h) + 0.5 * h
        X, Y = np.meshgrid(xs, ys, indexing="ij")
        covered = np.zeros(X.shape, bool)
        for cu, cv in zip(u, v):
            i0, i1 = np.searchsorted(xs, [cu - r, cu + r])
            j0, j1 = np.searchsorted(ys, [cv - r, cv + r])
            sub = (X[i0:i1, j0:j1] - cu) ** 2 + (Y[i0:i1, j0:j1] - cv) ** 2 <= r * r
            covered[i0:i1, j0:j1] |= sub
        return float(covered.sum()) * h * h


def read_multisphere(path):
    """Centres and radii of a LIGGGHTS multisphere template file (x y z r per
    line, '#' comments)."""
    d = np.loadtxt(path, comments="#", ndmin=2)
    return d[:, :3], d[:, 3]


def d_v(shape):
    return (6 * shape.volume() / math.pi) ** (1.0 / 3.0)


def _normal_basis(f):
    f = np.asarray(f, float) / np.linalg.norm(f)
    t = np.array([1.0, 0, 0]) if abs(f[0]) < 0.9 else np.array([0, 1.0, 0])
    p = np.cross(f, t)
    p /= np.linalg.norm(p)
    q = np.cross(f, p)
    return f, p, q


def mean_longitudinal_area(shape, f, n=N_LONG):
    """Projected area seen from directions m normal to f, averaged over the
    rotation of m about f (midpoint rule over n angles)."""
    f, p, q = _normal_basis(f)
    psi = (np.arange(n) + 0.5) * 2 * math.pi / n
    return float(np.mean([shape.projected_area(math.cos(s) * p + math.sin(s) * q)
                          for s in psi]))


def sphericities(shape, f):
    """(Phi, PhiPerp, PhiPar) for the flow direction f in the body frame."""
    dv = d_v(shape)
    a_eq = math.pi * dv * dv / 4
    phi = math.pi * dv * dv / shape.surface()
    phi_perp = a_eq / shape.projected_area(f)
    phi_par = a_eq / (shape.surface() / 2 - mean_longitudinal_area(shape, f))
    return phi, phi_perp, phi_par


def hs_cd(re, phi, phi_perp, phi_par, simplified=False):
    """Hoelzer & Sommerfeld (2008) drag coefficient."""
    if simplified:
        phi_par = phi_perp
    return (8 / (re * math.sqrt(phi_par)) + 16 / (re * math.sqrt(phi))
            + 3 / (math.sqrt(re) * phi ** 0.75)
            + 0.42 * 10 ** (0.4 * (-math.log10(phi)) ** 0.2) / phi_perp)


def di_felice_chi(re):
    return 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re)) ** 2 / 2)


def hs_force(slip, d, rho, mu, eps, sph, voidage=False, simplified=False):
    """|F| on one body at the slip speed, model A."""
    if slip <= 0:
        return 0.0
    re = eps * rho * slip * d / mu
    f = math.pi / 8 * hs_cd(re, *sph, simplified=simplified) * rho * d * d * slip * slip
    if voidage:
        f *= eps ** (2 - di_felice_chi(re))
    return f


def terminal_velocity(net_weight, d, rho, mu, eps, sph, voidage=False,
                      simplified=False):
    """Slip v_t with F(v_t) = net_weight (bisection to round-off)."""
    lo, hi = 0.0, 1e-3
    while hs_force(hi, d, rho, mu, eps, sph, voidage, simplified) < net_weight:
        hi *= 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if hs_force(mid, d, rho, mu, eps, sph, voidage, simplified) < net_weight:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _self_check():
    """Compare with the table of doc/models-shapes.md (4 digits)."""
    rod = Spherocylinder(1.1e-3, 5.5e-3)
    plate = Plate(5.5e-3, 1.1e-3, 0.33e-3)
    for shape, f, ref in [
        (rod, (1, 0, 0), (0.7319, 3.6593, 0.9366)),
        (rod, (0, 0, 1), (0.7319, 0.6006, 0.6355)),
        (plate, (1, 0, 0), (0.4660, 5.2808, 0.5951)),
        (plate, (0, 0, 1), (0.4660, 0.3168, 0.2802)),
        (plate, (0, 1, 0), (0.4660, 1.0562, 0.4624)),
    ]:
        got = sphericities(shape, f)
        for g, r in zip(got, ref):
            assert abs(g - r) < 6e-5, (type(shape).__name__, f, got, ref)
    assert abs(hs_cd(10, *sphericities(rod, (1, 0, 0))) - 4.1087) < 1e-4
    assert abs(hs_cd(100, *sphericities(plate, (0, 0, 1))) - 3.6919) < 1e-4
    print("shapes self-check passed")


if __name__ == "__main__":
    _self_check()
