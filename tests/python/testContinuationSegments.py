#!/usr/bin/python3
"""Unit test of the joins the tutorials' post-processing applies to a run
and its continuations (./Allrun -continue): caseio.later_segment_wins (a
DEM print or dump file appended to, whose time goes back at the restart)
and fluidbed.read_function_object_segments (postProcessing/<name>/<start>/
of each segment). Synthetic files with the answers written down."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
from foamdem import caseio, fluidbed  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402


# A history written to 0.5, continued from 0.3 (rows 0.3 .. 0.6 again)
rows = [(t / 10, 0) for t in range(6)] + [(t / 10, 1) for t in range(3, 7)]
out = caseio.later_segment_wins(rows, lambda r: r[0])
check("appended history: times increase, the continued rows from 0.3 on",
      [r[0] for r in out] == [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6]
      and [r[1] for r in out] == [0, 0, 0, 1, 1, 1, 1], str(out))
check("a file without a restart is unchanged",
      caseio.later_segment_wins(rows[:6], lambda r: r[0]) == rows[:6])
# Two continuations, the second from before the first's start
rows2 = rows + [(0.2, 2), (0.3, 2)]
out2 = caseio.later_segment_wins(rows2, lambda r: r[0])
check("second continuation from an earlier time replaces both",
      out2 == [(0, 0), (0.1, 0), (0.2, 2), (0.3, 2)], str(out2))

# surfaceFieldValue segments: postProcessing/inlet/0 (to 0.5) and /0.3
with tempfile.TemporaryDirectory() as case:
    for start, tag, times in (("0", 1.0, [0.1, 0.2, 0.3, 0.4, 0.5]),
                              ("0.3", 2.0, [0.4, 0.5, 0.6])):
        d = os.path.join(case, "postProcessing", "inlet", start)
        os.makedirs(d)
        with open(os.path.join(d, "surfaceFieldValue.dat"), "w") as f:
            f.write("# Region type : patch inlet\n# Time\tareaAverage(p)\tareaAverage(U)\n")
            for t in times:
                f.write("%g\t%g\t(0 0 %g)\n" % (t, tag * t, tag))
    s = fluidbed.read_function_object_segments(case, "inlet", "surfaceFieldValue.dat")
    check("function object: times joined by time",
          list(s["Time"]) == [0.1, 0.2, 0.3, 0.4, 0.5, 0.6], str(list(s["Time"])))
    check("function object: the continued segment's values from its first time",
          list(s["areaAverage(p)"]) == [0.1, 0.2, 0.3, 0.8, 1.0, 1.2]
          and list(s["areaAverage(U)"][:, 2]) == [1, 1, 1, 2, 2, 2], str(s["areaAverage(p)"]))

# A segment run twice from the same start time (killed before its next
# write, then continued again): OpenFOAM's writeFile finds
# surfaceFieldValue.dat there and writes surfaceFieldValue_0.3.dat; that
# second attempt's rows win. The first attempt went to 0.6 with tag 2, the
# second to 0.5 with tag 3.
with tempfile.TemporaryDirectory() as case:
    for start, fname, tag, times in (("0", "surfaceFieldValue.dat", 1.0, [0.1, 0.2, 0.3]),
                                     ("0.3", "surfaceFieldValue.dat", 2.0, [0.4, 0.5, 0.6]),
                                     ("0.3", "surfaceFieldValue_0.3.dat", 3.0, [0.4, 0.5])):
        d = os.path.join(case, "postProcessing", "inlet", start)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, fname), "w") as f:
            f.write("# Region type : patch inlet\n# Time\tareaAverage(p)\tareaAverage(U)\n")
            for t in times:
                f.write("%g\t%g\t(0 0 %g)\n" % (t, tag * t, tag))
    segs = [os.path.relpath(q, case) for q in
            caseio.function_object_segments(case, "inlet", "surfaceFieldValue.dat")]
    check("function object run twice from 0.3: the _0.3 file last",
          segs == ["postProcessing/inlet/0/surfaceFieldValue.dat",
                   "postProcessing/inlet/0.3/surfaceFieldValue.dat",
                   "postProcessing/inlet/0.3/surfaceFieldValue_0.3.dat"], str(segs))
    s = fluidbed.read_function_object_segments(case, "inlet", "surfaceFieldValue.dat")
    check("function object run twice from 0.3: the second attempt's rows",
          list(s["Time"]) == [0.1, 0.2, 0.3, 0.4, 0.5]
          and list(s["areaAverage(U)"][:, 2]) == [1, 1, 1, 3, 3], str(list(s["Time"])))

# The flow controller's log (slug.read_controller): postProcessing/<fo>/
# <start>/flowController.dat of a run to 0.5 and its continuation from
# 0.3 (another time step, so other times): the continuation's rows from
# 0.3 on, none of the first run's after 0.3 in between, whatever order the
# directories are listed in
from foamdem import slug  # noqa: E402
with tempfile.TemporaryDirectory() as case:
    for start, tag, times in (("0.3", 2.0, [0.3, 0.45, 0.6]),
                              ("0", 1.0, [0.1, 0.2, 0.3, 0.4, 0.5])):
        d = os.path.join(case, "postProcessing", "flowController", start)
        os.makedirs(d)
        with open(os.path.join(d, "flowController.dat"), "w") as f:
            for t in times:
                f.write("%g %g 0 0 0 0 1\n" % (t, tag))
    c = slug.read_controller(case)
    check("flow controller log: the continuation's rows from 0.3 on",
          list(c[:, 0]) == [0.1, 0.2, 0.3, 0.45, 0.6]
          and list(c[:, 1]) == [1, 1, 2, 2, 2], str(c[:, :2].tolist()))

finish()
