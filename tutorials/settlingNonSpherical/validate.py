#!/usr/bin/python3
"""settlingNonSpherical verification (the reference is a second
implementation of the same Hoelzer-Sommerfeld law, python/foamdem/shapes.py).

Frozen orientation (broadside, edgewise): the DEM settling velocity at the
end of the run against the Hoelzer-Sommerfeld (2008) terminal velocity with
the sphericities of the body's MEASURED orientation, computed here in Python
from the shape geometry (python/foamdem/shapes.py, independent of the C++
kernels). The body's mass comes from the DEM (LIGGGHTS insertion log), its
volume-equivalent diameter from the coupling's particle cloud (lagrangian d),
the void fraction from the last written field (it enters Re = eps rho |w|
d_v/mu). Fails if the terminal-velocity error exceeds --tol, if the run did
not reach 0.1 % of the terminal velocity by the model's own ODE, if the
orientation is not the prescribed one, or if a frozen body spun.

Free rotation: the angle of the long axis to the vertical over time is
written to results/orientation.dat and reported; the same terminal-velocity
check is applied at the measured orientation. With the pitching torque on
(Allrun -torque, default for free rotation) the rod must end within
--broadside-tol degrees of broadside-on (long axis horizontal; plate: face
horizontal). The exchange plan must list 'torque' exactly when the torque
model is on.

Writes results/summary.dat (and results/settling.png without --no-plot).
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "../.."), "python"))
from foamdem import caseio, shapes  # noqa: E402


def lig_strings(path):
    """'variable NAME string VALUE' lines."""
    out = {}
    for line in open(path):
        m = re.match(r"\s*variable\s+(\w+)\s+string\s+(\S+)", line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def shape_table(path):
    """hoelzerSommerfeldCoeffs.shapes entries: {type: {key: value}}."""
    text = caseio._strip_comments(open(path).read())
    block = re.search(r"shapes\s*\{(.*?\})\s*\}", text, flags=re.S).group(1)
    out = {}
    for m in re.finditer(r'"?(\d+)"?\s*\{([^}]*)\}', block):
        entries = dict(re.findall(r"(\w+)\s+([^;\s]+)\s*;", m.group(2)))
        out[int(m.group(1))] = entries
    return out


def cloud_values(path):
    """Values of a lagrangian scalar field file: 'N(v1 v2 ...)' or a list."""
    text = caseio._strip_comments(open(path).read())
    body = text.split("}", 1)[1]          # after the FoamFile header
    m = re.search(r"(\d+)\s*\(([^)]*)\)", body)
    return [float(x) for x in m.group(2).split()]


def read_dump(path):
    """Frames of a LIGGGHTS 'custom id x y z' dump: [(step, N x 3 array)];
    a continued run's frames replace the earlier run's from their step on."""
    return caseio.later_segment_wins(
        [(step, cols[:, 1:4]) for step, cols in caseio.dump_frames(path)], lambda f: f[0])


def body_axes(xyz):
    """Principal axes of the sphere centres, by decreasing spread: length,
    width, thickness (for the rod, width/thickness are any normal pair)."""
    c = xyz - xyz.mean(axis=0)
    _, _, vt = np.linalg.svd(c, full_matrices=False)
    axes = list(vt)
    while len(axes) < 3:
        axes.append(np.cross(axes[0], axes[1] if len(axes) > 1 else
                             np.cross(axes[0], [0.3, 0.5, 0.8])))
    e0 = axes[0] / np.linalg.norm(axes[0])
    e1 = axes[1] - np.dot(axes[1], e0) * e0
    e1 /= np.linalg.norm(e1)
    return e0, e1, np.cross(e0, e1)


def cell_uz(case, time, pos):
    """Vertical fluid velocity in the cell holding pos: the mesh is one
    uniform blockMesh block from the origin (system/blockMeshDict)."""
    text = caseio._strip_comments(open(os.path.join(case, "system/blockMeshDict")).read())
    scale = float(re.search(r"scale\s+([-+0-9.eE]+)\s*;", text).group(1))
    verts = re.search(r"vertices\s*\((.*?)\)\s*;", text, flags=re.S).group(1)
    pts = np.array([[float(x) for x in v.split()]
                    for v in re.findall(r"\(([^()]*)\)", verts)]) * scale
    n = [int(x) for x in re.search(r"hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)",
                                   text).groups()]
    ext = pts.max(axis=0)
    ijk = [min(n[k] - 1, int(pos[k] / ext[k] * n[k])) for k in range(3)]
    cell = ijk[0] + n[0] * (ijk[1] + n[1] * ijk[2])
    u = re.findall(r"\(([-+0-9.eE]+) ([-+0-9.eE]+) ([-+0-9.eE]+)\)",
                   open(os.path.join(case, time, "U")).read())
    return float(u[cell][2])


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--case", default=".")
    ap.add_argument("--tol", type=float, default=0.01,
                    help="bound on |v_DEM - v_t|/v_t at the end (default 0.01)")
    ap.add_argument("--broadside-tol", type=float, default=3.0,
                    help="free rotation with torque: bound on |angle - 90| at"
                         " the end [deg] (default 3)")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    case = args.case
    checks = []

    setup = lig_strings(os.path.join(case, "DEM/post/setup.lig"))
    shape_name, orient = setup["shape"], setup["orientation"]
    torque_on = setup.get("torque", "off") == "on"
    plan_torque = any(l.strip().startswith("torque (to DEM)")
                      for l in open(os.path.join(case, "log.pisoDEMFoam")))
    checks.append(("exchange plan lists torque iff the torque model is on",
                   plan_torque == torque_on))
    frozen = orient != "free"
    cp = os.path.join(case, "constant/couplingProperties")
    table = shape_table(cp)
    mtype = 1 if shape_name == "rod" else 2
    spec = table[mtype]
    if spec["shape"] == "spherocylinder":
        body = shapes.Spherocylinder(float(spec["diameter"]), float(spec["length"]))
    else:
        body = shapes.Plate(float(spec["length"]), float(spec["width"]),
                            float(spec["thickness"]))

    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    rhop = par["rhop"]
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    g = float(np.linalg.norm(caseio.foam_vector(os.path.join(case, "constant/g"), "value")))

    # The body as the DEM and the coupling have it
    # (a continued run: the insertion is in the first run's log, kept by
    # Allrun -continue as log.liggghts.before_continue_<time>)
    log = "".join(open(p).read() for p in
                  sorted(glob.glob(os.path.join(case, "log.liggghts.before_continue_*")))
                  + [os.path.join(case, "log.liggghts")])
    masses = re.findall(r"inserted (\d+) particle templates \(mass ([-+0-9.eE]+)\)", log)
    n_ins = sum(int(n) for n, _ in masses)
    m_body = float(masses[0][1])
    last = caseio.time_dirs(case)[-1]
    d_cloud = cloud_values(os.path.join(case, last, "lagrangian/particles/d"))
    d = d_cloud[0]
    vol = math.pi * d ** 3 / 6
    d_ideal = shapes.d_v(body)
    m_ideal = rhop * body.volume()
    checks.append(("one body inserted", n_ins == 1 and len(d_cloud) == 1))
    checks.append(("mass = ideal shape's (1e-6)", abs(m_body / m_ideal - 1) < 1e-6))
    checks.append(("d_v = ideal shape's (1e-6)", abs(d / d_ideal - 1) < 1e-6))

    eps = min(caseio.scalar_field_values(os.path.join(case, last, "voidfraction")))

    hist = np.array(caseio.later_segment_wins(
        np.loadtxt(os.path.join(case, "DEM/post/history.dat"), ndmin=2), lambda r: r[0]))
    t_dem, v_dem = hist[:, 0], -hist[:, 6]
    omega_max = float(np.max(np.abs(hist[:, 7:10])))
    lateral = float(np.max(np.hypot(hist[:, 4], hist[:, 5])))
    n_spheres = hist[:, 10]
    t_end = t_dem[-1]
    checks.append(("sphere count constant", np.all(n_spheres == n_spheres[0])))
    checks.append(("finite history", np.all(np.isfinite(hist))))

    # Orientation over time from the sphere centres
    frames = read_dump(os.path.join(case, "DEM/post/spheres.dump"))
    dt = t_dem[1] - t_dem[0]
    step0 = 1
    ang = []
    for step, xyz in frames:
        e0, e1, e2 = body_axes(xyz)
        tilt = math.degrees(math.acos(min(1.0, abs(e0[2]))))
        thick = math.degrees(math.acos(min(1.0, abs(e2[2]))))
        ang.append(((step - step0) * dt / 100, tilt, thick, e0, e1, e2))
    e0, e1, e2 = ang[-1][3:]
    z = np.array([0.0, 0.0, 1.0])
    if isinstance(body, shapes.Spherocylinder):
        ca = abs(float(np.dot(e0, z)))
        f_body = (ca, math.sqrt(max(0.0, 1 - ca * ca)), 0.0)
    else:
        f_body = tuple(abs(float(np.dot(e, z))) for e in (e0, e1, e2))
    tilt_end, thick_end = ang[-1][1], ang[-1][2]
    tilt_0 = ang[0][1]
    if orient == "edgewise":
        checks.append(("long axis vertical (0.5 deg)", tilt_end < 0.5))
    elif orient == "broadside":
        ok = abs(tilt_end - 90) < 0.5
        if isinstance(body, shapes.Plate):
            ok = ok and thick_end < 0.5
        checks.append(("long axis (plate: face) horizontal (0.5 deg)", ok))
    if frozen:
        checks.append(("no spin (rotation frozen)", omega_max == 0.0))
    broadside_dev = abs(thick_end if isinstance(body, shapes.Plate) else 90 - tilt_end)
    if not frozen and torque_on:
        checks.append(("broadside-on reached (%g deg)" % args.broadside_tol,
                       broadside_dev <= args.broadside_tol))

    def first_time(pred):
        for a in ang:
            if pred(a):
                return "%.3f" % a[0]
        return "never"

    # Hoelzer-Sommerfeld prediction at the measured orientation
    sph = shapes.sphericities(body, f_body)
    net = (m_body - rho * vol) * g
    v_t = shapes.terminal_velocity(net, d, rho, mu, eps, sph)

    # The model's own ODE from rest: was the terminal velocity reached?
    h = 1e-5
    n = int(round(t_end / h))
    t_ode = np.linspace(0, n * h, n + 1)
    v_ode = np.zeros(n + 1)

    def acc(v):
        return (net - shapes.hs_force(abs(v), d, rho, mu, eps, sph)) / m_body
    for k in range(n):
        v = v_ode[k]
        k1 = acc(v)
        k2 = acc(v + 0.5 * h * k1)
        k3 = acc(v + 0.5 * h * k2)
        k4 = acc(v + h * k3)
        v_ode[k + 1] = v + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    reached = abs(v_ode[-1] - v_t) / v_t
    checks.append(("ODE within 0.1 % of v_t at t_end", reached < 1e-3))

    err = abs(v_dem[-1] - v_t) / v_t
    err_hist = float(np.max(np.abs(v_dem - np.interp(t_dem, t_ode, v_ode)))) / v_t
    checks.append(("terminal velocity within tol", err <= args.tol))
    re_t = eps * rho * v_t * d / mu

    uz_cell = cell_uz(case, last, hist[-1, 1:4])
    err_slip = abs(v_dem[-1] + uz_cell - v_t) / v_t

    u_max = max(np.linalg.norm(np.array(
        [float(x) for x in re.findall(r"[-+0-9.eE]+", l)]))
        for l in re.findall(r"\(([-+0-9.eE]+ [-+0-9.eE]+ [-+0-9.eE]+)\)",
                            open(os.path.join(case, last, "U")).read()))

    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    with open(os.path.join(case, "results/orientation.dat"), "w") as f:
        f.write("# t [s]  angle(long axis, vertical) [deg]  angle(thickness axis, vertical) [deg]\n")
        for a in ang:
            f.write("%.5f %.4f %.4f\n" % a[:3])

    ok = all(c for _, c in checks)
    rows = [
        ("shape", "%s (%s)" % (shape_name, spec["shape"])),
        ("orientation", orient + (" (rotation frozen)" if frozen else " (rotation free)")),
        ("mass_DEM_kg", "%.6e" % m_body),
        ("d_v_m", "%.6e" % d),
        ("rhoParticle_kg_m3", "%g" % rhop),
        ("voidFraction", "%.6f" % eps),
        ("flowDirBody", "(%.4f %.4f %.4f)" % f_body),
        ("Phi_PhiPerp_PhiPar", "%.4f %.4f %.4f" % sph),
        ("Re_terminal", "%.3f" % re_t),
        ("v_terminal_HS_m_s", "%.6e" % v_t),
        ("v_DEM_end_m_s", "%.6e" % v_dem[-1]),
        ("t_end_s", "%g" % t_end),
        ("terminalError", "%.3e" % err),
        ("historyMaxError", "%.3e" % err_hist),
        ("fluidSpeedMax_m_s", "%.3e" % u_max),
        ("fluidUz_bodyCell_m_s", "%.3e" % uz_cell),
        ("slipError_cellFluid (report)", "%.3e" % err_slip),
        ("lateralSpeedMax_m_s", "%.3e" % lateral),
        ("omegaMax_rad_s", "%.3e" % omega_max),
        ("axisTilt_start_deg", "%.3f" % tilt_0),
        ("axisTilt_end_deg", "%.3f" % tilt_end),
        ("tolerance", "%g" % args.tol),
    ]
    if not frozen:
        rows.append(("pitchingTorque", "on" if torque_on else "off"))
        rows.append(("broadsideDeviation_end_deg", "%.3f" % broadside_dev))
        key = 2 if isinstance(body, shapes.Plate) else 1
        for lim in (10, 5, 2):
            rows.append(("time_within_%d_deg_of_broadside_s" % lim, first_time(
                lambda a: (a[key] if key == 2 else 90 - a[key]) <= lim)))
    rows += [("check: " + name, "ok" if c else "FAILED") for name, c in checks]
    rows.append(("pass", "yes" if ok else "no"))
    caseio.write_summary(case, rows)

    if not args.no_plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        ax.plot(t_ode, v_ode, "k-", lw=1, label="ODE, Hoelzer-Sommerfeld")
        ax.plot(t_dem[::5], v_dem[::5], "o", ms=3, mfc="none", label="foamDEM (DEM)")
        ax.axhline(v_t, color="grey", ls=":", label="terminal velocity")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("settling velocity [m/s]")
        ax.set_title("%s %s, Re_t = %.1f, error %.2f %%"
                     % (shape_name, orient, re_t, 100 * err))
        ax.legend(loc="lower right")
        ax2.plot([a[0] for a in ang], [a[1] for a in ang], "-o", ms=3)
        ax2.set_xlabel("t [s]")
        ax2.set_ylabel("long axis to vertical [deg]")
        ax2.set_ylim(-5, 95)
        fig.tight_layout()
        fig.savefig(os.path.join(case, "results/settling.png"), dpi=100)

    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
