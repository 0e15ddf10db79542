#!/usr/bin/python3
"""compareWindow.py CASE [CASE ...] --window T0 T1 [--fmin F] [--out FILE]
                  [--plot FILE.png] [--labels L1 L2 ...]
compareWindow.py CASE [CASE ...] --ramp [--u-fixed U ...] [--rise DH]
                  [--width W] [--out FILE] [--plot FILE.png] [--labels ...]

The plateau statistics of postprocess.py (python/foamdem/spouted.py: the
gauge pressure's RMS deviation and dominant frequency at the probe, the
highest sphere centre's mean and maximum: the body's centre in the
production representation, the highest of a body's spheres, up to half a
body length (2.6 mm) above its centre, with clumps) over one common window
T0..T1 for several runs of the case, each as it stands on disk (continued
segments joined as postprocess.py joins them). For the mesh check
(README): runs that differ in one setting, or a run started from another
run's state, compared over the same stretch of a plateau. Prints a table
and, with --out, writes it (one line per case: case rms_Pa
dominantFrequency_Hz maxHeightMean_m maxHeightMax_m samples cells).
With --plot, a figure of the cases' pressure, highest particle and
amplitude spectrum over the window (one colour per case, --labels for the
legend). Exits 1 if a case's data do not cover the window.

--ramp: the start of spouting on the inlet's ramp instead (up to the
first plateau's start in DEM/post/schedule.dat; spouted.ramp_onset): the
inlet velocity when the highest particle first stands more than DH
(--rise, default 2 mm) above its first sample (the filled bed), the
largest W-second (--width, default 0.05 s) average of the gauge pressure
with its inlet velocity, and the fixed bed's pressure at the --u-fixed
velocities (default 0.2 0.3 m/s). One line per case: case u_onset_m_s
t_onset_s p_peak_Pa u_peak_m_s t_peak_s complete, then p_Pa at each
--u-fixed velocity (nan at or past the onset). With --plot, the averaged
pressure and the highest particle against the inlet velocity. Exits 1 if
a case lacks its data, has no onset, or its pressure has not yet fallen
from its peak for one averaging width (complete 0; spouted.ramp_onset:
before the ramp's end a complete peak is still a judgement).
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", os.path.join(HERE, "..", "..")), "python"))
import postprocess as pp  # noqa: E402
from foamdem import spouted  # noqa: E402


def cells(case):
    """nCells from the mesh's owner file header (-1 if absent)."""
    owner = os.path.join(case, "constant/polyMesh/owner")
    if os.path.exists(owner):
        head = open(owner).read(2000)
        i = head.find("nCells:")
        if i >= 0:
            return int(head[i + 7:].split()[0])
    return -1


def table(head, lines, out):
    """Print the table, and write it to out if given."""
    text = head + "\n" + "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if out:
        with open(out, "w") as f:
            f.write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+")
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--window", type=float, nargs=2)
    mode.add_argument("--ramp", action="store_true")
    ap.add_argument("--u-fixed", type=float, nargs="+", default=[0.2, 0.3])
    ap.add_argument("--rise", type=float, default=0.002)
    ap.add_argument("--width", type=float, default=0.05)
    ap.add_argument("--fmin", type=float, default=0.0)
    ap.add_argument("--out")
    ap.add_argument("--plot")
    ap.add_argument("--labels", nargs="+")
    args = ap.parse_args()
    if args.labels and len(args.labels) != len(args.cases):
        sys.exit("compareWindow.py: %d labels for %d cases" % (len(args.labels), len(args.cases)))
    labels = dict(zip(args.cases, args.labels or args.cases))
    if args.ramp:
        return ramp(args, labels)
    t0, t1 = args.window
    lines, status, series = [], 0, []
    for case in args.cases:
        tp, p, hd = pp.load_signals(case)
        rows = spouted.plateau_statistics(tp, p, hd[:, 0], hd[:, 1], [(0.0, t0, t1)],
                                          0.0, 0.0, args.fmin)
        hstep = float(np.median(np.diff(hd[:, 0]))) if len(hd) > 1 else 0.0
        if (not rows or not rows[0]["complete"] or tp[0] > t0
                or hd[0, 0] > t0 or hd[-1, 0] < t1 - 1.5 * hstep):
            print("%s: the data (pressure %.4g-%.4g s, height %.4g-%.4g s) do not cover"
                  " %g-%g s" % (case, tp[0], tp[-1], hd[0, 0], hd[-1, 0], t0, t1))
            status = 1
            continue
        r = rows[0]
        ps, pv = spouted.select(tp, p, t0, t1)
        hs, hv = spouted.select(hd[:, 0], hd[:, 1], t0, t1)
        f, a = spouted.amplitude_spectrum(ps, pv)
        series.append((case, ps, pv, hs, hv, f, a, r))
        lines.append("%s %.6g %.6g %.6g %.6g %d %d" % (case, r["rms"], r["fdom"], r["hmean"],
                                                       r["hmax"], r["n"], cells(case)))
    head = ("# spoutedBed, window %g-%g s: case rms_Pa dominantFrequency_Hz"
            " maxHeightMean_m maxHeightMax_m probeSamples cells" % (t0, t1))
    table(head, lines, args.out)
    if args.plot and series:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(3, 1, figsize=(7, 7.5))
        for case, ps, pv, hs, hv, f, a, r in series:
            lab = labels[case]
            line, = ax[0].plot(ps, pv, lw=0.5, label="%s: s %.3g Pa" % (lab, r["rms"]))
            ax[1].plot(hs, hv, lw=0.8, color=line.get_color(),
                       label="%s: mean %.3g m, max %.3g m" % (lab, r["hmean"], r["hmax"]))
            ax[2].plot(f, a, lw=0.8, color=line.get_color(),
                       label="%s: %.3g Hz" % (lab, r["fdom"]))
        ax[0].set_ylabel("gauge pressure [Pa]")
        ax[1].set_ylabel("highest particle [m]")
        for k in (0, 1):
            ax[k].set_xlabel("t [s]")
        ax[2].set_xlabel("f [Hz]")
        ax[2].set_ylabel("amplitude [Pa]")
        ax[2].set_xlim(0, 30)
        for k in range(3):
            ax[k].legend(fontsize=7)
        ax[0].set_title("window %g-%g s" % (t0, t1), fontsize=9)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=80)
        plt.close(fig)
    return status


def ramp(args, labels):
    """The --ramp table and figure (module docstring)."""
    lines, status, series = [], 0, []
    for case in args.cases:
        schedule = os.path.join(case, "DEM/post/schedule.dat")
        inlet = pp.load_inlet_velocity(case)
        if not os.path.exists(schedule) or inlet is None:
            print("%s: no DEM/post/schedule.dat or postProcessing/inletVelocity" % case)
            status = 1
            continue
        tu, u = inlet
        tp, p, hd = pp.load_signals(case)
        # the ramp ends where the first plateau starts (prepare.py's schedule)
        t_end = np.loadtxt(schedule, ndmin=2)[0, 1]
        r = spouted.ramp_onset(tp, p, hd[:, 0], hd[:, 1], tu, u, t_end, args.width,
                               args.rise, args.u_fixed)
        status |= not r["complete"]
        series.append((case, hd[hd[:, 0] <= t_end], tu, u, r))
        lines.append("%s %.4g %.4g %.4g %.4g %.4g %d %s" % (
            case, r["u_onset"], r["t_onset"], r["p_peak"], r["u_peak"], r["t_peak"],
            r["complete"], " ".join("%.4g" % pf for uf, pf in r["fixed"])))
    head = ("# spoutedBed, the ramp (rise %g m, averages over %g s): case u_onset_m_s"
            " t_onset_s p_peak_Pa u_peak_m_s t_peak_s complete %s"
            % (args.rise, args.width, " ".join("p_%g_Pa" % uf for uf in args.u_fixed)))
    table(head, lines, args.out)
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        for case, hd, tu, u, r in series:
            lab = labels[case]
            line, = ax[0].plot(np.interp(r["ts"], tu, u), r["ps"], lw=0.8,
                               label="%s: peak %.3g Pa at %.3g m/s" % (lab, r["p_peak"], r["u_peak"]))
            ax[1].plot(np.interp(hd[:, 0], tu, u), hd[:, 1], lw=0.8, color=line.get_color(),
                       label="%s: onset %.3g m/s" % (lab, r["u_onset"]))
        ax[0].set_ylabel("gauge pressure, %g s average [Pa]" % args.width)
        ax[1].set_ylabel("highest particle [m]")
        ax[1].set_xlabel("inlet velocity [m/s]")
        for a in ax:
            a.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=80)
        plt.close(fig)
    return int(status)


if __name__ == "__main__":
    sys.exit(main())
