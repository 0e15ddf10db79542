#!/usr/bin/env python3
"""densePneumaticConveying: the sensitivity and cost table (error against
run time) of the like-for-like set-up.

    ./sensitivity.py [--variants a,b] [--np 2] [--end 2] [--window 1.5 2.0]
                     [--base NAME] [--work DIR] [--reuse name=DIR ...]
                     [--continue] [--table-only]

Each variant is a copy of this tutorial (in WORK/<name>, default
results/sensitivity/runs) with one change from the like-for-like set-up,
run with ./Allrun -np NP -end END (packing included), then measured with
postprocess.py --window T0 T1. A variant that already ran (its
WORK/<name>/results/summary_T0-T1.dat exists) is measured again only; with
--continue a variant whose run was cut off continues from its latest write.
--reuse name=DIR takes the run in DIR for that variant instead (the full
run for "likeForLike", for example: its window is the same if the run
passed T1).

--base NAME applies variant NAME's change first to every variant, so that
each variant differs from that base in one parameter only (the base itself
is the row "likeForLike" then, and every row is named "<variant>+<base>").
With --base demStep10 every run costs about half of the like-for-like one;
the demStep10 row against the like-for-like one says what the base changes.
Such runs go to WORK/<variant>+<base> and the tables to
OUT/sensitivity+<base>.dat/.md.

The variants (no parameter is moved away from the reference's values to
improve agreement; each one is a set-up choice the reference leaves open,
or one that foamDEM makes differently):

  likeForLike   the tutorial as it is (wall friction 0.343: harmonic mean)
  friction04    particle-wall sliding friction 0.4 (the wall's own value;
                the tutorial before the like-for-like set-up)
  demStep10     DEM step 1.25e-5 s (9.6 % of the Rayleigh time at
                E = 1e7) with couplingInterval 40: the same CFD step
  divided       void fraction divided over the cells, without the
                smoothing (the reference smooths with L = 2 d)
  refined       CFD mesh refined once in every direction (O-grid 8 x 8
                core + 4 radial cells, 5 mm along x: 8 x the cells)
  refined16     refined as 'refined', but the wall stays the tutorial's
                16-facet polygon (the same fluid volume): the cell size
                alone
  seed2         the packing of a second insertion seed (the same shape,
                particle count and fill method)
  saffman       Saffman's lift without Mei's correction (the reference's
                lift; the tutorial uses Saffman-Mei)
  facetedWall   the DEM's pipe wall is the CFD mesh's 16-facet polygon
                (pipeWallFacets 16), as the reference's DEM wall was its
                mesh's boundary, instead of the exact cylinder
  facetedWallFlatBottom
                facetedWall turned by half a facet: a facet at the bottom
                instead of a corner (the reference's orientation is not
                known)
  tangentialDampingOff
                no tangential damping in LIGGGHTS' Hertz-Mindlin contact
                (tangential_damping off, particle-particle and wall, packing
                and coupled run). LIGGGHTS adds the tangential damping to a
                sticking contact's spring force, so that force can exceed
                mu |F_n|; the reference's DEM caps spring plus damping at
                mu |F_n|. Without the damping the force never exceeds the
                cap: a bound on that difference
  viscousForce  the viscous-stress force V_p div(tau) on every particle
                (force model 'viscous'), on by default in the reference's
                code and off in the tutorial
  cellPoint     the fluid velocity and void fraction the forces see,
                interpolated at the particle's position (couplingKernel
                cellPoint), as the reference's finite-element code
                evaluates them, instead of its cell's values
  axialFill     the packing's fill along the pipe (axialFill 1: gravity
                -x against an end wall, a lid over the layer outside the
                body; fillTime 2 s), as the reference loaded its slug,
                instead of across it (gravity -y); then the same carve,
                thinning and settling
  axialFillFacetedWall
                axialFill inside the faceted DEM wall (pipeWallFacets 16):
                the reference's loading method, DEM wall and particle count
  axialFillThinned
                axialFillFacetedWall filled to capacity
                (axialFillToCapacity 1) and thinned at random to
                nParticles: the reference's count in its wall, over the
                whole shape
  axialFillSettle25
                axialFillThinned settled for 2.5 s under -y (settleTime;
                the reference's settling time) instead of 0.5 s
  axialFillCaseFriction
                axialFillFacetedWall with the case's friction during the
                fill (fillCaseFriction 1), as the reference loaded with its
                case's materials: the pipe wall carries more of the pile

Writes results/sensitivity/sensitivity.dat (one line per variant and
quantity: variant, quantity, foamDEM with the reference's measures, with
foamDEM's own, the reference's value, the difference in %, the wall time
of packing + coupled run to T1) and sensitivity.md (the table). The mass
flow is the one over the window (the cumulative one depends on the start).
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# The reference's published values (../shared/cases/dense-pneumatic-conveying.md)
REFERENCE = [
    ("gasVelocity", "m/s", 2.98),
    ("slugVelocity", "m/s", 1.30),
    ("particleVelocityInSlug", "m/s", 0.83),
    ("solidsMassFlowRate", "kg/s", 1.40),
    ("slugLength", "m", 0.47),
]


def sed(path, pattern, repl, count=1):
    """Replace a regular expression in a file; fail if it is not there."""
    with open(path) as f:
        text = f.read()
    new, n = re.subn(pattern, repl, text, count=count, flags=re.M)
    if n == 0:
        sys.exit("sensitivity.py: '%s' not found in %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(new)


def parameter(case, name, value):
    sed(os.path.join(case, "DEM/parameters"),
        r"^(variable\s+%s\s+equal\s+)\S+" % name, r"\g<1>%s" % value)


def coupling(case, pattern, repl):
    sed(os.path.join(case, "constant/couplingProperties"), pattern, repl)


def v_friction04(case):
    parameter(case, "wallPairHarmonic", 0)


def v_demStep10(case):
    parameter(case, "demTimestep", "1.25e-5")
    coupling(case, r"^couplingInterval\s+\d+;", "couplingInterval    40;")


def v_divided(case):
    coupling(case, r"^voidFraction\s+smoothed;", "voidFraction        divided;")


def v_refined(case):
    parameter(case, "nSquare", 8)
    parameter(case, "nRadial", 4)
    parameter(case, "cellLength", 0.005)


def wall_polygon(case, facets_per_edge=4):
    """The pipe wall as the polygon of the tutorial's own mesh: each of the
    O-grid's four outer block edges (90 degrees of the circle, an arc in
    system/blockMeshDict) becomes a polyLine through the points the
    tutorial's nSquare = 4 cells put on that arc. A finer mesh then keeps
    the tutorial's cross-section (16 facets, 0.00540 m^3 of fluid, as the
    reference's mesh) instead of approaching the exact cylinder."""
    import math
    with open(os.path.join(case, "DEM/parameters")) as f:
        R = 0.5 * float(re.search(r"^variable\s+pipeDiameter\s+equal\s+(\S+)",
                                  f.read(), re.M).group(1))
    # arc a b (x y z): the edge from vertex a to vertex b; vertices 4-7 at
    # xlo and 12-15 at xhi sit on the wall at 225, 315, 45 and 135 degrees
    start = {4: 225, 5: 315, 6: 45, 7: 135}

    def polyline(m):
        a, b, x = int(m.group(1)), int(m.group(2)), m.group(3)
        t0 = start[a if a < 8 else a - 8]
        pts = " ".join("(%s %.12g %.12g)" % (x, R * math.cos(math.radians(t)),
                                             R * math.sin(math.radians(t)))
                       for t in (t0 + 90.0 * k / facets_per_edge
                                 for k in range(1, facets_per_edge)))
        return "polyLine %d %d (%s)" % (a, b, pts)
    path = os.path.join(case, "system/blockMeshDict")
    with open(path) as f:
        text = f.read()
    new, n = re.subn(r"arc (\d+) (\d+) \((\$x(?:lo|hi)) \S+ \S+\)", polyline, text)
    if n != 8:
        sys.exit("sensitivity.py: expected 8 arc edges in %s, found %d" % (path, n))
    with open(path, "w") as f:
        f.write(new)


def v_refined16(case):
    v_refined(case)
    wall_polygon(case)


def v_seed2(case):
    # the insertion seed of the packing stage: a prime, as LIGGGHTS wants,
    # and not a seed of the particle template or distribution (32452843 was:
    # LIGGGHTS refused it)
    sed(os.path.join(case, "DEM/in.pack"), r"(insert/pack seed )49979687", r"\g<1>49979693")


def v_saffman(case):
    with open(os.path.join(case, "constant/couplingProperties"), "a") as f:
        f.write("\nsaffmanMeiLiftCoeffs { correction none; }\n")


def v_facetedWall(case):
    parameter(case, "pipeWallFacets", 16)


def v_facetedWallFlatBottom(case):
    v_facetedWall(case)
    parameter(case, "pipeWallFlatBottom", 1)


def v_tangentialDampingOff(case):
    # the keyword after the models of pair_style, at the end of a fix
    # wall/gran (LIGGGHTS wants it after the wall's arguments)
    sed(os.path.join(case, "DEM/contacts"), r"^(pair_style\s+gran .*)$",
        r"\g<1> tangential_damping off")
    for f in ("DEM/contacts", "DEM/in.pack"):
        sed(os.path.join(case, f), r"(fix\s+\S+\s+all\s+wall/gran [^\"\n]*?)(\s*)(\"|$)",
            r"\g<1> tangential_damping off\g<2>\g<3>", count=0)


def v_viscousForce(case):
    coupling(case, r"^(forceModels\s+\(diFelice)", r"\g<1> viscous")
    # the model's div(nu grad(U)^T), with the scheme of the solver's own
    sed(os.path.join(case, "system/fvSchemes"),
        r"^(\s*div\(\(\(voidfraction\*nuEff\)\*dev2\(T\(grad\(U\)\)\)\)\)\s+Gauss linear;)$",
        r"\g<1>\n    div((nu*T(grad(U)))) Gauss linear;")


def v_cellPoint(case):
    with open(os.path.join(case, "constant/couplingProperties"), "a") as f:
        f.write("\ncouplingKernel cellPoint;\n")


def v_axialFill(case):
    parameter(case, "axialFill", 1)
    # the fill along 1 m of pipe takes longer than the one across it
    parameter(case, "fillTime", "2.0")


def v_axialFillFacetedWall(case):
    v_axialFill(case)
    v_facetedWall(case)


def v_axialFillCaseFriction(case):
    v_axialFillFacetedWall(case)
    parameter(case, "fillCaseFriction", 1)


def v_axialFillThinned(case):
    v_axialFillFacetedWall(case)
    parameter(case, "axialFillToCapacity", 1)


def v_axialFillSettle25(case):
    v_axialFillThinned(case)
    # the reference settled its loaded slug for about 2.5 s under -y
    parameter(case, "settleTime", "2.5")


VARIANTS = [
    ("likeForLike", "the tutorial: wall friction 0.343 (harmonic mean)", None),
    ("friction04", "particle-wall friction 0.4 (the wall's own value)", v_friction04),
    ("demStep10", "DEM step 1.25e-5 s (9.6 % t_R), couplingInterval 40", v_demStep10),
    ("divided", "void fraction divided, no smoothing", v_divided),
    ("refined", "CFD mesh refined once (8 x the cells)", v_refined),
    ("refined16", "CFD mesh refined once inside the tutorial's 16-facet wall", v_refined16),
    ("seed2", "second packing seed", v_seed2),
    ("saffman", "Saffman lift without Mei's correction (the reference's)", v_saffman),
    ("facetedWall", "DEM pipe wall: the CFD mesh's 16-facet polygon (the reference's DEM wall)", v_facetedWall),
    ("facetedWallFlatBottom", "the faceted DEM wall turned by half a facet: a facet at the bottom", v_facetedWallFlatBottom),
    ("tangentialDampingOff", "no tangential damping in the Hertz-Mindlin contacts (bounds the reference's capped damping)", v_tangentialDampingOff),
    ("viscousForce", "the viscous-stress force V_p div(tau) on the particles (on by default in the reference's code)", v_viscousForce),
    ("cellPoint", "u_f and eps at the particle interpolated at its position (couplingKernel cellPoint), as the reference's finite elements evaluate them", v_cellPoint),
    ("axialFill", "the slug packed along the pipe (gravity -x against an end wall, under a lid over the layer; 2 s), as the reference loaded it", v_axialFill),
    ("axialFillFacetedWall", "axialFill inside the faceted DEM wall: the reference's loading, DEM wall and particle count", v_axialFillFacetedWall),
    ("axialFillThinned", "axialFillFacetedWall filled to capacity (35 339) and thinned at random to 32 194: the reference's particle count in its wall, spread over the whole shape", v_axialFillThinned),
    ("axialFillSettle25", "axialFillThinned settled for 2.5 s under -y (the reference's settling time) instead of 0.5 s", v_axialFillSettle25),
    ("axialFillCaseFriction", "axialFillFacetedWall with the case's friction during the fill (particle 0.3, wall 0.343, rolling 0.2) instead of 0.1 without rolling", v_axialFillCaseFriction),
]


def on_base(base_edit, edit):
    """The variant's edit after the base's."""
    def both(case):
        base_edit(case)
        if edit:
            edit(case)
    return both


def read_summary(path):
    out = {}
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) >= 3 and not line.startswith("#"):
                try:
                    out[p[0]] = float(p[2])
                except ValueError:
                    pass
    return out


def wall_time(case, t1):
    """Measured cost of packing + coupled run up to t1: the LIGGGHTS loop
    times of the packing log and, per solver log segment, the ClockTime
    (wall) and ExecutionTime (CPU time of rank 0, which a machine shared
    with other work inflates less than the wall time) at the last step
    <= t1."""
    pack = 0.0
    log = os.path.join(case, "DEM/log.pack")
    if os.path.exists(log):
        with open(log) as f:
            pack = sum(float(m.group(1)) for m in re.finditer(r"^Loop time of (\S+)", f.read(), re.M))
    coupled, cpu = 0.0, 0.0
    for log in sorted(glob.glob(os.path.join(case, "log.pisoDEMFoam*"))):
        t, last = None, None
        with open(log) as f:
            for line in f:
                if line.startswith("Time = "):
                    t = float(line.split()[2])
                elif "ClockTime" in line and t is not None and t <= t1 + 1e-9:
                    last = line.split()
        if last is not None:
            coupled += float(last[-2])
            cpu += float(last[2])
    return pack, coupled, cpu


def run_variant(name, edit, work, args):
    case = os.path.join(work, name)
    summary = os.path.join(case, "results", "summary_%g-%g.dat" % tuple(args.window))
    if os.path.exists(summary):
        return case
    if not (args.cont and os.path.isdir(os.path.join(case, "processor0" if args.np > 1 else "constant"))):
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(HERE, case, ignore=shutil.ignore_patterns(
            "results", "VTK", "processor*", "log.*", "post", "restart", "postProcessing",
            "[1-9]*", "0.[0-9]*"))
        if edit:
            edit(case)
        allrun = ["./Allrun", "-np", str(args.np), "-end", str(args.end)]
    else:
        allrun = ["./Allrun", "-np", str(args.np), "-end", str(args.end), "-continue"]
    print("variant %-12s %s" % (name, " ".join(allrun)), flush=True)
    start = time.monotonic()
    with open(os.path.join(case, "log.sensitivity"), "a") as log:
        r = subprocess.run(allrun, cwd=case, stdout=log, stderr=subprocess.STDOUT)
    print("    %.0f s wall, Allrun exit %d" % (time.monotonic() - start, r.returncode), flush=True)
    measure(case, args)
    return case


def measure(case, args):
    py = os.environ.get("FOAMDEM_PYTHON", sys.executable)
    r = subprocess.run([py, "postprocess.py", "--window"] + [str(w) for w in args.window],
                       cwd=case, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode not in (0, 1):
        print(r.stdout[-2000:])


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--variants", help="comma list (default: all)")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--end", type=float, default=2.0)
    ap.add_argument("--window", type=float, nargs=2, default=[1.5, 2.0])
    ap.add_argument("--work", default=os.path.join(HERE, "results", "sensitivity", "runs"))
    ap.add_argument("--out", default=os.path.join(HERE, "results", "sensitivity"))
    ap.add_argument("--reuse", action="append", default=[], metavar="NAME=DIR")
    ap.add_argument("--base", help="apply this variant's change to every run (see above)")
    ap.add_argument("--continue", dest="cont", action="store_true")
    ap.add_argument("--table-only", action="store_true", help="run nothing, tabulate what exists")
    args = ap.parse_args()

    reuse = dict(r.split("=", 1) for r in args.reuse)
    names = [v[0] for v in VARIANTS]
    if args.base is not None and args.base not in names[1:]:
        sys.exit("sensitivity.py: unknown base '%s'; valid: %s" % (args.base, ", ".join(names[1:])))
    base_edit = dict((n, e) for n, _, e in VARIANTS).get(args.base)
    suffix = "+" + args.base if args.base else ""
    wanted = args.variants.split(",") if args.variants else names
    for w in wanted:
        if w not in names:
            sys.exit("sensitivity.py: unknown variant '%s'; valid: %s" % (w, ", ".join(names)))
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for name, what, edit in VARIANTS:
        if name not in wanted or (args.base and name == args.base):
            continue
        if base_edit:
            edit = on_base(base_edit, edit)
            what = what + (" (on the %s base)" % args.base if name != "likeForLike"
                           else " with the %s change only (the base)" % args.base)
        name = name + suffix
        if name in reuse:
            case = os.path.abspath(reuse[name])
            if not os.path.exists(os.path.join(case, "results", "summary_%g-%g.dat" % tuple(args.window))):
                measure(case, args)
        elif args.table_only:
            case = os.path.join(args.work, name)
        else:
            case = run_variant(name, edit, args.work, args)
        summary = os.path.join(case, "results", "summary_%g-%g.dat" % tuple(args.window))
        if not os.path.exists(summary):
            print("variant %s: no %s" % (name, summary))
            continue
        s = read_summary(summary)
        pack, coupled, cpu = wall_time(case, args.window[1])
        rows.append((name, what, s, pack, coupled, cpu))

    dat = os.path.join(args.out, "sensitivity%s.dat" % suffix)
    md = os.path.join(args.out, "sensitivity%s.md" % suffix)
    w0, w1 = args.window
    with open(dat, "w") as f, open(md, "w") as g:
        f.write("# densePneumaticConveying sensitivity, window %g..%g s, np %d; SI units\n" % (w0, w1, args.np))
        f.write("# foamDEM_ref: the reference's measures (solidsMassFlowRate over the window);"
                " foamDEM_own: foamDEM's own; diff_pct: foamDEM_ref against the reference\n")
        f.write("# wall_s: measured wall time of packing + coupled run to %g s;"
                " cpu_s: packing wall + the coupled run's CPU time on rank 0\n" % w1)
        f.write("# variant quantity reference foamDEM_ref foamDEM_own diff_pct wall_s cpu_s\n")
        g.write("Window %g–%g s, np %d; reference's measures (foamDEM's own in brackets);"
                " difference from the reference in %%.\n\n" % (w0, w1, args.np))
        g.write("| variant | change | " + " | ".join(q for q, _, _ in REFERENCE)
                + " | wall (packing + coupled to %g s) | coupled CPU, rank 0 |\n" % w1)
        g.write("|---|---|" + "---|" * len(REFERENCE) + "---|---|\n")
        g.write("| reference | | " + " | ".join("%g %s" % (v, u) for _, u, v in REFERENCE) + " | | |\n")
        for name, what, s, pack, coupled, cpu in rows:
            cells = []
            for q, unit, ref in REFERENCE:
                rq = "ref_solidsMassFlowRateWindow" if q == "solidsMassFlowRate" else "ref_" + q
                vr, vo = s.get(rq, float("nan")), s.get(q, float("nan"))
                d = 100.0 * (vr - ref) / ref
                f.write("%-12s %-24s %8.4g %10.4g %10.4g %+7.1f %8.0f %8.0f\n"
                        % (name, q, ref, vr, vo, d, pack + coupled, pack + cpu))
                cells.append("%.3g (%.3g), %+.1f %%" % (vr, vo, d))
            g.write("| %s | %s | %s | %.0f + %.0f s | %.0f s |\n"
                    % (name, what, " | ".join(cells), pack, coupled, cpu))
        if rows:
            # each variant against the first row (the like-for-like set-up or the base)
            first = rows[0][2]
            g.write("\nChange from %s (the reference's measures; the mass flow by the own"
                    " measure Σ m v_x / L, which a 0.5 s window resolves):\n\n" % rows[0][0])
            g.write("| variant | " + " | ".join(q for q, _, _ in REFERENCE) + " |\n")
            g.write("|---|" + "---|" * len(REFERENCE) + "\n")
            for name, _, s, _, _, _ in rows[1:]:
                cells = []
                for q, _, _ in REFERENCE:
                    k = q if q == "solidsMassFlowRate" else "ref_" + q
                    a, b = s.get(k, float("nan")), first.get(k, float("nan"))
                    cells.append("%+.1f %%" % (100.0 * (a - b) / b))
                g.write("| %s | %s |\n" % (name, " | ".join(cells)))
    print("Table: %s\n       %s" % (dat, md))
    with open(md) as g:
        print(g.read())


if __name__ == "__main__":
    main()
