#!/usr/bin/python3
"""Unit test of python/foamdem/spouted.py (issue 18): synthetic pressure
signals of known frequencies and RMS, and a height signal of known mean and
maximum, through the plateau analysis the spoutedBed tutorial uses."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
from foamdem import spouted  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402


# Two plateaus; in each, the pressure is mean + a1 sin(2 pi f1 t) + a2
# sin(2 pi f2 t) sampled at 10 kHz, with a1 > a2, so the dominant frequency
# is f1 and the RMS deviation is sqrt((a1^2 + a2^2)/2) (exact for whole
# periods only; the analysed 3.25 s windows hold 9.75 and 22.75 periods
# (first plateau), 4.875 and 37.375 (second), so the checks allow for it)
dt = 1e-4
t = np.arange(0.0, 8.0 + dt / 2, dt)
windows = [(1.3, 0.0, 4.0), (1.9, 4.0, 8.0)]
spec = [(120.0, 3.0, 2.0, 7.0, 1.0), (80.0, 1.5, 0.5, 11.5, 0.3)]  # mean, f1, a1, f2, a2
p = np.zeros_like(t)
h = np.zeros_like(t)
for (u, t0, t1), (mean, f1, a1, f2, a2) in zip(windows, spec):
    m = (t >= t0) & (t < t1)
    p[m] = mean + a1 * np.sin(2 * math.pi * f1 * t[m]) + a2 * np.sin(2 * math.pi * f2 * t[m])
    h[m] = 0.1 * u + 0.01 * np.sin(2 * math.pi * 0.5 * t[m])
# the analysed window: 4 s less 0.5 s and 0.25 s = 3.25 s
rows = spouted.plateau_statistics(t, p, t, h, windows, 0.5, 0.25)
check("two plateaus analysed", len(rows) == 2, "%d rows" % len(rows))
for row, (u, t0, t1), (mean, f1, a1, f2, a2) in zip(rows, windows, spec):
    # 3.25 s windows: frequency resolution 1/3.25 = 0.308 Hz; f1 = 3 and 1.5
    # Hz are not on the grid, so the peak is the nearest bin
    df = 1.0 / (row["w1"] - row["w0"])
    check("plateau %.1f: window %.2f-%.2f s" % (u, row["w0"], row["w1"]),
          abs(row["w0"] - (t0 + 0.5)) < 1e-12 and abs(row["w1"] - (t1 - 0.25)) < 1e-12, "")
    check("plateau %.1f: dominant frequency %.3f Hz (%.1f Hz, bin %.3f Hz)"
          % (u, row["fdom"], f1, df), abs(row["fdom"] - f1) <= df / 2 + 1e-9, "")
    s_true = math.sqrt((a1 ** 2 + a2 ** 2) / 2)
    # over a window that is not a whole number of periods the sample RMS
    # deviates from the ideal by O(a/(f T)): bound 3 %
    check("plateau %.1f: rms %.4f (%.4f)" % (u, row["rms"], s_true),
          abs(row["rms"] / s_true - 1) < 0.03, "")
    hs = 0.1 * u + 0.01 * np.sin(2 * math.pi * 0.5 * t[(t >= row["w0"]) & (t <= row["w1"])])
    check("plateau %.1f: height mean %.5f, max %.5f" % (u, row["hmean"], row["hmax"]),
          abs(row["hmean"] - hs.mean()) < 1e-12 and abs(row["hmax"] - hs.max()) < 1e-12, "")

check("both windows complete", all(r["complete"] for r in rows), "")
# a run still going: data to 6 s, the second window (4.5-7.75 s) incomplete
cut = t <= 6.0
part = spouted.plateau_statistics(t[cut], p[cut], t[cut], h[cut], windows, 0.5, 0.25)
check("data to 6 s: first window complete, second not",
      len(part) == 2 and part[0]["complete"] and not part[1]["complete"],
      str([r["complete"] for r in part]))

# rms_deviation is the N - 1 form: for (1, 2, 3, 4) it is sqrt(5/3)
check("rms_deviation of 1..4 = sqrt(5/3)",
      abs(spouted.rms_deviation([1, 2, 3, 4]) - math.sqrt(5 / 3)) < 1e-15, "")
# a sine of amplitude 2 over whole periods: spectrum peak 2 at its frequency
tt = np.arange(0, 2.0, 1e-3)
f, a = spouted.amplitude_spectrum(tt, 5 + 2 * np.sin(2 * math.pi * 25 * tt))
k = int(np.argmax(a[1:])) + 1
check("spectrum peak of 2 sin(2 pi 25 t): %.4f at %.2f Hz" % (a[k], f[k]),
      abs(f[k] - 25) < 1e-9 and abs(a[k] - 2) < 1e-9, "")
# a constant offset and a Nyquist-frequency term (+-1 alternating, even
# count): after the mean is removed DC is 0; the alternating term of
# amplitude 1 shows as 1 in the Nyquist bin (not doubled)
alt = 5 + np.where(np.arange(tt.size) % 2 == 0, 1.0, -1.0)
f, a = spouted.amplitude_spectrum(tt, alt)
check("spectrum of 5 + (-1)^n: DC %.2e, Nyquist bin %.4f at %.0f Hz (1 at 500 Hz)"
      % (a[0], a[-1], f[-1]), a[0] < 1e-9 and abs(a[-1] - 1) < 1e-9 and abs(f[-1] - 500) < 1e-9, "")
# the second frequency of each plateau: the spectrum's second-highest
# local maximum, within half a bin of f2
for row, (mean, f1, a1, f2, a2) in zip(rows, spec):
    fa, aa = row["f"], row["a"]
    peaks = [i for i in range(1, aa.size - 1) if aa[i] > aa[i - 1] and aa[i] >= aa[i + 1]]
    second = sorted(peaks, key=lambda i: -aa[i])[1]
    df = fa[1] - fa[0]
    check("plateau %.1f: second peak %.3f Hz (%.1f Hz)" % (row["u"], fa[second], f2),
          abs(fa[second] - f2) <= df / 2 + 1e-9, "")

# The start of spouting on a ramp (spouted.ramp_onset): the inlet rises as
# u = 1.3 t to 1 s, then holds (written at 1 kHz, the pressure at 10 kHz).
# The fixed bed's pressure is A u + B u^2 up to the spout's break-through
# at t_b, then 20 Pa; on top, a 40 Hz ripple of 1 Pa (two whole periods in
# the 0.05 s average, so it averages out); after the ramp a larger pressure
# that must not count. The highest particle rests at 0.05 m until t_on,
# then rises at 0.1 m/s.
A, B, t_b, t_on = 60.0, 40.0, 0.55, 0.455
dt = 1e-4
t = np.arange(dt, 1.5 + dt / 2, dt)
tu = np.arange(1e-3, 1.5 + 1e-6, 1e-3)
u = np.minimum(1.3 * tu, 1.3)
pf = lambda uu: A * uu + B * uu ** 2  # noqa: E731
p = np.where(t < t_b, pf(np.minimum(1.3 * t, 1.3)), 20.0) + np.sin(2 * math.pi * 40.0 * t)
p[t > 1.0] = 200.0
th = np.arange(0.0, 1.5 + 1e-6, 0.01)
h = 0.05 + 0.1 * np.maximum(th - t_on, 0.0)
r = spouted.ramp_onset(t, p, th, h, tu, u, 1.0, width=0.05, rise=0.002,
                       u_fixed=(0.01, 0.2, 0.3, 0.8))
# first 100 Hz sample above 0.052 m: 0.05 + 0.1 (t - 0.455) > 0.052 at t > 0.475
check("ramp: onset at %.4f s, %.4f m/s (0.48 s, %.4f m/s)" % (r["t_onset"], r["u_onset"], 1.3 * 0.48),
      abs(r["t_onset"] - 0.48) < 1e-9 and abs(r["u_onset"] - 1.3 * 0.48) < 1e-6, "")
# the 0.05 s average is largest with its window just before t_b, centred
# at t_b - 0.025 s, where it is A u + B u^2 (to B (1.3 * 0.025)^2 / 3 and
# the ripple's sampling): within 0.1 % and one sample (1e-4 s) of that
want = pf(1.3 * (t_b - 0.025))
check("ramp: peak %.3f Pa at %.5f s, %.4f m/s (%.3f Pa at %.4f s), not the 200 Pa after the ramp"
      % (r["p_peak"], r["t_peak"], r["u_peak"], want, t_b - 0.025),
      abs(r["p_peak"] / want - 1) < 1e-3 and abs(r["t_peak"] - (t_b - 0.025)) < 1.5e-4
      and abs(r["u_peak"] - 1.3 * r["t_peak"]) < 1e-9, "")
fixed = dict(r["fixed"])
check("ramp: fixed-bed pressure at 0.2 and 0.3 m/s only (0.01 m/s is reached in the first"
      " half-width, 0.8 past the onset): %s" % r["fixed"],
      [uf for uf, pv in r["fixed"] if not math.isnan(pv)] == [0.2, 0.3], "")
for uf in (0.2, 0.3):
    check("ramp: p(%.1f) %.4f Pa (%.4f)" % (uf, fixed.get(uf, float("nan")), pf(uf)),
          abs(fixed.get(uf, 0.0) / pf(uf) - 1) < 5e-3, "")
check("ramp: complete", r["complete"], "")
# a run still going: no onset yet (data to 0.4 s), or its peak's average
# (centred at 0.525 s, ending at 0.55 s) not yet more than the 0.05 s width
# before the last average's end (data to 0.58 s); with data to 0.61 s it is
for cut, want_complete in ((0.4, False), (0.58, False), (0.61, True)):
    m, mh, mu = t <= cut, th <= cut, tu <= cut
    rc = spouted.ramp_onset(t[m], p[m], th[mh], h[mh], tu[mu], u[mu], 1.0)
    check("ramp: data to %.2f s complete %s" % (cut, want_complete),
          rc["complete"] == want_complete, str(rc["complete"]))
# a ramp shorter than one average: no figures, not complete
m = t <= 0.03
rc = spouted.ramp_onset(t[m], p[m], th[th <= 0.03], h[th <= 0.03], tu, u, 1.0)
check("ramp: data shorter than the 0.05 s average give NaN, not complete",
      math.isnan(rc["p_peak"]) and not rc["complete"], str(rc["p_peak"]))
# a bed that does not break through on the ramp: the pressure rises to the
# ramp's end, the top moves; with the data past the ramp the peak is at the
# ramp's end and final
p2 = np.where(t <= 1.0, pf(np.minimum(1.3 * t, 1.3)), 20.0)
r2 = spouted.ramp_onset(t, p2, th, h, tu, u, 1.0)
check("ramp: no break-through: peak %.3f Pa at %.4f s (the ramp's end), complete"
      % (r2["p_peak"], r2["t_peak"]),
      r2["complete"] and abs(r2["t_peak"] - 0.975) < 1.5e-4, "")

finish()
