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
a, b, n = fluidbed.fixed_bed_fit(u, dp, plateau)
umf = fluidbed.intersect(a, b, plateau)
# The constrained optimum of this set is the linear term alone:
# a = sum(u dp)/sum(u^2) by hand
a_lin = float(np.dot(u, dp) / np.dot(u, u))
check("bent data: a, b >= 0 and U_mf finite", a >= 0 and b >= 0 and math.isfinite(umf),
      "a %.6g b %.6g U_mf %.6g" % (a, b, umf))
check("bent data: the linear fit a = sum(u dP)/sum(u^2) = %.6g, U_mf = plateau/a" % a_lin,
      abs(a - a_lin) < 1e-9 * a_lin and b == 0.0 and abs(umf - plateau / a_lin) < 1e-12,
      "%.9g" % umf)

finish()
