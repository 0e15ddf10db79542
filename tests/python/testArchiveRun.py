#!/usr/bin/python3
"""Unit test of bin/foamDEMArchiveRun pack/unpack on a synthetic decomposed
case: what a continuation needs is in the archive and nothing else (time
directories 0 and the latest in every processor, the solver's DEM restart
and step file of the latest time only, the first and the newest dump, the
two newest script restarts, the logs), and unpack gives it back; with
--bodies, the restarts that have their bodies' states beside them are left
out (and LIGGGHTS's own, and older writes' bodies), a case whose Allrun
does not rebuild restarts, a bodies' file older than its restart and a
latest write without one are refused."""
import os
import subprocess
import sys
import tarfile
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bin",
                    "foamDEMArchiveRun")
tmp = tempfile.mkdtemp()
case = os.path.join(tmp, "case")
files = ["system/controlDict", "log.pisoDEMFoam", "log.pisoDEMFoam.continue_0.5"]
for p in ("processor0", "processor1"):
    for t in ("0", "0.5", "1", "1.5"):
        files.append("%s/%s/U" % (p, t))
files.append("processor1/2/U")                # only on one processor: not a write
for t in ("0.5", "1", "1.5", "2"):
    files += ["DEM/restart/%s.restart" % t, "DEM/restart/%s.step" % t]
for s in (100, 200, 300):
    files += ["DEM/post/restart/rebuild.%d.restart" % s, "DEM/post/dump/snap.%d.txt" % s]
files += ["results/summary.dat", "VTK/x.vtk"]
for f in files:
    os.makedirs(os.path.dirname(os.path.join(case, f)), exist_ok=True)
    open(os.path.join(case, f), "w").write(f)



def tool_run(*args):
    """foamDEMArchiveRun ARGS; its output printed"""
    r = subprocess.run([sys.executable, tool] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(r.stdout.strip())
    return r


archive = os.path.join(tmp, "run.tar.xz")
r = tool_run("pack", case, archive)
check("pack exits 0", r.returncode == 0)
with tarfile.open(archive) as tar:
    names = set(tar.getnames())
want = {"system/controlDict", "log.pisoDEMFoam", "log.pisoDEMFoam.continue_0.5",
        "processor0/0/U", "processor1/0/U", "processor0/1.5/U", "processor1/1.5/U",
        "DEM/restart/1.5.restart", "DEM/restart/1.5.step",
        "DEM/post/restart/rebuild.200.restart", "DEM/post/restart/rebuild.300.restart",
        "DEM/post/dump/snap.100.txt", "DEM/post/dump/snap.300.txt"}
check("the archive holds what a continuation needs", want <= names, str(sorted(want - names)))
unwanted = {"processor0/1/U", "processor1/2/U", "DEM/restart/1.restart",
            "DEM/restart/2.restart", "DEM/restart/1.step", "DEM/post/dump/snap.200.txt",
            "DEM/post/restart/rebuild.100.restart", "results/summary.dat", "VTK/x.vtk"}
check("and not the older writes, restarts and dumps", not (unwanted & names),
      str(sorted(unwanted & names)))
out = os.path.join(tmp, "unpacked")
r = tool_run("unpack", archive, out)
check("unpack gives the files back",
      r.returncode == 0 and all(open(os.path.join(out, f)).read() == f for f in want))

# --bodies: a restart with its bodies' states beside it is carried by them
for f in ("DEM/restart/1.5.bodies", "DEM/restart/1.bodies", "DEM/post/filled.restart",
          "DEM/post/filled.bodies", "DEM/post/fill.restart"):
    open(os.path.join(case, f), "w").write(f)
archive = os.path.join(tmp, "bodies.tar.xz")
# (only for a case whose Allrun rebuilds restarts from them)
r = tool_run("pack", case, archive, "--bodies")
check("--bodies refuses a case whose Allrun does not rebuild restarts",
      r.returncode != 0 and "does not rebuild" in r.stdout)
open(os.path.join(case, "Allrun"), "w").write("foamDEMLiggghts -readBodies X -restartOut Y\n")
r = tool_run("pack", case, archive, "--bodies")
check("pack --bodies exits 0", r.returncode == 0)
with tarfile.open(archive) as tar:
    names = set(tar.getnames())
want = {"DEM/restart/1.5.bodies", "DEM/restart/1.5.step", "DEM/post/filled.bodies",
        "DEM/post/fill.restart", "processor0/1.5/U", "log.pisoDEMFoam"}
check("--bodies: the bodies' states, the step, a restart without bodies and the rest",
      want <= names, str(sorted(want - names)))
unwanted = {"DEM/restart/1.5.restart", "DEM/post/filled.restart", "DEM/restart/1.bodies",
            "DEM/post/restart/rebuild.200.restart", "DEM/post/restart/rebuild.300.restart"}
check("--bodies: not the restarts the bodies carry, nor LIGGGHTS's own",
      not (unwanted & names), str(sorted(unwanted & names)))
check("--bodies: the restart kept is named", "DEM/post/fill.restart kept" in r.stdout)

# a bodies' file older than its restart (a fill that went on) is refused
os.utime(os.path.join(case, "DEM/post/filled.bodies"), (1e9, 1e9))
r = tool_run("pack", case, archive, "--bodies")
check("--bodies refuses bodies older than their restart",
      r.returncode != 0 and "filled.bodies is older than" in r.stdout)
os.utime(os.path.join(case, "DEM/post/filled.bodies"))

# and a latest write without them
os.remove(os.path.join(case, "DEM/restart/1.5.bodies"))
r = tool_run("pack", case, archive, "--bodies")
check("--bodies refuses a latest write without its bodies' states",
      r.returncode != 0 and "has no bodies' states" in r.stdout)
finish()
