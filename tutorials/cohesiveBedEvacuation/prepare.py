#!/usr/bin/python3
"""cohesiveBedEvacuation set-up: from constant/evacuationProperties write

  constant/triSurface/{walls,supply,vent}.stl   the fluid volume's surface,
                          by patch (snappyHexMesh); turned about z
  DEM/post/walls.stl      the DEM's walls: walls + supply (the bed rests on
                          the porous floor), no wall over the vent
  DEM/post/vent.stl       the vent's square (fix massflow/mesh deletes the
                          particles that cross it)
  DEM/post/setup.lig      LIGGGHTS variables (steps, materials, region)
  DEM/post/setupDict      blockMesh, snappyHexMesh, controlDict and 0/
                          entries

--ci        the CI variant (ci* entries)
--np N      processes (DEM grid and CFD decomposition, N slabs along x)
--end T     stop the coupled run at T instead of endTime (the solver writes
            there: Allrun -continue goes on to endTime, or to a later -end)
--continue  only set the end of a continued run (Allrun -continue) in
            DEM/post/setupDict: --end T, after the run's latest write, or the
            case's endTime; -ci must be the run's own
A new run refuses a case that has run (its writes, DEM restarts, logs, the
fill's bed or history): ./Allclean first.
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

PROPS = "constant/evacuationProperties"


def read_props(case, ci=False):
    """The entries of constant/evacuationProperties; with ci, each ciName
    entry replaces its counterpart name"""
    text = caseio._strip_comments(open(os.path.join(case, PROPS)).read())
    P = {m.group(1): float(m.group(2)) for m in
         re.finditer(r"(?m)^\s*(\w+)\s+([-+0-9.eE]+)\s*;", text)}
    if ci:
        for k in list(P):
            if k.startswith("ci") and len(k) > 2 and k[2].isupper():
                P[k[2].lower() + k[3:]] = P[k]
    return P


class Surface:
    """Triangles with outward normals, collected by region."""

    def __init__(self):
        self.regions = {}

    def tri(self, region, a, b, c):
        self.regions.setdefault(region, []).append((a, b, c))

    def quad(self, region, a, b, c, d, outward):
        """a b c d in order around the quad; flipped if its normal does not
        point along 'outward'"""
        n = _cross(_sub(b, a), _sub(c, a))
        if _dot(n, outward) < 0:
            a, b, c, d = d, c, b, a
        self.tri(region, a, b, c)
        self.tri(region, a, c, d)

    def rect(self, region, axis, c, u, v, outward_sign):
        """The rectangle axis = c, u0 <= first other coordinate <= u1,
        v0 <= second <= v1 (the other axes in x, y, z order)"""
        o = [i for i in range(3) if i != axis]

        def pt(a, b):
            p = [0.0, 0.0, 0.0]
            p[axis], p[o[0]], p[o[1]] = c, a, b
            return tuple(p)
        n = [0.0, 0.0, 0.0]
        n[axis] = outward_sign
        self.quad(region, pt(u[0], v[0]), pt(u[1], v[0]), pt(u[1], v[1]),
                  pt(u[0], v[1]), n)

    def rect_with_hole(self, region, axis, c, u, v, hu, hv, outward_sign,
                       hole_region=None):
        """A rectangle less the rectangle hu x hv inside it (four pieces);
        the hole itself goes to hole_region if given"""
        for uu, vv in (((u[0], hu[0]), v), ((hu[1], u[1]), v),
                       (hu, (v[0], hv[0])), (hu, (hv[1], v[1]))):
            if uu[1] - uu[0] > 1e-12 and vv[1] - vv[0] > 1e-12:
                self.rect(region, axis, c, uu, vv, outward_sign)
        if hole_region:
            self.rect(hole_region, axis, c, hu, hv, outward_sign)

    def turned(self, deg):
        c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
        out = Surface()
        for r, tris in self.regions.items():
            out.regions[r] = [tuple((c * p[0] - s * p[1], s * p[0] + c * p[1], p[2])
                                    for p in t) for t in tris]
        return out

    def write(self, path, regions, solid=None):
        """regions into one STL file: one solid per region, or all under
        the single name 'solid'"""
        with open(path, "w") as f:
            groups = [(solid, regions)] if solid else [(r, [r]) for r in regions]
            for name, rs in groups:
                f.write("solid %s\n" % name)
                for r in rs:
                    for t in self.regions.get(r, []):
                        n = _unit(_cross(_sub(t[1], t[0]), _sub(t[2], t[0])))
                        f.write("  facet normal %.6g %.6g %.6g\n    outer loop\n" % n)
                        for p in t:
                            f.write("      vertex %.9g %.9g %.9g\n" % p)
                        f.write("    endloop\n  endfacet\n")
                f.write("endsolid %s\n" % name)

    def volume(self, regions):
        """Enclosed volume (divergence theorem): a check that the surface is
        closed and its normals point out"""
        v = 0.0
        for r in regions:
            for a, b, c in self.regions.get(r, []):
                v += _dot(a, _cross(b, c)) / 6
        return v


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def _unit(a):
    m = math.sqrt(_dot(a, a)) or 1.0
    return (a[0] / m, a[1] / m, a[2] / m)


def geometry(P):
    """The fluid volume's surface, before the turn; regions walls, supply,
    vent. Returns (surface, dict of derived sizes)."""
    R, Hc = P["chamberRadius"], P["chamberHeight"]
    a, Ht, L = P["tubeWidth"], P["tubeTop"], P["ductHalfLength"]
    B, v = P["collectorSize"], P["ventWidth"]
    n = int(P["nSides"])
    h = a / 2
    S = Surface()

    # Chamber: the side, the floor (supply), the lid less the tube's square.
    # Angles include the square's corners, so that the lid is quads between
    # the circle and the square at the same angles.
    angles = sorted(set(round(t, 12) for t in
                        [2 * math.pi * i / n for i in range(n)] +
                        [math.pi / 4 * (2 * k + 1) for k in range(4)]))
    ring = [(R * math.cos(t), R * math.sin(t)) for t in angles]

    def on_square(t):
        c, s = math.cos(t), math.sin(t)
        f = h / max(abs(c), abs(s))
        return (f * c, f * s)
    sq = [on_square(t) for t in angles]
    for i in range(len(angles)):
        j = (i + 1) % len(angles)
        (x0, y0), (x1, y1) = ring[i], ring[j]
        mid = ((x0 + x1) / 2, (y0 + y1) / 2, 0.0)
        S.quad("walls", (x0, y0, 0.0), (x1, y1, 0.0), (x1, y1, Hc), (x0, y0, Hc), mid)
        S.tri("supply", (0.0, 0.0, 0.0), (x1, y1, 0.0), (x0, y0, 0.0))
        (s0, t0), (s1, t1) = sq[i], sq[j]
        S.quad("walls", (s0, t0, Hc), (x0, y0, Hc), (x1, y1, Hc), (s1, t1, Hc),
               (0.0, 0.0, 1.0))
    # Tube: four sides from the lid to the duct's floor
    S.rect("walls", 0, -h, (-h, h), (Hc, Ht), -1)
    S.rect("walls", 0, h, (-h, h), (Hc, Ht), 1)
    S.rect("walls", 1, -h, (-h, h), (Hc, Ht), -1)
    S.rect("walls", 1, h, (-h, h), (Hc, Ht), 1)
    # Duct along x: floor less the tube's square, roof, two sides
    S.rect_with_hole("walls", 2, Ht, (-L, L), (-h, h), (-h, h), (-h, h), -1)
    S.rect("walls", 2, Ht + a, (-L, L), (-h, h), 1)
    S.rect("walls", 1, -h, (-L, L), (Ht, Ht + a), -1)
    S.rect("walls", 1, h, (-L, L), (Ht, Ht + a), 1)
    # Collection chambers: cubes of side B centred on the duct's axis
    zc = Ht + h
    yB, zB = (-B / 2, B / 2), (zc - B / 2, zc + B / 2)
    duct_hole = ((-h, h), (Ht, Ht + a))
    for sign in (-1, 1):
        near, far = sign * L, sign * (L + B)
        # the wall the duct enters (outward: back toward the duct)
        S.rect_with_hole("walls", 0, near, yB, zB, duct_hole[0], duct_hole[1], -sign)
        if sign > 0:
            S.rect_with_hole("walls", 0, far, yB, zB, (-v / 2, v / 2),
                             (zc - v / 2, zc + v / 2), sign, hole_region="vent")
        else:
            S.rect("walls", 0, far, yB, zB, sign)
        xs = tuple(sorted((near, far)))
        S.rect("walls", 1, -B / 2, xs, zB, -1)
        S.rect("walls", 1, B / 2, xs, zB, 1)
        S.rect("walls", 2, zB[0], xs, yB, -1)
        S.rect("walls", 2, zB[1], xs, yB, 1)
    sizes = dict(zc=zc, zB=zB, xVent=L + B)
    return S, sizes


def continue_end(args, setup="DEM/post/setupDict"):
    """The end of a continued run, written as SETUP's endTime: --end T
    (after the run's latest write) or the case's own end (caseEndTime: a
    run stopped by -end goes on to it)."""
    if not os.path.exists(setup):
        sys.exit("prepare.py --continue: no %s: the case has not run (./Allrun)" % setup)
    caseio.check_variant(setup, args.ci)
    writes = [t for t in caseio.time_dirs("processor0" if args.np > 1 else ".")
              if float(t) > 0]
    latest = writes[-1] if writes else "0"
    if args.end is not None:
        end = caseio.check_end(args.end, latest, who="prepare.py --continue")
    else:
        try:
            end = float(caseio.foam_entry(setup, "caseEndTime"))
        except KeyError:
            return      # a set-up of an older version: its endTime as it is
        if not float(latest) < end:
            sys.exit("prepare.py --continue: the run has reached the case's end (%s s,"
                     " latest write %s): continue it to a later -end T" % (end, latest))
    text = open(setup).read()
    open(setup, "w").write(re.sub(r"(?m)^endTime .*$", "endTime %.9g;" % end, text))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--end", type=float, default=None)
    ap.add_argument("--continue", dest="cont", action="store_true")
    args = ap.parse_args()
    if args.np < 1:
        sys.exit("prepare.py: --np %d: the number of processes must be 1 or more" % args.np)
    if args.cont:
        continue_end(args)
        return
    caseio.refuse_new_run(".", ("DEM/post/packed.restart", "DEM/post/evacuation.dat",
                                "DEM/post/dump/*"))
    P = read_props(".", args.ci)
    t_stop = P["endTime"] if args.end is None else caseio.check_end(args.end, 0)

    S0, sz = geometry(P)
    vol = S0.volume(["walls", "supply", "vent"])
    R, Hc, a = P["chamberRadius"], P["chamberHeight"], P["tubeWidth"]
    expect = (math.pi * R * R * (P["nSides"] / (2 * math.pi)) *
              math.sin(2 * math.pi / P["nSides"]) * Hc  # the polygon's prism
              + a * a * (P["tubeTop"] - Hc) + a * a * 2 * P["ductHalfLength"]
              + 2 * P["collectorSize"] ** 3)
    if abs(vol / expect - 1) > 0.01:
        sys.exit("prepare.py: the surface encloses %.4g m^3, expected %.4g: "
                 "not closed or normals inward" % (vol, expect))
    S = S0.turned(P["rotation"])
    os.makedirs("constant/triSurface", exist_ok=True)
    os.makedirs("DEM/post", exist_ok=True)
    for r in ("walls", "supply", "vent"):
        S.write("constant/triSurface/%s.stl" % r, [r])
    S.write("DEM/post/walls.stl", ["walls", "supply"], solid="walls")
    S.write("DEM/post/vent.stl", ["vent"], solid="vent")

    # Background mesh: the turned geometry's bounding box plus a cell
    pts = [q for tris in S.regions.values() for t in tris for q in t]
    cell = P["backgroundCell"]
    lo = [min(q[i] for q in pts) - cell for i in range(3)]
    hi = [max(q[i] for q in pts) + cell for i in range(3)]
    ncell = [max(1, int(math.ceil((hi[i] - lo[i]) / cell))) for i in range(3)]
    hi = [lo[i] + ncell[i] * cell for i in range(3)]
    # A point inside the chamber, off every cell face
    th = math.radians(P["rotation"])
    x0, y0, z0 = 0.37 * R, 0.23 * R, 0.61 * Hc
    inside = (math.cos(th) * x0 - math.sin(th) * y0,
              math.sin(th) * x0 + math.cos(th) * y0, z0)
    # Time steps: the DEM step at rayleighFraction of the Rayleigh time, the
    # CFD step couplingInterval DEM steps, the write interval a whole number
    # of CFD steps
    r = P["diameter"] / 2
    G = P["youngsModulus"] / (2 * (1 + P["poissonsRatio"]))
    t_r = math.pi * r * math.sqrt(P["density"] / G) / (0.1631 * P["poissonsRatio"] + 0.8766)
    nc = int(P["couplingInterval"])
    n_write = int(math.ceil(P["writeInterval"] / (nc * P["rayleighFraction"] * t_r)))
    dt_cfd = P["writeInterval"] / n_write
    dt = dt_cfd / nc
    with open("DEM/post/setupDict", "w") as f:
        f.write("// written by prepare.py from %s%s\n" % (PROPS, " (ci)" if args.ci else ""))
        f.write("variant %s;\n" % caseio.variant(args.ci))
        f.write("xMin %.9g;\nyMin %.9g;\nzMin %.9g;\n" % tuple(lo))
        f.write("xMax %.9g;\nyMax %.9g;\nzMax %.9g;\n" % tuple(hi))
        f.write("nx %d;\nny %d;\nnz %d;\n" % tuple(ncell))
        f.write("surfaceLevel %d;\n" % int(P["surfaceLevel"]))
        f.write("insidePoint (%.9g %.9g %.9g);\n" % inside)
        f.write("endTime %.9g;\ndeltaT %.12g;\nwriteInterval %.9g;\n"
                % (t_stop, dt_cfd, P["writeInterval"]))
        # the case's own end, which Allrun -continue goes on to without -end
        f.write("caseEndTime %.9g;\n" % P["endTime"])
    # Gas at the boundaries (kinematic), k and epsilon at the supply
    rho_g = P["rhoGas"]
    with open("DEM/post/setupDict", "a") as f:
        f.write("couplingInterval %d;\n" % nc)
        f.write("supplyP0 %.9g;\nventP %.9g;\n"
                % (P["supplyTotalPressure"] / rho_g, P["ventPressure"] / rho_g))
        # k and epsilon at the supply from the chamber's superficial velocity
        # at the design vent velocity (the middle of the reference's 60-70)
        u_s = 65.0 * P["ventWidth"] ** 2 / (math.pi * R * R)
        k_s = 1.5 * (P["supplyIntensity"] * u_s) ** 2
        l_m = 0.07 * 2 * R
        f.write("kSupply %.9g;\nepsilonSupply %.9g;\n"
                % (k_s, 0.09 ** 0.75 * k_s ** 1.5 / l_m))

    # DEM: the box (the geometry's bounding box plus 3 mm), materials, the
    # fill, the vent's outward direction, the regions of the time series
    d = P["diameter"]
    m = 0.003
    dem_lo = [min(q[i] for q in pts) - m for i in range(3)]
    dem_hi = [max(q[i] for q in pts) + m for i in range(3)]
    n_part = int(P["nParticles"])
    print_every = max(1, int(round(1e-3 / dt)))
    write_steps = int(round(P["writeInterval"] / dt))
    v = dict(
        nProcX=args.np,
        xlo=dem_lo[0], xhi=dem_hi[0], ylo=dem_lo[1], yhi=dem_hi[1],
        zlo=dem_lo[2], zhi=dem_hi[2],
        E=P["youngsModulus"], nu=P["poissonsRatio"], e=P["restitution"],
        mu=P["friction"], ced=P["cohesionEnergyDensity"],
        r=d / 2, rho=P["density"], skin=0.3 * d, demDt=dt,
        nParticles=n_part, insRadius=R - 0.6 * d,
        insLo=max(P["fillLow"], 0.6 * d), insHi=P["fillHeight"],
        nSettle=int(round(P["settleTime"] / dt)),
        ventNx=math.cos(th), ventNy=math.sin(th),
        chamberR=R, chamberH=Hc, tubeR=0.5 * a, tubeLo=Hc + 0.005,
        tubeHi=P["tubeTop"] - 0.005,
        printSteps=print_every, writeSteps=write_steps,
        thermoSteps=10 * print_every)
    with open("DEM/post/setup.lig", "w") as f:
        f.write("# written by prepare.py from %s%s\n" % (PROPS, " (ci)" if args.ci else ""))
        f.write("# Rayleigh time %.4g s; DEM step %.4g s (%.1f %%); CFD step %.4g s\n"
                % (t_r, dt, 100 * dt / t_r, dt_cfd))
        for k, val in v.items():
            f.write("variable %-12s equal %.10g\n" % (k, val))

    print("prepare.py: surface volume %.4g m^3 (expected %.4g); background "
          "%d x %d x %d cells of %g m" % (vol, expect, ncell[0], ncell[1], ncell[2], cell))
    print("prepare.py: %d particles of %g m; Rayleigh time %.4g s, DEM step %.4g s, "
          "CFD step %.4g s" % (n_part, d, t_r, dt, dt_cfd))


if __name__ == "__main__":
    main()
