"""Carry a case as a run of multisphere bodies is carried from machine to
machine (bin/foamDEMArchiveRun pack --bodies, the case deleted, unpack), for
the integration checks checkTutorialContinuation and checkFillContinuation."""
import os
import shutil
import subprocess
import sys


def _run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    print(r.stdout.rstrip())
    if r.returncode != 0:
        sys.exit("FAILED: foamDEMArchiveRun %s exited %d" % (cmd[1], r.returncode))


def carry_as_bodies(work):
    """Pack WORK with --bodies into WORK.tar.xz, delete WORK, unpack it there;
    every step's output printed, the check ended (FAILED) if one fails."""
    archiver = os.path.join(os.environ["FOAMDEM_DIR"], "bin", "foamDEMArchiveRun")
    archive = work + ".tar.xz"
    _run([archiver, "pack", work, archive, "--bodies"])
    shutil.rmtree(work)
    _run([archiver, "unpack", archive, work])
    os.remove(archive)
