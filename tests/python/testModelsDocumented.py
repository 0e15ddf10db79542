#!/usr/bin/env python3
"""doc/models.md against the code's run-time selection tables.

Every model name documented in doc/models.md must be selectable, and every
selectable model must be documented there.

What the code offers is asked of the code: for each selection keyword of
constant/couplingProperties a copy of tutorials/settlingSphere is given an
unknown name, and the solver's FatalIOError lists the valid ones
("Valid <keyword> types : N(...)"). The families are found in the sources
(defineRunTimeSelectionTable in src/foamDEM); a family with no keyword here
fails the test, so a new one cannot go unchecked. foamDEM's fvOption
(flowController) sits in OpenFOAM's own fv::option table among OpenFOAM's
options; it is found from its registration in the sources. The keywords
that choose from a fixed list (CHOICES: couplingKernel, undisturbedVelocity)
are asked the same way.

What the document offers: in every '## ' section whose heading names a
keyword in backquotes, '(`keyword`...)', the first column of each table
whose header's first cell is 'name', in backquotes.

Usage: testModelsDocumented.py WORKDIR   (etc/bashrc sourced)
"""

import glob
import os
import re
import shutil
import subprocess
import sys

ROOT = os.environ.get("FOAMDEM_DIR") or os.path.join(os.path.dirname(__file__), "..", "..")
MODELS_MD = os.path.join(ROOT, "doc", "models.md")
SRC = os.path.join(ROOT, "src", "foamDEM")

# Base class of a selection table -> keyword of couplingProperties, and the
# foamDictionary value that selects an unknown name
KEYWORDS = {
    "demEngine": ("demEngine", "noSuchModel"),
    "locateModel": ("locate", "noSuchModel"),
    "voidFractionModel": ("voidFraction", "noSuchModel"),
    "forceModel": ("forceModels", "(noSuchModel)"),
    "momentumCouplingModel": ("momentumCoupling", "noSuchModel"),
    "pressureScheme": ("pressureScheme", "noSuchModel"),
    "particleOutput": ("particleOutput", "(noSuchModel)"),
}
FV_OPTIONS = "fvOptions"

# Keywords of couplingProperties that choose from a fixed list (an Enum, not
# a selection table), with the value that is not a choice
CHOICES = {
    "couplingKernel": "noSuchKernel",
    "undisturbedVelocity": "noSuchMethod",
}


def documented(path):
    """{keyword: [names]} of the name tables of models.md."""
    names = {}
    keyword = None
    in_table = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                m = re.search(r"\(`([A-Za-z]+)`", line)
                keyword = m.group(1) if m else None
                in_table = False
                continue
            if not line.startswith("|"):
                in_table = False
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not in_table:
                if cells[0] == "name" and re.match(r"^\|[-| ]+\|?$", next(f, "")):
                    if keyword is None:
                        sys.exit("testModelsDocumented: a name table under a heading"
                                 " without a keyword: %s" % line.strip())
                    in_table = True
                    names.setdefault(keyword, [])
                continue
            m = re.match(r"^`([A-Za-z][A-Za-z0-9]*)`(\s*\(.*\))?$", cells[0])
            if not m:
                sys.exit("testModelsDocumented: first cell of a row of the %s table"
                         " is not a `name`: %s" % (keyword, line.strip()))
            names[keyword].append(m.group(1))
    return names


def source_tables():
    """Base classes that define a selection table, and foamDEM's fvOptions."""
    bases, fv = set(), set()
    for path in glob.glob(os.path.join(SRC, "**", "*.C"), recursive=True):
        if "lnInclude" in path or os.sep + "Make" + os.sep in path:
            continue
        text = open(path, encoding="utf-8").read()
        bases.update(re.findall(r"defineRunTimeSelectionTable\(\s*(\w+)\s*,", text))
        for cls in re.findall(r"addToRunTimeSelectionTable\(\s*option\s*,\s*(\w+)\s*,", text):
            header = open(path[:-2] + ".H", encoding="utf-8").read()
            m = re.search(r'TypeName\("(\w+)"\)', header)
            if not m:
                sys.exit("testModelsDocumented: no TypeName for fvOption %s in %s.H"
                         % (cls, path[:-2]))
            fv.add(m.group(1))
    return bases, fv


def valid_names(work, keyword, value):
    """The names the solver lists for an unknown 'keyword' in a tiny case."""
    case = os.path.join(work, keyword)
    shutil.copytree(os.path.join(work, "base"), case)
    subprocess.run(["foamDictionary", "constant/couplingProperties", "-entry", keyword,
                    "-set" if keyword not in CHOICES else "-add", value], cwd=case, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(case, "log.pisoDEMFoam"), "w") as log:
        status = subprocess.run(["pisoDEMFoam"], cwd=case, stdout=log,
                                stderr=subprocess.STDOUT, timeout=60).returncode
    text = open(os.path.join(case, "log.pisoDEMFoam")).read()
    m = re.search(r"Valid %s types :\s*(\d+)\s*\(([^)]*)\)" % re.escape(keyword), text)
    if status == 0 or not m:
        sys.exit("testModelsDocumented: the solver did not list the valid %s types"
                 " (exit %d); see %s" % (keyword, status, case))
    listed = m.group(2).split()
    if len(listed) != int(m.group(1)):
        sys.exit("testModelsDocumented: %s: the list has %d names, says %s"
                 % (keyword, len(listed), m.group(1)))
    return listed


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    work = os.path.abspath(sys.argv[1])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = os.path.join(work, "base")
    shutil.copytree(os.path.join(ROOT, "tutorials", "settlingSphere"), base)
    subprocess.run(["./Allclean"], cwd=base, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    subprocess.run(["blockMesh"], cwd=base, check=True, stdout=subprocess.DEVNULL)

    failures = []
    bases, fv_options = source_tables()
    for b in sorted(bases - set(KEYWORDS)):
        failures.append("selection table %s (src/foamDEM) has no keyword in this test:"
                        " add it to KEYWORDS" % b)

    selectable = {}
    for b in sorted(bases & set(KEYWORDS)):
        keyword, value = KEYWORDS[b]
        selectable[keyword] = valid_names(work, keyword, value)
    selectable[FV_OPTIONS] = sorted(fv_options)
    for keyword, value in CHOICES.items():
        selectable[keyword] = valid_names(work, keyword, value)

    docs = documented(MODELS_MD)
    print("%-18s %-6s %s" % ("keyword", "count", "selectable (code) / documented (doc/models.md)"))
    for keyword in sorted(set(selectable) | set(docs)):
        code = set(selectable.get(keyword, []))
        doc = set(docs.get(keyword, []))
        print("%-18s %-6d %s" % (keyword, len(code), " ".join(sorted(code))))
        print("%-18s %-6d %s" % ("", len(doc), " ".join(sorted(doc))))
        if keyword not in selectable:
            failures.append("doc/models.md has a name table for '%s', which selects"
                            " nothing in the code" % keyword)
            continue
        for name in sorted(code - doc):
            failures.append("%s %s is selectable but not documented in doc/models.md"
                            % (keyword, name))
        for name in sorted(doc - code):
            failures.append("%s %s is documented in doc/models.md but not selectable"
                            " (valid: %s)" % (keyword, name, " ".join(sorted(code))))
        dup = sorted({n for n in docs.get(keyword, []) if docs[keyword].count(n) > 1})
        for name in dup:
            failures.append("%s %s is documented twice" % (keyword, name))

    for f in failures:
        print("FAIL: " + f)
    if failures:
        sys.exit(1)
    print("doc/models.md and the selection tables agree (%d names)"
          % sum(len(v) for v in selectable.values()))


if __name__ == "__main__":
    main()
