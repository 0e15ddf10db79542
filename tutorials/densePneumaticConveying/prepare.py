#!/usr/bin/python3
"""densePneumaticConveying set-up: derive the pipe, the slug shape, the
packing and the coupled run's output intervals from DEM/parameters and write
DEM/post/setup.lig (LIGGGHTS variables) and DEM/post/setupDict (blockMesh,
controlDict, fvOptions entries).

--ci        the CI variant (ci* values of DEM/parameters); a continued run
            must be given the same (setupDict's variant)
--continue  resume the coupled run: start from the latest time that has both
            OpenFOAM fields and the library's DEM restart of that time
            (DEM/restart/<time>.restart, writeDEMRestart; a run written
            before 2026-12-03 has DEM/post/restart/coupled.<step>.restart)
--np N      processes: the DEM and the CFD are split the same way, in two
            halves across the pipe (z, normal to gravity and the axis) and
            the rest along x: (N/2 1 2) for even N, (N 1 1) for odd N. The
            halves across the pipe hold the same load whatever the slug's
            position; an x split puts the slug on one rank at a time.
--end T     stop the coupled run at T instead of endTime (after its start;
            the solver writes there: continuable)
A new run (no --continue) refuses a case that has run (its writes, DEM
restarts, logs, packing or DEM histories): ./Allclean first.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402


def shape_volume(R, r, L, core, angle, layer_top, n=400):
    """Volume of the slug shape: the disc of radius R - r (r = 0: the bulk
    volume), between the two face planes or below layer_top, over the
    periodic length L (midpoint quadrature in y and x, chords in z)."""
    rc = R - r
    tan = math.tan(math.radians(angle))
    vol = 0.0
    dy = 2 * rc / n
    xs = [-L / 2 + (i + 0.5) * L / n for i in range(n)]
    dx = L / n
    for j in range(n):
        y = -rc + (j + 0.5) * dy
        chord = 2 * math.sqrt(max(rc * rc - y * y, 0.0))
        for x in xs:
            in_body = (abs(x) - core / 2) * tan <= R - y
            if in_body or y <= layer_top:
                vol += chord * dx * dy
    return vol


def write_face_stl(path, name, rects, half_width):
    """Planar rectangles (two triangles each), each (x_top, x_bottom, y_top,
    y_bottom) from the line x = x_top, y = y_top to the line x = x_bottom,
    y = y_bottom, across z in +-half_width: a temporary wall along one slug
    face (and the axial fill's lid) for the packing stage."""
    w = half_width
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for x_top, x_bottom, y_top, y_bottom in rects:
            a = (x_top, y_top, -w)
            b = (x_top, y_top, w)
            c = (x_bottom, y_bottom, w)
            d = (x_bottom, y_bottom, -w)
            for tri in ((a, b, c), (a, c, d)):
                f.write("  facet normal 0 0 0\n    outer loop\n")
                for v in tri:
                    f.write("      vertex %.9g %.9g %.9g\n" % v)
                f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


def write_pipe_stl(path, R, n, xlo, xhi, turn=0.0):
    """The pipe wall as an n-sided prism along x from xlo to xhi, corners
    at y = R cos(t), z = R sin(t) for t = (k + turn) 360/n degrees (the CFD
    mesh's wall points for n = 16 and turn 0), two triangles per facet."""
    ring = [(R * math.cos(2 * math.pi * (k + turn) / n),
             R * math.sin(2 * math.pi * (k + turn) / n)) for k in range(n)]
    with open(path, "w") as f:
        f.write("solid pipeWall\n")
        for k in range(n):
            (y0, z0), (y1, z1) = ring[k], ring[(k + 1) % n]
            a, b = (xlo, y0, z0), (xhi, y0, z0)
            c, d = (xhi, y1, z1), (xlo, y1, z1)
            for tri in ((a, b, c), (a, c, d)):
                f.write("  facet normal 0 0 0\n    outer loop\n")
                for v in tri:
                    f.write("      vertex %.12g %.12g %.12g\n" % v)
                f.write("    endloop\n  endfacet\n")
        f.write("endsolid pipeWall\n")


def latest_restart(case, dt_dem):
    """(time name, DEM step, restart file) of the latest write with a DEM
    restart: the library's (DEM/restart/<time>.restart, which also holds
    the coupling forces of that step) or, for runs written before
    2026-12-03, LIGGGHTS's own (DEM/post/restart/coupled.<step>.restart)."""
    tdir = case
    if os.path.isdir(os.path.join(case, "processor0")):
        tdir = os.path.join(case, "processor0")
    for name in reversed(caseio.time_dirs(tdir)):
        t = float(name)
        if t <= 0:
            continue
        step = int(round(t / dt_dem))
        for f in ("DEM/restart/%s.restart" % name,
                  "DEM/post/restart/coupled.%d.restart" % step):
            if os.path.isfile(os.path.join(case, f)):
                return name, step, f
    return None, None, None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", default=".")
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--continue", dest="cont", action="store_true")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--end", type=float, default=None)
    args = ap.parse_args()
    case = args.case
    if not args.cont:
        caseio.refuse_new_run(case, ("DEM/post/packed.restart", "DEM/post/history_*.dat",
                                     "DEM/post/dump/*"))
    else:
        caseio.check_variant(os.path.join(case, "DEM", "post", "setupDict"), args.ci)

    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))

    def p(name):
        ci_name = "ci" + name[0].upper() + name[1:]
        return par[ci_name] if args.ci and ci_name in par else par[name]

    R = par["pipeDiameter"] / 2
    r = par["dp"] / 2
    L = p("pipeLength")
    core = p("coreLength")
    angle = par["faceAngle"]
    layer_top = -R + par["layerHeight"]
    tan = math.tan(math.radians(angle))
    slug_span = core + 2 * (R - layer_top) / tan
    if slug_span >= L:
        sys.exit("prepare.py: the slug (core %.4g m + faces = %.4g m) does not fit"
                 " in the periodic length %.4g m" % (core, slug_span, L))
    nx = int(round(L / par["cellLength"]))
    if abs(nx * par["cellLength"] - L) > 1e-9:
        sys.exit("prepare.py: pipeLength must be a multiple of cellLength")

    dt_pack = par["packTimestep"]
    dt_dem = par["demTimestep"]

    def steps(interval, dt):
        n = int(round(interval / dt))
        if abs(n * dt - interval) > 1e-9 * interval:
            sys.exit("prepare.py: %g s is not a whole number of DEM steps of %g s"
                     % (interval, dt))
        return n

    v_shape = shape_volume(R, 0.0, L, core, angle, layer_top)
    vp = math.pi / 6 * par["dp"] ** 3
    s = math.radians(angle)

    facets = int(par.get("pipeWallFacets", 0))
    if facets != 0 and facets < 8:
        sys.exit("prepare.py: pipeWallFacets must be 0 (the exact cylinder) or"
                 " at least 8, got %d" % facets)

    # Particle-wall pair coefficients: the harmonic mean of the particle's
    # and the wall's value (the reference's DEM), or the wall's own value
    def pair(a, b):
        return 2 * a * b / (a + b) if par["wallPairHarmonic"] else b

    lig = {
        "wallPairFriction": pair(par["friction"], par["wallFriction"]),
        "wallPairRestitution": pair(par["restitution"], par["wallRestitution"]),
        "wallPairRolling": pair(par["rollingFriction"], par["wallRolling"]),
        # the fill's friction: packFriction without rolling friction, or
        # the case's own values (fillCaseFriction 1)
        "fillFriction": par["friction"] if par.get("fillCaseFriction", 0) else par["packFriction"],
        "fillWallFriction": (pair(par["friction"], par["wallFriction"])
                             if par.get("fillCaseFriction", 0) else par["packFriction"]),
        "fillRolling": par["rollingFriction"] if par.get("fillCaseFriction", 0) else 0.0,
        "fillWallRolling": (pair(par["rollingFriction"], par["wallRolling"])
                            if par.get("fillCaseFriction", 0) else 0.0),
        "pipeRadius": R,
        "pipeWallFacets": facets,
        # the packing's fill region: inside the wall (the inscribed circle
        # of a faceted wall)
        "fillRadius": R * math.cos(math.pi / facets) if facets else R,
        "xlo": -L / 2, "xhi": L / 2,
        "boxLo": -(R + 0.002), "boxHi": R + 0.002,
        "frontX": core / 2, "frontNx": -math.sin(s), "frontNy": -math.cos(s),
        "rearX": -core / 2, "rearNx": math.sin(s), "rearNy": -math.cos(s),
        "layerTop": layer_top,
        "axialFill": int(par.get("axialFill", 0)),
        # the axial fill's upper end wall: one diameter short of the
        # periodic plane, so that no contact reaches across it
        "fillXhi": L / 2 - par["dp"] if par.get("axialFill", 0) else L / 2,
        # Insertion target above what a random packing holds: every fill
        # period inserts into whatever room is left. The axial fill inserts
        # the case's particles (1 % more for the carve and the thinning) as
        # the reference inserted its 32 194: its pile, compressed along the
        # pipe, would hold about 10 % more (axialFillToCapacity 1 fills it
        # all, and the thinning then takes the excess out at random)
        "nFill": (int(math.ceil(1.01 * par["nParticles"]))
                  if par.get("axialFill", 0) and not par.get("axialFillToCapacity", 0)
                  and not args.ci
                  else int(math.ceil(0.7 * v_shape / vp))),
        "fillEvery": steps(par["fillPeriod"], dt_pack),
        "fillSteps": steps(p("fillTime"), dt_pack),
        "settleSteps": steps(p("settleTime"), dt_pack),
        "statSteps": steps(par["statInterval"], dt_dem),
        "dumpSteps": steps(p("dumpInterval"), dt_dem),
        "writeSteps": steps(p("writeInterval"), dt_dem),
        # CI: slug centred on the periodic plane, every particle kept
        "shiftX": L / 2 if args.ci else 0.0,
    }
    if args.ci:
        lig["nParticles"] = 1000000000

    start_time = "0"
    if args.cont:
        start_time, step, restart = latest_restart(case, dt_dem)
        if start_time is None:
            sys.exit("prepare.py --continue: no time directory with a matching"
                     " DEM restart (DEM/restart/<time>.restart)")
        fresh, segment = 0, str(step)
    else:
        restart = "DEM/post/packed.restart"
        fresh, segment = 1, "0"

    if args.np < 1:
        sys.exit("prepare.py: --np %d: the number of processes must be 1 or more" % args.np)
    # where the coupled run stops: endTime, or --end (the solver writes there)
    t_stop = p("endTime") if args.end is None else \
        caseio.check_end(args.end, start_time)
    grid = (args.np // 2, 1, 2) if args.np % 2 == 0 else (args.np, 1, 1)

    post = os.path.join(case, "DEM", "post")
    for d in (post, os.path.join(post, "dump"), os.path.join(post, "restart")):
        os.makedirs(d, exist_ok=True)
    with open(os.path.join(post, "setup.lig"), "w") as f:
        f.write("# Generated by Allrun (prepare.py) from DEM/parameters; do not edit\n")
        for k, v in lig.items():
            f.write("variable %-14s equal %.12g\n" % (k, v))
        f.write("variable %-14s equal %d\n" % ("fresh", fresh))
        f.write("variable %-14s equal %d\n" % ("procX", grid[0]))
        f.write("variable %-14s equal %d\n" % ("procZ", grid[2]))
        f.write("variable %-14s string %s\n" % ("restartFile", restart))
        f.write("variable %-14s string %s\n" % ("segment", segment))

    if facets:
        write_pipe_stl(os.path.join(post, "pipeWall.stl"), R, facets, -L / 2, L / 2,
                       0.5 if par.get("pipeWallFlatBottom", 0) else 0.0)

    # Temporary walls along the two faces, from the pipe top down to the
    # layer, for the fill of the packing stage. The axial fill adds a lid
    # over the layer outside the body (centres up to the layer top; the
    # faces end on it), from the faces to the end walls
    if lig["axialFill"]:
        y_lid = layer_top + r
        span = (R - y_lid) / tan
        lids = {"faceFront": (core / 2 + span, lig["fillXhi"]),
                "faceRear": (-core / 2 - span, -L / 2)}
    else:
        y_lid, span, lids = layer_top, (R - layer_top) / tan, {}
    for name, sign in (("faceFront", 1), ("faceRear", -1)):
        rects = [(sign * core / 2, sign * (core / 2 + span), R, y_lid)]
        if name in lids:
            rects.append(lids[name] + (y_lid, y_lid))
        write_face_stl(os.path.join(post, name + ".stl"), name, rects, R)

    with open(os.path.join(post, "setupDict"), "w") as f:
        f.write("// Generated by Allrun (prepare.py) from DEM/parameters; do not edit\n")
        geo = {"xlo": -L / 2, "xhi": L / 2, "R": R, "mR": -R, "s": R / 2,
               "ms": -R / 2, "c": R / math.sqrt(2), "mc": -R / math.sqrt(2)}
        for k, v in geo.items():
            f.write("%-14s %.12g;\n" % (k, v))
        f.write("%-14s %d;\n" % ("nSquare", int(par["nSquare"])))
        f.write("%-14s %d;\n" % ("nRadial", int(par["nRadial"])))
        f.write("%-14s %d;\n" % ("nx", nx))
        f.write("%-14s %s;\n" % ("variant", caseio.variant(args.ci)))
        f.write("%-14s %s;\n" % ("startTime", start_time))
        f.write("%-14s %.12g;\n" % ("endTime", t_stop))
        f.write("%-14s %.12g;\n" % ("writeInterval", p("writeInterval")))
        f.write("%-14s %.12g;\n" % ("gasVelocity", par["gasVelocity"]))
        f.write("%-14s (%d %d %d);\n" % (("decomposition",) + grid))

    print("densePneumaticConveying%s: pipe %.4g m x D %.4g m (%d cells along x),"
          " slug core %.4g m, span %.4g m, shape volume %.4g m^3 (%.0f particles"
          " at solid fraction 0.585), start %s%s"
          % (" (CI)" if args.ci else "", L, 2 * R, nx, core, slug_span, v_shape,
             0.585 * v_shape / vp, start_time,
             " (continued)" if args.cont else ""))


if __name__ == "__main__":
    main()
