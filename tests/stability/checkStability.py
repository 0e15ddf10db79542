#!/usr/bin/python3
"""Checks of a finished stability-suite run (tests/stability/runStability).

Generic checks, always:
  - the solver log has no NaN/Inf and no 'not finite';
  - every written time: voidfraction within [alphaMin, 1] (alphaMin from
    constant/couplingProperties, <voidFraction>Coeffs), U finite;
  - solid volume: sum_c (1 - eps_c) V_c = sum of the volumes of the
    particles written in the mesh at that time (V from 0/V, written by
    postProcess -func writeCellVolumes), relative error <= --volume-tol;
  - momentum balance lines of the log: relative mismatch <= --balance-tol;
  - DEM atom count (DEM/post/count.dat) == --particles, when given.
Case physics (--physics NAME) as described at each function below.
Prints the measured numbers and writes them to results/summary.dat.
Exit status 0 when all checks pass.
"""
import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("FOAMDEM_DIR", "."), "python"))
from foamdem import caseio, drag  # noqa: E402

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?(?:nan|inf)"

results = []     # (key, value) for results/summary.dat
failures = []


def record(key, value):
    results.append((key, value))
    print("%-34s %s" % (key, value))


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL: " + message)
    return ok


# ---------------------------------------------------------------- reading --

def internal_field(path):
    """Internal field values of a vol field file: (n,) or (n, 3) array, or a
    single uniform value (array of one row)."""
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+(\([^)]*\)|\S+?)\s*;", text)
    if m:
        vals = [float(x) for x in re.findall(NUM, m.group(1), flags=re.I)]
        return np.array([vals]) if len(vals) == 3 else np.array(vals)
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(",
                  text)
    if not m:
        raise ValueError("%s: cannot read internalField" % path)
    n = int(m.group(2))
    rest = text[m.end():]
    if m.group(1) == "vector":
        vals = re.findall(r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % (NUM, NUM, NUM),
                          rest, flags=re.I)[:n]
        return np.array([[float(a) for a in v] for v in vals])
    vals = re.findall(NUM, rest.split(")")[0], flags=re.I)[:n]
    return np.array([float(v) for v in vals])


def lagrangian(path):
    """Values of a lagrangian IOField file (scalar or vector); [] when the
    file is absent (nothing written) or empty."""
    if not os.path.isfile(path):
        return np.zeros((0,))
    text = open(path).read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", text)
    text = re.sub(r"//[^\n]*", "", text)
    m = re.search(r"(\d+)\s*\{([^}]*)\}", text)       # uniform list N{value}
    if m:
        vals = [float(x) for x in re.findall(NUM, m.group(2), flags=re.I)]
        return np.array([vals if len(vals) == 3 else vals[0]] * int(m.group(1)))
    m = re.search(r"(\d+)\s*\(", text)
    if not m:
        return np.zeros((0,))
    n = int(m.group(1))
    body = text[m.end():]
    if n == 0:
        return np.zeros((0,))
    vecs = re.findall(r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % (NUM, NUM, NUM), body,
                      flags=re.I)
    if vecs:
        return np.array([[float(a) for a in v] for v in vecs[:n]])
    vals = re.findall(NUM, body, flags=re.I)[:n]
    return np.array([float(v) for v in vals])


def read_dump(path):
    """DEM/post/particles.dump -> list of (step, array[id x y z vx vy vz r m])"""
    snaps = []
    lines = open(path).read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            rows = [list(map(float, lines[i + 9 + k].split()))
                    for k in range(n)]
            snaps.append((step, np.array(rows).reshape(n, 9)))
            i += 9 + n
        else:
            i += 1
    return snaps


def foam_dict_value(case, entry, default=None):
    out = subprocess.run(
        ["foamDictionary", "-entry", entry, "-value",
         os.path.join(case, "constant/couplingProperties")],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    value = out.stdout.strip()
    return value if out.returncode == 0 and value else default


def alpha_min(case):
    model = foam_dict_value(case, "voidFraction")
    value = foam_dict_value(case, model + "Coeffs.alphaMin", "0.3")
    return float(value)


def written_times(case):
    return [t for t in caseio.time_dirs(case)
            if float(t) > 0 and os.path.isfile(os.path.join(case, t, "voidfraction"))]


# --------------------------------------------------------- generic checks --

def check_log(log, expect_clean):
    text = open(log).read()
    bad = re.findall(r"(?i)[^\n]*(?:\bnan\b|\binf\b|not finite)[^\n]*", text)
    record("logLinesWithNaNInf", len(bad))
    if expect_clean:
        check(not bad, "the solver log mentions NaN/Inf: %s" % (bad[:1],))
    return text


def check_fields(case, tol_volume, check_volume, args):
    amin = alpha_min(case)
    V = internal_field(os.path.join(case, "0/V"))
    times = written_times(case)
    check(len(times) > 0, "no time directory with voidfraction written")
    eps_lo, eps_hi, u_max, vol_err = 1.0, 0.0, 0.0, 0.0
    n_in_mesh, n_clipped, solid_max = [], 0, 1.0
    for t in times:
        eps = internal_field(os.path.join(case, t, "voidfraction"))
        if eps.size == 1:
            eps = np.full(V.shape, eps[0])
        U = internal_field(os.path.join(case, t, "U"))
        check(np.all(np.isfinite(eps)), "t = %s: voidfraction not finite" % t)
        check(np.all(np.isfinite(U)), "t = %s: U not finite" % t)
        eps_lo, eps_hi = min(eps_lo, eps.min()), max(eps_hi, eps.max())
        n_clipped += int(np.sum(eps <= amin * (1 + 1e-12)))
        solid_max = min(solid_max, 1 - eps.min())
        u_max = max(u_max, float(np.max(np.linalg.norm(U, axis=-1))))
        check(eps.min() >= amin * (1 - 1e-12),
              "t = %s: voidfraction %.6g below alphaMin %g" % (t, eps.min(), amin))
        check(eps.max() <= 1 + 1e-12,
              "t = %s: voidfraction %.6g above 1" % (t, eps.max()))

        d = lagrangian(os.path.join(case, t, "lagrangian/particles/d"))
        n_in_mesh.append(len(d))
        solid_particles = float(np.sum(np.pi / 6 * d ** 3))
        solid_cells = float(np.sum((1 - eps) * V))
        if solid_particles > 0:
            err = abs(solid_cells - solid_particles) / solid_particles
        else:
            err = abs(solid_cells) / float(np.sum(V))
        vol_err = max(vol_err, err)
        if check_volume:
            check(err <= tol_volume,
                  "t = %s: sum (1-eps) V = %.10g m^3 but particles in the mesh"
                  " %.10g m^3 (relative %.3g > %g)"
                  % (t, solid_cells, solid_particles, err, tol_volume))
    record("alphaMin", amin)
    record("voidfractionMin", "%.6f" % eps_lo)
    record("voidfractionMax", "%.6f" % eps_hi)
    record("UmaxFluid_m_s", "%.4g" % u_max)
    record("cellsAtAlphaMin", n_clipped)
    if args.u_max is not None:
        check(u_max <= args.u_max, "fluid velocity %.3g m/s above %g" % (u_max, args.u_max))
    if args.dense is not None:
        record("minOverWritesOfMaxSolidFraction", "%.4f" % solid_max)
        check(solid_max >= args.dense,
              "densest cell has solid fraction %.3f < %g: not a dense case" % (solid_max, args.dense))
    if args.expect_clipped:
        check(n_clipped > 0, "no cell reached alphaMin: the case does not test the bounding")
    record("solidVolumeRelError", "%.3g" % vol_err)
    record("writtenTimes", " ".join(times))
    record("particlesInMeshPerWrite", " ".join(map(str, n_in_mesh)))
    return times, n_in_mesh


def check_balance(text, tol, n_steps_min):
    values = [float(v) for v in re.findall(
        r"foamDEM momentum balance: .*relative mismatch (%s)" % NUM, text, flags=re.I)]
    record("balanceLines", len(values))
    check(len(values) >= n_steps_min,
          "%d momentum balance lines, expected >= %d" % (len(values), n_steps_min))
    worst = max(values) if values else float("nan")
    record("balanceWorstMismatch", "%.3g" % worst)
    check(all(v <= tol for v in values),
          "momentum balance mismatch %.3g > %g" % (worst, tol))


def dem_counts(case):
    rows = np.loadtxt(os.path.join(case, "DEM/post/count.dat"), ndmin=2)
    return rows[:, 0], rows[:, 1].astype(int)


# --------------------------------------------------------- case physics --

def physics_stiff(case, args):
    """Stiff contacts: a block of spheres hits the floor at v0; every DEM
    step the DEM prints the largest particle-floor and particle-particle
    overlap and the kinetic plus potential energy (DEM/post/stiff.dat).
    (a) The largest overlap stays below the Hertz overlap of a column of k
    spheres hitting a wall at v0 with all its kinetic energy (an upper
    bound: restitution < 1 and the fluid dissipate); (b) the kinetic plus
    potential energy never exceeds its initial value (a too large step
    creates energy at stiff contacts)."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    E, nu, v0, k, r0 = par["E"], 0.3, par["v0"], par["column"], par["dp"] / 2
    m0 = par["rhop"] * math.pi * par["dp"] ** 3 / 6
    a = np.loadtxt(os.path.join(case, "DEM/post/stiff.dat"), ndmin=2)
    worst_wall = float(np.max(a[:, 1]))
    worst_pair = float(np.max(a[:, 2]))
    energy_ratio = float(np.max(a[:, 3] / a[0, 3]))
    # Hertz, sphere on a wall of the same material: E* = E/(2(1-nu^2)),
    # R* = r; energy k (1/2) m v0^2 stored as (8/15) E* sqrt(R*) delta^(5/2)
    e_star = E / (2 * (1 - nu ** 2))
    bound = (15 * k * m0 * v0 ** 2 / (16 * e_star * math.sqrt(r0))) ** 0.4
    single = (15 * m0 * v0 ** 2 / (16 * e_star * math.sqrt(r0))) ** 0.4
    record("demStepsLogged", len(a))
    record("maxOverlapWall_m", "%.4g" % worst_wall)
    record("maxOverlapPair_m", "%.4g" % worst_pair)
    record("hertzOverlapSingleImpact_m", "%.4g" % single)
    record("hertzOverlapBound_m", "%.4g" % bound)
    record("maxOverlapOverRadius", "%.4g" % (max(worst_wall, worst_pair) / r0))
    record("maxEnergyOverInitial", "%.8f" % energy_ratio)
    record("finalEnergyOverInitial", "%.4g" % (a[-1, 3] / a[0, 3]))
    check(worst_wall > 0, "no particle touched the floor: the case tests nothing")
    check(max(worst_wall, worst_pair) <= bound,
          "overlap %.3g m above the Hertz bound %.3g m" % (max(worst_wall, worst_pair), bound))
    check(energy_ratio <= 1 + 1e-9, "kinetic + potential energy grew to %.8f x initial" % energy_ratio)


def cell_index(case, x):
    """Cell of point x in the uniform block mesh of system/blockMeshDict."""
    bmd = os.path.join(case, "system/blockMeshDict")
    L = [caseio.foam_scalar(bmd, k) * 1e-3 for k in ("Lx", "Ly", "Lz")]
    n = [int(caseio.foam_scalar(bmd, k)) for k in ("nx", "ny", "nz")]
    ijk = [min(int(x[d] / L[d] * n[d]), n[d] - 1) for d in range(3)]
    return ijk[0] + n[0] * (ijk[1] + n[1] * ijk[2])


def physics_fine(case, args):
    """Very fine particles (tau_p/dt_CFD = 1e-3), implicit coupling: at the
    last write each particle's slip (particle velocity minus the fluid
    velocity of its cell) equals the terminal velocity of the same drag law
    at the cell's void fraction within --physics-tol, and the total fluid
    force on the particles balances their weight within --physics-tol."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    d, rhop, g = par["dp"], par["rhop"], par["g"]
    t = written_times(case)[-1]
    U = internal_field(os.path.join(case, t, "U"))
    eps = internal_field(os.path.join(case, t, "voidfraction"))
    snaps = read_dump(os.path.join(case, "DEM/post/particles.dump"))
    dt_dem = par["dt"]
    step = int(round(float(t) / dt_dem))
    snap = [a for s, a in snaps if s == step]
    check(len(snap) == 1, "no DEM dump at step %d (t = %s)" % (step, t))
    a = snap[0]
    vol = math.pi * d ** 3 / 6
    tau = rhop * d * d / (18 * mu)
    record("tauP_s", "%.4g" % tau)
    worst = 0.0
    for row in a:
        c = cell_index(case, row[1:4])
        slip = -(row[6] - U[c, 2])        # downward slip
        vt = drag.terminal_velocity(drag.schiller_naumann, d, rho, mu, eps[c],
                                    (rhop - rho) * vol * g)
        worst = max(worst, abs(slip - vt) / vt)
    record("terminalSlip_ODE_m_s", "%.6g" % vt)
    record("terminalSlipMaxRelError", "%.3g" % worst)
    check(worst <= args.physics_tol,
          "slip differs from the terminal velocity by %.3g (> %g)" % (worst, args.physics_tol))
    f = lagrangian(os.path.join(case, t, "lagrangian/particles/f"))
    weight = len(a) * rhop * vol * g
    err_f = abs(np.sum(f[:, 2]) - weight) / weight
    record("forceBalanceRelError", "%.3g" % err_f)
    check(err_f <= args.physics_tol,
          "fluid force on the particles %.6g N vs weight %.6g N" % (np.sum(f[:, 2]), weight))
    vmax = float(np.max(np.abs(U)))
    record("UmaxOverVt", "%.3g" % (vmax / vt))


def physics_high_re(case, args):
    """Slip Reynolds number >= 1e4: a sphere shot at v0 through quiescent
    liquid without gravity decelerates as the ODE m dv/dt = -K(v) v with
    the same drag law (RK4, dt 1e-6 s); max |v_DEM - v_ODE|/v_ODE over the
    history <= --physics-tol, at the end <= --end-tol, and Re >= 1e4 over
    the whole history."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    d, rhop, v0 = par["dp"], par["rhop"], par["v0"]
    law = drag.LAWS[args.law]
    hist = np.loadtxt(os.path.join(case, "DEM/post/history.dat"))
    t_dem, v_dem = hist[:, 0], hist[:, 1]
    m = rhop * math.pi * d ** 3 / 6
    t_end = t_dem[-1]
    h, v, t, ts, vs = 1e-6, v0, 0.0, [0.0], [v0]
    acc = lambda u: -law(d, rho, mu, 1.0, abs(u)) * u / m  # noqa: E731
    while t < t_end + h / 2:
        k1 = acc(v)
        k2 = acc(v + h / 2 * k1)
        k3 = acc(v + h / 2 * k2)
        k4 = acc(v + h * k3)
        v += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += h
        ts.append(t)
        vs.append(v)
    v_ode = np.interp(t_dem, ts, vs)
    err = float(np.max(np.abs(v_dem - v_ode) / v_ode))
    re_min = rho * float(np.min(v_dem)) * d / mu
    record("ReStart", "%.4g" % (rho * v0 * d / mu))
    record("ReEnd", "%.4g" % re_min)
    record("vEnd_DEM_m_s", "%.6g" % v_dem[-1])
    record("vEnd_ODE_m_s", "%.6g" % v_ode[-1])
    err_end = abs(v_dem[-1] - v_ode[-1]) / v_ode[-1]
    record("historyMaxRelError", "%.3g" % err)
    record("endRelError", "%.3g" % err_end)
    check(err_end <= args.end_tol, "end velocity differs from the ODE by %.3g (> %g)" % (err_end, args.end_tol))
    check(re_min >= 1e4, "slip Reynolds number fell to %.4g < 1e4" % re_min)
    check(err <= args.physics_tol, "history differs from the ODE by %.3g (> %g)" % (err, args.physics_tol))


def physics_outside(case, args):
    """A particle outside the mesh gets no fluid force: its vertical
    velocity is free fall, vz = -g t, to --physics-tol relative, while the
    particle inside the mesh is slowed by the fluid (|vz| < 0.5 g t)."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    snaps = read_dump(os.path.join(case, "DEM/post/particles.dump"))
    g, dt = par["g"], par["dt"]
    worst, inside_ratio = 0.0, 0.0
    for step, a in snaps[1:]:
        t = step * dt
        out = a[a[:, 0] == par["idOutside"]][0]
        ins = a[a[:, 0] == par["idInside"]][0]
        worst = max(worst, abs(out[6] + g * t) / (g * t))
        inside_ratio = abs(ins[6]) / (g * t)
    record("freeFallMaxRelError", "%.3g" % worst)
    record("insideVzOverFreeFallAtEnd", "%.3g" % inside_ratio)
    check(worst <= args.physics_tol, "outside particle deviates from free fall by %.3g" % worst)
    check(inside_ratio < 0.5, "inside particle falls freely: it gets no fluid force")


def physics_outlet(case, args):
    """Particles leaving through the outlet: every particle that
    disappears from the DEM was last seen within one coupling step's travel
    of the outlet plane, moving out; the DEM atom count equals the initial
    count minus those departures at every output step; and the particles
    written in the mesh at each write are those of the DEM inside the mesh."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    snaps = read_dump(os.path.join(case, "DEM/post/particles.dump"))
    z_out = par["zlo"]
    n0 = len(snaps[0][1])
    seen = {int(i): row for i, row in zip(snaps[0][1][:, 0], snaps[0][1])}
    gone, bad = set(), []
    t_count, n_count = dem_counts(case)
    count_at = {int(round(t / par["dt"])): n for t, n in zip(t_count, n_count)}
    mismatch = 0
    for step, a in snaps[1:]:
        ids = set(int(i) for i in a[:, 0])
        for i in list(seen):
            if i not in ids and i not in gone:
                row = seen[i]
                travel = abs(row[6]) * par["dt"] * par["nout"] * 2 + row[7]
                if not (row[6] < 0 and row[3] - z_out <= travel):
                    bad.append(i)
                gone.add(i)
        for row in a:
            seen[int(row[0])] = row
        if step in count_at and count_at[step] != n0 - len(gone):
            mismatch += 1
    record("particlesInitial", n0)
    record("particlesLeft", len(gone))
    record("particlesRemaining", n0 - len(gone))
    record("countMismatches", mismatch)
    check(len(gone) > 0, "no particle left: the case tests nothing")
    check(n0 - len(gone) > 0, "all particles left: keep some inside")
    check(not bad, "particles %s vanished away from the outlet" % bad)
    check(mismatch == 0, "DEM atom count != initial - departures at %d steps" % mismatch)
    # Written cloud vs DEM particles inside the mesh at the write times
    for t in written_times(case):
        step = int(round(float(t) / par["dt"]))
        snap = [a for s, a in snaps if s == step]
        if not snap:
            continue
        inside = int(np.sum(snap[0][:, 3] >= z_out))
        n = len(lagrangian(os.path.join(case, t, "lagrangian/particles/d")))
        check(n == inside, "t = %s: %d particles written, %d inside the mesh" % (t, n, inside))


def physics_settle(case, args):
    """Spheres denser than the fluid, released from rest in a closed box,
    settle: (a) no particle ends above its start (1 um slack); (b) no
    particle is ever faster than the terminal velocity of an isolated
    sphere of its size and density in unbounded fluid (Schiller-Naumann,
    eps = 1, python/foamdem/drag.py): walls, neighbours and the return flow
    only slow it down, and the approach to the terminal velocity is
    monotonic; (c) the fluid moves no faster than the fastest particle
    (the flow is driven only by the particles)."""
    par = caseio.liggghts_variables(os.path.join(case, "DEM/parameters"))
    tp = os.path.join(case, "constant/transportProperties")
    rho = caseio.foam_scalar(tp, "rho")
    mu = rho * caseio.foam_scalar(tp, "nu")
    snaps = read_dump(os.path.join(case, "DEM/post/particles.dump"))
    z0 = {int(r[0]): r[3] for r in snaps[0][1]}
    z1 = {int(r[0]): r[3] for r in snaps[-1][1]}
    rise = max(z1[i] - z0[i] for i in z0)
    vt = {}
    for r in snaps[0][1]:
        d, m = 2 * r[7], r[8]
        vol = math.pi * d ** 3 / 6
        vt[int(r[0])] = drag.terminal_velocity(
            drag.schiller_naumann, d, rho, mu, 1.0, (m - rho * vol) * par["g"])
    v_max, ratio = 0.0, 0.0
    for _, a in snaps:
        v = np.linalg.norm(a[:, 4:7], axis=1)
        v_max = max(v_max, float(v.max()))
        ratio = max(ratio, max(v[k] / vt[int(a[k, 0])] for k in range(len(a))))
    u_max = max(float(np.max(np.linalg.norm(
        internal_field(os.path.join(case, t, "U")), axis=-1))) for t in written_times(case))
    record("largestRise_m", "%.4g" % rise)
    record("maxParticleSpeed_m_s", "%.4g" % v_max)
    record("isolatedTerminalVelocity_m_s", "%.4g" % min(vt.values()))
    record("maxParticleSpeedOverTerminal", "%.4g" % ratio)
    record("maxFluidSpeedOverParticle", "%.4g" % (u_max / v_max))
    check(rise <= 1e-6, "a particle rose by %.3g m" % rise)
    check(ratio <= 1.0, "a particle reached %.3g x the terminal velocity of an isolated sphere" % ratio)
    check(u_max <= v_max, "fluid speed %.3g m/s above the fastest particle %.3g m/s" % (u_max, v_max))


def physics_one_cell(case, args):
    """All particles in one cell: at the start every particle centre lies
    in the same cell (the case is what it says); reports how many are still
    there at the end."""
    snaps = read_dump(os.path.join(case, "DEM/post/particles.dump"))
    cells0 = set(cell_index(case, r[1:4]) for r in snaps[0][1])
    record("cellsHoldingParticlesAtStart", len(cells0))
    check(len(cells0) == 1, "particles start in %d cells, not one" % len(cells0))
    c = cells0.pop() if cells0 else -1
    n_end = sum(1 for r in snaps[-1][1] if cell_index(case, r[1:4]) == c)
    record("particlesInThatCellAtEnd", n_end)


PHYSICS = {
    "oneCell": physics_one_cell,
    "settle": physics_settle,
    "stiff": physics_stiff,
    "fine": physics_fine,
    "highRe": physics_high_re,
    "outside": physics_outside,
    "outlet": physics_outlet,
}


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--particles", type=int, help="expected constant DEM atom count")
    ap.add_argument("--outside", type=int, default=0,
                    help="particles outside the mesh (not written) at every write")
    ap.add_argument("--balance-tol", type=float, default=1e-10)
    ap.add_argument("--volume-tol", type=float, default=1e-9)
    ap.add_argument("--no-volume", action="store_true",
                    help="report, but do not check, the solid volume")
    ap.add_argument("--expect", action="append", default=[],
                    help="regular expression the solver log must contain")
    ap.add_argument("--u-max", type=float, help="bound on |U| at the writes")
    ap.add_argument("--dense", type=float,
                    help="the densest cell's solid fraction must reach this at every write")
    ap.add_argument("--expect-clipped", action="store_true",
                    help="some cell must be at alphaMin (the bounding is exercised)")
    ap.add_argument("--physics", choices=sorted(PHYSICS))
    ap.add_argument("--physics-tol", type=float, default=0.01)
    ap.add_argument("--end-tol", type=float, default=0.005)
    ap.add_argument("--law", default="schillerNaumann")
    args = ap.parse_args()
    case = args.case

    text = check_log(os.path.join(case, "log.pisoDEMFoam"), True)
    for rx in args.expect:
        check(re.search(rx, text) is not None, "expected /%s/ in the solver log" % rx)
    times, n_in_mesh = check_fields(case, args.volume_tol, not args.no_volume, args)
    n_steps = len(re.findall(r"(?m)^Time = ", text))
    check_balance(text, args.balance_tol, n_steps)

    if args.particles is not None:
        t, n = dem_counts(case)
        record("demAtomCountMinMax", "%d %d" % (n.min(), n.max()))
        check(np.all(n == args.particles),
              "DEM atom count %d..%d, expected %d" % (n.min(), n.max(), args.particles))
        check(all(k == args.particles - args.outside for k in n_in_mesh),
              "particles written in the mesh %s, expected %d"
              % (n_in_mesh, args.particles - args.outside))
    if args.physics:
        PHYSICS[args.physics](case, args)

    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    with open(os.path.join(case, "results/summary.dat"), "w") as f:
        for k, v in results:
            f.write("%-34s %s\n" % (k, v))
        f.write("%-34s %s\n" % ("pass", "no" if failures else "yes"))
    print("%d check(s) failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
