#!/usr/bin/python3
"""fluidizedBed set-up: derive the column, the packing and the velocity
sweep from DEM/parameters and write DEM/post/setup.lig (LIGGGHTS),
DEM/post/setupDict (blockMesh, controlDict) and DEM/post/inletVelocity (inlet table)."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, fluidbed  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--case", default=".")
    ap.add_argument("-n", type=int, default=None,
                    help="number of particles (default: DEM/parameters)")
    ap.add_argument("--ci", action="store_true",
                    help="the shorter sweep of the CI variant (ci* times)")
    args = ap.parse_args()
    case = args.case

    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    n = args.n if args.n is not None else int(par["nParticles"])
    if n < 100:
        sys.exit("prepare.py: nParticles must be at least 100, got %d" % n)
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    g = float(np.linalg.norm(caseio.foam_vector(os.path.join(case, "constant/g"), "value")))
    pre = "ci" if args.ci else ""

    def t(name):
        return par[pre + name[0].upper() + name[1:]] if pre else par[name]

    try:
        s = fluidbed.write_setup(case, par, n, t("tUp"), t("tHold"), t("tDown"),
                                 rho, mu, g, 0.4 if args.ci else 0.2)
    except ValueError as e:
        sys.exit("prepare.py: %s" % e)
    print(
        "fluidizedBed: %d particles, column %.4g x %.4g x %.4g m (%d x %d x %d"
        " cells), static bed ~%.4g m, sweep to %.4g m/s, end %.4g s"
        % (n, s["width"], s["depth"], s["height"], s["nx"], s["ny"], s["nz"],
           s["bedHeightEstimate"], s["uMax"], s["tEnd"]))


if __name__ == "__main__":
    main()
