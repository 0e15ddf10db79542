"""Cost levels of fluidizedBed for bin/foamDEMWorkPrecision.

The quantity is the minimum fluidisation velocity from the decreasing sweep
of the CI bed (4000 spheres), against Ergun at the measured voidage. The
plateau pressure drop is not used: its check does not pass yet (README).
Levels change the CFD step with the coupling interval (the DEM step stays
2.5e-5 s).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio  # noqa: E402

QUANTITY = "U_mf [m/s]"
ALLRUN_ARGS = ["-ci"]


def _step(dt, interval):
    # controlDict includes a file Allrun writes, so foamDictionary cannot
    # read it before the run: sed
    return ["sed -i 's/^deltaT .*/deltaT          %g;/' system/controlDict" % dt,
            "foamDictionary constant/couplingProperties -entry couplingInterval -set %d" % interval]


LEVELS = [
    ("dt1e-3", "CFD step 1e-3 s, 40 DEM steps per CFD step", _step(1e-3, 40)),
    ("dt5e-4", "CFD step 5e-4 s, 20 DEM steps per CFD step (default)", []),
    ("dt2.5e-4", "CFD step 2.5e-4 s, 10 DEM steps per CFD step", _step(2.5e-4, 10)),
]


def measure(case_dir):
    summary = caseio.read_summary(case_dir)
    return float(summary["Umf_decreasing_m_s"]), float(summary["Umf_Ergun_m_s"])
