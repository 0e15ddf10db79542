"""Read the small things a foamDEM validation needs from a case directory."""
import glob
import os
import re
import sys

_NUMBER = r"[-+0-9.eE]+"


def _strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def foam_entry(path, key):
    """The raw value of a top-level 'key value;' entry of an OpenFOAM dict."""
    text = _strip_comments(open(path).read())
    m = re.search(r"(?m)^\s*" + re.escape(key) + r"\s+([^;]*);", text)
    if not m:
        raise KeyError("%s: no entry '%s'" % (path, key))
    return m.group(1).strip()


def foam_scalar(path, key):
    """A scalar entry, with or without dimensions: 'nu 1e-6;' or
    'nu [0 2 -1 0 0 0 0] 1e-6;'."""
    value = foam_entry(path, key)
    return float(re.sub(r"\[[^\]]*\]", "", value).split()[-1])


def foam_vector(path, key):
    value = foam_entry(path, key)
    m = re.search(r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % ((_NUMBER,) * 3), value)
    return tuple(float(x) for x in m.groups())


def foam_word_list(path, key):
    value = foam_entry(path, key)
    return value.strip("() ").split()


def liggghts_variables(path):
    """'variable NAME equal VALUE' lines of a LIGGGHTS include file."""
    out = {}
    for line in open(path):
        m = re.match(r"\s*variable\s+(\w+)\s+equal\s+(%s)\s*$" % _NUMBER, line)
        if m:
            out[m.group(1)] = float(m.group(2))
    return out


def stopped_by_signal(log):
    """The line "foamDEM run: stopped by SIGUSR2 at t = ..." of a solver
    log (a run a SIGUSR2 stopped before its endTime: stopSignals.H), or
    None. A driver that runs pisoDEMFoam itself must not take such a run,
    which ends with status 0, for a finished one."""
    try:
        with open(log) as f:
            for line in f:
                if line.startswith("foamDEM run: stopped by SIGUSR2 at t = "):
                    return line.strip()
    except OSError:
        pass
    return None


def time_dirs(case):
    """Numeric time directories of a case, sorted (none if CASE is not a
    directory)."""
    times = []
    if not os.path.isdir(case):
        return []
    for name in os.listdir(case):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    return [name for _, name in sorted(times)]


def run_outputs(case=".", extra=()):
    """What a run of a tutorial case has written, relative to the case: its
    time directories after 0, processor directories, the library's DEM
    restarts, the solver's logs, postProcessing, and the case's own
    outputs (EXTRA: paths or glob patterns, e.g. a DEM stage's restart).
    A new run on such a case would delete or mix with them."""
    found = [d for d in time_dirs(case) if float(d) > 0]
    for pattern in ("processor*", "DEM/restart/*.restart", "log.pisoDEMFoam*",
                    "postProcessing") + tuple(extra):
        found += [os.path.relpath(f, case) for f in glob.glob(os.path.join(case, pattern))]
    return sorted(set(found))


def refuse_new_run(case=".", extra=(), who="prepare.py",
                   advice="continue it (Allrun -continue) or clean it first (./Allclean)"):
    """Stop (sys.exit, nothing written) when the case has run (run_outputs):
    a tutorial's ./Allrun without -continue must not delete its results or
    mix its output with theirs. ADVICE: what to do instead."""
    ran = run_outputs(case, extra)
    if ran:
        sys.exit("%s: this case has run already (%s); a new run would delete or"
                 " mix with its results: %s" % (who, " ".join(ran[:3]), advice))


def check_end(end, start, last=None, who="prepare.py"):
    """The end a run is stopped at (Allrun -end T): after its start and, if
    LAST is given (a schedule's end), at most LAST; stops (sys.exit)
    otherwise. Without LAST a run may go on past the case's endTime."""
    if not float(start) < end:
        sys.exit("%s: --end %g: the coupled run's end must be after its start"
                 " (%s s)" % (who, end, start))
    if last is not None and end > last * (1 + 1e-12):
        sys.exit("%s: --end %g: the coupled run's end must be at most the"
                 " schedule's end (%.9g s)" % (who, end, last))
    return end


def variant(ci):
    """The set-up's 'variant' entry (setupDict) of a run with or without
    -ci: 'ci' or 'full' (check_variant reads it back)."""
    return "ci" if ci else "full"


def check_variant(setup, ci, who="prepare.py --continue"):
    """A continued run's -ci must be the run's own: SETUP (the set-up
    prepare.py wrote when the run started) says 'variant ci;' or 'variant
    full;'. Stops (sys.exit, nothing written) on another; a set-up without
    the entry (an older version's) is taken as it comes."""
    try:
        own = foam_entry(setup, "variant")
    except (IOError, OSError, KeyError):
        return
    if own != variant(ci):
        sys.exit("%s: the run was set up %s the CI variant (%s): continue it %s -ci"
                 % (who, "as" if own == "ci" else "without", setup,
                    "with" if own == "ci" else "without"))


def scalar_field_values(path):
    """Internal values of a volScalarField file (uniform or nonuniform)."""
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+(%s)\s*;" % _NUMBER, text)
    if m:
        return [float(m.group(1))]
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;",
                  text, flags=re.S)
    if not m:
        raise ValueError("%s: cannot read internalField" % path)
    return [float(x) for x in m.group(2).split()]


def write_summary(case, rows):
    """Write (key, value) rows to <case>/results/summary.dat, one per line,
    and print them."""
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    width = max([20] + [len(k) + 1 for k, _ in rows])
    lines = ["%-*s %s" % (width, k, v) for k, v in rows]
    with open(os.path.join(case, "results", "summary.dat"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def read_summary(case):
    """The key -> value (string) entries of <case>/results/summary.dat as
    written by write_summary; comment lines are skipped."""
    entries = {}
    with open(os.path.join(case, "results", "summary.dat")) as f:
        for line in f:
            parts = line.split(None, 1)
            if len(parts) == 2 and not line.startswith("#"):
                entries[parts[0]] = parts[1].strip()
    return entries


def dump_frames(path):
    """Frames of a multi-frame LIGGGHTS text dump ('dump custom' to one
    file): [(step, N x ncol array of the per-atom columns, in file order)]."""
    import numpy as np
    frames = []
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            rows = [lines[i + 9 + k].split() for k in range(n)]
            frames.append((step, np.array([[float(x) for x in r] for r in rows])))
            i += 9 + n
        else:
            i += 1
    return frames


def later_segment_wins(rows, key):
    """Rows (or dump frames) of a file that a continued run (./Allrun
    -continue) appended to: where the key (time or step) goes back, the
    later segment replaces the earlier one's rows from that key on."""
    out = []
    for r in rows:
        while out and key(out[-1]) >= key(r):
            out.pop()
        out.append(r)
    return out


def function_object_segments(case, name, fname):
    """Paths of postProcessing/<name>/<start time>/<fname> (name may be a
    glob pattern, e.g. "*"), a run's and its
    continuations' (each starts a directory named by its start time), in
    the order they were written: by start time, and within one start time
    <stem>.dat before <stem>_<start>.dat. OpenFOAM's writeFile names a
    table <stem>_<start>.dat when <stem>.dat is already there, i.e. when a
    segment is run again from the same start time (a session killed
    before the next write), and overwrites that second name on any later
    attempt, so the suffixed file is always the latest attempt's."""
    import glob
    top = os.path.join(case, "postProcessing", name)
    paths = [(p, 0) for p in glob.glob(os.path.join(top, "*", fname))]
    if fname.endswith(".dat"):
        for d in glob.glob(os.path.join(top, "*")):
            again = os.path.join(d, "%s_%s.dat" % (fname[:-4], os.path.basename(d)))
            if os.path.isfile(again):
                paths.append((again, 1))
    paths.sort(key=lambda pa: (float(os.path.basename(os.path.dirname(pa[0]))), pa[1]))
    return [p for p, _ in paths]


_ANY_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?\b(?:nan|inf)\b", re.I)


def file_numbers(path):
    """Every number of an OpenFOAM ASCII field or cloud file after its
    FoamFile header (comments left out), in file order, nan and inf included:
    what a check compares between two runs' writes."""
    with open(path) as f:
        text = f.read()
    if "FoamFile" in text:
        text = text.split("}", 1)[1]
    return [float(x) for x in _ANY_NUMBER.findall(_strip_comments(text))]


def case_processes(case, command=None, below=False):
    """(pid, MPI rank) of the processes whose working directory is CASE (or
    below it, with below=True), this process left out; with COMMAND, only
    those whose executable's name is COMMAND. The rank is 0 outside mpirun.
    Processes are told apart by working directory, never by name alone."""
    case = os.path.realpath(case)
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            cwd = os.path.realpath("/proc/%s/cwd" % pid)
            if cwd != case and not (below and cwd.startswith(case + os.sep)):
                continue
            if command is not None:
                with open("/proc/%s/cmdline" % pid, "rb") as f:
                    cmd = f.read().split(b"\0")
                if not cmd or os.path.basename(cmd[0]).decode() != command:
                    continue
            with open("/proc/%s/environ" % pid, "rb") as f:
                env = dict(e.split(b"=", 1) for e in f.read().split(b"\0") if b"=" in e)
            found.append((int(pid), int(env.get(b"OMPI_COMM_WORLD_RANK", b"0"))))
        except (OSError, ValueError):
            continue
    return found
