#!/usr/bin/python3
"""ErgunPackedBed with every dense drag law against Ergun.

    ./everyLaw.py [--laws a,b] [--ci] [--work DIR] [--out DIR] [--table-only]

Runs a copy of this tutorial per drag law (WORK/<law>, default
results/everyLaw/runs) with ./Allrun -drag LAW (the full bed, or the CI bed
with --ci), and tabulates, per law and inlet velocity, the pressure drop
between the planes against Ergun's equation at the same void fraction and
length (Ergun, 1952, with 150 and 1.75). Ergun is an independent reference
here for every law but gidaspow, whose dense branch is Ergun itself (that
row is the check of the numerics). Also given: the law's own uniform-bed
prediction against Ergun (what the correlation alone says, without the
CFD-DEM), so that the run's error splits into the law's deviation from
Ergun and foamDEM's error against the law.

Writes OUT/everyLaw.dat (one line per law and velocity) and OUT/everyLaw.md
(the table); OUT defaults to results/everyLaw.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
LAWS = ["gidaspow", "diFelice", "kochHill", "beetstra", "tenneti", "rong"]


def read_rows(summary):
    """The plateau rows of results/summary.dat as dicts by column name."""
    cols, rows, head = None, [], {}
    with open(summary) as f:
        for line in f:
            if line.startswith("# U_m_s"):
                cols = line[1:].split()
            elif line.startswith("#"):
                p = line[1:].split(None, 1)
                if len(p) == 2:
                    head[p[0]] = p[1].strip()
            elif cols and line.strip():
                rows.append(dict(zip(cols, map(float, line.split()))))
    return head, rows


def run(law, work, ci):
    case = os.path.join(work, law)
    summary = os.path.join(case, "results", "summary.dat")
    if os.path.exists(summary):
        return case, None
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(HERE, case, ignore=shutil.ignore_patterns(
        "results", "VTK", "processor*", "log.*", "post", "restart", "postProcessing",
        "[1-9]*", "0.[0-9]*"))
    # (the files an option of a run in the tutorial itself edited, put back)
    subprocess.run(["./Allclean"], cwd=case, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    cmd = ["./Allrun", "-drag", law] + (["-ci"] if ci else [])
    print("%-10s %s" % (law, " ".join(cmd)), flush=True)
    start = time.monotonic()
    with open(os.path.join(case, "log.everyLaw"), "w") as log:
        r = subprocess.run(cmd, cwd=case, stdout=log, stderr=subprocess.STDOUT)
    wall = time.monotonic() - start
    print("    %.0f s wall, Allrun exit %d" % (wall, r.returncode), flush=True)
    with open(os.path.join(case, "results", "wall_s"), "w") as f:
        f.write("%.1f\n" % wall)
    return case, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--laws", help="comma list (default: %s)" % ",".join(LAWS))
    ap.add_argument("--ci", action="store_true", help="the CI bed (3 000 spheres)")
    ap.add_argument("--work", default=os.path.join(HERE, "results", "everyLaw", "runs"))
    ap.add_argument("--out", default=os.path.join(HERE, "results", "everyLaw"))
    ap.add_argument("--table-only", action="store_true")
    args = ap.parse_args()
    laws = args.laws.split(",") if args.laws else LAWS
    for law in laws:
        if law not in LAWS:
            sys.exit("everyLaw.py: unknown law '%s'; valid: %s" % (law, ", ".join(LAWS)))
    os.makedirs(args.out, exist_ok=True)

    table = []
    for law in laws:
        case = os.path.join(args.work, law)
        if not args.table_only:
            run(law, args.work, args.ci)
        summary = os.path.join(case, "results", "summary.dat")
        if not os.path.exists(summary):
            print("%s: no %s" % (law, summary))
            continue
        head, rows = read_rows(summary)
        wall_file = os.path.join(case, "results", "wall_s")
        wall = float(open(wall_file).read()) if os.path.exists(wall_file) else float("nan")
        table.append((law, head, rows, wall))

    dat = os.path.join(args.out, "everyLaw.dat")
    md = os.path.join(args.out, "everyLaw.md")
    with open(dat, "w") as f, open(md, "w") as g:
        f.write("# ErgunPackedBed (%s bed), pressure drop between two planes inside a frozen"
                " bed, per drag law, against Ergun's equation at the planes' void fraction\n"
                % ("CI" if args.ci else "full"))
        f.write("# dP_Pa: foamDEM; dP_Ergun_Pa: Ergun; errorVsErgun = dP/dP_Ergun - 1;"
                " dP_law_Pa: the law's own uniform-bed prediction; lawVsErgun ="
                " dP_law/dP_Ergun - 1; errorVsLaw = dP/dP_law - 1; wall_s: the whole"
                " Allrun (packing + coupled + check)\n")
        f.write("# law U_m_s eps dP_Pa dP_Ergun_Pa errorVsErgun dP_law_Pa lawVsErgun"
                " errorVsLaw wall_s\n")
        g.write("| law | U (m/s) | ε | ΔP foamDEM (Pa) | ΔP Ergun (Pa) | foamDEM vs Ergun"
                " | law's own prediction vs Ergun | foamDEM vs the law | wall (s) |\n")
        g.write("|---|---|---|---|---|---|---|---|---|\n")
        for law, head, rows, wall in table:
            for r in rows:
                lawpred = r["dP_Ergun_Pa"]   # the law's own prediction (Ergun for gidaspow)
                f.write("%-10s %5.2f %.5f %10.4f %10.4f %+9.4f %10.4f %+9.4f %+9.4f %7.1f\n"
                        % (law, r["U_m_s"], r["eps"], r["dP_Pa"], r["dP_ErgunLaw_Pa"],
                           r["errorVsErgun"], lawpred, lawpred / r["dP_ErgunLaw_Pa"] - 1,
                           r["error"], wall))
                g.write("| %s | %.1f | %.4f | %.2f | %.2f | %+.1f %% | %+.1f %% | %+.2f %% | %.0f |\n"
                        % (law, r["U_m_s"], r["eps"], r["dP_Pa"], r["dP_ErgunLaw_Pa"],
                           100 * r["errorVsErgun"], 100 * (lawpred / r["dP_ErgunLaw_Pa"] - 1),
                           100 * r["error"], wall))
    print("Table: %s\n       %s" % (dat, md))
    print(open(md).read())
    return 0


if __name__ == "__main__":
    sys.exit(main())
