"""The drag of one smooth sphere as fitted to experiments: independent
references for the terminal velocity, not drag laws of foamDEM.

- Brown & Lawler (2003), "Sphere drag and settling velocity revisited",
  J. Environ. Eng. 129(3):222-231. A fit to experimental data corrected
  for wall effects, for Re < 2e5:
      C_D = 24/Re (1 + 0.150 Re^0.681) + 0.407/(1 + 8710/Re).
- Clift, Grace & Weber (1978), "Bubbles, Drops, and Particles", Academic
  Press, Table 5.2: the standard drag curve in pieces, w = log10 Re:
      Re <= 0.01          C_D = 3/16 + 24/Re
      0.01 < Re <= 20     C_D = 24/Re (1 + 0.1315 Re^(0.82 - 0.05 w))
      20 < Re <= 260      C_D = 24/Re (1 + 0.1935 Re^0.6305)
      260 < Re <= 1500    log10 C_D = 1.6435 - 1.1242 w + 0.1558 w^2
      1500 < Re <= 1.2e4  log10 C_D = -2.4571 + 2.5558 w - 0.9295 w^2
                                      + 0.1049 w^3
  (only up to 1.2e4 here).

Re = rho U d / mu with U the sphere's speed relative to the far fluid.
"""
import math


def brown_lawler(re):
    """C_D of Brown & Lawler (2003)."""
    return 24 / re * (1 + 0.150 * re ** 0.681) + 0.407 / (1 + 8710 / re)


def clift_grace_weber(re):
    """C_D of Clift, Grace & Weber's (1978) standard drag curve, Re <= 1.2e4."""
    w = math.log10(re)
    if re <= 0.01:
        return 3 / 16 + 24 / re
    if re <= 20:
        return 24 / re * (1 + 0.1315 * re ** (0.82 - 0.05 * w))
    if re <= 260:
        return 24 / re * (1 + 0.1935 * re ** 0.6305)
    if re <= 1500:
        return 10 ** (1.6435 - 1.1242 * w + 0.1558 * w * w)
    if re <= 1.2e4:
        return 10 ** (-2.4571 + 2.5558 * w - 0.9295 * w * w + 0.1049 * w ** 3)
    raise ValueError("clift_grace_weber: Re = %g above 1.2e4" % re)


CURVES = {
    "brownLawler": brown_lawler,
    "cliftGraceWeber": clift_grace_weber,
}


def terminal_velocity(cd, d, rhop, rho, mu, g):
    """Terminal velocity [m/s] of a sphere of diameter d and density rhop
    in a fluid (rho, mu) under gravity g, from the force balance
        (rhop - rho) g pi d^3/6 = (pi/8) C_D(Re) rho d^2 U^2,
    solved for U by bisection on log U (the drag grows with U for any
    monotonic C_D Re^2)."""
    weight = (rhop - rho) * g * math.pi * d ** 3 / 6
    if weight <= 0:
        raise ValueError("terminal_velocity: the sphere does not sink")

    def excess(u):
        re = rho * u * d / mu
        return math.pi / 8 * cd(re) * rho * d * d * u * u - weight

    # Start from the smaller of the Stokes speed and the speed at C_D = 0.4
    stokes = weight / (3 * math.pi * mu * d)
    newton = math.sqrt(weight / (math.pi / 8 * 0.4 * rho * d * d))
    lo = hi = min(stokes, newton)
    while excess(lo) > 0:
        lo /= 2
    while excess(hi) < 0:
        hi *= 2
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if excess(mid) < 0:
            lo = mid
        else:
            hi = mid
        if hi / lo - 1 < 1e-13:
            break
    return math.sqrt(lo * hi)


def drag_coefficient(u, d, rhop, rho, g):
    """C_D that a terminal velocity u implies: 4 (rhop - rho) g d/(3 rho u^2)."""
    return 4 * (rhop - rho) * g * d / (3 * rho * u * u)
