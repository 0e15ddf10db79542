"""The expansion of a liquid-fluidised bed of uniform spheres: the
independent reference of the liquidFluidizedBed tutorial, and the bed
voidage measured from particle heights.

- Richardson & Zaki (1954), Trans. Inst. Chem. Eng. 32:35:
      U / U_t = eps^n
  U the superficial liquid velocity, U_t the terminal velocity of one
  sphere in the unbounded liquid, eps the bed voidage.
- Garside & Al-Dibouni (1977), Ind. Eng. Chem. Process Des. Dev. 16:206,
  the exponent from the terminal Reynolds number Re_t = rho U_t d / mu:
      (5.1 - n) / (n - 2.7) = 0.1 Re_t^0.9
  (no wall correction: the tutorial's side walls are periodic).
- U_t from Brown & Lawler's (2003) fit to measured sphere drag
  (foamdem.standardDrag), not from a drag law of foamDEM.
"""
import math

from foamdem import standardDrag


def exponent_garside(re_t):
    """n of Garside & Al-Dibouni (1977) at the terminal Reynolds number."""
    a = 0.1 * re_t ** 0.9
    return (5.1 + 2.7 * a) / (1 + a)


def reference(d, rhop, rho, mu, g):
    """(U_t, Re_t, n): terminal velocity of one sphere (Brown & Lawler),
    its Reynolds number and the Richardson-Zaki exponent."""
    ut = standardDrag.terminal_velocity(standardDrag.brown_lawler, d, rhop, rho, mu, g)
    re_t = rho * ut * d / mu
    return ut, re_t, exponent_garside(re_t)


def voidage(u, ut, n):
    """Bed voidage of Richardson-Zaki at the superficial velocity u."""
    return (u / ut) ** (1.0 / n)


def velocity(eps, ut, n):
    """Superficial velocity of Richardson-Zaki at the bed voidage eps."""
    return ut * eps ** n


def interior_voidage(z, vp, area, lo=0.1, hi=0.8):
    """Voidage of the bed's interior from the particle centre heights z:
    the particles between the lo and hi fractions of the sorted heights
    fill (hi - lo) N V_p in the slab between those heights, so
        eps = 1 - (hi - lo) N V_p / (area (z_hi - z_lo)).
    The layers next to the distributor (ordered by the floor) and the
    bed surface (diffuse at high voidage) are left out. area is the bed's
    cross-section (periodic sides: the whole of it)."""
    zs = sorted(z)
    n = len(zs)
    if n < 20:
        raise ValueError("interior_voidage: %d particles are too few" % n)
    i0 = int(round(lo * (n - 1)))
    i1 = int(round(hi * (n - 1)))
    count = i1 - i0
    height = zs[i1] - zs[i0]
    if height <= 0:
        raise ValueError("interior_voidage: the particles are at one height")
    return 1.0 - count * vp / (area * height)


def mean_height_voidage(z_mean, z_floor, n, vp, area):
    """Voidage of the whole bed if it is uniform from the floor up: its
    height is then twice the mean centre height above the floor."""
    return 1.0 - n * vp / (area * 2.0 * (z_mean - z_floor))


def _self_check():
    # Garside & Al-Dibouni's limits: n -> 5.1 as Re_t -> 0, -> 2.7 as Re_t -> inf
    assert abs(exponent_garside(1e-12) - 5.1) < 1e-9
    assert abs(exponent_garside(1e12) - 2.7) < 1e-6
    # voidage and velocity invert each other
    assert abs(voidage(velocity(0.63, 0.15, 2.9), 0.15, 2.9) - 0.63) < 1e-12
    # a uniform column of centres at solid fraction 0.3 (1000 particles)
    vp, area = 1.0, 1.0
    z = [i * vp / (0.3 * area) for i in range(1000)]
    assert abs(interior_voidage(z, vp, area) - 0.7) < 1e-9


if __name__ == "__main__":
    _self_check()
    print("richardsonZaki: self-check passed")
