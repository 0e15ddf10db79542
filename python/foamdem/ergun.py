"""Packed-bed helpers for foamDEM validations.

Ergun's pressure gradient and minimum fluidisation, the exact volume of
spheres inside horizontal slabs (void-fraction profiles and bed height from
the particle data), and readers for what a packed-bed check needs from a
case: the particle cloud (<time>/lagrangian/<cloud>/positions, d, U), patch
values (e.g. the inlet flux phi) and horizontal cell layers.

Formulas: /work/shared/reference/correlations.md ("Packed and fluidised
beds"): Ergun (1952), dP/L = 150 mu U phi^2/(eps^3 d^2)
+ 1.75 rho U^2 phi/(eps^3 d), U superficial, phi = 1 - eps; Wen and Yu
(1966), Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7.
"""
import math
import os
import re

import numpy as np

_NUMBER = r"[-+0-9.eE]+"


# ----------------------------------------------------------------- physics

def ergun_gradient(U, eps, d, rho, mu):
    """Ergun's pressure gradient -dp/dz [Pa/m] at superficial velocity U."""
    U = np.asarray(U, dtype=float)
    eps = np.asarray(eps, dtype=float)
    phi = 1.0 - eps
    return (150.0 * mu * U * phi ** 2 / (eps ** 3 * d ** 2)
            + 1.75 * rho * U * np.abs(U) * phi / (eps ** 3 * d))


def ergun_umf(eps, d, rho, rhop, mu, g):
    """Minimum fluidisation velocity: the U at which Ergun's gradient equals
    the bed's buoyant weight per volume, (1 - eps)(rho_p - rho) g."""
    phi = 1.0 - eps
    a = 1.75 * rho * phi / (eps ** 3 * d)
    b = 150.0 * mu * phi ** 2 / (eps ** 3 * d ** 2)
    c = -phi * (rhop - rho) * g
    return (-b + math.sqrt(b * b - 4.0 * a * c)) / (2.0 * a)


def wen_yu_umf(d, rho, rhop, mu, g):
    """Minimum fluidisation velocity of Wen and Yu (no void fraction)."""
    ar = rho * (rhop - rho) * g * d ** 3 / mu ** 2
    re_mf = math.sqrt(33.7 ** 2 + 0.0408 * ar) - 33.7
    return re_mf * mu / (rho * d)


# ------------------------------------------------------- particle geometry

def _cap_volume(t, r):
    """Volume of a sphere of radius r below the plane at height t above its
    centre (t clipped to [-r, r])."""
    t = np.clip(t, -r, r)
    return np.pi * (r + t) ** 2 * (2.0 * r - t) / 3.0


def sphere_slab_volume(zc, r, a, b):
    """Exact volume of each sphere (centre height zc, radius r) between the
    horizontal planes z = a and z = b > a."""
    zc = np.asarray(zc, dtype=float)
    r = np.broadcast_to(np.asarray(r, dtype=float), zc.shape)
    return _cap_volume(b - zc, r) - _cap_volume(a - zc, r)


def solid_fraction_profile(zc, r, area, edges):
    """Solid fraction of the slabs between consecutive edges (exact sphere
    volumes; the column cross-section is area)."""
    edges = np.asarray(edges, dtype=float)
    out = np.empty(len(edges) - 1)
    for i in range(len(out)):
        out[i] = (np.sum(sphere_slab_volume(zc, r, edges[i], edges[i + 1]))
                  / (area * (edges[i + 1] - edges[i])))
    return out


def bed_top(zc, r, area, z_floor, dz):
    """Top of a bed resting on z = z_floor, and the bulk solid fraction.

    The solid fraction profile is computed in slabs of thickness dz from the
    floor to the highest sphere top. The bulk value phi_b is the median of
    the profile from 2 diameters above the floor to that highest top. The
    bed top is where the profile, scanned downwards, first reaches phi_b/2
    (linear interpolation between slab centres): the top layer's roughness
    counts half, as a dividing surface.
    Returns (z_top, phi_b, slab centres, profile).
    """
    zc = np.asarray(zc, dtype=float)
    r = np.broadcast_to(np.asarray(r, dtype=float), zc.shape)
    z_max = float(np.max(zc + r))
    n = int(math.ceil((z_max - z_floor) / dz))
    edges = z_floor + dz * np.arange(n + 1)
    prof = solid_fraction_profile(zc, r, area, edges)
    zmid = 0.5 * (edges[1:] + edges[:-1])
    d_mean = 2.0 * float(np.mean(r))
    core = zmid > z_floor + 2.0 * d_mean
    phi_b = float(np.median(prof[core]))
    half = 0.5 * phi_b
    above = np.nonzero(prof >= half)[0]
    k = int(above[-1])
    if k + 1 >= len(prof):
        z_top = float(edges[-1])
    else:
        f0, f1 = prof[k], prof[k + 1]
        z_top = float(zmid[k] + (f0 - half) / (f0 - f1) * (zmid[k + 1] - zmid[k]))
    return z_top, phi_b, zmid, prof


# --------------------------------------------------------------- case data

def _body(text):
    """The text after an OpenFOAM file's FoamFile header."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    m = re.search(r"FoamFile\s*\{[^}]*\}", text)
    return text[m.end():] if m else text


def _list(text, ncomp):
    """An OpenFOAM ascii list 'N(...)' or 'N{value}' of scalars (ncomp 1)
    or vectors (ncomp 3), as an array."""
    m = re.match(r"\s*(\d+)\s*\{\s*(.*?)\s*\}", text, flags=re.S)
    if m:
        n = int(m.group(1))
        vals = [float(x) for x in re.findall(_NUMBER, m.group(2))]
        return np.tile(np.array(vals[:ncomp]), (n, 1)).squeeze()
    m = re.match(r"\s*(\d+)\s*\((.*)\)", text, flags=re.S)
    if not m:
        raise ValueError("not an OpenFOAM list: %r" % text[:60])
    n = int(m.group(1))
    vals = np.array(re.findall(_NUMBER, m.group(2)), dtype=float)
    if vals.size != n * ncomp:
        raise ValueError("list of %d entries holds %d numbers" % (n, vals.size))
    return vals.reshape(n, ncomp).squeeze() if ncomp > 1 else vals


def cloud_positions(case, time, cloud="particles"):
    """Cartesian positions (N x 3) of a cloud from its 'positions' file
    (lines '(x y z) celli')."""
    path = os.path.join(case, time, "lagrangian", cloud, "positions")
    rows = re.findall(r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)\s*-?\d+" % ((_NUMBER,) * 3),
                      _body(open(path).read()))
    return np.array(rows, dtype=float).reshape(-1, 3)


def cloud_field(case, time, name, cloud="particles"):
    """A scalar (d) or vector (U, f) field of a cloud."""
    path = os.path.join(case, time, "lagrangian", cloud, name)
    body = _body(open(path).read()).strip()
    ncomp = 3 if re.match(r"\d+\s*[({]\s*\(", body) else 1
    return _list(body, ncomp)


def patch_entry(path, patch, key="value"):
    """The raw text of an entry of a patch in a field file's boundaryField."""
    text = _body(open(path).read())
    m = re.search(r"boundaryField\s*\{", text)
    pos = m.end()
    m = re.search(r"(?m)^\s*\"?%s\"?\s*\{" % re.escape(patch), text[pos:])
    if not m:
        raise KeyError("%s: no patch %s" % (path, patch))
    start = pos + m.end()
    depth, i = 1, start
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    block = text[start:i - 1]
    m = re.search(r"(?m)^\s*%s\s+(.*?);" % re.escape(key), block, flags=re.S)
    if not m:
        raise KeyError("%s: patch %s has no %s" % (path, patch, key))
    return m.group(1)


def patch_scalars(path, patch):
    """Values of a scalar field (e.g. phi) on a patch."""
    value = patch_entry(path, patch).strip()
    m = re.match(r"uniform\s+(%s)$" % _NUMBER, value)
    if m:
        return np.array([float(m.group(1))])
    m = re.match(r"nonuniform\s+List<scalar>\s*(.*)$", value, flags=re.S)
    return _list(m.group(1), 1)


def mesh_bounds(case):
    """Bounding box (min, max) of constant/polyMesh/points (ascii)."""
    path = os.path.join(case, "constant", "polyMesh", "points")
    pts = _list(_body(open(path).read()).strip(), 3)
    return pts.min(axis=0), pts.max(axis=0)


def cell_layers(cz, tol=1e-9):
    """Distinct cell-centre heights (sorted) and, per cell, its layer index."""
    cz = np.asarray(cz, dtype=float)
    order = np.argsort(cz)
    levels = []
    index = np.empty(len(cz), dtype=int)
    for i in order:
        if not levels or cz[i] - levels[-1] > tol:
            levels.append(cz[i])
        index[i] = len(levels) - 1
    return np.array(levels), index


def patch_n_faces(case, patch):
    """Number of faces of a patch (constant/polyMesh/boundary)."""
    text = _body(open(os.path.join(case, "constant", "polyMesh", "boundary")).read())
    m = re.search(r"\b%s\s*\{[^}]*?nFaces\s+(\d+)\s*;" % re.escape(patch), text, flags=re.S)
    if not m:
        raise KeyError("no patch %s in constant/polyMesh/boundary" % patch)
    return int(m.group(1))
