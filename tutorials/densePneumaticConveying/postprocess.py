#!/usr/bin/python3
"""densePneumaticConveying post-processing.

Reads the DEM statistics (DEM/post/axial_*.dat, history_*.dat, dumps), the
flow controller's log (postProcessing/driveGas/*/flowController.dat) and the
solver logs, and writes
  results/summary.dat     quasi-steady averages and standard deviations of
                          the gas velocity, slug velocity, in-slug particle
                          velocity, solids mass flow rate and slug length,
                          and the mechanics checks;
  results/timeSeries.png  the same quantities and the controller force
                          against time;
  results/slugMap.png     axial solid fraction against x and t.

Slug: axial bins (binWidth) whose solid fraction exceeds slugThreshold; the
slug is the longest connected run of such bins on the periodic axis
(foamdem.slug). Its velocity is the rate of change of its unwrapped centre
(mid-point of its ends), from a local linear fit over +-smoothTime; the
in-slug particle velocity v_p is the mean v_x of the particles in the slug's
bins; the solids mass flow rate is sum(m v_x)/L (the mean over the pipe of
the flow through a section). Also reported: the mean solid fraction of the
slug bins (phi_s), the median of the other bins (the layer, phi_layer), and
the slug velocity that continuity predicts from them,
v_p phi_s / (phi_s - phi_layer) (the slug picks up the resting layer at its
front and leaves it at its rear), a consistency check of the measured one.

The reference's measures (the case page's "How the reference measured
them", foamdem.slug.reference_measures) are computed next to these from
the particle dumps (every dumpInterval: 0.025 s as the reference's frames;
CI 0.005 s): slices of one particle diameter with the void fraction of the
particle centres in the slice of the exact cylinder, a moving average over
5 slices, slug slices at solid fraction >= 0.45, front and rear at the inner
edges of the end slices, slug velocity from the unwrapped front by central
differences over +-refStencilFrames frames (0.075 s; CI: 0.015 s), the
particles-in-slug velocity as the magnitude of their mean velocity vector,
and the solids mass flow rate from the net mass crossing the plane
x = massFlowPlane, accumulated from t = 0 and divided by the elapsed time
(also over the window alone, to compare runs). The full run writes
results/comparison.dat: each quantity's published value, foamDEM with the
reference's measures and with its own.

Checks (exit status 1 if one fails; --ci also applies them, the full run
reports them): no particle lost (count constant, the same ids in every
dump), particles crossed the periodic plane (image flags between dumps),
every particle located in the CFD mesh at every coupling step (no 'not
found in the CFD mesh' warning in the solver logs), and the controller
holds the target within 2 % after its transient (--ci: t > 0.02 s; full
run: over the quasi-steady window; the time of the last larger excursion is
reported).
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, slug  # noqa: E402

TRANSIENT = 0.02        # controller transient excluded from its check [s]

# The reference's published results, quasi-steady state t > 4 s (Lavrinec
# et al.; case page dense-pneumatic-conveying.md): mean, standard deviation
REFERENCE = [
    ("gasVelocity", 2.98, 0.02),
    ("slugVelocity", 1.30, 0.02),
    ("particleVelocityInSlug", 0.83, 0.01),
    ("solidsMassFlowRate", 1.40, None),
    ("slugLength", 0.47, 0.01),
]
TOLERANCE = 0.02        # relative error allowed of the mean gas velocity
SMOOTH_TIME = 0.025     # half-width of the slug velocity fit [s]


def concat_history(case):
    """The DEM history of every segment (history_<start step>.dat), joined
    in the order of their start steps; where segments overlap, the later
    segment's rows replace the earlier's."""
    rows = []
    files = glob.glob(os.path.join(case, "DEM/post/history_*.dat"))
    for f in sorted(files, key=lambda f: int(re.search(r"history_(\d+)\.dat$", f).group(1))):
        d = np.loadtxt(f, ndmin=2)
        if d.size:
            rows.append(d)
    if not rows:
        raise ValueError("no DEM/post/history_*.dat")
    d = np.vstack(rows)
    _, idx = np.unique(d[::-1, 0], return_index=True)
    return d[::-1][idx]


def concat_axial(case, dt):
    files, parts = slug.read_segments(os.path.join(case, "DEM/post/axial_*.dat"),
                                      slug.read_axial)
    if not parts:
        raise ValueError("no DEM/post/axial_*.dat")
    coord = parts[0][1]
    steps = np.concatenate([p[0] for p in parts])
    count = np.vstack([p[2] for p in parts])
    vx = np.vstack([p[3] for p in parts])
    rho = np.vstack([p[4] for p in parts])
    _, idx = np.unique(steps[::-1], return_index=True)
    sel = (len(steps) - 1 - idx)
    return steps[sel] * dt, coord, count[sel], vx[sel], rho[sel]


def local_slope(t, x, half_width):
    """dx/dt from a linear fit over t +- half_width."""
    v = np.full(len(t), np.nan)
    for i in range(len(t)):
        m = np.abs(t - t[i]) <= half_width + 1e-12
        if m.sum() >= 3:
            v[i] = np.polyfit(t[m], x[m], 1)[0]
    return v


def stats(values, mask):
    v = np.asarray(values)[mask]
    v = v[np.isfinite(v)]
    if v.size == 0:
        return np.nan, np.nan
    return float(v.mean()), float(v.std())


def p_ci(par, name, ci):
    """A parameter, or its ci* counterpart in the CI variant."""
    ci_name = "ci" + name[0].upper() + name[1:]
    return par[ci_name] if ci and ci_name in par else par[name]


def solver_logs(case):
    return sorted(glob.glob(os.path.join(case, "log.pisoDEMFoam*")))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", default=".")
    ap.add_argument("--ci", action="store_true", help="CI variant: window after the transient")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--window", type=float, nargs=2, metavar=("T0", "T1"),
                    help="quasi-steady window [s] (default: the last"
                         " quasiSteadyTime of the run); writes"
                         " results/summary_T0-T1.dat, no plots")
    args = ap.parse_args()
    case = args.case

    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    setup = caseio.liggghts_variables(os.path.join(case, "DEM/post/setup.lig"))
    L = setup["xhi"] - setup["xlo"]
    R = setup["pipeRadius"]
    box_area = (setup["boxHi"] - setup["boxLo"]) ** 2
    pipe_area = np.pi * R * R
    rhop = par["rhop"]
    dx = par["binWidth"]
    threshold = par["slugThreshold"]
    ubar = par["gasVelocity"]

    hist = concat_history(case)
    t_h, n_h, mvx_h = hist[:, 0], hist[:, 1], hist[:, 2]
    t_a, coord, count, vx, rho = concat_axial(case, par["demTimestep"])
    phi = rho * box_area / (rhop * pipe_area)
    ctrl = slug.read_controller(case)
    t_c, u_c, f_c = ctrl[:, 0], ctrl[:, 1], ctrl[:, 4]

    # Slug per axial snapshot
    rear, front, length, v_part, phi_s, phi_l = (np.full(len(t_a), np.nan)
                                                 for _ in range(6))
    for i in range(len(t_a)):
        s = slug.slug_in_profile(phi[i], coord, dx, threshold)
        if s is None:
            continue
        rear[i], front[i], length[i] = s["rear"], s["front"], s["length"]
        b = s["bins"]
        v_part[i] = np.sum(count[i, b] * vx[i, b]) / max(np.sum(count[i, b]), 1)
        phi_s[i] = np.mean(phi[i, b])
        phi_l[i] = np.median(np.delete(phi[i], b))
    have = np.isfinite(length)
    centre = np.full(len(t_a), np.nan)
    v_slug = np.full(len(t_a), np.nan)
    if have.sum() >= 3:
        centre[have] = slug.unwrap(0.5 * (rear[have] + front[have]), L)
        v_slug[have] = local_slope(t_a[have], centre[have], SMOOTH_TIME)
    mdot = mvx_h / L
    # Continuity across the slug: it picks up the resting layer at its front
    # and leaves it at its rear, so v_slug = v_p phi_s / (phi_s - phi_layer)
    v_cont = v_part * phi_s / (phi_s - phi_l)

    # Quasi-steady window
    t_end = max(t_h[-1], t_c[-1])
    if args.window:
        t0, t_end = args.window
    elif args.ci:
        t0 = TRANSIENT
    else:
        t0 = max(t_end - par["quasiSteadyTime"], TRANSIENT)
    window = lambda t: (t >= t0) & (t <= t_end + 1e-9)
    w_c, w_a, w_h = window(t_c), window(t_a), window(t_h)

    table = [
        ("gasVelocity", "m/s", stats(u_c, w_c)),
        ("slugVelocity", "m/s", stats(v_slug, w_a)),
        ("particleVelocityInSlug", "m/s", stats(v_part, w_a)),
        ("solidsMassFlowRate", "kg/s", stats(mdot, w_h)),
        ("slugLength", "m", stats(length, w_a)),
        ("slugSolidFraction", "-", stats(phi_s, w_a)),
        ("layerSolidFraction", "-", stats(phi_l, w_a)),
        ("slugVelocityContinuity", "m/s", stats(v_cont, w_a)),
        ("controllerForce", "N/m^3", stats(f_c, w_c)),
    ]

    # The reference's measures, from the particle frames
    dumps = glob.glob(os.path.join(case, "DEM/post/dump/particles.*.txt"))
    x_plane = p_ci(par, "massFlowPlane", args.ci)
    ref = slug.reference_measures(dumps, par["demTimestep"], setup["xlo"], L, R,
                                  par["dp"], rhop, x_plane)
    t_r = ref["t"]
    v_front = slug.central_difference(t_r, ref["front"], int(par["refStencilFrames"]))
    w_r = window(t_r)
    crossed = ref["crossedMass"]
    i0, i1 = np.flatnonzero(w_r)[[0, -1]] if w_r.sum() >= 2 else (0, len(t_r) - 1)
    # Cumulative from the first frame (t = 0) to the end of the window
    mdot_cum = crossed[i1] / (t_r[i1] - t_r[0])
    mdot_window = (crossed[i1] - crossed[i0]) / max(t_r[i1] - t_r[i0], 1e-300)
    ref_table = [
        ("gasVelocity", "m/s", stats(u_c, w_c)),
        ("slugVelocity", "m/s", stats(v_front, w_r)),
        ("particleVelocityInSlug", "m/s", stats(ref["vParticles"], w_r)),
        ("solidsMassFlowRate", "kg/s", (mdot_cum, np.nan)),
        ("slugLength", "m", stats(ref["length"], w_r)),
        ("solidsMassFlowRateWindow", "kg/s", (mdot_window, np.nan)),
    ]
    # The same as the reference's post-processing script computes them
    # (slices of its mesh's cross-section, refScriptArea; the mass flow from
    # the entries beyond the plane, script_mass_flow, averaged over the
    # window as the published value is over t > 4 s)
    ref_s = slug.reference_measures(dumps, par["demTimestep"], setup["xlo"], L, R,
                                    par["dp"], rhop, x_plane,
                                    area=par["refScriptArea"])
    v_front_s = slug.central_difference(t_r, ref_s["front"], int(par["refStencilFrames"]))
    mdot_script = slug.script_mass_flow(t_r, ref_s["enteredMass"])
    script_table = [
        ("slugVelocity", "m/s", stats(v_front_s, w_r)),
        ("particleVelocityInSlug", "m/s", stats(ref_s["vParticles"], w_r)),
        ("solidsMassFlowRate", "kg/s", stats(mdot_script, w_r)),
        ("slugLength", "m", stats(ref_s["length"], w_r)),
    ]
    # The slug's axial force balance (N), from the dumps' force columns
    vf = stats(v_front, w_r)[0]
    fb = slug.force_balance(ref, w_r, vf)
    fb_table = [
        ("gasForceOnSlug", "N", fb["fGasSlug"]),
        ("wallForceOnSlug", "N", fb["fWallSlug"]),
        ("pickUpForce", "N", fb["pickUp"]),
        ("residualOnSlug", "N", fb["residualSlug"]),
        ("gasForceOnLayer", "N", fb["fGasLayer"]),
        ("wallForceOnLayer", "N", fb["fWallLayer"]),
        ("gasAndWallOnAll", "N", fb["totalParticles"]),
        ("slugMass", "kg", fb["massSlug"]),
        ("slugParticleVx", "m/s", fb["vxSlug"]),
        ("layerVelocity", "m/s", fb["vxLayer"]),
        ("layerMassPerLength", "kg/m", fb["layerMassPerLength"]),
    ]
    multi_runs = int(np.sum(ref["runs"][w_r] > 1))
    ref_finite = all(np.isfinite(m) for _, _, (m, _) in ref_table)

    # Checks
    n0 = int(n_h[0])
    crossings, n_crossed, same_ids, dump_counts = slug.periodic_crossings(dumps)
    lost = int(n0 - n_h.min()) if len(n_h) else -1
    ids_ok = same_ids and all(c == n0 for c in dump_counts)
    not_found = 0
    for f in solver_logs(case):
        not_found += open(f, errors="replace").read().count("not found in the CFD mesh")
    # The controller check over the window (CI: everything after the
    # transient); the settling time is the last time the error exceeded the
    # tolerance
    rel = np.abs(u_c / ubar - 1)
    err = float(np.max(rel[w_c])) if w_c.any() else np.nan
    outside = t_c[rel > TOLERANCE]
    t_settle = float(outside[-1]) if outside.size else 0.0
    checks = [
        ("noParticleLost", lost == 0 and ids_ok,
         "%d particles, %d lost, same ids in all %d dumps: %s"
         % (n0, lost, len(dump_counts), "yes" if ids_ok else "no")),
        ("periodicCrossing", crossings > 0,
         "%d crossings by %d particles (image flags between %d dumps)"
         % (crossings, n_crossed, len(dump_counts))),
        ("allLocated", not_found == 0,
         "%d coupling steps with particles not found in the CFD mesh" % not_found),
        ("referenceMeasures", ref_finite,
         "slug found in %d of %d frames of the window (%d frames with more than"
         " one run of slug slices); all quantities finite: %s"
         % (int(np.isfinite(ref["length"][w_r]).sum()), int(w_r.sum()), multi_runs,
            "yes" if ref_finite else "no")),
        ("controllerHoldsTarget", np.isfinite(err) and err <= TOLERANCE,
         "max |Umean/Ubar - 1| after %.3g s = %.4g (allowed %.3g); last"
         " excursion beyond it at t = %.4g s"
         % (t0, err, TOLERANCE, t_settle)),
    ]

    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    summary = os.path.join(case, "results", "summary%s.dat"
                           % ("_%g-%g" % (t0, t_end) if args.window else ""))
    with open(summary, "w") as f:
        f.write("# densePneumaticConveying%s: %d particles, pipe %.4g m, t = %.4g..%.4g s"
                " (window)\n" % (" CI" if args.ci else "", n0, L, t0, t_end))
        f.write("# slug: axial bins of %.4g m with solid fraction > %.3g, longest"
                " periodic run\n" % (dx, threshold))
        f.write("# quantity unit mean std\n")
        for name, unit, (m, s) in table:
            f.write("%-24s %-6s %12.6g %12.6g\n" % (name, unit, m, s))
        f.write("# the reference's measures (particle frames every %.4g s; slices of"
                " %.4g m, exact cylinder cross-section; %d-slice moving average;"
                " slug at solid fraction >= 0.45; front velocity over +-%d frames;"
                " mass flow across x = %.4g m, cumulative from t = %.4g s and over"
                " the window)\n"
                % (p_ci(par, "dumpInterval", args.ci), par["dp"], 5,
                   int(par["refStencilFrames"]), x_plane, t_r[0]))
        for name, unit, (m, s) in ref_table:
            f.write("ref_%-24s %-6s %12.6g %12.6g\n" % (name, unit, m, s))
        f.write("# as the reference's post-processing script computes them: slices"
                " of its mesh's cross-section (%.6g m^2); mass flow from the"
                " particles beyond x = %.4g m that were not there in the previous"
                " frame (all of them in the first), entries before each frame over"
                " the elapsed time, averaged over the window\n"
                % (par["refScriptArea"], x_plane))
        for name, unit, (m, s) in script_table:
            f.write("script_%-21s %-6s %12.6g %12.6g\n" % (name, unit, m, s))
        if np.isfinite(fb["fGasSlug"]):
            f.write("# the slug's axial force balance over the window (the reference's"
                    " slug; the layer: all other particles): gas and wall forces from"
                    " the dumps; pick-up = layer mass per length x (front velocity -"
                    " layer velocity) x (slug particles' vx - layer velocity); residual"
                    " = gas + wall - pick-up (contacts with the layer, unsteadiness)\n")
            for name, unit, m in fb_table:
                f.write("fb_%-25s %-6s %12.6g\n" % (name, unit, m))
        f.write("# checks\n")
        for name, ok, text in checks:
            f.write("%-24s %-4s %s\n" % (name, "PASS" if ok else "FAIL", text))
    print(open(summary).read())

    if not args.ci and not args.window:
        own = dict((name, m) for name, _, (m, _) in table)
        refm = dict((name, m) for name, _, (m, _) in ref_table)
        scriptm = dict((name, m) for name, _, (m, _) in script_table)
        scriptm["gasVelocity"] = refm["gasVelocity"]
        path = os.path.join(case, "results", "comparison.dat")
        with open(path, "w") as f:
            f.write("# densePneumaticConveying against Lavrinec et al. (case page"
                    " dense-pneumatic-conveying.md), window %.4g..%.4g s, SI units\n"
                    % (t0, t_end))
            f.write("# foamDEM_referenceMeasures: the reference's definitions;"
                    " foamDEM_ownMeasures: postprocess.py's axial bins\n")
            f.write("# solidsMassFlowRate: reference measure cumulative from t = 0"
                    " (as published); own measure sum(m v_x)/L over the window\n")
            f.write("# foamDEM_scriptMeasures: as the reference's post-processing"
                    " script computes them (mesh cross-section slices, entries"
                    " beyond the plane)\n")
            f.write("# name reference foamDEM_referenceMeasures foamDEM_ownMeasures"
                    " foamDEM_scriptMeasures\n")
            for name, value, _ in REFERENCE:
                f.write("%-24s %10.4g %12.5g %12.5g %12.5g\n"
                        % (name, value, refm[name], own[name], scriptm[name]))
        print(open(path).read())

    if not args.no_plot and not args.window:
        plot(case, t_c, u_c, f_c, ubar, t_a, v_slug, v_part, length, t_h, mdot,
             coord, phi, t0, (t_r, v_front, ref["vParticles"], ref["length"],
                              crossed / np.maximum(t_r - t_r[0], 1e-300)))

    return 0 if all(ok for _, ok, _ in checks) else 1


def plot(case, t_c, u_c, f_c, ubar, t_a, v_slug, v_part, length, t_h, mdot, coord, phi, t0,
         ref):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(5, 1, figsize=(8, 12), sharex=True)
    ax[0].plot(t_c, u_c, lw=0.8, label="mean gas velocity (void-fraction weighted)")
    ax[0].axhline(ubar, color="k", ls="--", lw=0.8, label="target")
    ax[0].set_ylabel("m/s")
    ax[0].legend(loc="best", fontsize=8)
    ax[1].plot(t_c, f_c, lw=0.8, color="C3")
    ax[1].set_ylabel("controller force\nN/m$^3$")
    t_r, v_front, v_ref, len_ref, mdot_cum = ref
    ax[2].plot(t_a, v_slug, lw=0.8, label="slug")
    ax[2].plot(t_a, v_part, lw=0.8, label="particles in slug")
    ax[2].plot(t_r, v_front, "o-", ms=2, lw=0.8, label="slug front (reference's measure)")
    ax[2].plot(t_r, v_ref, "s-", ms=2, lw=0.8, label="particles in slug (reference's)")
    ax[2].set_ylabel("velocity m/s")
    ax[2].legend(loc="best", fontsize=8)
    ax[3].plot(t_h, mdot, lw=0.8, color="C2", label="sum(m v_x)/L")
    ax[3].plot(t_r[1:], mdot_cum[1:], lw=0.8, color="C5",
               label="plane crossings, cumulative (reference's)")
    ax[3].legend(loc="best", fontsize=8)
    ax[3].set_ylabel("solids mass\nflow rate kg/s")
    ax[4].plot(t_a, length, lw=0.8, color="C4", label="axial bins")
    ax[4].plot(t_r, len_ref, "o-", ms=2, lw=0.8, color="C6", label="reference's slices")
    ax[4].legend(loc="best", fontsize=8)
    ax[4].set_ylabel("slug length m")
    ax[4].set_xlabel("t (s)")
    for a in ax:
        a.axvline(t0, color="grey", lw=0.6, ls=":")
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(case, "results/timeSeries.png"), dpi=120)
    plt.close(fig)

    fig, a = plt.subplots(figsize=(8, 4))
    dx = coord[1] - coord[0] if len(coord) > 1 else 1
    extent = [coord[0] - dx / 2, coord[-1] + dx / 2, t_a[0], t_a[-1]]
    im = a.imshow(phi, aspect="auto", origin="lower", extent=extent,
                  vmin=0, vmax=0.65, cmap="viridis")
    fig.colorbar(im, ax=a, label="solid fraction")
    a.set_xlabel("x (m)")
    a.set_ylabel("t (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "results/slugMap.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
