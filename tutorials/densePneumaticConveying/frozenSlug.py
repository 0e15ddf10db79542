#!/usr/bin/env python3
"""densePneumaticConveying: the gas force on a frozen slug on several CFD
meshes (why the 'refined' sensitivity variant slows the slug).

    ./frozenSlug.py [--variants coarse,base,refined,refined16] [--end 0.1]
                    [--work DIR] [--out DIR] [--table-only]

One packing (DEM/in.pack of the demStep10 base, np 2) is frozen in every
mesh: the coupled DEM script gets 'unfix integrate' and 'velocity all set
0 0 0' (foamDEM then keeps the particles fixed and integrates the drag
explicitly), and pisoDEMFoam runs serially to END (the controller holds
the mean gas velocity near 3 m/s from about 0.03 s on). At the last frame
it reports, per mesh:
  - the fluid volume of the mesh (checkMesh) against pi R^2 L;
  - the controller's mean gas velocity and force;
  - the axial gas force on the slug's particles (the reference's slug
    detection) and on the layer's, and the slug's force per unit mean gas
    velocity;
  - in the slug's core (0.12 m inside either face): the mean void
    fraction and the gas flux eps u_x in seven bands of height.

The meshes (each one change from the tutorial's O-grid, as sensitivity.py):
  coarse     2 x 2 core cells, 1 radial, 20 mm along x (8-facet wall)
  base       the tutorial: 4 x 4, 2 radial, 10 mm (16 facets, 0.00540 m^3,
             the reference mesh's fluid volume)
  refined    8 x 8, 4 radial, 5 mm (32 facets, nearer the cylinder)
  refined16  as refined inside the base's 16-facet wall (sensitivity.py
             wall_polygon): the cell size alone
The refined meshes run with couplingInterval 10 (CFD step 1.25e-4 s):
at the tutorial's 5e-4 s the frozen slug's fluid Courant number reached
2.3 and PISO diverged at t = 0.0115 s.

Writes OUT/frozenSlug.dat and OUT/frozenSlug.md (default
results/frozenSlug).
"""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", os.path.join(HERE, "../..")), "python"))
import sensitivity as sens  # noqa: E402
from foamdem import caseio, slug  # noqa: E402


def v_coarse(case):
    sens.parameter(case, "nSquare", 2)
    sens.parameter(case, "nRadial", 1)
    sens.parameter(case, "cellLength", 0.02)


MESHES = [
    ("coarse", v_coarse, 40),
    ("base", None, 40),
    ("refined", sens.v_refined, 10),
    ("refined16", sens.v_refined16, 10),
]


def run(cmd, case, log):
    with open(os.path.join(case, log), "w") as f:
        r = subprocess.run(cmd, cwd=case, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode:
        sys.exit("frozenSlug.py: %s failed in %s (see %s)" % (cmd[0], case, log))


def field(path):
    """internalField of a volScalarField or volVectorField (ascii or binary)"""
    with open(path, "rb") as f:
        raw = f.read()
    m = re.search(rb"internalField\s+nonuniform\s+List<(\w+)>\s*\n?(\d+)\s*\n?\(", raw)
    if not m:
        raise ValueError("%s: no nonuniform internalField" % path)
    n, k = int(m.group(2)), (3 if m.group(1) == b"vector" else 1)
    if re.search(rb"format\s+binary", raw[:2000]):
        a = np.frombuffer(raw[m.end():m.end() + 8 * n * k], dtype="<f8")
    else:
        body = raw[m.end():].decode()
        body = body[:body.index("\n)")]
        a = np.array(body.replace("(", " ").replace(")", " ").split(), float)
    return a.reshape(n, 3) if k == 3 else a


# a run's outputs, left out of the copies (prepare.py refuses a case that
# has run)
RUN_OUTPUTS = shutil.ignore_patterns("results", "VTK", "processor*", "log.*", "post", "restart",
                                     "postProcessing", "[1-9]*", "0.[0-9]*")


def pack(work, np_):
    case = os.path.join(work, "pack")
    if os.path.exists(os.path.join(case, "DEM/post/packed.restart")):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(HERE, case, ignore=RUN_OUTPUTS)
    sens.v_demStep10(case)
    run([sys.executable, "prepare.py", "--np", str(np_)], case, "log.prepare")
    t0 = time.time()
    cmd = ["foamDEMLiggghts", "-in", "DEM/in.pack", "-log", "DEM/log.pack",
           "-screen", "DEM/post/screen.pack"]
    if np_ > 1:
        cmd = ["mpirun", "--allow-run-as-root", "-np", str(np_)] + cmd
    run(cmd, case, "log.packing")
    print("packing: %.0f s" % (time.time() - t0))
    return case


def frozen(work, packed, name, edit, interval, end):
    case = os.path.join(work, name)
    if os.path.exists(os.path.join(case, "done")):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(HERE, case, ignore=RUN_OUTPUTS)
    sens.v_demStep10(case)
    if edit:
        edit(case)
    sens.coupling(case, r"^couplingInterval\s+\d+;", "couplingInterval    %d;" % interval)
    sens.sed(os.path.join(case, "system/controlDict"), r"^deltaT\s+\S+;",
             "deltaT          %.12g;" % (1.25e-5 * interval))
    run([sys.executable, "prepare.py", "--np", "1"], case, "log.prepare")
    sens.sed(os.path.join(case, "DEM/post/setupDict"), r"^endTime .*", "endTime        %g;" % end)
    sens.sed(os.path.join(case, "DEM/post/setupDict"), r"^writeInterval .*",
             "writeInterval  %g;" % end)
    shutil.copy(os.path.join(packed, "DEM/post/packed.restart"), os.path.join(case, "DEM/post/"))
    sens.sed(os.path.join(case, "DEM/in.liggghts"), r"^(include\s+DEM/contacts)$",
             r"\1\nunfix           integrate\nvelocity        all set 0 0 0")
    run(["blockMesh"], case, "log.blockMesh")
    run(["checkMesh"], case, "log.checkMesh")
    t0 = time.time()
    run(["pisoDEMFoam"], case, "log.pisoDEMFoam")
    stopped = caseio.stopped_by_signal(os.path.join(case, "log.pisoDEMFoam"))
    if stopped:
        sys.exit("frozenSlug.py: %s in %s: run it again" % (stopped, case))
    with open(os.path.join(case, "done"), "w") as f:
        f.write("%.0f\n" % (time.time() - t0))
    return case


def analyse(case):
    """The figures of one frozen run (see the module's docstring)"""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    R, L, dp = 0.5 * float(par["pipeDiameter"]), float(par["pipeLength"]), float(par["dp"])
    dumps = sorted(glob.glob(os.path.join(case, "DEM/post/dump/particles.*.txt")),
                   key=lambda f: int(re.findall(r"\.(\d+)\.txt$", f)[0]))
    _, d = slug.read_dump(dumps[-1])
    rear, front, length, _ = slug.reference_slug(d[:, 1], -L / 2, L, R, dp, 0.45, 5)
    inside = np.mod(d[:, 1] - rear, L) < length
    fgas = d[:, 8]
    ctl = slug.read_controller(case)[-1]
    volume = float(re.search(r"Total volume = (\S+?)\.?\s", open(
        os.path.join(case, "log.checkMesh")).read()).group(1))
    t = caseio.time_dirs(case)[-1]
    tdir = os.path.join(case, t)
    for func in ("writeCellCentres", "writeCellVolumes"):
        subprocess.run(["postProcess", "-case", case, "-time", t, "-func", func],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    C, V = field(os.path.join(tdir, "C")), field(os.path.join(tdir, "V"))
    U, eps = field(os.path.join(tdir, "U")), field(os.path.join(tdir, "voidfraction"))
    cx = np.mod(C[:, 0] - rear, L)
    core = (cx > 0.12) & (cx < length - 0.12)
    out = {
        "t": float(t), "cells": C.shape[0], "volume": volume,
        "volumeOverCylinder": volume / (math.pi * R * R * L),
        "Umean": ctl[1], "force": ctl[4],
        "fSlug": fgas[inside].sum(), "fLayer": fgas[~inside].sum(),
        "nSlug": int(inside.sum()), "slugLength": length,
        "epsCore": np.sum(eps[core] * V[core]) / V[core].sum(),
        "fluxCore": np.sum(eps[core] * U[core, 0] * V[core]) / V[core].sum(),
        "wall": float(open(os.path.join(case, "done")).read()),
    }
    out["fSlugPerU"] = out["fSlug"] / out["Umean"]
    edges = np.linspace(-R, R, 8)
    bands = []
    for a, b in zip(edges[:-1], edges[1:]):
        s = core & (C[:, 1] >= a) & (C[:, 1] < b)
        if s.any():
            w = V[s]
            bands.append((a, b, np.sum(eps[s] * w) / w.sum(),
                          np.sum(eps[s] * U[s, 0] * w) / w.sum(),
                          np.sum(eps[s] * U[s, 0] * w) / np.sum(eps[core] * U[core, 0] * V[core])))
    out["bands"] = bands
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--variants", default=",".join(m[0] for m in MESHES))
    ap.add_argument("--end", type=float, default=0.1)
    ap.add_argument("--np", type=int, default=2, help="processes of the packing stage")
    ap.add_argument("--work", default=os.path.join(HERE, "results", "frozenSlug", "runs"))
    ap.add_argument("--out", default=os.path.join(HERE, "results", "frozenSlug"))
    ap.add_argument("--table-only", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    os.makedirs(a.out, exist_ok=True)
    chosen = a.variants.split(",")
    unknown = set(chosen) - set(m[0] for m in MESHES)
    if unknown:
        sys.exit("frozenSlug.py: unknown variant(s) %s; valid: %s"
                 % (", ".join(sorted(unknown)), ", ".join(m[0] for m in MESHES)))
    packed = None if a.table_only else pack(a.work, a.np)
    rows = []
    for name, edit, interval in MESHES:
        if name not in chosen:
            continue
        if not a.table_only:
            frozen(a.work, packed, name, edit, interval, a.end)
        case = os.path.join(a.work, name)
        if os.path.exists(os.path.join(case, "done")):
            rows.append((name, analyse(case)))
    if not rows:
        sys.exit("frozenSlug.py: no finished run in %s" % a.work)
    ref = dict(rows).get("base")
    with open(os.path.join(a.out, "frozenSlug.dat"), "w") as f:
        f.write("# mesh cells fluidVolume_m3 volumeOverCylinder Umean_m_s force_N_m3 "
                "fSlug_N fLayer_N fSlugPerU_N_s_m epsSlugCore fluxSlugCore_m_s wall_s\n")
        for name, r in rows:
            f.write("%s %d %.7g %.5f %.5f %.6g %.5g %.5g %.5g %.5f %.5f %.0f\n"
                    % (name, r["cells"], r["volume"], r["volumeOverCylinder"], r["Umean"],
                       r["force"], r["fSlug"], r["fLayer"], r["fSlugPerU"], r["epsCore"],
                       r["fluxCore"], r["wall"]))
    with open(os.path.join(a.out, "frozenSlug.md"), "w") as f:
        f.write("Frozen slug (one packing, %d particles in the slug), t = %g s; "
                "`./frozenSlug.py`.\n\n" % (rows[0][1]["nSlug"], rows[0][1]["t"]))
        f.write("| mesh | cells | fluid volume / pi R^2 L | mean gas velocity | gas force on "
                "the slug | per mean gas velocity | change | slug core eps | wall |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for name, r in rows:
            change = ("%+.1f %%" % (100 * (r["fSlugPerU"] / ref["fSlugPerU"] - 1))) if ref else ""
            f.write("| %s | %d | %.4f | %.3f m/s | %.2f N | %.2f N s/m | %s | %.3f | %.0f s |\n"
                    % (name, r["cells"], r["volumeOverCylinder"], r["Umean"], r["fSlug"],
                       r["fSlugPerU"], change, r["epsCore"], r["wall"]))
        f.write("\nGas flux in the slug core by height (eps, eps u_x in m/s, share of the "
                "core's flux):\n\n| band y [mm] | " + " | ".join(n for n, _ in rows) + " |\n")
        f.write("|---|" + "---|" * len(rows) + "\n")
        edges = np.linspace(-42, 42, 8)
        for i in range(7):
            cells = []
            for _, r in rows:
                b = [q for q in r["bands"] if abs(1e3 * q[0] - edges[i]) < 1e-6]
                cells.append("%.3f, %.2f, %.3f" % b[0][2:] if b else "-")
            f.write("| %+.0f..%+.0f | %s |\n" % (edges[i], edges[i + 1], " | ".join(cells)))
    print(open(os.path.join(a.out, "frozenSlug.md")).read())
    return 0


if __name__ == "__main__":
    sys.exit(main())
