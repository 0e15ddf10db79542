#!/usr/bin/python3
"""mixedBedNonSpherical checks: boundedness (void fraction within
[alphaMin, 1] and U, p, voidfraction finite at every write) and mass
conservation (the LIGGGHTS sphere count and total mass constant over the
run, the coupled body count constant at every write and equal to the
inserted count). Reports the bed's mean height before and after the flow
starts. Writes results/summary.dat; exits 1 if a check fails."""
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
    case = "."
    checks = []
    cp = os.path.join(case, "constant/couplingProperties")
    text = caseio._strip_comments(open(cp).read())
    alpha_min = float(re.search(r"alphaMin\s+([-+0-9.eE]+)", text).group(1))

    log = open(os.path.join(case, "log.liggghts")).read()
    ins = re.findall(r"a total of (\d+) particle templates \(mass ([-+0-9.eE]+)\)", log)
    n_bodies, m_inserted = int(ins[-1][0]), float(ins[-1][1])

    bed = np.loadtxt(os.path.join(case, "DEM/post/bed.dat"))
    t, nsph, mass, zmean = bed[:, 0], bed[:, 1], bed[:, 2], bed[:, 3]
    checks.append(("DEM history finite", bool(np.all(np.isfinite(bed)))))
    checks.append(("sphere count constant", bool(np.all(nsph == nsph[0]))))
    dm = float(np.max(np.abs(mass / mass[0] - 1)))
    checks.append(("sphere mass constant (1e-12)", dm < 1e-12))
    checks.append(("sphere mass = inserted mass (1e-6)", abs(mass[0] / m_inserted - 1) < 1e-6))

    vmin, vmax, counts, finite = 1.0, 0.0, [], True
    for time in caseio.time_dirs(case)[1:]:
        eps = np.array(numbers_in_field(os.path.join(case, time, "voidfraction")))
        for f in ("U", "p"):
            finite &= bool(np.all(np.isfinite(numbers_in_field(os.path.join(case, time, f)))))
        finite &= bool(np.all(np.isfinite(eps)))
        vmin, vmax = min(vmin, eps.min()), max(vmax, eps.max())
        counts.append(cloud_size(os.path.join(case, time, "lagrangian/particles/d")))
    checks.append(("U, p, voidfraction finite", finite))
    checks.append(("voidfraction in [alphaMin, 1]",
                   vmin >= alpha_min - 1e-12 and vmax <= 1 + 1e-12))
    checks.append(("body count constant = inserted", all(c == n_bodies for c in counts)))

    def zm_at(tq):
        return float(np.interp(tq, t, zmean))
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
        ("zMean_t0.25_m (settled, no flow)", "%.5f" % zm_at(0.25)),
        ("zMean_end_m", "%.5f" % zmean[-1]),
    ]
    rows += [("check: " + n, "ok" if c else "FAILED") for n, c in checks]
    rows.append(("pass", "yes" if ok else "no"))
    caseio.write_summary(".", rows)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
