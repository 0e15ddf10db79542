#!/usr/bin/python3
"""ErgunPackedBed: pressure drop across the interior of a frozen packed bed
against Ergun's law with the bed's measured void fraction. With gidaspow
(the default), whose dense branch is Ergun, this is a verification of the
coupling's numerics; with another law, the error against the law's own
uniform-bed prediction is a verification and errorVsErgun a validation
against an independent correlation.

Measured: rho x the difference of the layer-averaged kinematic pressure
between two horizontal planes of cell centres inside the bed (one cell
away from the floor and from the bed top), at the end of each inlet
velocity plateau. Ergun: the same planes' distance L and the void fraction
of the slab between them, from the exact volume of the spheres inside it.
The superficial velocity U is the inlet's superficial flux (alphaPhi, the
flux of eps u) over the column cross-section; it must equal the velocity the
inlet prescribes (U of 0/U) to round-off, whatever the void fraction next to
the inlet (a bed resting on the inlet: the void fraction's inlet value is 1,
see pisoDEMFoam).

With --drag LAW other than gidaspow the measured pressure drop is compared
with that law's own uniform-bed prediction, -dp/dz = n K(u) u/eps with
u = U/eps, n = (1 - eps)/V_p and K the law's coefficient (foamdem.drag): a
verification against a second implementation of the law, not a validation.

Also reported, not asserted: the whole bed (inlet plenum to outlet) against
Ergun with the whole bed's height and mean void fraction, and how much the
cell-to-cell void fraction fluctuations can move the result (series and
parallel bounds). Writes results/summary.dat and results/ergun.png; exits 1
if a check fails.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, drag, ergun  # noqa: E402


def fail(msg):
    print("validate.py: FAIL: " + msg)
    return msg


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--case", default=".")
    ap.add_argument("--tol", type=float, default=0.02,
                    help="bound on |dP - dP_Ergun|/dP_Ergun (default 0.02)")
    ap.add_argument("--steady-tol", type=float, default=1e-3,
                    help="bound on the relative change of dP between the last"
                         " two writes of a plateau (default 1e-3)")
    ap.add_argument("--bed", default="DEM/bed.full",
                    help="LIGGGHTS file with the column width W of the packing"
                         " (default DEM/bed.full)")
    ap.add_argument("--floor", type=float,
                    help="height the bed rests on in the coupled stage (Allrun"
                         " -floor; default zFloor of DEM/parameters)")
    ap.add_argument("--drag", default="gidaspow",
                    help="drag law of the run (Allrun -drag): gidaspow is"
                         " checked against Ergun, another law against its own"
                         " uniform-bed prediction (default gidaspow)")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    case = args.case
    failures = []

    # ---------------------------------------------------------- input data
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    par.update(caseio.liggghts_variables(os.path.join(case, args.bed)))
    d, rhop, W, z_floor = par["dp"], par["rhop"], par["W"], par["zFloor"]
    if args.floor is not None:
        z_floor = args.floor
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    g = float(np.linalg.norm(caseio.foam_vector(os.path.join(case, "constant/g"), "value")))
    area = W * W

    lo, hi = ergun.mesh_bounds(case)
    if max(abs(lo[0]), abs(lo[1]), abs(hi[0] - W), abs(hi[1] - W)) > 1e-9:
        failures.append(fail("mesh x/y extent %s-%s differs from the DEM column"
                             " width W = %g m of %s" % (lo, hi, W, args.bed)))

    times = [t for t in caseio.time_dirs(case) if float(t) > 0]
    if not times:
        sys.exit("validate.py: no written time directories")

    cz = np.array(caseio.scalar_field_values(os.path.join(case, times[-1], "Cz")))
    levels, layer = ergun.cell_layers(cz)
    h = float(np.median(np.diff(levels)))
    n_per_layer = np.bincount(layer)

    def layer_mean(values):
        return np.bincount(layer, weights=values) / n_per_layer

    # ------------------------------------------------------------- the bed
    pos = ergun.cloud_positions(case, times[-1])
    diam = np.broadcast_to(ergun.cloud_field(case, times[-1], "d"), (len(pos),))
    r = 0.5 * diam
    vp = ergun.cloud_field(case, times[-1], "U").reshape(-1, 3)
    pos0 = ergun.cloud_positions(case, times[0])
    v_max = float(np.max(np.linalg.norm(vp, axis=1)))
    moved = float(np.max(np.abs(pos - pos0))) if pos0.shape == pos.shape else np.inf
    if v_max > 0 or moved > 1e-12:
        failures.append(fail("the bed is not frozen: max |v| %g m/s, max"
                             " displacement %g m" % (v_max, moved)))
    if np.max(np.abs(diam - d)) > 1e-12:
        failures.append(fail("particle diameters differ from dp = %g" % d))

    vs_total = float(np.sum(np.pi / 6 * diam ** 3))
    z_top, phi_bulk, zprof, prof = ergun.bed_top(pos[:, 2], r, area, z_floor, d / 20)
    H = z_top - z_floor
    eps_bed = 1 - vs_total / (area * H)

    # Measuring planes: cell-centre layers one cell inside the bed
    inside = [k for k, z in enumerate(levels)
              if z - 0.5 * h >= z_floor + h - 1e-9 and z + 0.5 * h <= z_top - h + 1e-9]
    if len(inside) < 3:
        sys.exit("validate.py: the bed (%g m deep) is too shallow for the"
                 " mesh (cells of %g m)" % (H, h))
    k1, k2 = inside[0], inside[-1]
    z1, z2 = levels[k1], levels[k2]
    L = z2 - z1
    eps = 1 - np.sum(ergun.sphere_slab_volume(pos[:, 2], r, z1, z2)) / (area * L)

    # CFD cells between the planes: end layers count half (the pressure
    # difference between cell centres spans half of each end cell)
    alpha = np.array(caseio.scalar_field_values(os.path.join(case, times[-1], "voidfraction")))
    sel = (layer >= k1) & (layer <= k2)
    w = np.where((layer == k1) | (layer == k2), 0.5, 1.0)[sel]
    a_cells = alpha[sel]
    eps_cells = float(np.sum(w * a_cells) / np.sum(w))
    std_cells = float(np.sqrt(np.sum(w * (a_cells - eps_cells) ** 2) / np.sum(w)))
    if a_cells.max() > 0.8:
        failures.append(fail("a cell between the planes has eps %.3f > 0.8:"
                             " gidaspow is not on its Ergun branch there" % a_cells.max()))

    if args.drag == "gidaspow":
        prediction = lambda U, e: ergun.ergun_gradient(U, e, d, rho, mu)
    else:
        if args.drag not in drag.LAWS:
            sys.exit("validate.py: --drag %s: no prediction; valid: %s"
                     % (args.drag, " ".join(sorted(drag.LAWS))))
        law = drag.LAWS[args.drag]
        vp1 = np.pi / 6 * d ** 3

        def prediction(U, e):
            u = U / e
            return (1 - e) / vp1 * law(d, rho, mu, e, u) * u / e

    umf_ergun = ergun.ergun_umf(eps_bed, d, rho, rhop, mu, g)
    umf_wenyu = ergun.wen_yu_umf(d, rho, rhop, mu, g)

    # --------------------------------------------------- velocity plateaus
    plateaus = []          # [U, [times]]
    n_inlet = ergun.patch_n_faces(case, "inlet")
    flux_err = 0.0
    for t in times:
        phi_in = ergun.patch_scalars(os.path.join(case, t, "alphaPhi"), "inlet")
        U = -(phi_in.sum() if phi_in.size > 1 else phi_in[0] * n_inlet) / area
        U_in = float(ergun.patch_entry(os.path.join(case, t, "U"), "inlet")
                     .split("(")[1].split(")")[0].split()[2])
        flux_err = max(flux_err, abs(U - U_in) / abs(U_in))
        if plateaus and abs(U - plateaus[-1][0]) <= 1e-9 * abs(U):
            plateaus[-1][1].append(t)
        else:
            plateaus.append([U, [t]])
    if len(plateaus) < 3:
        failures.append(fail("expected 3 inlet velocity plateaus, found %d" % len(plateaus)))

    rows = []
    profiles = []
    for U, ts in plateaus:
        p_layers = []
        for t in ts[-2:]:
            p = np.array(caseio.scalar_field_values(os.path.join(case, t, "p")))
            p_layers.append(rho * layer_mean(p))
        dP = p_layers[-1][k1] - p_layers[-1][k2]
        dP_e = float(prediction(U, eps)) * L
        err = (dP - dP_e) / dP_e
        if len(p_layers) == 2:
            dP_prev = p_layers[0][k1] - p_layers[0][k2]
            change = abs(dP - dP_prev) / abs(dP)
        else:
            change = np.inf
        # Whole bed: plenum (lowest layer) to the outlet (p = 0)
        dP_bed = p_layers[-1][0]
        dP_bed_e = float(prediction(U, eps_bed)) * H
        # Cell fluctuations: series (layers in a row) and parallel bounds
        G = ergun.ergun_gradient(U, a_cells, d, rho, mu)
        G0 = float(ergun.ergun_gradient(U, eps_cells, d, rho, mu))
        series = np.sum(w * G) / np.sum(w) / G0 - 1
        parallel = np.sum(w) / np.sum(w / G) / G0 - 1
        dP_ergun = float(ergun.ergun_gradient(U, eps, d, rho, mu)) * L
        rows.append(dict(U=U, dP=dP, dP_e=dP_e, err=err, change=change,
                         dP_ergun=dP_ergun, err_ergun=(dP - dP_ergun) / dP_ergun,
                         dP_bed=dP_bed, dP_bed_e=dP_bed_e,
                         err_bed=(dP_bed - dP_bed_e) / dP_bed_e,
                         cells=G0 / float(ergun.ergun_gradient(U, eps, d, rho, mu)) - 1,
                         series=series, parallel=parallel, t=ts[-1]))
        profiles.append((U, p_layers[-1]))

        if abs(err) > args.tol:
            failures.append(fail("U = %.3g m/s: error %.3e exceeds %g" % (U, err, args.tol)))
        if change > args.steady_tol:
            failures.append(fail("U = %.3g m/s: plateau not steady (dP changed by"
                                 " %.2e between its last two writes)" % (U, change)))
        if U >= min(umf_ergun, umf_wenyu):
            failures.append(fail("U = %.3g m/s is not below minimum fluidisation"
                                 " (%.3g m/s)" % (U, min(umf_ergun, umf_wenyu))))

    if flux_err > 1e-8:
        failures.append(fail("the superficial inflow (alphaPhi over the inlet / A)"
                             " differs from the inlet velocity by %.3e (relative)"
                             % flux_err))
    max_err = max(abs(row["err"]) for row in rows)
    ok = not failures

    # -------------------------------------------------------------- output
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    head = [
        ("particles", "%d" % len(pos)),
        ("d_m", "%g" % d),
        ("rhoParticle_kg_m3", "%g" % rhop),
        ("rhoFluid_kg_m3", "%g" % rho),
        ("muFluid_Pa_s", "%g" % mu),
        ("columnWidth_m", "%g (periodic in x and y)" % W),
        ("cellSize_m", "%g" % h),
        ("bedFloor_m", "%g" % z_floor),
        ("bedTop_m", "%.5f (solid fraction falls to half its bulk %.4f)" % (z_top, phi_bulk)),
        ("bedHeight_H_m", "%.5f" % H),
        ("bedVoidFraction", "%.5f (particle volume / (A H))" % eps_bed),
        ("planes_z1_z2_m", "%.4f %.4f (cell centres, layers %d and %d)" % (z1, z2, k1, k2)),
        ("L_m", "%.4f" % L),
        ("eps_planes", "%.5f (exact sphere volume between the planes)" % eps),
        ("eps_cells", "%.5f (CFD cells between the planes, std %.4f, min %.3f, max %.3f)"
         % (eps_cells, std_cells, a_cells.min(), a_cells.max())),
        ("Umf_Ergun_m_s", "%.4f (eps = bedVoidFraction)" % umf_ergun),
        ("Umf_WenYu_m_s", "%.4f" % umf_wenyu),
        ("frozenBed", "max |v| %g m/s, max displacement %g m" % (v_max, moved)),
        ("drag", "%s (compared with %s)" % (args.drag, "Ergun" if args.drag == "gidaspow"
                                              else "its own uniform-bed prediction")),
        ("inletFluxError", "%.3e (|alphaPhi_inlet/A - U_inlet|/U_inlet, largest)" % flux_err),
        ("maxError", "%.3e" % max_err),
        ("tolerance", "%g" % args.tol),
        ("pass", "yes" if ok else "no"),
    ]
    cols = ("U_m_s", "dP_Pa", "dP_Ergun_Pa", "error", "eps", "L_m", "t_s",
            "steadyChange", "dPbed_Pa", "dPbed_Ergun_Pa", "errorBed",
            "epsCellsEffect", "seriesBound", "parallelBound", "dP_ErgunLaw_Pa",
            "errorVsErgun")
    with open(os.path.join(case, "results/summary.dat"), "w") as f:
        f.write("# ErgunPackedBed: pressure drop between two planes inside a frozen"
                " packed bed vs Ergun\n")
        for k, v in head:
            f.write("# %-18s %s\n" % (k, v))
        f.write("# dP between the planes; dPbed plenum to outlet vs Ergun(bedVoidFraction, H);"
                " epsCellsEffect = Ergun(eps_cells)/Ergun(eps) - 1; dP_Ergun_Pa: the prediction of the drag law (Ergun for gidaspow);\n# series/parallelBound ="
                " cell-average / harmonic cell-average of Ergun(eps_cell) over Ergun(eps_cells) - 1;\n"
                "# dP_ErgunLaw_Pa: Ergun's equation itself at eps and L, whatever the drag law;"
                " errorVsErgun = dP/dP_ErgunLaw - 1 (a validation for every law but gidaspow, whose dense branch is Ergun)\n")
        f.write("# " + " ".join("%-14s" % c for c in cols) + "\n")
        for row in rows:
            f.write("  " + " ".join("%-14.6g" % x for x in (
                row["U"], row["dP"], row["dP_e"], row["err"], eps, L, float(row["t"]),
                row["change"], row["dP_bed"], row["dP_bed_e"], row["err_bed"],
                row["cells"], row["series"], row["parallel"], row["dP_ergun"],
                row["err_ergun"])) + "\n")
    for k, v in head:
        print("%-18s %s" % (k, v))
    print("%8s %10s %10s %10s %10s %10s" % ("U", "dP", "predicted", "error", "dPbed", "errorBed"))
    for row in rows:
        print("%8.4f %10.3f %10.3f %10.3e %10.3f %10.3e" % (
            row["U"], row["dP"], row["dP_e"], row["err"], row["dP_bed"], row["err_bed"]))

    if not args.no_plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
        Us = np.array([row["U"] for row in rows])
        uu = np.linspace(0, 1.1 * Us.max(), 100)
        ax.plot(uu, ergun.ergun_gradient(uu, eps, d, rho, mu) * L, "k-", lw=1,
                label="Ergun, eps = %.4f, L = %.1f mm" % (eps, 1e3 * L))
        ax.plot(Us, [row["dP"] for row in rows], "o", ms=7, mfc="none", mew=1.5,
                label="foamDEM, between the planes")
        ax.plot(uu, ergun.ergun_gradient(uu, eps_bed, d, rho, mu) * H, "k--", lw=0.8,
                label="Ergun, whole bed (eps %.4f, H = %.1f mm)" % (eps_bed, 1e3 * H))
        ax.plot(Us, [row["dP_bed"] for row in rows], "s", ms=5, mfc="none",
                label="foamDEM, whole bed (not asserted)")
        ax.set_xlabel("superficial velocity U [m/s]  (U_mf = %.2f m/s)" % umf_ergun)
        ax.set_ylabel("pressure drop [Pa]")
        ax.set_title("ErgunPackedBed, %d spheres: max error %.2f %%" % (len(pos), 100 * max_err))
        ax.legend(loc="upper left", fontsize=8)
        for U, pl in profiles:
            bx.plot(pl, levels * 1e3, ".-", label="U = %.2f m/s" % U)
        for z in (z_floor, z_top):
            bx.axhline(z * 1e3, color="grey", ls=":", lw=1)
        for z in (z1, z2):
            bx.axhline(z * 1e3, color="k", ls="--", lw=0.8)
        bx.set_xlabel("layer-averaged p [Pa]")
        bx.set_ylabel("z [mm]  (dotted: bed floor, top; dashed: planes)")
        bx.legend(loc="upper right", fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(case, "results/ergun.png"), dpi=100)

    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
