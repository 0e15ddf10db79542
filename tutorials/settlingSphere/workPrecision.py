"""Cost levels of settlingSphere for bin/foamDEMWorkPrecision.

The quantity is the sphere's settling velocity at the end of the CI run,
against the terminal velocity of the ODE with the same drag law. Levels
change the CFD step (with the coupling interval, so the DEM step stays
1e-5 s) and the mesh. In unresolved CFD-DEM a finer mesh is not always more
accurate: the sphere's own momentum source disturbs its cell more when the
cell is smaller.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

QUANTITY = "terminal velocity [m/s]"
ALLRUN_ARGS = ["-ci"]


def _step(dt, interval):
    return ["foamDictionary system/controlDict -entry deltaT -set %g" % dt,
            "foamDictionary constant/couplingProperties -entry couplingInterval -set %d" % interval]


def _mesh(n):
    return ["foamDictionary system/blockMeshDict -entry blocks -set "
            "'(hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1))'" % (n, n, 4 * n)]


LEVELS = [
    ("dt4e-3", "CFD step 4e-3 s, 400 DEM steps per CFD step", _step(4e-3, 400)),
    ("dt2e-3", "CFD step 2e-3 s, 200 DEM steps per CFD step", _step(2e-3, 200)),
    ("dt1e-3", "CFD step 1e-3 s, 100 DEM steps per CFD step (default)", _step(1e-3, 100)),
    ("dt5e-4", "CFD step 5e-4 s, 50 DEM steps per CFD step", _step(5e-4, 50)),
    ("mesh4", "4 x 4 x 16 cells (d/h = 0.1)", _mesh(4)),
    ("mesh10", "10 x 10 x 40 cells (d/h = 0.25)", _mesh(10)),
]

# The documented trends (doc/validation.md, work-precision), asserted by
# foamDEMWorkPrecision --check: the error does not depend on the CFD step
# (measured spread 1.5e-4 over the four steps, error 2.5e-3 to 2.65e-3), and
# stays within the CI check's 0.5 %.
TRENDS = [
    ("flat", ["dt4e-3", "dt2e-3", "dt1e-3", "dt5e-4"], 5e-4),
    ("below", ["dt4e-3", "dt2e-3", "dt1e-3", "dt5e-4"], 5e-3),
]


def measure(case_dir):
    summary = caseio.read_summary(case_dir)
    return float(summary["v_DEM_end_m_s"]), float(summary["v_terminal_ODE_m_s"])
