#!/usr/bin/python3
"""settlingSphere verification: the DEM velocity history of the coupled run
against the ODE  m dv/dt = (rho_p - rho) V g - K(v) v  with the same drag
law and the void fraction the particle saw. Writes results/summary.dat and
results/settling.png; exits 1 if the terminal-velocity error exceeds --tol.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, drag  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--case", default=".")
    ap.add_argument("--tol", type=float, default=0.005,
                    help="bound on |v_DEM - v_t|/v_t at the end (default 0.005)")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    case = args.case

    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    d, rhop = par["dp"], par["rhop"]
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    g = float(np.linalg.norm(caseio.foam_vector(os.path.join(case, "constant/g"), "value")))
    models = caseio.foam_word_list(os.path.join(case, "constant/couplingProperties"), "forceModels")
    laws = [m for m in models if m in drag.LAWS]
    if len(laws) != 1:
        sys.exit("validate.py: expected one drag law of %s in forceModels, got %s"
                 % (sorted(drag.LAWS), models))
    law_name = laws[0]
    law = drag.LAWS[law_name]

    # Void fraction seen by the particle: the smallest in the last write
    last = caseio.time_dirs(case)[-1]
    eps = min(caseio.scalar_field_values(os.path.join(case, last, "voidfraction")))

    hist = np.loadtxt(os.path.join(case, "DEM/post/history.dat"))
    t_dem, v_dem = hist[:, 0], -hist[:, 2]          # settling speed, downward
    t_end = t_dem[-1]

    vol = np.pi * d ** 3 / 6
    v_t = drag.terminal_velocity(law, d, rho, mu, eps, (rhop - rho) * vol * g)
    t_ode, v_ode = drag.settle(law, d, rho, mu, eps, rhop, g, t_end)
    v_ode_at_dem = np.interp(t_dem, t_ode, v_ode)

    err_terminal = abs(v_dem[-1] - v_t) / v_t
    err_history = np.max(np.abs(v_dem - v_ode_at_dem)) / v_t
    re_t = rho * v_t * d / mu

    rows = [
        ("dragLaw", law_name),
        ("d_m", "%g" % d),
        ("rhoParticle_kg_m3", "%g" % rhop),
        ("voidFraction", "%.6f" % eps),
        ("Re_terminal", "%.3f" % re_t),
        ("v_terminal_ODE_m_s", "%.6e" % v_t),
        ("v_DEM_end_m_s", "%.6e" % v_dem[-1]),
        ("t_end_s", "%g" % t_end),
        ("terminalError", "%.3e" % err_terminal),
        ("historyMaxError", "%.3e" % err_history),
        ("tolerance", "%g" % args.tol),
        ("pass", "yes" if err_terminal <= args.tol else "no"),
    ]
    caseio.write_summary(case, rows)

    if not args.no_plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(t_ode, v_ode, "k-", lw=1, label="ODE, same drag law")
        ax.plot(t_dem[::5], v_dem[::5], "o", ms=3, mfc="none", label="foamDEM (DEM)")
        ax.axhline(v_t, color="grey", ls=":", label="terminal velocity")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("settling velocity [m/s]")
        ax.set_title("settlingSphere, %s, Re_t = %.0f, error %.2f %%"
                     % (law_name, re_t, 100 * err_terminal))
        ax.legend(loc="lower right")
        fig.tight_layout()
        fig.savefig(os.path.join(case, "results/settling.png"), dpi=100)

    return 0 if err_terminal <= args.tol else 1


if __name__ == "__main__":
    sys.exit(main())
