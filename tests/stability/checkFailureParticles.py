#!/usr/bin/env python3
"""Stability suite: the particles a NaN/Inf stop writes belong to the same
step as the fluid fields it writes (demCoupling::stopWithLastGoodState,
writeParticlesAtFailure).

    checkFailureParticles.py CASE GOODTIME STEP [NEXTSTEP]

CASE/GOODTIME/lagrangian/particles/{U,demId} (the cloud written at the
stop) must hold every particle of the DEM's own dump CASE/DEM/post/
particles.dump at DEM step STEP (the last good coupling step), with the
same velocity to 1e-10 (relative; the case writes 16 digits). If the dump
has a finite frame at NEXTSTEP (the failed step), the cloud must differ
from it, so that the check tells the two steps apart. Exit 0 on success.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "python"))
from foamdem import caseio  # noqa: E402

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf", re.I)


def field_numbers(path):
    """The numbers of an ASCII OpenFOAM IOField after its header: the
    count first, then the entries' components."""
    with open(path) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r"FoamFile\s*\{[^}]*\}", " ", text, flags=re.S)
    return [float(t) for t in NUMBER.findall(text)]


def cloud(case, time):
    d = os.path.join(case, time, "lagrangian", "particles")
    u, ids = field_numbers(os.path.join(d, "U")), field_numbers(os.path.join(d, "demId"))
    n = int(ids[0])
    if int(u[0]) != n or len(u) != 1 + 3 * n or len(ids) != 1 + n:
        sys.exit("FAIL: %s: U and demId do not hold the same %d particles" % (d, n))
    return dict((int(ids[1 + k]), tuple(u[1 + 3 * k:4 + 3 * k])) for k in range(n))


def dump_frames(path):
    """{step: {id: (vx, vy, vz)}} of the stability base's particle dump
    (columns id x y z vx vy vz radius mass; caseio.dump_frames reads it)."""
    return dict((step, dict((int(r[0]), tuple(r[4:7])) for r in rows))
                for step, rows in caseio.dump_frames(path))


def distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    case, good, step = sys.argv[1], sys.argv[2], int(sys.argv[3])
    nxt = int(sys.argv[4]) if len(sys.argv) == 5 else None
    c = cloud(case, good)
    frames = dump_frames(os.path.join(case, "DEM", "post", "particles.dump"))
    if step not in frames:
        sys.exit("FAIL: no DEM dump frame at step %d (frames: %s)" % (step, sorted(frames)[-5:]))
    ref = frames[step]
    ok = True
    if sorted(c) != sorted(ref):
        print("FAIL: the cloud at %s holds ids %s, the DEM at step %d %s"
              % (good, sorted(c)[:10], step, sorted(ref)[:10]))
        return 1
    worst = max(distance(c[i], ref[i]) / max(math.sqrt(sum(v * v for v in ref[i])), 1e-12)
                for i in c)
    print("cloud at %s against the DEM at step %d: %d particles, largest relative"
          " velocity difference %.3g (allowed 1e-10)" % (good, step, len(c), worst))
    ok = worst <= 1e-10
    if nxt is not None and nxt in frames:
        nf = frames[nxt]
        finite = all(all(math.isfinite(x) for x in v) for v in nf.values())
        if finite:
            sep = max(distance(c[i], nf[i]) / max(math.sqrt(sum(v * v for v in nf[i])), 1e-12)
                      for i in c)
            print("against the failed step %d: largest relative difference %.3g" % (nxt, sep))
            if sep <= 1e-10:
                print("FAIL: the check cannot tell the last good step from the failed one")
                ok = False
        else:
            print("the failed step %d has non-finite velocities in the DEM dump" % nxt)
    print("particles of the last good step: %s" % ("ok" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
