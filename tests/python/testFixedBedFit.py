#!/usr/bin/python3
"""Unit test of python/foamdem/fluidbed.py's fixed-bed fit and U_mf
intersection (fluidizedBed's validate.py): exact Ergun-like data are
recovered, and noisy points whose free least-squares parabola bends down
(b < 0, so it never reaches the plateau: U_mf NaN) give a finite U_mf from
the fit with a, b >= 0."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
from foamdem import fluidbed  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

plateau = 1000.0
# Exact data dP = 2000 U + 5000 U^2 (U_mf: 5000 U^2 + 2000 U - 1000 = 0,
# U = (-2000 + sqrt(4e6 + 2e7))/1e4 = 0.289897949)
u = np.linspace(0.02, 0.4, 20)
dp = 2000 * u + 5000 * u ** 2
a, b, n = fluidbed.fixed_bed_fit(u, dp, plateau)
umf = fluidbed.intersect(a, b, plateau)
check("exact data: a = 2000, b = 5000", abs(a - 2000) < 1e-6 and abs(b - 5000) < 1e-6,
      "a %.9g b %.9g (%d points)" % (a, b, n))
check("exact data: U_mf = 0.289897949 by hand", abs(umf - 0.289897949) < 1e-8, "%.9f" % umf)

# Points on a line with the top ones low: the free fit has b < 0 and a
# maximum below the plateau
u = np.array([0.05, 0.10, 0.15, 0.20, 0.25, 0.30])
dp = np.array([150.0, 300.0, 450.0, 580.0, 640.0, 660.0])
m = np.vstack([u, u ** 2]).T
(af, bf), *_ = np.linalg.lstsq(m, dp, rcond=None)
check("the free fit of the bent data bends down and misses the plateau (test premise)",
      bf < 0 and math.isnan(fluidbed.intersect(af, bf, plateau)), "a %.6g b %.6g" % (af, bf))


def brute_force(u, dp, na=801, nb=801):
    """Least squares over a grid of a, b >= 0 (an independent search, not
    the code's two one-term fits), refined once around its best point."""
    a_hi = 2 * float(np.dot(u, dp) / np.dot(u, u))
    b_hi = 2 * float(np.dot(u ** 2, dp) / np.dot(u ** 2, u ** 2))
    lo_a, hi_a, lo_b, hi_b = 0.0, a_hi, 0.0, b_hi
    for _ in range(3):
        A, B = np.meshgrid(np.linspace(lo_a, hi_a, na), np.linspace(lo_b, hi_b, nb))
        r = ((dp[None, None, :] - A[..., None] * u - B[..., None] * u ** 2) ** 2).sum(-1)
        k = np.unravel_index(np.argmin(r), r.shape)
        da, db = (hi_a - lo_a) / (na - 1), (hi_b - lo_b) / (nb - 1)
        ab = A[k], B[k]
        lo_a, hi_a = max(0.0, ab[0] - 2 * da), ab[0] + 2 * da
        lo_b, hi_b = max(0.0, ab[1] - 2 * db), ab[1] + 2 * db
    return ab, float(r[k])


def sse(u, dp, a, b):
    return float(((dp - a * u - b * u ** 2) ** 2).sum())


for name, uu, yy in (("bent over (b < 0 free)", u, dp),
                     ("negative linear term (a < 0 free)",
                      np.array([0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35]),
                      None)):
    if yy is None:
        # dP = -300 U + 8000 U^2 plus a little noise: the free fit's a < 0,
        # the constrained optimum is the quadratic term alone
        yy = -300 * uu + 8000 * uu ** 2 + np.array([3.0, -2.0, 1.0, -4.0, 2.0, 0.0, -1.0])
        k = (yy > 0.05 * plateau) & (yy < 0.75 * plateau)
        mm = np.vstack([uu[k], uu[k] ** 2]).T
        (af, bf), *_ = np.linalg.lstsq(mm, yy[k], rcond=None)
        check("%s: the free fit's a < 0 (test premise)" % name, af < 0, "a %.6g b %.6g" % (af, bf))
    a, b, n = fluidbed.fixed_bed_fit(uu, yy, plateau)
    umf = fluidbed.intersect(a, b, plateau)
    # the fit takes the fixed-bed points only, 0.05 < dP/plateau < 0.75
    keep = (yy > 0.05 * plateau) & (yy < 0.75 * plateau)
    (ga, gb), gr = brute_force(uu[keep], yy[keep])
    check("%s: a, b >= 0 and U_mf finite" % name, a >= 0 and b >= 0 and math.isfinite(umf),
          "a %.6g b %.6g U_mf %.6g" % (a, b, umf))
    check("%s: least squares over its %d points no worse than a grid search over"
          " a, b >= 0" % (name, n),
          n == keep.sum() and sse(uu[keep], yy[keep], a, b) <= gr * (1 + 1e-9) + 1e-12,
          "SSE %.9g (a %.6g, b %.6g) against the grid's %.9g (a %.6g, b %.6g)"
          % (sse(uu[keep], yy[keep], a, b), a, b, gr, ga, gb))

finish()
