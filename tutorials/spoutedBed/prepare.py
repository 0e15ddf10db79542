#!/usr/bin/python3
"""spoutedBed set-up: from constant/spoutedBedProperties, derive the cone,
the mesh, the particles of the selected set in the selected representation
(spheres: the production representation, one sphere per particle; clumps:
the fidelity representation, multisphere bodies that keep the plates'
thickness; see README), the DEM and CFD steps and the inlet schedule, and
write
  DEM/post/setup.lig     LIGGGHTS variables and per-type commands
  DEM/post/walls.stl     the cone's and upper section's side walls
  DEM/post/setupDict     blockMesh, controlDict and 0/U entries
  constant/hoelzerSommerfeldShapes  the drag model's shape table
  DEM/post/particles.dat one line per shape: what the sphere (or clump)
                         stands for
  DEM/post/representation  the engine's shapedSpheres entry
  DEM/post/<shape>.multisphere, .liggghts  the clumps' templates (clumps)

--ci          the CI variant (ci* entries)
--set NAME    override the dictionary's set
--np N        DEM processor grid (N 1 1) and the CFD decomposition
--end T       stop the coupled run at T (after the start, at most the
              schedule's end; the solver writes there: continuable)
--representation spheres|clumps   override the dictionary's representation
--fraction F  keep this fraction of each shape's particles (default 1,
              ciFraction with --ci)
--realisation R  override the dictionary's realisation: the seed of the
              random insertion (0: that of every earlier run; 1, 2, ...,
              10000: other insertions of the same bed)
--continue    start from the latest time with a DEM restart (or, without
              one, from the fill: time 0); the set, the representation,
              the fraction and the realisation are the run's own (from
              DEM/post/particles.dat) unless given, and must agree with it
--map-from SOURCE TIME
              start from another run's state at its write TIME (SOURCE: a
              run of this case, serial or decomposed) on this case's own
              mesh (Allrun -mapFrom: the mesh check): copy SOURCE's DEM
              restart of TIME (and its step), its 100 Hz heights,
              snapshots and function-object output up to TIME, and make the
              time directory TIME from 0/ for mapFields to fill (SOURCE
              relative to this case). The set, representation, fraction and
              realisation are SOURCE's; the rest of the set-up written here must be
              SOURCE's but for the mesh (the DEM and CFD steps, particles,
              materials, domain, probe, schedule: the restart holds SOURCE's
              bodies and step count, and the history is joined), else it
              stops and names what differs; the coupling and turbulence
              settings (constant/) are this case's own
"""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

PROPS = "constant/spoutedBedProperties"


def read_props(case):
    text = caseio._strip_comments(open(os.path.join(case, PROPS)).read())
    props = {}
    for m in re.finditer(r"(?m)^\s*(\w+)\s+([-+0-9.eE]+)\s*;", text):
        props[m.group(1)] = float(m.group(2))
    m = re.search(r"(?m)^\s*set\s+(\w+)\s*;", text)
    props["set"] = m.group(1)
    m = re.search(r"(?m)^\s*representation\s+(\w+)\s*;", text)
    props["representation"] = m.group(1) if m else "spheres"
    m = re.search(r"clumpSpheres\s*\((.*?)\n\)\s*;", text, flags=re.S)
    props["clumpSpheres"] = {}
    if m:
        for row in re.findall(r"\(([^()]*)\)", m.group(1)):
            f = row.split()
            props["clumpSpheres"][f[0]] = [int(v) for v in f[1:]]
    m = re.search(r"plateaus\s*\(([^)]*)\)", text)
    props["plateaus"] = [float(v) for v in m.group(1).split()]
    m = re.search(r"shapes\s*\((.*?)\n\)\s*;", text, flags=re.S)
    shapes = []
    for row in re.findall(r"\(([^()]*)\)", m.group(1)):
        f = row.split()
        shapes.append({"name": f[0], "kind": f[1], "length": float(f[2]),
                       "width": float(f[3]), "thickness": float(f[4]),
                       "mass": float(f[5])})
    props["shapes"] = shapes
    m = re.search(r"sets\s*\{(.*?)\}", text, flags=re.S)
    props["sets"] = {k: [float(v) for v in vals.split()]
                     for k, vals in re.findall(r"(\w+)\s*\(([^)]*)\)\s*;", m.group(1))}
    return props


def ideal_volume(s):
    if s["kind"] == "plate":
        return s["length"] * s["width"] * s["thickness"]
    D, L = s["width"], s["length"]
    return math.pi * D * D / 4 * (L - D) + math.pi * D ** 3 / 6


def rayleigh_time(r, rho, E, nu):
    G = E / (2 * (1 + nu))
    return math.pi * r * math.sqrt(rho / G) / (0.1631 * nu + 0.8766)


def next_prime(n):
    """The smallest prime >= n (trial division: n is about 1e8)."""
    n = max(n, 2)
    while any(n % d == 0 for d in range(2, int(math.isqrt(n)) + 1)):
        n += 1
    return n


def insertion_seed(base, realisation, taken):
    """The insertion's seed (LIGGGHTS fix insert/pack: a prime > 10000).
    Realisation 0 keeps the base seed, that of every run before the key
    existed; realisation r > 0 takes the smallest prime >= base + 100003 r
    that no other fix uses (taken): the same bed, inserted at other random
    positions (and, clumps, at other orientations). The distribution's
    seed is not changed: it hands out the particles left over when each
    shape's count is rounded down, so the bed's make-up stays realisation
    0's exactly."""
    if realisation == 0:
        return base
    seed = next_prime(base + 100003 * realisation)
    while seed in taken:
        seed = next_prime(seed + 1)
    return seed


def continued_run(args, path, what="--continue"):
    """A continued run keeps its set, representation, fraction and
    realisation: take them from the first run's DEM/post/particles.dat
    header where the command line does not give them, and refuse a command
    line that differs."""
    if not os.path.exists(path):
        return
    head = open(path).readline()
    m = re.match(r"# set (\w+)( \(CI\))?, representation (\w+):.*; fraction ([-+0-9.eE]+)"
                 r"(; realisation (\d+))?", head)
    if not m and what != "--continue":
        sys.exit("prepare.py %s: %s does not say the run's set, representation and"
                 " fraction (a set-up of an older version)" % (what, path))
    if not m:
        return          # a set-up of an older version: the command line's
    # (a header without a realisation: a set-up from before the key, i.e. 0)
    own = {"set": m.group(1), "representation": m.group(3), "fraction": float(m.group(4)),
           "realisation": int(m.group(6) or 0)}
    given = {"set": args.set, "representation": args.representation,
             "fraction": args.fraction, "realisation": args.realisation}
    for key, v in given.items():
        if v is not None and v != own[key]:
            sys.exit("prepare.py %s: the run was set up with %s %s (%s), not %s"
                     % (what, key, own[key], path, v))
    if bool(m.group(2)) != args.ci:
        sys.exit("prepare.py %s: the run was set up %s the CI variant (%s)"
                 % (what, "as" if m.group(2) else "without", path))
    args.fraction = own["fraction"]
    args.set = own["set"]
    args.representation = own["representation"]
    args.realisation = own["realisation"]


# the fill's outputs, besides those of every tutorial (caseio.run_outputs)
FILL_OUTPUTS = ("DEM/post/height.dat", "DEM/post/filled.restart", "DEM/post/fill.restart",
                "DEM/post/filled.bodies", "DEM/post/fill.bodies")


def map_source(source, time):
    """Check the run to map from (Allrun -mapFrom) before anything is
    written: its DEM restart and its fields of TIME, its particle
    description; and that this case has not run (its own state would mix
    with the source's)."""
    def need(path, what):
        if not os.path.exists(path):
            sys.exit("prepare.py --map-from %s %s: %s (%s) not found"
                     % (source, time, what, path))
    need(os.path.join(source, "DEM", "restart", "%s.restart" % time), "its DEM restart of that time")
    if not (os.path.isdir(os.path.join(source, time))
            or os.path.isdir(os.path.join(source, "processor0", time))):
        sys.exit("prepare.py --map-from %s %s: no time directory %s in %s or its"
                 " processor0 (the write times are those with a DEM restart in"
                 " DEM/restart)" % (source, time, time, source))
    need(os.path.join(source, "DEM", "post", "particles.dat"), "its particle description")
    need(os.path.join(source, "DEM", "post", "setupDict"), "its set-up")
    caseio.refuse_new_run(".", FILL_OUTPUTS, "prepare.py --map-from",
                          "map into a clean case (./Allclean)")


def copy_until(src, dst, t_end):
    """Copy a text file of rows that start with their time, without the rows
    after t_end (comment lines kept)."""
    tol = 1e-9 * max(1.0, abs(t_end))
    with open(src) as fin, open(dst, "w") as fout:
        for line in fin:
            f = line.split()
            if f and not line.lstrip().startswith("#"):
                try:
                    if float(f[0]) > t_end + tol:
                        continue
                except ValueError:
                    pass
            fout.write(line)


def setup_entries(path):
    """The entries of a setupDict (keyword -> text; inletTable whole)."""
    text = open(path).read()
    entries = dict(re.findall(r"(?m)^(\w+)\s+([^\n;]*);", text))
    m = re.search(r"inletTable\s*\((.*?)\n\);", text, flags=re.S)
    entries["inletTable"] = m.group(1).strip() if m else ""
    return entries


def map_check_setup(source, time, post):
    """A run started from SOURCE's state must have SOURCE's particles,
    materials, DEM and CFD steps, domain, probe and schedule: the restart
    holds SOURCE's bodies and step count (setup.lig's demDt, setupDict's
    deltaT and couplingInterval), and the history copied from SOURCE is
    joined to this run's. Only the mesh (and the process count) may
    differ. Compares the files prepare.py wrote with SOURCE's."""
    spost = os.path.join(source, "DEM", "post")
    differ = []
    free = {"nWidth", "nThickness", "nCone", "nUpper", "coneGrading", "startTime",
            "endTime", "writeInterval", "decomposition"}
    a, b = setup_entries(os.path.join(spost, "setupDict")), \
        setup_entries(os.path.join(post, "setupDict"))
    for k in sorted(set(a) | set(b)):
        if k not in free and a.get(k) != b.get(k):
            differ.append("%s (source %s, here %s)" % (
                k, (a.get(k) or "none")[:40], (b.get(k) or "none")[:40]))
    skip = re.compile(r"^variable\s+(fresh|restartFile|nProcX)\s")
    names = ["setup.lig", "materials.lig", "templates.lig", "particles.dat",
             "representation", "schedule.dat"] + \
        sorted(os.path.basename(f) for f in glob.glob(os.path.join(post, "*.multisphere")))
    pairs = [(os.path.join(spost, n), os.path.join(post, n), "DEM/post/" + n) for n in names]
    pairs.append((os.path.join(source, "constant", "hoelzerSommerfeldShapes"),
                  os.path.join("constant", "hoelzerSommerfeldShapes"),
                  "constant/hoelzerSommerfeldShapes"))
    for fa, fb, label in pairs:
        la = [x for x in open(fa)] if os.path.exists(fa) else None
        lb = [x for x in open(fb)] if os.path.exists(fb) else None
        if la is None and lb is None:
            continue
        if la is None or lb is None or [x for x in la if not skip.match(x)] != \
                [x for x in lb if not skip.match(x)]:
            differ.append(label)
    if differ:
        sys.exit("prepare.py --map-from %s %s: this case's set-up differs from the"
                 " source's in: %s. A run started from another run's state takes"
                 " its particles, materials, steps, domain, probe and schedule:"
                 " give this case the source's %s apart from the mesh keys"
                 " (nWidth, nThickness, firstCellHeight, lastConeCell, nUpper; with"
                 " --ci, ciNWidth and ciNUpper)"
                 % (source, time, "; ".join(differ), PROPS))


def map_copy(source, time, dt, post):
    """The source's state and history up to TIME, into this case (see
    --map-from)."""
    t = float(time)
    os.makedirs(os.path.join("DEM", "restart"), exist_ok=True)
    # the restart and the step it was written at (the solver checks that
    # the DEM script read it)
    for ext in (".restart", ".step"):
        f = os.path.join(source, "DEM", "restart", time + ext)
        if os.path.exists(f):
            shutil.copy2(f, os.path.join("DEM", "restart", time + ext))
    hsrc = os.path.join(source, "DEM", "post", "height.dat")
    if os.path.exists(hsrc):
        copy_until(hsrc, os.path.join(post, "height.dat"), t)
    for path in glob.glob(os.path.join(source, "DEM", "post", "dump", "snap.*.txt")):
        if int(path.split(".")[-2]) * dt <= t * (1 + 1e-9):
            shutil.copy2(path, os.path.join(post, "dump"))
    # function objects' output (probes, inlet velocity): the segments that
    # start before TIME, cut at TIME; this run's own start at TIME
    for d in glob.glob(os.path.join(source, "postProcessing", "*", "*")):
        try:
            start = float(os.path.basename(d))
        except ValueError:
            continue
        if start >= t or not os.path.isdir(d):
            continue
        rel = os.path.relpath(d, source)
        os.makedirs(rel, exist_ok=True)
        for f in os.listdir(d):
            if os.path.isfile(os.path.join(d, f)):
                copy_until(os.path.join(d, f), os.path.join(rel, f), t)
    shutil.rmtree(time, ignore_errors=True)
    shutil.copytree("0", time)


def clump_template(row, seed, post):
    """Write the row's multisphere template with tools/shapes/foamDEMShapes
    (mass and inertia of the ideal shape at the row's density, i.e. the
    table's mass) and return the lines to include."""
    tool = os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "tools", "shapes",
                        "foamDEMShapes")
    cmd = [sys.executable, tool, "--name", row["name"], "--type", str(row["type"]),
           "--atom-type", str(row["type"]), "--density", "%.10g" % row["rho"],
           "--seed", str(seed), "--ideal-mass", "--allow-gaps", "--out", post]
    if row["kind"] == "plate":
        cmd += ["--shape", "plate", "--length", "%.10g" % row["length"],
                "--width", "%.10g" % row["width"], "--thickness", "%.10g" % row["thickness"],
                "--spheres-along", str(row["layout"][0]),
                "--spheres-across", str(row["layout"][1])]
    else:
        cmd += ["--shape", "spherocylinder", "--diameter", "%.10g" % row["width"],
                "--length", "%.10g" % row["length"], "--spheres", str(row["layout"][0])]
    out = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True)
    with open(os.path.join(post, "%s.report" % row["name"]), "w") as f:
        f.write(out.stdout)
    if out.returncode != 0:
        sys.exit("prepare.py: foamDEMShapes failed for %s:\n%s" % (row["name"], out.stdout))
    lines = []
    for line in open(os.path.join(post, "%s.liggghts" % row["name"])):
        if line.startswith("fix "):
            lines.append(line.replace("spheres file %s.multisphere" % row["name"],
                                      "spheres file %s/%s.multisphere"
                                      % (post.replace("./", "", 1), row["name"]))
                         .replace("pts_%s " % row["name"], "pts%d " % row["type"])
                         .replace("ntry 1000000", "ntry 100000"))
    if len(lines) != 1:
        sys.exit("prepare.py: foamDEMShapes wrote %d template lines for %s"
                 % (len(lines), row["name"]))
    return lines[0]


def clump_errors(rows, post):
    """DEM/post/clumpErrors.dat: each clump against its ideal shape, in
    volume, surface, Phi (foamDEMShapes's report) and Phi_perp face-on (flow
    along the plate's thickness, across the rod) and edge-on (along the
    length), each with its own d_v; the mass is the table's in both."""
    from foamdem import shapes  # numpy: only the clumps need it
    with open(os.path.join(post, "clumpErrors.dat"), "w") as f:
        f.write("# The clumps (representation clumps) against their ideal shapes:"
                " (clump/ideal - 1) in %; Phi_perp = (pi d_v^2/4) / shadow area,"
                " face-on = flow along body z (plate thickness, across the rod),"
                " edge-on = along body x (length); each body's own d_v. The mass is"
                " the table's in both (error 0); the drag and the void fraction use"
                " the ideal shape's Phi and Phi_perp\n")
        f.write("# name spheres volume_pct surface_pct Phi_ideal Phi_clump Phi_pct"
                " PhiPerpFace_ideal PhiPerpFace_clump PhiPerpFace_pct"
                " PhiPerpEdge_ideal PhiPerpEdge_clump PhiPerpEdge_pct\n")
        for row in rows:
            if row["n"] == 0:
                continue
            rep_ = open(os.path.join(post, "%s.report" % row["name"])).read()
            vals = {}
            for key in ("ideal", "clump \\(union\\)"):
                m = re.search(r"(?m)^%s\s*:\s*V\s+(\S+)\s+S\s+(\S+)\s+d_v\s+(\S+)\s+Phi\s+(\S+)"
                              % key, rep_)
                vals[key[:5]] = [float(v) for v in m.groups()]
            V0, S0, dv0, phi0 = vals["ideal"]
            V1, S1, dv1, phi1 = vals["clump"]
            ideal = shapes.Plate(row["length"], row["width"], row["thickness"]) \
                if row["kind"] == "plate" else shapes.Spherocylinder(row["width"], row["length"])
            centres, radii = shapes.read_multisphere(
                os.path.join(post, "%s.multisphere" % row["name"]))
            clump = shapes.Clump(centres, radii[0])
            out = [row["name"], "%d" % row["spheres"], "%+.2f" % (100 * (V1 / V0 - 1)),
                   "%+.2f" % (100 * (S1 / S0 - 1)), "%.4f" % phi0, "%.4f" % phi1,
                   "%+.2f" % (100 * (phi1 / phi0 - 1))]
            for n in ((0, 0, 1), (1, 0, 0)):
                p0 = math.pi * dv0 ** 2 / 4 / ideal.projected_area(n)
                p1 = math.pi * dv1 ** 2 / 4 / clump.projected_area(n)
                out += ["%.4f" % p0, "%.4f" % p1, "%+.2f" % (100 * (p1 / p0 - 1))]
            f.write(" ".join(out) + "\n")


def schedule(props, ci):
    """Inlet velocity table (t, U) and the plateaus' windows: a linear ramp
    to the first plateau over rampTime, then each plateau for plateauTime
    (a step change between plateaus, as a ramp over 1e-6 plateauTime)."""
    ramp = props["ciRampTime" if ci else "rampTime"]
    hold = props["ciPlateauTime" if ci else "plateauTime"]
    u = props["plateaus"]
    jump = 1e-6 * hold
    table = [(0.0, 0.0), (ramp, u[0])]
    windows = []
    for i, v in enumerate(u):
        t0, t1 = ramp + i * hold, ramp + (i + 1) * hold
        windows.append((v, t0, t1))
        table.append((t1, v))
        if i + 1 < len(u):
            table.append((t1 + jump, u[i + 1]))
    return table, windows


def rebuild_insertion(bodies_file):
    """DEM/post/rebuild.lig: the insertion of DEM/in.fill with -var rebuild 1,
    i.e. as many bodies of each type as BODIES (a body-state file) holds, one
    type after the other, each from its own template (pts<type> of
    templates.lig) in the fill's insertion region; foamDEMLiggghts then sets
    them from BODIES. (The fill's own insertion draws each body's type at
    random: another insertion would not give the same counts.)"""
    from foamdem import bodies
    try:
        counts = bodies.counts_by_type(bodies_file)
    except (OSError, ValueError) as e:
        sys.exit("prepare.py: %s" % e)
    if not counts:
        sys.exit("prepare.py: %s holds no bodies" % bodies_file)

    # LIGGGHTS's seeds: primes above 10 000, two for each type (the
    # primes above 1 000 000 in turn)
    primes = [next_prime(1000001)]
    while len(primes) < 2 * len(counts):
        primes.append(next_prime(primes[-1] + 1))
    total = 0
    with open(os.path.join("DEM", "post", "rebuild.lig"), "w") as f:
        f.write("# Generated by prepare.py --rebuild-insertion %s; do not edit\n"
                "# (insert/pack fills its region up to a count of bodies: the\n"
                "# bodies inserted so far, those of this type added; the most\n"
                "# numerous type first)\n" % bodies_file)
        order = sorted(counts.items(), key=lambda tn: (-tn[1], tn[0]))
        for k, (t, n) in enumerate(order):
            total += n
            f.write("fix rbd%d all particledistribution/discrete/numberbased %d 1 pts%d 1.0\n"
                    % (t, primes[2 * k], t))
            f.write("fix rbi%d all insert/pack seed %d distributiontemplate rbd%d &\n"
                    "    insert_every once overlapcheck yes all_in yes ${insertOrientation} &\n"
                    "    region ins particles_in_region %d ntry_mc 10000\n"
                    % (t, primes[2 * k + 1], t, total))
            if k == 0:
                f.write("fix ms all multisphere allow_group_and_set yes\n")
            f.write("run 1\nvariable rbn%d equal f_rbi%d[1]\n"
                    "print \"REBUILD: type %d: ${rbn%d} of %d bodies inserted\"\n"
                    "unfix rbi%d\n" % (t, t, t, t, n, t))
    print("prepare.py: DEM/post/rebuild.lig inserts %s" % ", ".join(
        "%d of type %d" % (n, t) for t, n in sorted(counts.items())))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--set", default=None)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--end", type=float, default=None)
    ap.add_argument("--continue", dest="cont", action="store_true")
    ap.add_argument("--representation", default=None, choices=("spheres", "clumps"))
    ap.add_argument("--fraction", type=float, default=None)
    ap.add_argument("--realisation", type=int, default=None)
    ap.add_argument("--map-from", nargs=2, default=None, metavar=("SOURCE", "TIME"))
    ap.add_argument("--rebuild-insertion", default=None, metavar="BODIES")
    args = ap.parse_args()
    case = "."
    if args.rebuild_insertion:
        rebuild_insertion(args.rebuild_insertion)
        return
    P = read_props(case)
    if args.map_from and args.cont:
        sys.exit("prepare.py: --map-from starts a new run; it does not go with --continue")
    if args.np < 1:
        sys.exit("prepare.py: --np %d: the number of processes must be 1 or more" % args.np)
    if not args.cont and not args.map_from:
        caseio.refuse_new_run(".", FILL_OUTPUTS)
    if args.cont:
        continued_run(args, os.path.join(case, "DEM", "post", "particles.dat"))
    if args.map_from:
        source, map_time = args.map_from
        map_source(source, map_time)
        continued_run(args, os.path.join(source, "DEM", "post", "particles.dat"),
                      "--map-from %s %s" % (source, map_time))
    if args.fraction is not None and not 0 < args.fraction <= 1:
        sys.exit("prepare.py: --fraction %g: the fraction of each shape's particles"
                 " must be in (0, 1]" % args.fraction)

    realisation = args.realisation if args.realisation is not None else \
        P.get("realisation", 0.0)
    if realisation != int(realisation) or not 0 <= realisation <= 10000:
        sys.exit("prepare.py: realisation %g (%s, command line or keyword realisation):"
                 " a whole number from 0 to 10000 (0: the insertion of every earlier run;"
                 " 1, 2, ...: other random insertions of the same bed)"
                 % (realisation, PROPS))
    realisation = int(realisation)

    def p(key):
        return P["ci" + key[0].upper() + key[1:]] if args.ci and \
            ("ci" + key[0].upper() + key[1:]) in P else P[key]

    set_name = args.set or P["set"]
    if set_name not in P["sets"]:
        sys.exit("prepare.py: unknown set '%s' in %s; valid sets: %s"
                 % (set_name, PROPS, " ".join(sorted(P["sets"]))))
    rep = args.representation or P["representation"]
    if rep not in ("spheres", "clumps"):
        sys.exit("prepare.py: unknown representation '%s' (%s, command line or"
                 " keyword representation); valid: spheres clumps" % (rep, PROPS))
    clumps = rep == "clumps"
    grams = P["sets"][set_name]
    if len(grams) != len(P["shapes"]):
        sys.exit("prepare.py: set %s lists %d masses for %d shapes"
                 % (set_name, len(grams), len(P["shapes"])))

    # Geometry (z up, x across, y through the thickness)
    half = math.radians(P["coneAngle"] / 2)
    w0, w1 = P["inletWidth"], p("topWidth")
    Hc = (w1 - w0) / 2 / math.tan(half)
    Hu = p("upperHeight")
    T = P["thickness"]
    # cone cells: geometric growth from firstCellHeight to about lastConeCell
    a, b = P["firstCellHeight"], P["lastConeCell"]
    r = (Hc - a) / (Hc - b)
    nCone = max(2, int(round(1 + math.log(b / a) / math.log(r))))
    grading = b / a

    # Particles. spheres: one sphere per particle, of the ideal shape's
    # volume and the table's mass (density = mass / ideal volume). clumps:
    # a multisphere body of spheres of the plate's thickness or the rod's
    # diameter (clumpSpheres layouts), with the table's mass and the ideal
    # shape's inertia scaled by the same ratio (the same density)
    frac = args.fraction if args.fraction is not None else \
        (P["ciFraction"] if args.ci else 1.0)
    E, nu = P["youngsModulus"], P["poissonsRatio"]
    rows, dt_r, dt_prod = [], [], []
    for t, (s, g) in enumerate(zip(P["shapes"], grams), start=1):
        V = ideal_volume(s)
        dv = (6 * V / math.pi) ** (1 / 3)
        rho = s["mass"] / V
        n = int(round(frac * g * 1e-3 / s["mass"]))
        r_contact = dv / 2
        layout = [1]
        if clumps:
            layout = P["clumpSpheres"].get(s["name"])
            if not layout or len(layout) != (2 if s["kind"] == "plate" else 1):
                sys.exit("prepare.py: %s: clumpSpheres has no valid layout for %s"
                         " (plate: spheres along and across; rod: spheres)"
                         % (PROPS, s["name"]))
            r_contact = (s["thickness"] if s["kind"] == "plate" else s["width"]) / 2
        rows.append(dict(s, type=t, grams=g, volume=V, dv=dv, rho=rho, n=n,
                         massRatio=s["mass"] / (P["rhoApparent"] * V),
                         layout=layout,
                         spheres=layout[0] * (layout[1] if len(layout) > 1 else 1)))
        if n > 0:
            dt_r.append(rayleigh_time(r_contact, rho, E, nu))
            dt_prod.append(rayleigh_time(dv / 2, rho, E, nu))
    N = sum(row["n"] for row in rows)
    if N == 0:
        sys.exit("prepare.py: set %s with fraction %g has no particles" % (set_name, frac))
    # The DEM step: at most rayleighFraction of the smallest Rayleigh time,
    # and such that the write interval is a whole number of CFD steps (so
    # that the fields and the DEM restarts are written at the same times).
    # Clumps keep about the production representation's CFD step: more DEM
    # steps per CFD step
    nc = int(P["couplingInterval"])
    if clumps:
        nc = max(1, int(round(nc * min(dt_prod) / min(dt_r))))
    n_write = int(math.ceil(p("writeInterval") / (nc * P["rayleighFraction"] * min(dt_r))))
    dt_cfd = p("writeInterval") / n_write
    dt = dt_cfd / nc

    table, windows = schedule(P, args.ci)
    t_end = table[-1][0]

    start_time, restart, fresh = "0", "DEM/post/filled.restart", 1
    if args.cont:
        best = None
        # a decomposed run writes its times in processor0/
        where = os.path.join(case, "processor0") \
            if os.path.isdir(os.path.join(case, "processor0")) else case
        for d in caseio.time_dirs(where):
            if float(d) > 0 and os.path.exists(
                    os.path.join(case, "DEM", "restart", "%s.restart" % d)):
                best = d
        # the solver hands the DEM script that restart (foamDEMRestart);
        # without a write the coupled stage starts again from the fill
        # (Allrun continues the fill first if it did not end)
        if best is not None:
            start_time, restart, fresh = best, "DEM/restart/%s.restart" % best, 0
    if args.map_from:
        start_time, restart, fresh = map_time, "DEM/restart/%s.restart" % map_time, 0
    # where the coupled run stops: the schedule's end, or --end (the solver
    # writes there, also between write times)
    t_stop = t_end if args.end is None else caseio.check_end(args.end, start_time, t_end)

    post = os.path.join(case, "DEM", "post")
    for d in (post, os.path.join(post, "restart"), os.path.join(post, "dump")):
        os.makedirs(d, exist_ok=True)

    # Side walls (STL): the two cone planes and the two upper walls
    def quad(f, p0, p1, p2, p3):
        for tri in ((p0, p1, p2), (p0, p2, p3)):
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in tri:
                f.write("      vertex %.9g %.9g %.9g\n" % v)
            f.write("    endloop\n  endfacet\n")
    with open(os.path.join(post, "walls.stl"), "w") as f:
        f.write("solid walls\n")
        for s_ in (-1, 1):
            xb, xt = s_ * w0 / 2, s_ * w1 / 2
            quad(f, (xb, 0, 0), (xb, T, 0), (xt, T, Hc), (xt, 0, Hc))
            quad(f, (xt, 0, Hc), (xt, T, Hc), (xt, T, Hc + Hu), (xt, 0, Hc + Hu))
        f.write("endsolid walls\n")

    present = [row for row in rows if row["n"] > 0]
    steps = lambda t: max(1, int(round(t / dt)))  # noqa: E731
    # insertion region: inside the cone above its bottom
    z_ins0 = 0.02
    x_ins = w0 / 2 + z_ins0 * math.tan(half) - 0.002
    z_ins1 = min(Hc, z_ins0 + 0.45 if not args.ci else z_ins0 + 0.15)
    lig = {
        "nTypes": len(rows) + 1, "wallType": len(rows) + 1,
        "xlo": -w1 / 2 - 0.001, "xhi": w1 / 2 + 0.001, "ylo": 0.0, "yhi": T,
        "zlo": -0.001, "zhi": Hc + Hu,
        "youngsModulus": E, "poissonsRatio": nu,
        "restitution": P["restitution"], "friction": P["friction"],
        "wallFriction": P["wallFriction"], "rollingFriction": P["rollingFriction"],
        "characteristicVelocity": P["characteristicVelocity"],
        "demDt": dt, "nParticles": N,
        "insXlo": -x_ins, "insXhi": x_ins, "insYlo": 0.0005, "insYhi": T - 0.0005,
        "insZlo": z_ins0, "insZhi": z_ins1,
        "settleSteps": steps(p("settleTime")),
        "fillRestartSteps": steps(P["fillRestartInterval"]),
        "heightSteps": steps(P["heightInterval"]),
        "writeSteps": steps(p("writeInterval")),
        "nProcX": args.np, "clumps": int(clumps),
    }
    with open(os.path.join(post, "setup.lig"), "w") as f:
        f.write("# Generated by Allrun (prepare.py) from %s; do not edit\n" % PROPS)
        for k, v in lig.items():
            f.write("variable %-22s equal %.12g\n" % (k, v))
        f.write("variable %-22s equal %d\n" % ("fresh", fresh))
        f.write("variable %-22s string %s\n" % ("restartFile", restart))
        # clumps: no rolling resistance (the true shape resists rolling),
        # random initial orientations
        f.write('variable %-22s string "%s"\n' % (
            "rollingModel", "rolling_friction off" if clumps else "rolling_friction epsd2"))
        f.write('variable %-22s string "%s"\n' % (
            "insertOrientation", "orientation random" if clumps else "verbose yes"))
    # Templates and the distribution (number fractions, exact)
    seeds = [15485863, 15485867, 32452843, 32452867, 49979687, 49979693,
             67867967, 67867979, 86028121, 86028157]
    with open(os.path.join(post, "templates.lig"), "w") as f:
        f.write("# Generated by prepare.py: one %s template per shape of set %s\n"
                % ("multisphere" if clumps else "sphere", set_name))
        dist = []
        if clumps:
            # a template for every shape, so that the multisphere types are
            # 1..6 (LIGGGHTS indexes its per-type data by them); the
            # distribution lists the set's
            for k, row in enumerate(rows):
                f.write(clump_template(row, seeds[k], post))
        for k, row in enumerate(present):
            if not clumps:
                f.write("fix pts%d all particletemplate/sphere %d atom_type %d "
                        "density constant %.10g radius constant %.10g\n"
                        % (row["type"], seeds[k], row["type"], row["rho"], row["dv"] / 2))
            dist.append("pts%d %.12g" % (row["type"], row["n"] / N))
        k = len(rows) if clumps else len(present)
        f.write("fix pdd all particledistribution/discrete/numberbased %d %d %s\n"
                % (seeds[k], len(present), " ".join(dist)))
        f.write("variable insertSeed equal %d\n"
                % insertion_seed(seeds[k + 1], realisation, seeds))
    # Materials: types 1..6 the shapes, the last type the walls; friction
    # 1.0 between particles, 0.9 with the walls; one restitution and one
    # rolling friction for all pairs
    nt = len(rows) + 1
    with open(os.path.join(post, "materials.lig"), "w") as f:
        f.write("# Generated by prepare.py: %d particle types + the wall (type %d)\n"
                % (len(rows), nt))
        f.write("fix m1 all property/global youngsModulus peratomtype %s\n"
                % " ".join(["%.6g" % E] * nt))
        f.write("fix m2 all property/global poissonsRatio peratomtype %s\n"
                % " ".join(["%.6g" % nu] * nt))

        def matrix(v_pp, v_pw):
            return " ".join("%.6g" % (v_pw if (i == nt or j == nt) else v_pp)
                            for i in range(1, nt + 1) for j in range(1, nt + 1))
        f.write("fix m3 all property/global coefficientRestitution peratomtypepair %d %s\n"
                % (nt, matrix(P["restitution"], P["restitution"])))
        f.write("fix m4 all property/global coefficientFriction peratomtypepair %d %s\n"
                % (nt, matrix(P["friction"], P["wallFriction"])))
        f.write("fix m5 all property/global coefficientRollingFriction peratomtypepair %d %s\n"
                % (nt, matrix(P["rollingFriction"], P["rollingFriction"])))
        f.write("fix m6 all property/global characteristicVelocity scalar %.6g\n"
                % P["characteristicVelocity"])
    realisation_tag = "; realisation %d" % realisation if realisation else ""
    # the fraction as given (read back by --continue): %g where that is
    # exact, as every earlier set-up wrote it, else all its digits
    frac_text = "%g" % frac if float("%g" % frac) == frac else repr(frac)
    with open(os.path.join(post, "particles.dat"), "w") as f:
        if clumps:
            f.write("# set %s%s, representation clumps: multisphere bodies of"
                    " spheresPerParticle spheres of the plate's thickness or the rod's"
                    " diameter; mass = table mass, inertia = ideal shape's x mass ratio;"
                    " fraction %s%s\n" % (set_name, " (CI)" if args.ci else "",
                                           frac_text, realisation_tag))
        else:
            f.write("# set %s%s, representation spheres: one sphere per particle, d ="
                    " d_v of the ideal shape, density = table mass / ideal volume;"
                    " fraction %s%s\n" % (set_name, " (CI)" if args.ci else "",
                                           frac_text, realisation_tag))
        f.write("# type name kind grams count mass_kg idealVolume_m3 d_v_m density_kg_m3"
                " massOverIdealMass spheresPerParticle\n")
        for row in rows:
            f.write("%d %s %s %.4g %d %.6e %.6e %.6e %.2f %.3f %d\n"
                    % (row["type"], row["name"], row["kind"], row["grams"], row["n"],
                       row["mass"], row["volume"], row["dv"], row["rho"], row["massRatio"],
                       row["spheres"]))
    if clumps:
        clump_errors(rows, post)
    with open(os.path.join(post, "representation"), "w") as f:
        f.write("// Generated by prepare.py: representation %s\n" % rep)
        f.write("dragIntegration %s;\n" % ("explicit" if clumps else "implicit"))
        f.write("shapedSpheres   %s;\n" % ("false" if clumps else "true"))

    # Drag model shape table, by atom type
    with open(os.path.join(case, "constant", "hoelzerSommerfeldShapes"), "w") as f:
        f.write("// Generated by prepare.py from %s: the drag model's shape per"
                " atom type; do not edit\n" % PROPS)
        for row in rows:
            if row["kind"] == "plate":
                f.write('"%d" { shape plate; length %.6g; width %.6g; thickness %.6g; }\n'
                        % (row["type"], row["length"], row["width"], row["thickness"]))
            else:
                f.write('"%d" { shape spherocylinder; diameter %.6g; length %.6g; }\n'
                        % (row["type"], row["width"], row["length"]))

    with open(os.path.join(post, "setupDict"), "w") as f:
        f.write("// Generated by Allrun (prepare.py) from %s; do not edit\n" % PROPS)
        geo = {"xb": w0 / 2, "mxb": -w0 / 2, "xt": w1 / 2, "mxt": -w1 / 2,
               "T": T, "Hc": Hc, "Htop": Hc + Hu, "coneGrading": grading,
               "probeZ": P["probeHeight"], "probeY": T / 2,
               "deltaT": dt_cfd, "endTime": t_stop, "writeInterval": p("writeInterval")}
        for k, v in geo.items():
            f.write("%-16s %.12g;\n" % (k, v))
        f.write("%-16s %d;\n" % ("nWidth", int(p("nWidth"))))
        f.write("%-16s %d;\n" % ("nThickness", int(P["nThickness"])))
        f.write("%-16s %d;\n" % ("nCone", nCone))
        f.write("%-16s %d;\n" % ("nUpper", int(p("nUpper"))))
        f.write("%-16s %d;\n" % ("couplingInterval", nc))
        f.write("%-16s %s;\n" % ("startTime", start_time))
        f.write("inletTable\n(\n")
        for t, v in table:
            f.write("    (%.9g (0 0 %.9g))\n" % (t, v))
        f.write(");\n")
        f.write("%-16s %.12g;\n" % ("mixingLength", 0.07 * P["hydraulicDiameter"]))
        f.write("%-16s %.12g;\n" % ("intensity", P["intensity"]))
        f.write("%-16s (%d 1 1);\n" % ("decomposition", args.np))
    with open(os.path.join(post, "schedule.dat"), "w") as f:
        f.write("# plateau velocity [m/s], window start [s], window end [s]\n")
        for v, t0, t1 in windows:
            f.write("%.6g %.9g %.9g\n" % (v, t0, t1))

    if args.map_from:
        # the set-up as the source's but for the mesh, then its state
        map_check_setup(source, map_time, post)
        map_copy(source, map_time, dt, post)

    print("spoutedBed%s: set %s, representation %s (%d spheres), %d particles (%s), cone %.4g m tall (%d cells,"
          " grading %.3g), upper %.4g m (%d cells), %d x %d cells across; DEM step"
          " %.3g s (%.0f %% of the smallest Rayleigh time %.3g s), CFD step %.3g s;"
          " schedule to %.4g s; start %s, end %.9g"
          % (" (CI)" if args.ci else "", set_name, rep,
             sum(row["n"] * row["spheres"] for row in rows), N,
             ", ".join("%s %d" % (row["name"], row["n"]) for row in present),
             Hc, nCone, grading, Hu, int(p("nUpper")), int(p("nWidth")),
             int(P["nThickness"]), dt, 100 * dt / min(dt_r), min(dt_r), dt_cfd,
             t_end, start_time, t_stop))


if __name__ == "__main__":
    main()
