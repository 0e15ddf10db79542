#!/usr/bin/python3
"""cohesiveBedEvacuation: the table of the studies Allstudies ran.

    studies.py [DIR]       (default: studies)

Reads, for each study DIR/<name> that has results (postprocess.py), its
summary, its time series and fractions, its wall and CPU time (the last
ExecutionTime/ClockTime line of log.pisoDEMFoam) and its Courant numbers
(the volume average and the maximum pisoDEMFoam prints at every step,
averaged and maximised over the run; for a log of a solver that printed
only the maximum, from log.meanCourant if there is one: OpenFOAM's
CourantNo and volFieldValue function objects at every write), and
writes

  results/studies.dat   one line per study (a run that stopped before its
                        end, diverged, is marked and has no results):
                        mean and largest Courant
                        number, CPU and wall time, the fraction of the bed
                        evacuated at 0.10, 0.15 and 0.20 s, the fraction
                        that reached collector B or left through the vent,
                        the mean particle velocity in the outlet tube, the
                        gas velocity at the vent over the last quarter and
                        before the first particle entered the tube; and
                        each quantity's difference from the study's
                        reference level (time step: ci1, the smallest step;
                        mesh and restitution: base)
  results/studies.png   the fraction evacuated against time of every study,
                        and the difference of the fraction evacuated at the
                        end against CPU time for the time-step and mesh
                        studies
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

from postprocess import read_table  # noqa: E402  (the case's own)

ORDER = ["ci1", "base", "ci3", "ci4", "mesh3mm", "e0.1", "e0.5"]
WHAT = {
    "base": "the tutorial: couplingInterval 2, 2 mm background mesh, e 0.3",
    "ci1": "couplingInterval 1 (CFD step halved)",
    "ci3": "couplingInterval 3",
    "ci4": "couplingInterval 4",
    "mesh3mm": "3 mm background mesh (1.5 mm at walls)",
    "e0.1": "restitution 0.1",
    "e0.5": "restitution 0.5",
}
# The level each study is compared with
REFERENCE = {"ci1": "ci1", "base": "ci1", "ci3": "ci1", "ci4": "ci1",
             "mesh3mm": "base", "e0.1": "base", "e0.5": "base"}
TIMES = (0.10, 0.15, 0.20)


def at(rows, t):
    """The value (column 1) at the row nearest to t, or nan past the end"""
    if not rows or t > rows[-1][0] + 1e-3:
        return float("nan")
    return min(rows, key=lambda r: abs(r[0] - t))[1]


def times(log):
    cpu = wall = float("nan")
    for line in open(log):
        m = re.match(r"ExecutionTime = ([\d.eE+-]+) s\s+ClockTime = ([\d.eE+-]+) s", line)
        if m:
            cpu, wall = float(m.group(1)), float(m.group(2))
    return cpu, wall


def courant(d):
    text = open(os.path.join(d, "log.pisoDEMFoam")).read()
    pairs = re.findall(r"Courant number mean = ([\d.eE+-]+) max = ([\d.eE+-]+)", text)
    # (a diverging run's last lines are not Courant numbers of its flow)
    pairs = [(m, p) for m, p in pairs if float(p) < 1e3]
    mean = [float(m) for m, _ in pairs]
    peak = [float(p) for _, p in pairs]
    if not pairs and os.path.exists(os.path.join(d, "log.meanCourant")):
        text = open(os.path.join(d, "log.meanCourant")).read()
        mean = [float(v) for v in re.findall(
            r"volAverage\(region0\) of Co = ([\d.eE+-]+)", text)]
        peak = [float(v) for v in re.findall(
            r"max\(region0\) of Co = ([\d.eE+-]+)", text)]
    if not mean:
        return float("nan"), float("nan")
    return sum(mean) / len(mean), max(peak)


def clean_vent_velocity(path, ts):
    """The mean gas velocity at the vent from 0.02 s (start-up) to the
    first particle in the outlet tube: the gas flow before the load"""
    first = next((r[0] for r in ts if r[2] > 0), ts[-1][0])
    u = [float(line.split()[2]) for line in open(path)
         if re.match(r"# [\d.eE+-]+ ", line)
         and 0.02 <= float(line.split()[1]) < first]
    return sum(u) / len(u) if u else float("nan")


def study(d):
    s = caseio.read_summary(d)
    ts = read_table(os.path.join(d, "results", "timeSeries.dat"))
    fr = read_table(os.path.join(d, "results", "fractions.dat"))
    cpu, wall = times(os.path.join(d, "log.pisoDEMFoam"))
    co_mean, co_max = courant(d)
    last = fr[-1]
    asked = caseio.foam_scalar(os.path.join(d, "DEM", "post", "setupDict"), "endTime")
    if ts[-1][0] < asked - 2e-3:
        # stopped early (the solver's NaN check): no results, only where
        return dict(coMean=co_mean, coMax=co_max, cpu=cpu, wall=wall,
                    end=ts[-1][0], stopped=True,
                    **{k: float("nan") for k in (
                        ["evac%.2f" % t for t in TIMES]
                        + ["reachedB", "tubeVelocity", "ventVelocity",
                           "ventVelocityClean"])},
                    series=[(r[0], r[1]) for r in ts])
    return dict(stopped=False,
        coMean=co_mean, coMax=co_max, cpu=cpu, wall=wall,
        end=float(s["endTime_s"]),
        **{"evac%.2f" % t: at(ts, t) for t in TIMES},
        reachedB=last[5] + last[6],
        ventVelocityClean=clean_vent_velocity(
            os.path.join(d, "results", "timeSeries.dat"), ts),
        tubeVelocity=float(s["tubeParticleVelocityMean_m_s"]),
        ventVelocity=float(s["ventVelocityLastQuarter_m_s"]),
        series=[(r[0], r[1]) for r in ts])


def main():
    top = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "studies")
    found = {}
    for name in ORDER:
        d = os.path.join(top, name)
        if os.path.exists(os.path.join(d, "results", "summary.dat")):
            found[name] = study(d)
    if not found:
        sys.exit("studies.py: no study with results in %s" % top)
    keys = ["evac0.10", "evac0.15", "evac0.20", "reachedB", "tubeVelocity",
            "ventVelocity", "ventVelocityClean"]
    os.makedirs("results", exist_ok=True)
    with open("results/studies.dat", "w") as f:
        f.write("# cohesiveBedEvacuation studies (%s), all from one packed bed\n" % top)
        f.write("# study coMean coMax cpu_s wall_s end_s " + " ".join(keys)
                + " | reference " + " ".join("d_" + k for k in keys) + "\n")
        f.write("# evac<t>: fraction of the bed out of the chamber at t; reachedB: "
                "collector B + deleted at the vent, at the end; velocities in m/s "
                "(ventVelocityClean: from 0.02 s to the first particle in the tube); "
                "d_: difference from the reference study (fractions: absolute; "
                "velocities: relative)\n")
        for name, r in found.items():
            ref = found.get(REFERENCE[name])
            diffs = []
            for k in keys:
                if ref is None or math.isnan(r[k]) or math.isnan(ref[k]):
                    diffs.append("nan")
                elif "Velocity" in k:
                    diffs.append("%+.4f" % (r[k] / ref[k] - 1))
                else:
                    diffs.append("%+.4f" % (r[k] - ref[k]))
            f.write("%-8s %.4f %.3f %8.1f %8.1f %.4f " % (
                name, r["coMean"], r["coMax"], r["cpu"], r["wall"], r["end"])
                + " ".join("%.4f" % r[k] for k in keys)
                + " | %-5s " % REFERENCE[name] + " ".join(diffs)
                + "  # " + WHAT[name]
                + (" (stopped at %.4g s: diverged)" % r["end"] if r["stopped"] else "")
                + "\n")
    print(open("results/studies.dat").read())

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return 0
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    for name, r in found.items():
        t, e = zip(*r["series"])
        a1.plot(t, e, label=name + (" (diverged at %.4g s)" % r["end"]
                                    if r["stopped"] else ""), lw=1.2,
                ls="-" if name in ("base", "ci1", "ci3", "ci4") else "--")
    a1.set_xlabel("t [s]")
    a1.set_ylabel("fraction of the bed out of the chamber")
    a1.legend(fontsize=8)
    a1.grid(alpha=0.3)
    for name, r in found.items():
        ref = found.get(REFERENCE[name])
        if (name.startswith("e") or ref is None or name == REFERENCE[name]
                or r["stopped"]):
            continue
        err = abs(r["evac0.20"] - ref["evac0.20"])
        a2.plot(r["cpu"], err, "o", color="C0" if name.startswith("ci") or name == "base" else "C1")
        a2.annotate("%s (Co %.2f)" % (name, r["coMean"]), (r["cpu"], err),
                    textcoords="offset points", xytext=(4, 3), fontsize=8)
    a2.set_xlabel("CPU time of the coupled run [s]")
    a2.set_ylabel("|fraction evacuated at 0.2 s - reference|")
    a2.set_title("time step (vs ci1), mesh (vs base)", fontsize=9)
    a2.grid(alpha=0.3)
    a2.margins(0.2)
    fig.tight_layout()
    fig.savefig("results/studies.png", dpi=80)
    return 0


if __name__ == "__main__":
    sys.exit(main())
