#!/usr/bin/python3
"""settlingSphere as the cells shrink: the terminal-velocity error against
the ODE of the same drag law (validate.py) at several particle-to-cell size
ratios d/h, without and with the undisturbed-velocity treatment (see
doc/models.md, "Undisturbed fluid velocity").

The sphere is the tutorial's (d = 1 mm glass in water, schillerNaumann,
Re_t = 146, model A, implicit coupling, CFD step 1e-3 s, DEM step 1e-5 s,
the CI length 0.25 s). The mesh is a box of 20 x 20 x 80 mm (x, y in
[10, 30] mm, z in [80, 160] mm; the sphere starts at (20, 20, 140) mm, as in
the tutorial, and falls about 33 mm) with cubic cells of h = d/(d/h), so
that d/h = 1 stays small (32 000 cells).

- without: the tutorial as it is (`centre` void fraction, couplingKernel
  cell, undisturbedVelocity none);
- with (--kernel smoothed, the default): voidFraction smoothed (base
  divided, smoothingLengthInDiameters 2), couplingKernel voidFraction,
  undisturbedVelocity selfInducedCorrection;
- with --kernel cell: the tutorial plus undisturbedVelocity
  selfInducedCorrection only.

    ./meshConvergence.py                       d/h = 0.1 0.25 0.5 1, table
    ./meshConvergence.py --out ../../doc/validation/settlingSphere/meshConvergence.dat
    ./Allrun -meshConvergence -ci              the CI check (CTest)

Each run is a copy of the case in <work>/<dOverH>_<with|without>
(./Allrun -ci). The error is |v_DEM(end) - v_t|/v_t, v_t the terminal
velocity of the ODE (validate.py's terminalError); the wall time is that of
./Allrun -ci (blockMesh, pisoDEMFoam, validate.py). Exits 1 if a run fails
or a corrected run's error exceeds --max-error [%].
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

D_MM = 1.0
# The corrected runs' settings with --kernel smoothed
SMOOTHED = [["voidFraction", "smoothed"],
            ["smoothedCoeffs", "{ base divided; smoothingLengthInDiameters 2; }"],
            ["couplingKernel", "voidFraction"]]
BOX_MM = ((10.0, 30.0), (10.0, 30.0), (80.0, 160.0))


def foam_set(cwd, dict_path, entry, value):
    r = subprocess.run(["foamDictionary", dict_path, "-entry", entry, "-set", value],
                       cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode:
        sys.exit("meshConvergence.py: foamDictionary %s -entry %s failed:\n%s"
                 % (dict_path, entry, r.stderr))


def prepare(case, work, d_over_h, correct, extra, box, end_time):
    if os.path.exists(work):
        shutil.rmtree(work)
    shutil.copytree(case, work, ignore=shutil.ignore_patterns(
        "results", "VTK", "processor*", "log.*", "post", "restart", "[1-9]*", "0.*"))
    subprocess.run(["./Allclean"], cwd=work, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    h = D_MM / d_over_h
    n = [int(round((b[1] - b[0]) / h)) for b in box]
    (x0, x1), (y0, y1), (z0, z1) = box
    verts = ("((%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g) (%g %g %g))"
             % (x0, y0, z0, x1, y0, z0, x1, y1, z0, x0, y1, z0,
                x0, y0, z1, x1, y0, z1, x1, y1, z1, x0, y1, z1))
    foam_set(work, "system/blockMeshDict", "vertices", verts)
    foam_set(work, "system/blockMeshDict", "blocks",
             "(hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1))" % tuple(n))
    foam_set(work, "constant/couplingProperties", "undisturbedVelocity",
             "selfInducedCorrection" if correct else "none")
    for entry, value in extra:
        foam_set(work, "constant/couplingProperties", entry, value)
    if end_time != 0.25:
        # Allrun -ci sets endTime 0.25 and writeInterval 0.05
        allrun = os.path.join(work, "Allrun")
        text = open(allrun).read()
        old = "endTime 0.25 writeInterval 0.05"
        if text.count(old) != 1:
            sys.exit("meshConvergence.py: Allrun -ci no longer sets endTime 0.25")
        text = text.replace(old, "endTime %g writeInterval %g" % (end_time, end_time))
        open(allrun, "w").write(text)
    return n


def run_one(case, root, d_over_h, correct, extra, box, end_time):
    work = os.path.join(root, "%g_%s" % (d_over_h, "with" if correct else "without"))
    cells = prepare(case, work, d_over_h, correct, extra, box, end_time)
    t0 = time.time()
    with open(os.path.join(work, "log.Allrun"), "w") as f:
        rc = subprocess.run(["./Allrun", "-ci"], cwd=work, stdout=f,
                            stderr=subprocess.STDOUT).returncode
    wall = time.time() - t0
    summary = os.path.join(work, "results/summary.dat")
    if not os.path.exists(summary):
        print("meshConvergence.py: run %s failed (rc %d), see %s/log.*" % (work, rc, work))
        return None, wall, cells
    s = caseio.read_summary(work)
    return float(s["terminalError"]), wall, cells


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--d-over-h", type=float, nargs="+", default=[0.1, 0.25, 0.5, 1.0])
    ap.add_argument("--with-only", action="store_true", help="only the corrected runs")
    ap.add_argument("--without-only", action="store_true", help="only the uncorrected runs")
    ap.add_argument("--set", nargs=2, action="append", default=[], metavar=("ENTRY", "VALUE"),
                    help="also set a couplingProperties entry in every run")
    ap.add_argument("--set-with", nargs=2, action="append", default=[],
                    metavar=("ENTRY", "VALUE"),
                    help="also set a couplingProperties entry in the corrected runs only")
    ap.add_argument("--kernel", choices=("smoothed", "cell"), default="smoothed",
                    help="the corrected runs' kernel: smoothed (voidFraction smoothed, base"
                    " divided, L = 2 d, couplingKernel voidFraction; the default) or cell"
                    " (the tutorial's centre void fraction and cell kernel)")
    ap.add_argument("--work", default="results/meshConvergence",
                    help="directory of the runs (default results/meshConvergence)")
    ap.add_argument("--max-error", type=float, default=None,
                    help="fail if a corrected run's error exceeds this [%%]")
    ap.add_argument("--box", type=float, nargs=6, default=None,
                    metavar=("X0", "X1", "Y0", "Y1", "Z0", "Z1"),
                    help="the mesh's box [mm] (default 10 30 10 30 80 160)")
    ap.add_argument("--end-time", type=float, default=0.25,
                    help="run length [s] (default 0.25, the CI length)")
    ap.add_argument("--out", default="results/meshConvergence.dat")
    args = ap.parse_args()
    if args.kernel == "smoothed":
        args.set_with = SMOOTHED + args.set_with
    box = BOX_MM if args.box is None else tuple(
        (args.box[2 * i], args.box[2 * i + 1]) for i in range(3))

    case = os.path.dirname(os.path.abspath(__file__))
    root = os.path.abspath(args.work)
    os.makedirs(root, exist_ok=True)

    rows = []
    ok = True
    for r in args.d_over_h:
        res = {}
        for correct in (False, True):
            if (correct and args.without_only) or (not correct and args.with_only):
                res[correct] = (None, None, None)
                continue
            extra = args.set + (args.set_with if correct else [])
            err, wall, cells = run_one(case, root, r, correct, extra, box, args.end_time)
            res[correct] = (err, wall, cells)
            print("d/h = %g, %s correction: error %s, wall %.1f s, cells %s"
                  % (r, "with" if correct else "without",
                     "failed" if err is None else "%.3f %%" % (100 * err), wall, cells),
                  flush=True)
            if err is None:
                ok = False
            elif correct and args.max_error is not None and 100 * err > args.max_error:
                ok = False
                print("meshConvergence.py: d/h = %g with the correction: error %.3f %% > %g %%"
                      % (r, 100 * err, args.max_error))
        rows.append((r, res))

    def fmt(x, f):
        return "nan" if x is None else f % x

    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as f:
        f.write("# settlingSphere mesh convergence (tutorials/settlingSphere/meshConvergence.py)\n")
        f.write("# error: |v_DEM - v_t|/v_t [%%] at t = %g s, v_t the terminal velocity of the ODE\n"
                % args.end_time)
        f.write("#   m dv/dt = (rho_p - rho) V g - K(v) v with the same drag law (schillerNaumann,\n")
        f.write("#   Re_t = 146; validate.py's terminalError)\n")
        f.write("# run: d = 1 mm glass sphere in water, model A, implicit coupling, CFD step\n")
        f.write("#   1e-3 s, DEM step 1e-5 s; box x %g-%g, y %g-%g, z %g-%g mm\n"
                % tuple(v for b in box for v in b))
        f.write("#   of cubic cells h = d/(d/h), the sphere released at (20, 20, 140) mm\n")
        f.write("#   ./Allrun -ci per run, serial, at nice 19 on a shared 2-core machine\n")
        f.write("# errorWithout: the tutorial's centre void fraction, couplingKernel cell,\n")
        f.write("#   undisturbedVelocity none; errorWith: undisturbedVelocity selfInducedCorrection\n")
        if args.set:
            f.write("# also set in couplingProperties (both): %s\n"
                    % ", ".join("%s %s" % (e, v) for e, v in args.set))
        if args.set_with:
            f.write("# also set in couplingProperties (errorWith runs only): %s\n"
                    % ", ".join("%s %s" % (e, v) for e, v in args.set_with))
        f.write("# wall_s: wall time of ./Allrun -ci (blockMesh, pisoDEMFoam, validate.py)\n")
        f.write("%-8s %-13s %-13s %-14s %-14s\n"
                % ("dOverH", "errorWithout", "errorWith", "wallWithout_s", "wallWith_s"))
        for r, res in rows:
            e0, w0, _ = res[False]
            e1, w1, _ = res[True]
            f.write("%-8g %-13s %-13s %-14s %-14s\n"
                    % (r, fmt(None if e0 is None else 100 * e0, "%.4f"),
                       fmt(None if e1 is None else 100 * e1, "%.4f"),
                       fmt(w0, "%.1f"), fmt(w1, "%.1f")))
    print("Table: %s" % args.out)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
