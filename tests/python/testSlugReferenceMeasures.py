#!/usr/bin/python3
"""Unit test of foamdem.slug's reference measures (the densePneumaticConveying
case page's definitions) on synthetic particle frames whose answers follow
by hand from those definitions:

- a periodic pipe (L = 1 m, R = 0.042 m, d = 5 mm) holds a slug of solid
  fraction 0.6 over 0.4 m and a layer of 0.3 elsewhere, particles spread
  evenly along x in each region;
- one slice in the middle of the slug holds half its particles;
- the whole pattern translates rigidly at u along x (positions wrapped into
  the box with image flags), the slug particles carry the velocity vector
  (0.8, 0, 0.6) (magnitude 1), the layer's (0.1, 0, 0).

Expected: the moving average bridges the looser slice (one slug); with
the threshold 0.45 midway between 0.6 and 0.3, the 5-slice
moving average marks exactly the slug's 80 slices; the front is the lower
edge of the last, the rear the upper edge of the first, so the length is
0.4 - 2 d = 0.39 m; the slug velocity is u; the particles-in-slug velocity
is 1; the mass crossing a fixed plane over a time in which the pattern
moves a whole number of pipe lengths is exactly M u T / L.

Force balance (frames with the two force columns of the tutorial's dumps):
slug particles more than 2 d inside the slug's ends carry a gas force of
1 mN and a wall force of -0.4 mN, layer particles more than 2 d from the
slug 0.2 mN and -0.25 mN, the others none; the sums over the reference's
slug and over the rest are then those counts times the forces, and the
slug particles' mean axial velocity is 0.8.

The reference's script's variants (ScriptMeasures): slices of a smaller
cross-section lengthen the slug by a slice at each end (by hand from the
5-slice averages); its entries beyond the plane equal the net crossings
for the rigid pattern, count the first frame's particles beyond the plane,
and count a particle that crosses forward, back and forward twice, also
when its position is a periodic image outside the box.
"""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from foamdem import slug  # noqa: E402

L, XLO, R, DP, RHOP = 1.0, -0.5, 0.042, 0.005, 890.0
DT_DEM = 5e-6
VP = np.pi / 6 * DP ** 3


def make_pattern(slug_length=0.4, phi_slug=0.6, phi_layer=0.3):
    """Particle x (relative to the slug rear at 0), and whether in the slug."""
    per_m = lambda phi: phi * np.pi * R * R / VP
    n_s = int(round(per_m(phi_slug) * slug_length))
    n_l = int(round(per_m(phi_layer) * (L - slug_length)))
    xs = (np.arange(n_s) + 0.5) * slug_length / n_s
    # A looser slice in the middle of the slug (half its particles): the
    # moving average bridges it, the raw slices would split the slug
    hole = np.flatnonzero((xs >= 0.2) & (xs < 0.2 + DP))[::2]
    xs = np.delete(xs, hole)
    n_s = len(xs)
    xl = slug_length + (np.arange(n_l) + 0.5) * (L - slug_length) / n_l
    return np.concatenate([xs, xl]), np.concatenate([np.ones(n_s, bool), np.zeros(n_l, bool)])


F_SLUG, W_SLUG, F_LAYER, W_LAYER = 1e-3, -4e-4, 2e-4, -2.5e-4


def pattern_forces(x0, in_slug):
    core = in_slug & (x0 > 2 * DP) & (x0 < 0.4 - 2 * DP)
    far = ~in_slug & (x0 > 0.4 + 2 * DP) & (x0 < L - 2 * DP)
    fg = np.where(core, F_SLUG, np.where(far, F_LAYER, 0.0))
    fw = np.where(core, W_SLUG, np.where(far, W_LAYER, 0.0))
    return fg, fw, int(core.sum()), int(far.sum())


def write_frames(folder, u, dt_frame, n_frames, rear0=-0.3, forces=False):
    x0, in_slug = make_pattern()
    n = len(x0)
    v = np.where(in_slug[:, None], [0.8, 0.0, 0.6], [0.1, 0.0, 0.0])
    fg, fw, _, _ = pattern_forces(x0, in_slug)
    files = []
    for k in range(n_frames):
        xu = XLO + np.mod(rear0 - XLO, L) + x0 + u * k * dt_frame  # unwrapped
        ix = np.floor((xu - XLO) / L)
        x = xu - ix * L
        step = int(round(k * dt_frame / DT_DEM))
        path = os.path.join(folder, "particles.%d.txt" % step)
        with open(path, "w") as f:
            f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (step, n))
            f.write("ITEM: BOX BOUNDS pp ff ff\n-0.5 0.5\n-0.044 0.044\n-0.044 0.044\n")
            cols = [np.arange(1, n + 1), x, np.zeros(n), np.zeros(n), v, ix]
            if forces:
                f.write("ITEM: ATOMS id x y z vx vy vz ix v_fxGas f_force_pipeWall[1]\n")
                np.savetxt(f, np.column_stack(cols + [fg, fw]),
                           fmt="%d %.9g %g %g %g %g %g %d %.9g %.9g")
            else:
                f.write("ITEM: ATOMS id x y z vx vy vz ix\n")
                np.savetxt(f, np.column_stack(cols), fmt="%d %.9g %g %g %g %g %g %d")
        files.append(path)
    return files, n * RHOP * VP


class ReferenceMeasures(unittest.TestCase):

    def run_case(self, u, n_frames, forces=False):
        with tempfile.TemporaryDirectory() as tmp:
            files, mass = write_frames(tmp, u, 0.025, n_frames, forces=forces)
            out = slug.reference_measures(files, DT_DEM, XLO, L, R, DP, RHOP, 0.375)
        return out, mass

    def test_aligned(self):
        # u dt = 0.04 m: eight slices per frame; 0.625 s: one pipe length
        out, mass = self.run_case(1.6, 26)
        t = out["t"]
        self.assertTrue(np.all(np.isfinite(out["length"])))
        np.testing.assert_allclose(out["length"], 0.4 - 2 * DP, atol=1e-9)
        self.assertTrue(np.all(out["runs"] == 1))
        v = slug.central_difference(t, out["front"], 3)
        np.testing.assert_allclose(v[3:-3], 1.6, rtol=1e-9)
        self.assertTrue(np.all(np.isnan(v[:3])) and np.all(np.isnan(v[-3:])))
        np.testing.assert_allclose(out["vParticles"], 1.0, rtol=1e-12)
        mdot = out["crossedMass"][-1] / (t[-1] - t[0])
        self.assertAlmostEqual(mdot / (mass * 1.6 / L), 1.0, places=12)

    def test_not_aligned(self):
        # u dt = 0.0325 m (6.5 slices): the ends jitter by at most a slice
        out, mass = self.run_case(1.3, 21)
        self.assertTrue(np.all(np.abs(out["length"] - (0.4 - 2 * DP)) <= DP + 1e-9))
        v = slug.central_difference(out["t"], out["front"], 3)[3:-3]
        self.assertLess(np.max(np.abs(v / 1.3 - 1)), DP / (6 * 0.0325) + 1e-9)
        np.testing.assert_allclose(out["vParticles"], 1.0, rtol=1e-12)

    def test_force_balance(self):
        out, _ = self.run_case(1.6, 26, forces=True)
        _, _, n_core, n_far = pattern_forces(*make_pattern())
        np.testing.assert_allclose(out["fGasSlug"], n_core * F_SLUG, rtol=1e-9)
        np.testing.assert_allclose(out["fWallSlug"], n_core * W_SLUG, rtol=1e-9)
        np.testing.assert_allclose(out["fGasLayer"], n_far * F_LAYER, rtol=1e-9)
        np.testing.assert_allclose(out["fWallLayer"], n_far * W_LAYER, rtol=1e-9)
        np.testing.assert_allclose(out["vxSlug"], 0.8, rtol=1e-12)
        fb = slug.force_balance(out, np.ones(len(out["t"]), bool), 1.6)
        self.assertAlmostEqual(fb["totalParticles"],
                               n_core * (F_SLUG + W_SLUG) + n_far * (F_LAYER + W_LAYER), places=12)
        # without the force columns: no force balance
        out, _ = self.run_case(1.6, 4)
        self.assertTrue(np.all(np.isnan(out["fGasSlug"])))


class ScriptMeasures(unittest.TestCase):
    """The reference's post-processing script's variants of the measures:
    slices of another cross-section (its mesh's) and the mass flow from the
    particles that enter the part of the pipe beyond the plane."""

    def test_area(self):
        # Slices of a cross-section 1.15 times smaller: the solid fractions
        # scale by 1.15, so a 5-slice window with 2 slug slices (0.42 x
        # 1.15 = 0.483) is slug and one with 1 (0.36 x 1.15 = 0.414) is
        # not: the slug gains a slice at each end, 82 slices, length 0.40 m
        with tempfile.TemporaryDirectory() as tmp:
            files, _ = write_frames(tmp, 1.6, 0.025, 4)
            out = slug.reference_measures(files, DT_DEM, XLO, L, R, DP, RHOP, 0.375,
                                          area=np.pi * R * R / 1.15)
        np.testing.assert_allclose(out["length"], 0.4, atol=1e-9)

    def test_entries_rigid(self):
        # The rigid pattern moves 0.04 m per frame, less than the 0.125 m
        # beyond the plane: every particle that crosses enters once, so the
        # entries after the first frame are the net crossings; the first
        # frame counts the layer beyond the plane (0.375-0.5 m lies in the
        # layer: phi 0.3 over 0.125 m of pipe, to one particle)
        with tempfile.TemporaryDirectory() as tmp:
            files, _ = write_frames(tmp, 1.6, 0.025, 26)
            out = slug.reference_measures(files, DT_DEM, XLO, L, R, DP, RHOP, 0.375)
        m = RHOP * VP
        np.testing.assert_allclose(out["enteredMass"][1:], np.diff(out["crossedMass"]),
                                   rtol=0, atol=1e-12)
        first = 0.3 * np.pi * R * R * 0.125 * RHOP
        self.assertLessEqual(abs(out["enteredMass"][0] - first), m)
        rate = slug.script_mass_flow(out["t"], out["enteredMass"])
        self.assertTrue(np.isnan(rate[0]))
        # frame i: the entries of frames 0..i-1 over t_i - t_0
        i = 10
        self.assertAlmostEqual(rate[i], np.sum(out["enteredMass"][:i]) / (out["t"][i] - out["t"][0]),
                               places=14)

    @staticmethod
    def measure_positions(frames):
        """reference_measures of frames given as lists of x (ids 1, 2, ...
        at rest, y = z = 0, image flag 0), one frame per 1000 DEM steps."""
        with tempfile.TemporaryDirectory() as tmp:
            files = []
            for k, xs in enumerate(frames):
                path = os.path.join(tmp, "particles.%d.txt" % (1000 * k))
                with open(path, "w") as f:
                    f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (1000 * k, len(xs)))
                    f.write("ITEM: BOX BOUNDS pp ff ff\n-0.5 0.5\n-0.044 0.044\n-0.044 0.044\n")
                    f.write("ITEM: ATOMS id x y z vx vy vz ix\n")
                    for i, x in enumerate(xs):
                        f.write("%d %g 0 0 0 0 0 0\n" % (i + 1, x))
                files.append(path)
            return slug.reference_measures(files, DT_DEM, XLO, L, R, DP, RHOP, 0.375)

    def test_entries_back_and_forth(self):
        # One particle crosses the plane forward, back and forward again:
        # the net crossing is one, the script's entries are two (no sign)
        out = self.measure_positions([[x, -0.2] for x in (0.37, 0.38, 0.37, 0.38)])
        m = RHOP * VP
        np.testing.assert_allclose(out["crossedMass"], [0, m, 0, m], atol=1e-15)
        np.testing.assert_allclose(out["enteredMass"], [0, m, 0, m], atol=1e-15)
        self.assertAlmostEqual(np.sum(out["enteredMass"]) / out["crossedMass"][-1], 2.0)

    def test_entries_images(self):
        # Positions outside the box (periodic images, as a dump may hold
        # between re-wraps) count by their wrapped position: -0.62 is
        # 0.38 (beyond the plane), 1.37 is 0.37 (not beyond)
        out = self.measure_positions([[x] for x in (0.37, -0.62, 1.37, 0.38)])
        m = RHOP * VP
        np.testing.assert_allclose(out["enteredMass"], [0, m, 0, m], atol=1e-15)

    def test_script_rate(self):
        rate = slug.script_mass_flow(np.array([0.0, 1.0, 2.0, 4.0]),
                                     np.array([3.0, 1.0, 2.0, 5.0]))
        np.testing.assert_allclose(rate[1:], [3.0, 2.0, 1.5])


if __name__ == "__main__":
    unittest.main()
