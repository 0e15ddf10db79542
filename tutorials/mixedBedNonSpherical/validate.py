#!/usr/bin/python3
"""mixedBedNonSpherical checks: boundedness (void fraction within
[alphaMin, 1] and U, p, voidfraction finite at every write), mass
conservation (the LIGGGHTS sphere count and total mass constant over the
run, the coupled body count constant at every write and equal to the
inserted count), an empty inlet layer (void fraction exactly 1 in the
bottom cell layer at every write) and fluidisation:
  - the bed was at rest before the flow (|mean vertical body velocity| at
    the flow start below --rest-speed);
  - expansion: the bed's mean height above the floor, averaged over the
    fluidised window, at least --min-expansion times its packed value
    (at the flow start);
  - pressure drop: the inlet pressure (rho times the area-averaged
    kinematic p; outlet p = 0, p without hydrostatics) averaged over the
    window, divided by the buoyant weight per area W/A = M g (1 -
    rho/rho_p)/A, within [--dp-min, --dp-max]. Its standard error is
    estimated from 12 block means and reported.
Writes results/summary.dat; exits 1 if a check fails."""
import argparse
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402


def numbers_in_field(path):
    """All internal-field numbers of a vol field (uniform or nonuniform)."""
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+([^;]*);", text)
    if m:
        return [float(x) for x in re.findall(r"[-+0-9.eEnaNfI]+", m.group(1))]
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\((.*?)\n\)\s*;",
                  text, flags=re.S)
    return [float(x) for x in m.group(2).replace("(", " ").replace(")", " ").split()]


def cloud_size(path):
    text = open(path).read().split("}", 1)[1]
    return int(re.search(r"(\d+)\s*\(", text).group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--floor", type=float, default=0.005,
                    help="DEM floor height [m] (DEM/in.liggghts)")
    ap.add_argument("--flow-start", type=float, default=0.2,
                    help="time the inlet ramp starts [s] (0/U)")
    ap.add_argument("--window", type=float, nargs=2, default=(0.3, 0.65),
                    help="fluidised averaging window [s]")
    ap.add_argument("--rest-speed", type=float, default=5e-3)
    ap.add_argument("--min-expansion", type=float, default=1.2)
    ap.add_argument("--dp-min", type=float, default=0.7)
    ap.add_argument("--dp-max", type=float, default=1.25)
    args = ap.parse_args()
    case = "."
    checks = []
    cp = os.path.join(case, "constant/couplingProperties")
    text = caseio._strip_comments(open(cp).read())
    alpha_min = float(re.search(r"alphaMin\s+([-+0-9.eE]+)", text).group(1))

    # the insertion is in the first run's LIGGGHTS log (./Allrun -continue
    # keeps it as log.liggghts.before_continue_<t>)
    logs = sorted(glob.glob(os.path.join(case, "log.liggghts.before_continue_*")),
                  key=lambda p: float(p.rsplit("_", 1)[1]))
    log = "".join(open(p).read() for p in logs + [os.path.join(case, "log.liggghts")])
    ins = re.findall(r"a total of (\d+) particle templates \(mass ([-+0-9.eE]+)\)", log)
    n_bodies, m_inserted = int(ins[-1][0]), float(ins[-1][1])

    # rows of a continued run replace the earlier ones from its start
    bed = np.loadtxt(os.path.join(case, "DEM/post/bed.dat"), ndmin=2)
    bed = np.array(caseio.later_segment_wins(list(bed), key=lambda r: r[0]))
    t, nsph, mass, zmean = bed[:, 0], bed[:, 1], bed[:, 2], bed[:, 3]
    checks.append(("DEM history finite", bool(np.all(np.isfinite(bed)))))
    checks.append(("sphere count constant", bool(np.all(nsph == nsph[0]))))
    dm = float(np.max(np.abs(mass / mass[0] - 1)))
    checks.append(("sphere mass constant (1e-12)", dm < 1e-12))
    checks.append(("sphere mass = inserted mass (1e-6)", abs(mass[0] / m_inserted - 1) < 1e-6))

    # cells of the single blockMesh block, bottom layer first (i + nx j + ...)
    nxy = 9
    bottom_min = 1.0
    vmin, vmax, counts, finite = 1.0, 0.0, [], True
    for time in caseio.time_dirs(case)[1:]:
        eps = np.array(numbers_in_field(os.path.join(case, time, "voidfraction")))
        bottom_min = min(bottom_min, float(eps[:nxy].min()) if eps.size > 1 else float(eps[0]))
        for f in ("U", "p"):
            finite &= bool(np.all(np.isfinite(numbers_in_field(os.path.join(case, time, f)))))
        finite &= bool(np.all(np.isfinite(eps)))
        vmin, vmax = min(vmin, eps.min()), max(vmax, eps.max())
        counts.append(cloud_size(os.path.join(case, time, "lagrangian/particles/d")))
    checks.append(("U, p, voidfraction finite", finite))
    checks.append(("voidfraction in [alphaMin, 1]",
                   vmin >= alpha_min - 1e-12 and vmax <= 1 + 1e-12))
    checks.append(("body count constant = inserted", all(c == n_bodies for c in counts)))

    checks.append(("inlet cell layer empty (eps = 1)", bottom_min == 1.0))

    def zm_at(tq):
        return float(np.interp(tq, t, zmean))

    # Fluidisation: expansion of the bed's mean height above the floor
    vz = bed[:, 5]
    v_rest = float(np.interp(args.flow_start, t, vz))
    checks.append(("bed at rest at the flow start", abs(v_rest) < args.rest_speed))
    w0, w1 = args.window
    win = (t >= w0) & (t <= w1)
    h0 = zm_at(args.flow_start) - args.floor
    h = float(zmean[win].mean()) - args.floor
    expansion = h / h0
    checks.append(("bed expanded (mean height >= %g x packed)" % args.min_expansion,
                   expansion >= args.min_expansion))

    # Pressure drop against the buoyant weight per area
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    rhop = float(re.search(r"variable\s+rhop\s+equal\s+([-+0-9.eE]+)",
                           open(os.path.join(case, "DEM/in.liggghts")).read()).group(1))
    g = float(np.linalg.norm(caseio.foam_vector(os.path.join(case, "constant/g"), "value")))
    pdat = np.array(caseio.later_segment_wins(
        [r for path in caseio.function_object_segments(case, "inletPressure",
                                                        "surfaceFieldValue.dat")
         for r in np.loadtxt(path, comments="#", ndmin=2)],
        key=lambda r: r[0]))
    tw = (pdat[:, 0] >= w0) & (pdat[:, 0] <= w1)
    area = 0.015 * 0.015
    w_area = mass[0] * g * (1 - rho / rhop) / area
    dp = rho * pdat[tw, 1]
    ratio = float(dp.mean()) / w_area
    blocks = [b.mean() / w_area for b in np.array_split(dp, 12)]
    sem = float(np.std(blocks, ddof=1) / np.sqrt(len(blocks)))
    checks.append(("pressure drop / (W/A) in [%g, %g]" % (args.dp_min, args.dp_max),
                   args.dp_min <= ratio <= args.dp_max))
    ok = all(c for _, c in checks)
    rows = [
        ("bodiesInserted", "%d" % n_bodies),
        ("massInserted_kg", "%.6e" % m_inserted),
        ("spheres", "%d" % nsph[0]),
        ("sphereMassMaxRelChange", "%.3e" % dm),
        ("bodyCountsAtWrites", " ".join(str(c) for c in counts)),
        ("voidfractionMin", "%.6f" % vmin),
        ("voidfractionMax", "%.6f" % vmax),
        ("alphaMin", "%g" % alpha_min),
        ("voidfractionMin_inletLayer", "%.6f" % bottom_min),
        ("vzMean_at_flowStart_m_s", "%.3e" % v_rest),
        ("bedMeanHeight_packed_m (t = %g s)" % args.flow_start, "%.5f" % h0),
        ("bedMeanHeight_fluidised_m (%g-%g s)" % (w0, w1), "%.5f" % h),
        ("expansion", "%.3f" % expansion),
        ("zMax_fluidised_mean_m", "%.5f" % float(bed[win, 4].mean())),
        ("buoyantWeightPerArea_Pa", "%.3f" % w_area),
        ("inletPressure_mean_Pa", "%.3f" % float(dp.mean())),
        ("dP_over_WA", "%.3f" % ratio),
        ("dP_over_WA_stdError (12 blocks)", "%.3f" % sem),
        ("inletPressure_rms_Pa", "%.3f" % float(dp.std())),
        ("zMean_end_m", "%.5f" % zmean[-1]),
    ]
    rows += [("check: " + n, "ok" if c else "FAILED") for n, c in checks]
    rows.append(("pass", "yes" if ok else "no"))
    caseio.write_summary(".", rows)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
