#!/usr/bin/env python3
"""The projected area (shadow) of a sphere clump, foamdem.shapes.Clump, on
cases with closed forms: one sphere (pi r^2), two apart (2 pi r^2), two
overlapping at centre distance d (2 pi r^2 minus the lens 2 r^2 acos(d/2r)
- (d/2) sqrt(4 r^2 - d^2)), the same pair seen along its axis (pi r^2),
and a tilted view of the pair (the distance projected)."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
from foamdem.shapes import Clump  # noqa: E402


def lens(r, d):
    return 2 * r * r * math.acos(d / (2 * r)) - 0.5 * d * math.sqrt(4 * r * r - d * d)


def union2(r, d):
    return 2 * math.pi * r * r - (lens(r, d) if d < 2 * r else 0.0)


def main():
    r = 0.165e-3
    failures = []

    def check(name, got, want, tol=2e-3):
        rel = abs(got / want - 1)
        print("%-46s %.6e  want %.6e  rel %.1e" % (name, got, want, rel))
        if rel > tol:
            failures.append(name)

    check("one sphere", Clump([(0, 0, 0)], r).projected_area((0, 0, 1)), math.pi * r * r)
    check("two spheres apart", Clump([(0, 0, 0), (3 * r, 0, 0)], r)
          .projected_area((0, 0, 1)), 2 * math.pi * r * r)
    d = 1.2 * r
    pair = Clump([(0, 0, 0), (d, 0, 0)], r)
    check("two overlapping, seen across", pair.projected_area((0, 0, 1)), union2(r, d))
    check("two overlapping, seen along the axis", pair.projected_area((1, 0, 0)),
          math.pi * r * r)
    a = math.radians(60)
    check("two overlapping, seen at 60 deg to the axis",
          pair.projected_area((math.cos(a), 0, math.sin(a))), union2(r, d * math.sin(a)))
    if failures:
        print("FAILED:", ", ".join(failures))
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
