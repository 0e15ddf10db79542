#!/usr/bin/python3
"""cohesiveBedEvacuation post-processing.

Reads DEM/post/evacuation.dat (the DEM's time series: particles present,
crossed and deleted at the vent, in the chamber, in the outlet tube and
their mean vertical velocity), the vent's and supply's surfaceFieldValue
output, and the particle positions at each write (DEM/post/dump), and
writes

  results/timeSeries.dat   t, fraction evacuated, particles in the tube and
                           their mean vertical velocity, vent gas velocity
  results/fractions.dat    at each write: the fraction of the bed in the
                           chamber, the tube, the duct, collection chambers
                           A and B, and deleted at the vent
  results/tubeProfile.dat  the particles' mean vertical velocity in four
                           height bins of the outlet tube (all writes
                           pooled), next to that of a lone sphere
                           accelerated from rest at the tube's mouth by the
                           mean gas velocity in the tube while it held
                           particles (vent flow / tube area; Schiller-
                           Naumann drag of foamdem.drag, gravity): what a particle alone
                           would reach in the tube's length
  results/summary.dat      the figures the README reports
  results/timeSeries.png   particle velocity in the tube, gas velocity at
                           the vent, fraction evacuated, against time

--ci   pass/fail checks of the CI variant:
       - the flow is established: the vent's volume flow equals the supply's
         within 1 % and varies by less than 10 % over the last quarter of
         the run, the vent velocity above 30 m/s;
       - the fill inserted all the particles asked for;
       - particles crossed the vent and were deleted (at least one);
       - the account is exact at every line: present + deleted = initial;
       - the run reached its end time.
"""
import argparse
import bisect
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, drag  # noqa: E402

import prepare  # noqa: E402  (the case's own geometry parameters)


def read_table(path):
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        line = line.replace("(", " ").replace(")", " ")
        rows.append([float(x) for x in line.split()])
    return rows


def field_value(name):
    rows = []
    for f in caseio.function_object_segments(".", name, "surfaceFieldValue.dat"):
        rows.extend(read_table(f))
    # a continuation's lines replace the earlier run's from its start on
    return caseio.later_segment_wins(rows, lambda r: r[0])


def classify(P, x, y, z):
    """Where a particle is, from its position (turned back by 'rotation')"""
    th = math.radians(P["rotation"])
    c, s = math.cos(th), math.sin(th)
    xr, yr = c * x + s * y, -s * x + c * y
    h, L = P["tubeWidth"] / 2, P["ductHalfLength"]
    if z < P["chamberHeight"] and xr * xr + yr * yr < P["chamberRadius"] ** 2:
        return "chamber"
    if z < P["tubeTop"] and abs(xr) <= h and abs(yr) <= h:
        return "tube"
    if abs(xr) <= L:
        return "duct"
    return "collectorA" if xr < 0 else "collectorB"


def lone_sphere_velocity(P, u_gas, heights):
    """Vertical velocity of a lone sphere (the case's diameter and density)
    accelerated from rest at the tube's mouth by a uniform upward gas
    velocity u_gas (Schiller-Naumann drag, foamdem.drag; gravity), at the
    given heights above the mouth, in increasing order"""
    d, rho_g = P["diameter"], P["rhoGas"]
    mu = rho_g * P["nuGas"]
    mass = P["density"] * math.pi / 6 * d ** 3
    v = z = 0.0
    dt = 1e-6
    out = []
    for h in heights:
        while z < h:
            slip = u_gas - v
            a = drag.schiller_naumann(d, rho_g, mu, 1.0, abs(slip)) * slip / mass - 9.81
            v += a * dt
            z += v * dt
            if v <= 0 and a <= 0:
                return out + [0.0] * (len(heights) - len(out))
        out.append(v)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ci", action="store_true")
    a = ap.parse_args()
    P = prepare.read_props(".", a.ci)
    setup = caseio.liggghts_variables("DEM/post/setup.lig")
    n_asked = int(setup["nParticles"])
    dt = float(setup["demDt"])
    end_time = caseio.foam_scalar("DEM/post/setupDict", "endTime")
    os.makedirs("results", exist_ok=True)

    ev = caseio.later_segment_wins(read_table("DEM/post/evacuation.dat"),
                                   lambda r: r[0])
    # The bed: what the fill stage inserted (insert/pack may fall short of
    # nParticles when the region is too small for it), at the first line
    n0 = int(round(ev[0][1] + ev[0][3]))
    if n0 != n_asked:
        print("postprocess.py: the fill inserted %d of the %d particles asked for"
              % (n0, n_asked))
    # the DEM's time is step x dt from the restart's step 0
    t = [r[0] for r in ev]
    n = [int(round(r[1])) for r in ev]
    deleted = [int(round(r[3])) for r in ev]
    in_chamber = [int(round(r[4])) for r in ev]
    in_tube = [int(round(r[5])) for r in ev]
    vz_tube = [r[6] for r in ev]

    vent_u = field_value("vent")          # t, Ux, Uy, Uz, p
    vent_q = field_value("ventFlow")      # t, sum(phi)
    supply_q = field_value("supplyFlow")
    a_vent = P["ventWidth"] ** 2
    tq = [r[0] for r in vent_q]
    u_vent = [r[1] / a_vent for r in vent_q]

    with open("results/timeSeries.dat", "w") as f:
        f.write("# t_s fractionEvacuated inTube vzTube_m_s (DEM, every %g s)\n"
                % (t[1] - t[0] if len(t) > 1 else 0))
        for i in range(len(t)):
            f.write("%.6g %.6g %d %.6g\n" % (t[i], 1 - in_chamber[i] / n0,
                                             in_tube[i], vz_tube[i]))
        f.write("# t_s ventVelocity_m_s (volume flow / vent area) "
                "ventVelocityAreaAverage_m_s\n")
        for r, q in zip(vent_u, vent_q):
            f.write("# %.6g %.6g %.6g\n" % (q[0], q[1] / a_vent,
                                            math.sqrt(r[1] ** 2 + r[2] ** 2 + r[3] ** 2)))

    # Where the particles are at each write
    dumps = []
    for path in glob.glob("DEM/post/dump/where.*.txt"):
        step = int(re.search(r"where\.(\d+)\.txt", path).group(1))
        dumps.append((step, path))
    fr_rows = []
    places = ["chamber", "tube", "duct", "collectorA", "collectorB"]
    n_bins = 4
    z_mouth, tube_len = P["chamberHeight"], P["tubeTop"] - P["chamberHeight"]
    bin_n = [0] * n_bins
    bin_vz = [0.0] * n_bins
    for step, path in sorted(dumps):
        counts = dict.fromkeys(places, 0)
        lines = open(path).read().split("ITEM: ATOMS")[1].strip().splitlines()[1:]
        for line in lines:
            v = line.split()
            where = classify(P, float(v[1]), float(v[2]), float(v[3]))
            counts[where] += 1
            if where == "tube":
                k = int((float(v[3]) - z_mouth) / tube_len * n_bins)
                if 0 <= k < n_bins:
                    bin_n[k] += 1
                    bin_vz[k] += float(v[6])
        fr_rows.append((step * dt, counts, n0 - len(lines)))
    with open("results/fractions.dat", "w") as f:
        f.write("# t_s " + " ".join(places) + " deletedAtVent (fractions of the "
                "%d particles of the bed)\n" % n0)
        for tt, c, gone in fr_rows:
            f.write("%.6g " % tt + " ".join("%.5f" % (c[p] / n0) for p in places)
                    + " %.5f\n" % (gone / n0))

    # The tube's velocity profile against a lone sphere's in the mean gas
    # velocity in the tube while it held particles (the vent's volume flow
    # at the DEM's sample times with particles in the tube)
    loaded = []
    for tt, k in zip(t, in_tube):
        if k > 0 and tq:
            j = min(bisect.bisect_left(tq, tt), len(tq) - 1)
            loaded.append(u_vent[j])
    u_vent_loaded = sum(loaded) / len(loaded) if loaded else sum(u_vent) / len(u_vent)
    u_tube_gas = u_vent_loaded * a_vent / P["tubeWidth"] ** 2
    centres = [(k + 0.5) * tube_len / n_bins for k in range(n_bins)]
    lone = lone_sphere_velocity(P, u_tube_gas, centres)
    with open("results/tubeProfile.dat", "w") as f:
        f.write("# height above the tube's mouth [m], particle samples (all writes), "
                "their mean vz [m/s], a lone sphere's vz from rest at the mouth in "
                "%.4g m/s of gas (the mean vent flow while the tube held particles "
                "/ tube area) [m/s]\n"
                % u_tube_gas)
        for k in range(n_bins):
            f.write("%.4f %d %.4f %.4f\n" % (
                centres[k], bin_n[k],
                bin_vz[k] / bin_n[k] if bin_n[k] else float("nan"), lone[k]))

    # The last quarter of the run: the established flow
    q0 = 0.75 * tq[-1]
    last = [u for tt, u in zip(tq, u_vent) if tt >= q0]
    u_mean = sum(last) / len(last)
    u_spread = (max(last) - min(last)) / u_mean
    qv = vent_q[-1][1]
    qs = -supply_q[-1][1]
    moving = [v for v, k in zip(vz_tube, in_tube) if k > 0]
    vz_mean = sum(moving) / len(moving) if moving else float("nan")
    rows = [
        ("particlesAsked", n_asked, ""),
        ("particlesInitial", n0, "inserted by the fill"),
        ("particlesPresentEnd", n[-1], ""),
        ("deletedAtVentEnd", deleted[-1], ""),
        ("fractionEvacuatedEnd", 1 - in_chamber[-1] / n0, ""),
        ("ventVelocityLastQuarter_m_s", u_mean, "volume flow / vent area"),
        ("ventFlowOverSupplyFlow", qv / qs if qs else float("nan"), ""),
        ("tubeParticleVelocityMean_m_s", vz_mean,
         "mass-weighted vz in the tube, mean over samples with particles"),
        ("tubeGasVelocityLoaded_m_s", u_tube_gas,
         "mean vent flow while the tube held particles / tube area"),
        ("tubeTopBinParticleVelocity_m_s",
         bin_vz[-1] / bin_n[-1] if bin_n[-1] else float("nan"),
         "mean vz in the tube's top quarter, all writes pooled"),
        ("loneSphereTubeTopBinVelocity_m_s", lone[-1],
         "a lone sphere from rest at the mouth, same height"),
        ("endTime_s", t[-1], ""),
    ]
    caseio.write_summary(".", [(k, "%.6g" % v) for k, v, _ in rows])

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(3, 1, figsize=(6, 7), sharex=True)
        ax[0].plot(t, vz_tube, lw=0.8)
        ax[0].axhspan(5, 6, color="0.85", label="reference 5-6 m/s")
        ax[0].set_ylabel("particle vz in tube [m/s]")
        ax[0].legend(loc="upper left", fontsize=8)
        ax[1].plot(tq, u_vent, lw=0.8)
        ax[1].axhspan(60, 70, color="0.85", label="reference 60-70 m/s")
        ax[1].set_ylabel("gas velocity at vent [m/s]")
        ax[1].legend(loc="lower right", fontsize=8)
        ax[2].plot(t, [1 - c / n0 for c in in_chamber], lw=0.8, label="left the chamber")
        ax[2].plot(t, [d / n0 for d in deleted], lw=0.8, label="deleted at the vent")
        ax[2].set_ylabel("fraction of the bed")
        ax[2].set_xlabel("t [s]")
        ax[2].legend(loc="upper left", fontsize=8)
        fig.tight_layout()
        fig.savefig("results/timeSeries.png", dpi=90)
    except ImportError:
        print("postprocess.py: no matplotlib, no plot")

    if not a.ci:
        return 0
    ok = True

    def check(cond, msg):
        nonlocal ok
        print(("ok:   " if cond else "FAIL: ") + msg)
        ok = ok and cond

    check(abs(qv / qs - 1) < 0.01 and u_spread < 0.10 and u_mean > 30,
          "flow established: vent flow / supply flow %.4f (within 1 %%), vent "
          "velocity %.1f m/s (> 30) varying by %.1f %% (< 10 %%) over the last quarter"
          % (qv / qs, u_mean, 100 * u_spread))
    check(n0 == n_asked, "the fill inserted all %d particles asked for (%d)"
          % (n_asked, n0))
    check(deleted[-1] > 0,
          "%d particle(s) crossed the vent and were deleted" % deleted[-1])
    bad = [(tt, k, d) for tt, k, d in zip(t, n, deleted) if k + d != n0]
    check(not bad, "account exact at all %d lines: present + deleted = %d%s"
          % (len(t), n0, "" if not bad else "; first mismatch at t = %g: %d + %d"
             % bad[0]))
    check(t[-1] >= end_time - 2e-3 and "End" in open(
        max(glob.glob("log.pisoDEMFoam*"), key=os.path.getmtime)).read(),
          "the run reached t = %.4g s of %.4g s and ended" % (t[-1], end_time))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
