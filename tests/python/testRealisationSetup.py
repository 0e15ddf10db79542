#!/usr/bin/python3
"""The spoutedBed set-up's realisation (tutorials/spoutedBed/prepare.py,
no solver): in a temporary copy of the tutorial,
- realisation 0 writes the insertion seed of every earlier run, 67867979
  (the 70 % set, spheres);
- realisation 2 changes that seed alone, to a prime, and every other line
  of DEM/post/templates.lig is realisation 0's;
- prepare.py --continue keeps the run's realisation (2, from
  DEM/post/particles.dat) though the dictionary says 0, and refuses
  another one on the command line (exit 1, naming the keyword);
- a realisation that is not a whole number from 0 to 10000 is refused."""
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from checks import check, finish  # noqa: E402

tutorial = os.path.join(here, "..", "..", "tutorials", "spoutedBed")
env = dict(os.environ, FOAMDEM_DIR=os.path.abspath(os.path.join(here, "..", "..")))


def prepare(case, *args):
    return subprocess.run([sys.executable, "prepare.py", "--set", "spherocylinders70"]
                          + list(args), cwd=case, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)


def templates(case):
    lines = open(os.path.join(case, "DEM", "post", "templates.lig")).read().splitlines()
    seed = [int(l.split()[3]) for l in lines if l.startswith("variable insertSeed ")]
    return seed, [l for l in lines if not l.startswith("variable insertSeed ")]


def header(case):
    return open(os.path.join(case, "DEM", "post", "particles.dat")).readline()


def is_prime(n):
    return n > 10000 and all(n % d for d in range(2, int(n ** 0.5) + 1))


with tempfile.TemporaryDirectory() as tmp:
    cases = {}
    for name in ("r0", "r2"):
        cases[name] = os.path.join(tmp, name)
        shutil.copytree(tutorial, cases[name],
                        ignore=shutil.ignore_patterns("__pycache__", "results"))
    out0 = prepare(cases["r0"])
    out2 = prepare(cases["r2"], "--realisation", "2")
    check("prepare.py runs for realisations 0 and 2", out0.returncode == 0
          and out2.returncode == 0, out0.stdout[-300:] + out2.stdout[-300:])
    (s0, rest0), (s2, rest2) = templates(cases["r0"]), templates(cases["r2"])
    check("realisation 0: the insertion seed of every earlier run (67867979)",
          s0 == [67867979], str(s0))
    check("realisation 2: another insertion seed, a prime > 10000",
          len(s2) == 1 and s2 != s0 and is_prime(s2[0]), str(s2))
    check("realisation 2: every other line of templates.lig is realisation 0's",
          rest0 == rest2)
    check("particles.dat says realisation 2 (and nothing for 0)",
          header(cases["r2"]).rstrip().endswith("; realisation 2")
          and "realisation" not in header(cases["r0"]), header(cases["r2"]))

    out = prepare(cases["r2"], "--continue")
    check("--continue keeps the run's realisation 2 (the dictionary says 0)",
          out.returncode == 0 and templates(cases["r2"])[0] == s2
          and header(cases["r2"]).rstrip().endswith("; realisation 2"),
          out.stdout[-300:] + str(templates(cases["r2"])[0]))
    out = prepare(cases["r2"], "--continue", "--realisation", "3")
    check("--continue refuses another realisation, naming it",
          out.returncode == 1 and "realisation 2" in out.stdout, out.stdout[-300:])
    for bad in ("-1", "10001"):
        out = prepare(cases["r0"], "--realisation", bad)
        check("realisation %s refused (exit 1, keyword named)" % bad,
              out.returncode == 1 and "keyword realisation" in out.stdout,
              out.stdout[-300:])
    props = os.path.join(cases["r0"], "constant", "spoutedBedProperties")
    text = open(props).read()
    open(props, "w").write(text.replace("realisation         0;", "realisation         1.5;"))
    out = prepare(cases["r0"])
    check("realisation 1.5 in the dictionary refused",
          out.returncode == 1 and "realisation 1.5" in out.stdout, out.stdout[-300:])

finish()
