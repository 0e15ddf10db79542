#!/usr/bin/python3
"""spoutedBed post-processing: per inlet-velocity plateau, the gauge
pressure's RMS deviation and dominant frequency and the maximum particle
height (python/foamdem/spouted.py), as the reference reported them; plots
and particle snapshots; checks.

Reads postProcessing/pressureProbe/*/p (every CFD step),
postProcessing/inletVelocity/*/surfaceFieldValue.dat (or the _<start>.dat
of a segment run twice from one start), DEM/post/height.dat
(100 Hz: time, highest sphere centre, sphere count, total mass; with
clumps the highest of the clumps' spheres, up to half a body length above
its body's centre),
DEM/post/schedule.dat and DEM/post/particles.dat (prepare.py), the dumps
DEM/post/dump/snap.*.txt.

Writes results/<set>/plateaus.dat (inletVelocity rms_Pa
dominantFrequency_Hz maxHeightMean_m maxHeightMax_m), results/summary.dat,
results/<set>/timeSeries.png (pressure and height), spectra.png and
snapshot_<U>.png.

Each plateau's window drops its first 1/8 and last 1/16 (0.5 s and 0.25 s
of the reference's 4 s plateaus); the first plateau counts from the end of
the ramp. The dominant frequency is searched above --fmin Hz.

--ci        CI checks: the schedule is applied, the probe is written every
            CFD step, the analysis gives finite values for every plateau.
All runs: the set's particles were inserted (the first snapshot's spheres
per type over spheres per particle), the solver couples one particle per
body, no sphere is lost and the mass is constant.
--no-plot   skip the PNGs
--skip S    drop the first S seconds of each window instead of 1/8 of the
            hold (to compare a run started later within a plateau, e.g.
            from another run's state, over the same window)
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, spouted  # noqa: E402


def concat(case, name, fname, read=lambda path: np.loadtxt(path, comments="#", ndmin=2)):
    """Rows of postProcessing/<name>/*/<fname> of a run and its
    continuations (caseio.function_object_segments: each segment's file,
    in the order they were written), by time, the later segment winning
    where they overlap; read(path) gives a file's rows."""
    parts = []
    for path in caseio.function_object_segments(case, name, fname):
        d = read(path)
        if d.size:
            parts.append(d)
    if not parts:
        return None
    out = parts[0]
    for d in parts[1:]:
        out = np.vstack([out[out[:, 0] < d[0, 0]], d])
    return out


def latest_segments(d):
    """Rows of a file that continued runs append to: where the time goes
    back (a run continued from an earlier write), the later rows replace
    the earlier ones from that time on."""
    keep = []
    for row in d:
        while keep and keep[-1][0] >= row[0] - 1e-12:
            keep.pop()
        keep.append(row)
    return np.array(keep)


def load_signals(case):
    """The probe's times and gauge pressure [Pa] (rho p, every CFD step) and
    the rows of DEM/post/height.dat, continued segments joined."""
    rho = caseio.foam_scalar(os.path.join(case, "constant/transportProperties"), "rho")
    probe = concat(case, "pressureProbe", "p")
    hfile = os.path.join(case, "DEM/post/height.dat")
    if probe is None or not os.path.exists(hfile):
        sys.exit("%s: no %s: the coupled run has not written it (see its"
                 " log.pisoDEMFoam*)" % (case, "postProcessing/pressureProbe/*/p"
                                         if probe is None else "DEM/post/height.dat"))
    hd = latest_segments(np.loadtxt(hfile, comments="#", ndmin=2))
    return probe[:, 0], rho * probe[:, 1], hd


def read_vector_column(path):
    """surfaceFieldValue.dat of a vector: time and the three components."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        nums = re.findall(r"[-+0-9.eE]+", line.replace("(", " ").replace(")", " "))
        rows.append([float(v) for v in nums[:4]])
    return np.array(rows)


def load_inlet_velocity(case):
    """The inlet's area-averaged U (postProcessing/inletVelocity, every CFD
    step): times and vertical components, continued segments joined; None
    if there are none."""
    iv = concat(case, "inletVelocity", "surfaceFieldValue.dat", read_vector_column)
    return None if iv is None else (iv[:, 0], iv[:, 3])


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--fmin", type=float, default=0.0)
    ap.add_argument("--skip", type=float, default=None)
    args = ap.parse_args()
    case = "."
    checks = []

    head = open("DEM/post/particles.dat").readline()
    set_name = re.search(r"# set (\w+)", head).group(1)
    m = re.search(r"representation (\w+).*; fraction ([-+0-9.eE]+)", head)
    representation, fraction = (m.group(1), float(m.group(2))) if m else ("spheres", None)
    m = re.search(r"; realisation (\d+)", head)
    realisation = int(m.group(1)) if m else 0
    parts = np.genfromtxt("DEM/post/particles.dat", comments="#", dtype=None,
                          encoding=None)
    n_inserted = int(sum(int(r[4]) for r in parts))
    # DEM/post/height.dat counts spheres: one per particle, or each clump's
    # (column spheresPerParticle; older set-ups have one sphere each);
    # target, replaced below by the first snapshot's count
    n_spheres = int(sum(int(r[4]) * (int(r[10]) if len(r) > 10 else 1) for r in parts))
    windows = [tuple(r) for r in np.loadtxt("DEM/post/schedule.dat", ndmin=2)]
    hold = windows[0][2] - windows[0][1]
    setup = open("DEM/post/setupDict").read()
    dt_cfd = float(re.search(r"(?m)^deltaT\s+([-+0-9.eE]+);", setup).group(1))

    tp, pp, hd = load_signals(case)
    th, hh, nh, mh = hd[:, 0], hd[:, 1], hd[:, 2], hd[:, 3]

    skip = hold / 8 if args.skip is None else args.skip
    rows = spouted.plateau_statistics(tp, pp, th, hh, windows, skip, hold / 16,
                                      args.fmin)
    out = os.path.join("results", set_name)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "plateaus.dat"), "w") as f:
        f.write("# spoutedBed, set %s%s, representation %s%s: per inlet velocity"
                " plateau, in its window (first %s and last 1/16 dropped)\n"
                % (set_name, " (CI)" if args.ci else "", representation,
                   ("" if fraction in (None, 1.0) else ", fraction %g of the particles" % fraction)
                   + ("" if realisation == 0 else ", realisation %d" % realisation),
                   "1/8" if args.skip is None else "%g s" % skip))
        f.write("# gauge pressure at the probe (rho p, p = 0 at the outlet, no"
                " hydrostatic head): RMS deviation (N - 1) and dominant frequency of its"
                " amplitude spectrum; highest particle centre above the inlet plane:"
                " mean and maximum\n")
        f.write("# inletVelocity rms_Pa dominantFrequency_Hz maxHeightMean_m maxHeightMax_m\n")
        f.write("# only plateaus whose window the run has reached to its end\n")
        for r in rows:
            if not r["complete"]:
                continue
            f.write("%.3g %.6g %.6g %.6g %.6g\n" % (r["u"], r["rms"], r["fdom"],
                                                  r["hmean"], r["hmax"]))

    summary = [("set", set_name), ("representation", representation),
               ("fraction", "%g" % (1.0 if fraction is None else fraction)),
               ("realisation", "%d" % realisation),
               ("particlesInserted", "%d" % n_inserted),
               ("cfdStep_s", "%.6g" % dt_cfd),
               ("probeSamples", "%d" % tp.size)]
    for r in rows:
        summary.append(("plateau_%.3g_m_s (window %.4g-%.4g s, %d samples%s)"
                        % (r["u"], r["w0"], r["w1"], r["n"],
                           "" if r["complete"] else
                           ", INCOMPLETE: data end at %.4g s" % tp[-1]),
                        "rms %.4g Pa, f %.4g Hz, hmean %.4g m, hmax %.4g m"
                        % (r["rms"], r["fdom"], r["hmean"], r["hmax"])))

    # The inserted composition, from the first snapshot (spheres of each
    # type / spheres per particle): insertion by number fractions makes the
    # total exact and each shape's count close to its target, so with
    # clumps the sphere count is the snapshot's, not n_spheres
    first = sorted(glob.glob("DEM/post/dump/snap.*.txt"),
                   key=lambda path: int(path.split(".")[-2]))
    t0 = read_dump(first[0], ("type",)) if first else None
    if t0 is not None:
        counts = np.bincount(t0[:, 0].astype(int), minlength=len(parts) + 1)
        n_spheres = int(counts.sum())
        bodies = [(str(r[1]), counts[int(r[0])] / (int(r[10]) if len(r) > 10 else 1),
                   int(r[4])) for r in parts]
        summary.append(("insertedPerShape (target)", ", ".join(
            "%s %g (%d)" % b_ for b_ in bodies)))
        checks.append(("particles inserted = the set's count (%d)" % n_inserted,
                       int(round(sum(b_[1] for b_ in bodies))) == n_inserted))
    # The coupled particles (the solver's count of bodies and free spheres
    # at its start): one per inserted particle, so a clump is one body
    for path in sorted(glob.glob("log.pisoDEMFoam*")):
        m = re.search(r"DEM steps per CFD step, (\d+) particles", open(path).read())
        if m:
            checks.append(("%s couples %d particles (one per body)" % (path, n_inserted),
                           int(m.group(1)) == n_inserted))
    # Checks (all runs): particles and mass conserved
    checks.append(("no particle lost (sphere count = inserted at every 100 Hz sample)",
                   bool(np.all(nh == n_spheres))))
    dm = float(np.max(np.abs(mh / mh[0] - 1)))
    summary.append(("massMaxRelChange", "%.3e" % dm))
    checks.append(("mass constant (1e-12)", dm < 1e-12))
    if args.ci:
        # schedule applied: the inlet's area-averaged U against the table
        # (no inlet data, postProcessing/inletVelocity: a failed check, not
        # a traceback)
        inlet = load_inlet_velocity(case)
        err = float("nan")
        if inlet is not None:
            tu, uz = inlet
            table = re.search(r"inletTable\s*\((.*?)\n\);", setup, flags=re.S).group(1)
            tab = np.array([[float(v) for v in re.findall(r"[-+0-9.eE]+", line)][::3][:1]
                            + [float(re.findall(r"[-+0-9.eE]+", line)[-1])]
                            for line in table.strip().splitlines()])
            want = np.interp(tu, tab[:, 0], tab[:, 1])
            err = float(np.max(np.abs(uz - want)))
        summary.append(("inletVelocity_maxError_m_s", "%.3e" % err))
        checks.append(("schedule applied (inlet U within 1e-6 m/s of the table)"
                       + ("" if inlet is not None else ": no inlet data"), err < 1e-6))
        # every CFD step: the sample count is the step count, and the
        # spacing is the step to the probe file's printed precision
        dts = np.diff(tp)
        n_steps = int(round((tp[-1] - tp[0]) / dt_cfd)) + 1
        rate_ok = tp.size == n_steps and bool(np.all(np.abs(dts - dt_cfd) < 1e-3 * dt_cfd))
        summary.append(("probeSamples_expected", "%d" % n_steps))
        summary.append(("probeInterval_s", "%.6g-%.6g" % (dts.min(), dts.max())))
        checks.append(("probe written every CFD step", rate_ok))
        finite = len(rows) == len(windows) and all(r["complete"] for r in rows) and all(
            np.isfinite(r["rms"]) and np.isfinite(r["fdom"]) and np.isfinite(r["hmax"])
            for r in rows)
        checks.append(("analysis gives finite values for every plateau", finite))

    if not args.no_plot:
        plots(out, tp, pp, th, hh, rows, windows)
    ok = all(c for _, c in checks)
    summary += [("check: " + n, "ok" if c else "FAILED") for n, c in checks]
    summary.append(("pass", "yes" if ok else "no"))
    caseio.write_summary(".", summary)
    for r in rows:
        print("plateau %.3g m/s: rms %.4g Pa, dominant %.4g Hz, max height mean %.4g m,"
              " max %.4g m%s" % (r["u"], r["rms"], r["fdom"], r["hmean"], r["hmax"],
                                 "" if r["complete"] else " (INCOMPLETE window)"))
    for n, c in checks:
        print("%-60s %s" % (n, "ok" if c else "FAILED"))
    return 0 if ok else 1


def plots(out, tp, pp, th, hh, rows, windows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(2, 1, figsize=(8, 5), sharex=True)
    ax[0].plot(tp, pp, lw=0.3)
    ax[0].set_ylabel("gauge pressure at the probe [Pa]")
    ax[1].plot(th, hh, lw=0.6)
    ax[1].set_ylabel("highest particle [m]")
    ax[1].set_xlabel("t [s]")
    for r in rows:
        for a in ax:
            a.axvspan(r["w0"], r["w1"], color="0.9", zorder=-1)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "timeSeries.png"), dpi=90)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        if not r["complete"]:
            continue
        ax.plot(r["f"], r["a"], lw=0.8, label="%.3g m/s (%.3g Hz)" % (r["u"], r["fdom"]))
    ax.set_xlim(0, 30)
    ax.set_xlabel("f [Hz]")
    ax.set_ylabel("amplitude [Pa]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "spectra.png"), dpi=90)
    plt.close(fig)

    # Snapshots: the dump nearest each plateau's middle
    dumps = {}
    for path in glob.glob("DEM/post/dump/snap.*.txt"):
        dumps[int(path.split(".")[-2])] = path
    if not dumps:
        return
    dt = float(re.search(r"variable demDt\s+equal\s+([-+0-9.eE]+)",
                         open("DEM/post/setup.lig").read()).group(1))
    steps = np.array(sorted(dumps))
    for u, t0, t1 in windows:
        k = steps[np.argmin(np.abs(steps * dt - 0.5 * (t0 + t1)))]
        if not t0 <= k * dt <= t1:
            continue                        # the run has not reached it
        d = read_dump(dumps[k])
        if d is None:
            continue
        fig, ax = plt.subplots(figsize=(5, 5))
        sc = ax.scatter(d[:, 0], d[:, 2], c=d[:, 2], s=1, cmap="viridis")
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("height above the inlet [m]")
        ax.set_title("%.3g m/s, t = %.3g s" % (u, k * dt))
        fig.colorbar(sc, ax=ax, label="height [m]")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "snapshot_%.3g.png" % u), dpi=80)
        plt.close(fig)


def read_dump(path, columns=("x", "y", "z")):
    lines = open(path).read().splitlines()
    try:
        i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    except StopIteration:
        return None
    cols = lines[i].split()[2:]
    data = np.loadtxt(lines[i + 1:], ndmin=2)
    return data[:, [cols.index(c) for c in columns]]


if __name__ == "__main__":
    sys.exit(main())
