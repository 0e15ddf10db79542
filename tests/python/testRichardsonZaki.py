#!/usr/bin/python3
"""Unit test of python/foamdem/richardsonZaki.py (issue 12 item 1): the
reference of the liquidFluidizedBed validation (Richardson-Zaki with
Garside & Al-Dibouni's exponent and Brown & Lawler's terminal velocity)
and the bed-interior voidage measured from particle heights."""
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
from foamdem import richardsonZaki as rz  # noqa: E402
from foamdem import standardDrag as sd  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402


# Garside & Al-Dibouni's equation as published, (5.1 - n)/(n - 2.7) =
# 0.1 Re_t^0.9, holds for the returned n (the inversion is ours)
for re in (0.1, 1.0, 10.0, 147.5, 1000.0):
    n = rz.exponent_garside(re)
    lhs = (5.1 - n) / (n - 2.7)
    check("Garside & Al-Dibouni at Re_t %g: n = %.5f" % (re, n),
          abs(lhs / (0.1 * re ** 0.9) - 1) < 1e-12 and 2.7 < n < 5.1, "%.15g" % lhs)

# By hand at Re_t = 100: a = 0.1 x 100^0.9 = 6.309573445,
# n = (5.1 + 2.7 a)/(1 + a) = 22.13584830/7.309573445 = 3.0283365
check("n(Re_t = 100) = 3.0283365 by hand",
      abs(rz.exponent_garside(100.0) - 3.0283365) < 1e-6, "%.8f" % rz.exponent_garside(100.0))

# The tutorial's reference: 1 mm glass (2500) in water (1000, 1e-3 Pa s):
# U_t from Brown & Lawler solves the force balance with C_D(Re_t)
d, rhop, rho, mu, g = 1e-3, 2500.0, 1000.0, 1e-3, 9.81
ut, re_t, n = rz.reference(d, rhop, rho, mu, g)
drag = math.pi / 8 * sd.brown_lawler(re_t) * rho * d * d * ut * ut
weight = (rhop - rho) * g * math.pi * d ** 3 / 6
check("U_t = %.5f m/s balances the buoyant weight" % ut, abs(drag / weight - 1) < 1e-9,
      "%.3e" % (drag / weight - 1))
check("Re_t %.1f, n %.3f in the intermediate range (100-300, 2.8-3.1)" % (re_t, n),
      100 < re_t < 300 and 2.8 < n < 3.1)

# Richardson-Zaki's law and its inverse
for eps in (0.45, 0.6, 0.9):
    u = rz.velocity(eps, ut, n)
    check("eps(U(eps)) = eps at %g" % eps, abs(rz.voidage(u, ut, n) - eps) < 1e-12)
# By hand: U_t 0.15 m/s, n 3, eps 0.6: U = 0.15 x 0.216 = 0.0324 m/s;
# n 2.5: 0.15 x 0.6^2.5 = 0.15 x 0.2788548 = 0.04182822 m/s
check("U(0.6; 0.15 m/s, n 3) = 0.0324 m/s by hand",
      abs(rz.velocity(0.6, 0.15, 3.0) - 0.0324) < 1e-12, "%.10g" % rz.velocity(0.6, 0.15, 3.0))
check("U(0.6; 0.15 m/s, n 2.5) = 0.04182822 m/s by hand",
      abs(rz.velocity(0.6, 0.15, 2.5) - 0.04182822) < 1e-8, "%.10g" % rz.velocity(0.6, 0.15, 2.5))
check("eps(0.0324 m/s; 0.15 m/s, n 3) = 0.6 by hand",
      abs(rz.voidage(0.0324, 0.15, 3.0) - 0.6) < 1e-12, "%.10g" % rz.voidage(0.0324, 0.15, 3.0))

# Interior voidage of random beds of known solid fraction: centres uniform
# in a slab of height H, N V_p / (A H) = phi; the 10th-80th percentile
# estimate is unbiased (within the sampling scatter, ~1/sqrt(0.7 N))
random.seed(1)
for phi in (0.1, 0.3, 0.55):
    n_p, vp, area = 20000, 1.0, 1.0
    height = n_p * vp / (phi * area)
    z = [random.uniform(0, height) for _ in range(n_p)]
    e = rz.interior_voidage(z, vp, area)
    check("interior voidage of a uniform random bed at phi %g: %.4f" % (phi, 1 - e),
          abs((1 - e) / phi - 1) < 0.02)
# A bed with a dense bottom layer and a diffuse top: the interior is
# measured, not the bed average
z = ([random.uniform(0, 1) for _ in range(500)]           # dense bottom layer
     + [random.uniform(1, 41) for _ in range(8000)]       # interior: 200 per unit height
     + [41 + 10 * random.random() ** 0.3 for _ in range(500)])
area, vp = 1.0, 1.0
e = rz.interior_voidage(z, vp, area)
# the 10-80 % band (the 900th to the 7200th of 9000 heights) lies inside
# the interior, 1 to 41 (the 500th to the 8500th)
check("interior voidage skips the bottom layer and the diffuse top: phi %.1f" % ((1 - e)),
      abs((1 - e) / 200 - 1) < 0.03)
# mean-height voidage of a uniform bed from the floor: H = 2 (zmean - zfloor)
check("mean-height voidage of a uniform bed",
      abs(rz.mean_height_voidage(0.01 + 0.05, 0.01, 100, 1e-6, 1e-2) - (1 - 100e-6 / (1e-2 * 0.1))) < 1e-12)

finish()
