#!/usr/bin/env python3
"""Stability suite: the DEM restart a NaN/Inf stop leaves with
failureDEMRestart lastGoodStep is the DEM state of the last good step, the
step whose fluid fields it writes (demCoupling::stopWithLastGoodState).

    checkPairedRestart.py CASE GOODTIME STEP

CASE/DEM/restart/GOODTIME.restart must exist beside CASE/GOODTIME/U (a
parallel run's CASE/processor*/GOODTIME/U);
LIGGGHTS (liggghts, serial) reads it and must find itself at DEM step STEP
with every particle of the DEM's own dump CASE/DEM/post/particles.dump at
STEP, at the same velocity to 1e-10 (relative). The .step file beside the
restart must say STEP too. Exit 0 on success.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkFailureParticles import distance, dump_frames  # noqa: E402

INPUT = """read_restart    %s
print           "PAIRED_STEP $(step)"
write_dump      all custom %s id vx vy vz modify sort id format "%%d %%.17g %%.17g %%.17g"
"""


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    case, good, step = os.path.abspath(sys.argv[1]), sys.argv[2], int(sys.argv[3])
    restart = os.path.join(case, "DEM", "restart", good + ".restart")
    fields = [os.path.join(case, good, "U")]
    if os.path.isdir(os.path.join(case, "processor0")):
        # a parallel run writes the fields per processor
        fields = [os.path.join(case, p, good, "U") for p in sorted(os.listdir(case))
                  if p.startswith("processor")]
    for f in [restart] + fields:
        if not os.path.isfile(f):
            print("FAIL: %s not written" % f)
            return 1
    written = int(open(os.path.join(case, "DEM", "restart", good + ".step")).read())
    work = os.path.join(case, "pairedRestartCheck")
    os.makedirs(work, exist_ok=True)
    dump = os.path.join(work, "atoms.dump")
    with open(os.path.join(work, "in.read"), "w") as f:
        f.write(INPUT % (restart, dump))
    out = subprocess.run(["liggghts", "-in", "in.read", "-log", "log.read"], cwd=work,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True).stdout
    lines = [l for l in out.splitlines() if l.startswith("PAIRED_STEP")]
    if not lines or not os.path.isfile(dump):
        print("FAIL: LIGGGHTS did not read %s:\n%s" % (restart, out[-2000:]))
        return 1
    read = int(lines[-1].split()[1])
    rows = {}
    with open(dump) as f:
        text = f.read().split("ITEM: ATOMS")[1].splitlines()[1:]
    for l in text:
        t = l.split()
        if len(t) == 4:
            rows[int(t[0])] = tuple(float(x) for x in t[1:])
    ref = dump_frames(os.path.join(case, "DEM", "post", "particles.dump")).get(step)
    if ref is None:
        print("FAIL: no DEM dump frame at step %d" % step)
        return 1
    same = sorted(rows) == sorted(ref)
    worst = max(distance(rows[i], ref[i]) / max(distance(ref[i], (0, 0, 0)), 1e-12)
                for i in ref) if same else float("inf")
    print("%s: LIGGGHTS reads step %d (the .step file %d, expected %d); %d particles,"
          " ids %s the dump's at step %d, largest relative velocity difference %.3g"
          " (allowed 1e-10)" % (restart, read, written, step, len(rows),
                                 "equal to" if same else "NOT equal to", step, worst))
    ok = read == step and written == step and same and worst <= 1e-10
    print("paired DEM restart: %s" % ("ok" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
