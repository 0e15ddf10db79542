#!/usr/bin/python3
"""liquidFluidizedBed with every dense drag law against Richardson-Zaki.

    ./everyLaw.py [--laws a,b] [--ci] [--jobs N] [--work DIR] [--out DIR]
                  [--table-only]

Runs a copy of this tutorial per drag law (WORK/<law>, default
results/everyLaw/runs) with ./Allrun -drag LAW (the full programme, or the
CI one with --ci), N at a time (default 1; the runs are serial, so N up to
the number of cores), and tabulates, per law and velocity, the bed voidage
against Richardson & Zaki (1954) with U_t of Brown & Lawler and n of
Garside & Al-Dibouni (validate.py), and the law's own uniform-bed voidage.

Writes OUT/richardsonZaki.dat (one line per law and velocity:
law superficialVelocity_m_s voidFraction_foamDEM voidFraction_RZ, then the
std over the averaging window, the law's own voidage and the wall time of
the law's whole Allrun) and OUT/richardsonZaki.md (the table, and per law
the mean and largest |eps - eps_RZ|); OUT defaults to results/everyLaw.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
LAWS = ["diFelice", "kochHill", "beetstra", "tenneti", "rong", "gidaspow"]


def read_summary(path):
    head, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("# Richardson-Zaki:"):
                head["rz"] = line[2:].strip()
            elif line.startswith("#"):
                continue
            elif line.strip():
                v = line.split()
                rows.append({"epsAimed": float(v[0]), "U": float(v[1]), "eps": float(v[2]),
                             "std": float(v[3]), "epsMean": float(v[4]), "epsRZ": float(v[5]),
                             "error": float(v[6]), "epsLaw": float(v[7]), "dPW": float(v[8])})
    return head, rows


def start(law, work, ci):
    case = os.path.join(work, law)
    if os.path.exists(os.path.join(case, "results", "summary.dat")):
        return None
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(HERE, case, ignore=shutil.ignore_patterns(
        "results", "VTK", "processor*", "log.*", "post", "restart", "[1-9]*", "0.[0-9]*",
        "postProcessing"))
    # (the files an option of a run in the tutorial itself edited, put back)
    subprocess.run(["./Allclean"], cwd=case, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    cmd = ["./Allrun", "-drag", law] + (["-ci"] if ci else [])
    print("%-10s %s" % (law, " ".join(cmd)), flush=True)
    log = open(os.path.join(case, "log.everyLaw"), "w")
    return law, case, subprocess.Popen(cmd, cwd=case, stdout=log, stderr=subprocess.STDOUT), \
        time.monotonic()


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--laws", help="comma list (default: %s)" % ",".join(LAWS))
    ap.add_argument("--ci", action="store_true", help="the CI programme")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--work", default=os.path.join(HERE, "results", "everyLaw", "runs"))
    ap.add_argument("--out", default=os.path.join(HERE, "results", "everyLaw"))
    ap.add_argument("--table-only", action="store_true")
    args = ap.parse_args()
    laws = args.laws.split(",") if args.laws else LAWS
    for law in laws:
        if law not in LAWS:
            sys.exit("everyLaw.py: unknown law '%s'; valid: %s" % (law, ", ".join(LAWS)))
    os.makedirs(args.out, exist_ok=True)

    if not args.table_only:
        queue, running = list(laws), []
        while queue or running:
            while queue and len(running) < max(args.jobs, 1):
                job = start(queue.pop(0), args.work, args.ci)
                if job:
                    running.append(job)
            for job in list(running):
                law, case, proc, t0 = job
                if proc.poll() is not None:
                    wall = time.monotonic() - t0
                    print("%-10s %.0f s wall, Allrun exit %d" % (law, wall, proc.returncode),
                          flush=True)
                    os.makedirs(os.path.join(case, "results"), exist_ok=True)
                    with open(os.path.join(case, "results", "wall_s"), "w") as f:
                        f.write("%.1f %d\n" % (wall, args.jobs))
                    running.remove(job)
            time.sleep(2)

    table = []
    for law in laws:
        case = os.path.join(args.work, law)
        summary = os.path.join(case, "results", "summary.dat")
        if not os.path.exists(summary):
            print("%s: no %s" % (law, summary))
            continue
        head, rows = read_summary(summary)
        wf = os.path.join(case, "results", "wall_s")
        wall = float(open(wf).read().split()[0]) if os.path.exists(wf) else float("nan")
        table.append((law, head, rows, wall))

    dat = os.path.join(args.out, "richardsonZaki.dat")
    md = os.path.join(args.out, "richardsonZaki.md")
    with open(dat, "w") as f, open(md, "w") as g:
        rz = table[0][1].get("rz", "") if table else ""
        f.write("# liquidFluidizedBed (%s programme): bed voidage per drag law (model A) against"
                " Richardson-Zaki, %s\n" % ("CI" if args.ci else "full", rz))
        f.write("# voidFraction_foamDEM: the bed interior (10th-80th percentile of the particle"
                " heights), mean over the stage's averaging window; std: its standard deviation"
                " over the window; voidFraction_law: the law's own uniform-bed voidage; wall_s:"
                " the law's whole Allrun (packing + coupled + check), %d run(s) at a time on the"
                " machine\n" % args.jobs)
        f.write("# law superficialVelocity_m_s voidFraction_foamDEM voidFraction_RZ std"
                " voidFraction_law wall_s\n")
        g.write("| law | U (m/s) | ε foamDEM (std) | ε Richardson–Zaki | foamDEM − RZ"
                " | the law alone | foamDEM − the law | ΔP/W |\n|---|---|---|---|---|---|---|---|\n")
        summary = []
        for law, head, rows, wall in table:
            for r in rows:
                f.write("%-10s %.6g %.6f %.6f %.5f %.6f %.1f\n"
                        % (law, r["U"], r["eps"], r["epsRZ"], r["std"], r["epsLaw"], wall))
                g.write("| %s | %.4f | %.3f (%.3f) | %.3f | %+.3f | %.3f | %+.3f | %.3f |\n"
                        % (law, r["U"], r["eps"], r["std"], r["epsRZ"], r["error"], r["epsLaw"],
                           r["eps"] - r["epsLaw"], r["dPW"]))
            errs = [abs(r["error"]) for r in rows]
            summary.append((law, sum(errs) / len(errs), max(errs), wall))
        g.write("\n| law | mean abs(ε − ε_RZ) | largest | wall (s) |\n|---|---|---|---|\n")
        for law, mean, big, wall in sorted(summary, key=lambda s: s[1]):
            g.write("| %s | %.3f | %.3f | %.0f |\n" % (law, mean, big, wall))
    print("Table: %s\n       %s" % (dat, md))
    print(open(md).read())
    return 0


if __name__ == "__main__":
    sys.exit(main())
