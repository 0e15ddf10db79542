"""Slug statistics of periodic pneumatic conveying from LIGGGHTS output.

Inputs are the files the densePneumaticConveying tutorial writes:
  - axial profiles of 'fix ave/spatial ... x lower dx vx density/mass'
    (one block per output step: bin, coordinate, count, mean v_x, mass per
    bin volume);
  - particle dumps 'id x y z vx vy vz ix' (ix: image flag along x);
  - the flowController log (time, mean gas velocity, target, force, ...).

Slug identification: axial bins whose solid fraction exceeds a threshold
are dense; on the periodic axis the slug is the longest connected run of
dense bins (the run may wrap around the periodic plane). Its ends are
refined by linear interpolation of the solid fraction to the threshold
between the last dense and the first dilute bin.
"""
import glob
import os
import re

import numpy as np


def read_axial(path):
    """Blocks of a fix ave/spatial file -> (steps[nt], coord[nb],
    count[nt, nb], vx[nt, nb], rho[nt, nb])."""
    steps, counts, vxs, rhos = [], [], [], []
    coord = None
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    i = 0
    while i < len(lines):
        head = lines[i].split()
        if not head:
            i += 1
            continue
        step, nb = int(head[0]), int(head[1])
        block = np.array([[float(x) for x in l.split()] for l in lines[i + 1:i + 1 + nb]])
        i += 1 + nb
        if block.shape[0] != nb:
            break  # incomplete last block of a running simulation
        coord = block[:, 1]
        steps.append(step)
        counts.append(block[:, 2])
        vxs.append(block[:, 3])
        rhos.append(block[:, 4])
    if coord is None:
        raise ValueError("%s: no complete block" % path)
    return (np.array(steps), coord, np.array(counts), np.array(vxs), np.array(rhos))


def read_segments(pattern, reader):
    """Concatenate the outputs of a run and its continuations (one file per
    segment, named by its first DEM step); a later segment replaces what an
    earlier one wrote from its first step on."""
    files = glob.glob(pattern)
    key = lambda f: int(re.findall(r"_(\d+)\.dat$", f)[0])
    files.sort(key=key)
    parts = [reader(f) for f in files]
    return files, parts


def longest_circular_run(mask):
    """(start, length) of the longest run of True in a circular boolean
    array; (-1, 0) if none, (0, n) if all True."""
    n = len(mask)
    if not mask.any():
        return -1, 0
    if mask.all():
        return 0, n
    # Start scanning just after a False so that runs do not wrap the scan
    k0 = int(np.argmin(mask)) + 1
    best, best_start, run, run_start = 0, -1, 0, None
    for j in range(n):
        k = (k0 + j) % n
        if mask[k]:
            if run == 0:
                run_start = k
            run += 1
            if run > best:
                best, best_start = run, run_start
        else:
            run = 0
    return best_start, best


def slug_in_profile(phi, coord, dx, threshold):
    """The slug of one axial solid-fraction profile on a periodic axis.

    Returns dict(rear, front, length, bins) with rear/front the upstream and
    downstream ends (x, front unwrapped to be >= rear), or None if no bin is
    dense (or all are: no slug)."""
    n = len(phi)
    dense = phi > threshold
    start, length = longest_circular_run(dense)
    if length == 0 or length == n:
        return None
    last = (start + length - 1) % n
    before = (start - 1) % n
    after = (last + 1) % n

    def frac(inside, outside):
        # Fraction of the way from a dense bin centre to the dilute one
        # where phi falls to the threshold
        a, b = phi[inside], phi[outside]
        return float(np.clip((a - threshold) / max(a - b, 1e-12), 0, 1))

    rear = coord[start] - dx * frac(start, before)
    front = coord[start] + dx * (length - 1) + dx * frac(last, after)
    bins = [(start + j) % n for j in range(length)]
    return {"rear": rear, "front": front, "length": front - rear, "bins": bins}


def unwrap(x, period):
    """Unwrap a periodic position history."""
    x = np.asarray(x, dtype=float)
    out = x.copy()
    for i in range(1, len(x)):
        d = x[i] - x[i - 1]
        out[i] = out[i - 1] + d - period * np.round(d / period)
    return out


def read_dump(path):
    """A LIGGGHTS text dump 'id x y z vx vy vz ix' -> (step, array sorted
    by id). The numbers are parsed in one call (a full-size frame of
    32 194 particles in a fraction of a second)."""
    with open(path) as f:
        head = [f.readline() for _ in range(9)]
        body = f.read()
    step, n = int(head[1]), int(head[3])
    ncol = len(head[8].split()) - 2
    data = np.fromstring(body, sep=" ")
    if n == 0 or data.size != n * ncol:
        raise ValueError("%s: %d atoms listed, %d numbers read" % (path, n, data.size))
    data = data.reshape(n, ncol)
    return step, data[np.argsort(data[:, 0], kind="stable")]


def periodic_crossings(dump_files):
    """Crossings of the periodic plane between consecutive dumps, from the
    image flags: (total crossings, particles that crossed, ids equal in all
    dumps?, particle counts)."""
    files = sorted(dump_files, key=lambda f: int(re.findall(r"\.(\d+)\.txt$", f)[0]))
    total, crossed, same_ids, counts = 0, set(), True, []
    prev = None
    for f in files:
        _, d = read_dump(f)
        counts.append(d.shape[0])
        if prev is not None:
            if d.shape[0] != prev.shape[0] or (d[:, 0] != prev[:, 0]).any():
                same_ids = False
            else:
                dix = d[:, 7] - prev[:, 7]
                total += int(np.abs(dix).sum())
                crossed |= set(d[dix != 0, 0].astype(int))
        prev = d
    return total, len(crossed), same_ids, counts


def read_controller(case):
    """flowController logs of all run segments, concatenated by time:
    columns time, Umean, Ubar, force[m/s^2], force[N/m^3], r, updated."""
    from foamdem import caseio
    rows = []
    # segments in the order they ran (by start time); a continuation's rows
    # replace the earlier segment's from its first time on
    for f in caseio.function_object_segments(case, "*", "flowController.dat"):
        rows.extend(np.loadtxt(f, ndmin=2))
    if not rows:
        raise ValueError("%s: no flowController.dat" % case)
    return np.array(caseio.later_segment_wins(rows, lambda r: r[0]))


# ---------------------------------------------------------------------------
# The reference's measures (Lavrinec et al.; the case page
# dense-pneumatic-conveying.md, "How the reference measured them"), from
# particle frames (dumps 'id x y z vx vy vz ix'):
#   - slices one particle diameter long, void fraction from the particle
#     centres, eps = 1 - N V_p / V_slice, with V_slice the slice of the exact
#     cylinder (pi R^2 dx);
#   - a periodic moving average over nAverage slices;
#   - slug slices: smoothed eps <= 1 - phiMin; the front is the lower edge
#     of the last slug slice, the rear the upper edge of the first; length =
#     front - rear (plus the pipe length if the slug wraps). Of several runs
#     of slug slices the longest is the slug;
#   - slug velocity from the unwrapped front by central differences over
#     +-stencil frames;
#   - particles-in-slug velocity: the magnitude of the mean velocity vector
#     of the particles with rear <= x < front;
#   - solids mass flow rate: the mass of the particles that cross the plane
#     x = xPlane (net, by particle id from frame to frame), accumulated from
#     the first frame and divided by the elapsed time.
# ---------------------------------------------------------------------------

def periodic_moving_average(values, n):
    """Mean over n consecutive entries centred on each (n odd), periodic."""
    half = n // 2
    return sum(np.roll(values, k) for k in range(-half, half + 1)) / n


def reference_slug(x, xlo, L, R, dp, phi_min, n_average, area=None):
    """The slug of one frame by the reference's slices: (rear, front,
    length, number of separate slug runs) or None when no slice (or every
    slice) is slug. x: particle centres along the axis (any image). area:
    the slices' cross-section (default the exact cylinder's, pi R^2)."""
    n = int(round(L / dp))
    width = L / n
    if area is None:
        area = np.pi * R * R
    xw = np.mod(x - xlo, L)
    k = np.minimum((xw / width).astype(int), n - 1)
    count = np.bincount(k, minlength=n)
    eps = 1 - count * (np.pi / 6 * dp ** 3) / (area * width)
    dense = periodic_moving_average(eps, n_average) <= 1 - phi_min
    start, run = longest_circular_run(dense)
    if run == 0 or run == n:
        return None
    runs = int(np.sum(dense & ~np.roll(dense, 1)))
    last = (start + run - 1) % n
    rear = xlo + (start + 1) * width
    front = xlo + last * width
    if last < start:
        front += L
    return rear, front, front - rear, runs


FORCE_KEYS = ("fGasSlug", "fWallSlug", "fGasLayer", "fWallLayer", "massSlug",
              "vxSlug", "vxLayer", "layerMassPerLength")


def force_balance(ref, window, v_front):
    """The slug's axial force balance over the frames selected by window
    (boolean array), from reference_measures' force sums (NaN without the
    force columns in the dumps). v_front: the slug front's velocity.

    In a frame moving with the slug, the layer enters at the front with the
    layer's velocity and leaves at the rear with the slug particles'. The
    pick-up force is the momentum this takes per unit time:
    (mass of layer per length) (v_front - v_layer) (v_slug - v_layer).
    The rest of the gas and wall forces on the slug is carried by contacts
    with the layer and by unsteadiness (the residual)."""
    def mean(key):
        a = ref[key][window]
        a = a[np.isfinite(a)]
        return float(np.mean(a)) if a.size else np.nan
    out = {k: mean(k) for k in FORCE_KEYS}
    lam, vl, vs = out["layerMassPerLength"], out["vxLayer"], out["vxSlug"]
    out["pickUp"] = lam * (v_front - vl) * (vs - vl)
    out["residualSlug"] = out["fGasSlug"] + out["fWallSlug"] - out["pickUp"]
    out["totalParticles"] = (out["fGasSlug"] + out["fWallSlug"]
                             + out["fGasLayer"] + out["fWallLayer"])
    return out


def reference_measures(dump_files, dt, xlo, L, R, dp, rhop, x_plane,
                       phi_min=0.45, n_average=5, area=None):
    """The reference's frame-wise measures of a run's dumps (sorted by step).

    Returns a dict of arrays over the frames: t, rear, front (unwrapped
    along the run), length, vParticles (|mean velocity vector| in the
    slug), runs (separate slug runs in the frame), crossedMass (net mass
    across x_plane since the first frame), enteredMass (the mass of the
    particles beyond x_plane, x_plane < x < xlo + L, that were not there
    in the previous frame; in the first frame all of them: the count of
    the reference's script, see script_mass_flow). Frames without a slug
    have NaN. area: the slices' cross-section (reference_slug)."""
    files = sorted(dump_files, key=lambda f: int(re.findall(r"\.(\d+)\.txt$", f)[0]))
    m = rhop * np.pi / 6 * dp ** 3
    out = {k: np.full(len(files), np.nan) for k in
           ("t", "rear", "front", "length", "vParticles", "runs", "crossedMass",
            "enteredMass") + FORCE_KEYS}
    prev_ids, prev_side, crossed = None, None, 0.0
    prev_beyond = np.zeros(0)
    for i, f in enumerate(files):
        step, d = read_dump(f)
        ids, x, v = d[:, 0], d[:, 1], d[:, 4:7]
        out["t"][i] = step * dt
        # Side of the plane, counted over the periodic images: it changes
        # by one per crossing (x + ix L is the unwrapped position)
        side = np.floor((x + d[:, 7] * L - x_plane) / L)
        if prev_ids is not None:
            if ids.shape != prev_ids.shape or (ids != prev_ids).any():
                raise ValueError("%s: particle ids differ from the previous frame" % f)
            crossed += m * float(np.sum(side - prev_side))
        out["crossedMass"][i] = crossed
        prev_ids, prev_side = ids, side
        beyond = ids[np.mod(x - xlo, L) > x_plane - xlo]
        out["enteredMass"][i] = m * float(np.sum(~np.isin(beyond, prev_beyond)))
        prev_beyond = beyond
        s = reference_slug(x, xlo, L, R, dp, phi_min, n_average, area)
        if s is None:
            continue
        rear, front, length, runs = s
        inside = np.mod(x - rear, L) < length
        out["rear"][i], out["front"][i], out["length"][i] = rear, front, length
        out["runs"][i] = runs
        if inside.any():
            out["vParticles"][i] = float(np.linalg.norm(v[inside].mean(axis=0)))
        if d.shape[1] >= 10:
            # Axial forces of the gas and the wall (dump columns 9 and 10),
            # summed over the slug's particles and over the others (the
            # layer), and the others' mean axial velocity and mass per length
            out["fGasSlug"][i] = float(np.sum(d[inside, 8]))
            out["fWallSlug"][i] = float(np.sum(d[inside, 9]))
            out["fGasLayer"][i] = float(np.sum(d[~inside, 8]))
            out["fWallLayer"][i] = float(np.sum(d[~inside, 9]))
            out["massSlug"][i] = m * float(np.sum(inside))
            out["vxSlug"][i] = float(np.mean(v[inside, 0])) if inside.any() else np.nan
            if (~inside).any() and length < L:
                out["vxLayer"][i] = float(np.mean(v[~inside, 0]))
                out["layerMassPerLength"][i] = m * float(np.sum(~inside)) / (L - length)
    have = np.isfinite(out["front"])
    if have.any():
        out["front"][have] = unwrap(out["front"][have], L)
    return out


def script_mass_flow(t, entered):
    """The solids mass flow rate as the reference's post-processing script
    computes it (read for the comparison; the case page describes the
    intent, "the mass that crosses the plane, accumulated from t = 0 and
    divided by the elapsed time"): at frame i, the entries of the frames
    before it, sum_{k<i} entered_k / (t_i - t_0). The entries count every
    particle that is beyond the plane and was not in the previous frame,
    whichever way it came, and the first frame counts all the particles
    beyond the plane. NaN at the first frame."""
    rate = np.full(len(t), np.nan)
    if len(t) > 1:
        before = np.cumsum(entered)[:-1]
        rate[1:] = before / (t[1:] - t[0])
    return rate


def central_difference(t, x, stencil):
    """dx/dt by central differences over +-stencil samples (NaN where the
    stencil leaves the series or meets a NaN)."""
    v = np.full(len(t), np.nan)
    for i in range(stencil, len(t) - stencil):
        a, b = i - stencil, i + stencil
        v[i] = (x[b] - x[a]) / (t[b] - t[a])
    return v
