#!/usr/bin/python3
"""Writes data/meshes/skirt.obj: a flared skirt, the lateral surface of a truncated cone around
the z axis, from a waist ring (radius 0.17 m at z = 1.0 m) down to its hem (radius 0.26 m at
z = 0.50 m). 48 cells around and 16 down, each cut along alternating diagonals; faces
counter-clockwise seen from outside. Rest shape = this shape (tissu's cloth.mesh). Standard
library only: /usr/bin/python3 scripts/make_skirt.py"""
import math
import pathlib

AROUND, DOWN = 48, 16
WAIST_RADIUS_M, HEM_RADIUS_M = 0.17, 0.26
WAIST_HEIGHT_M, HEM_HEIGHT_M = 1.0, 0.50


def vertex(ring, k):
    """Index (from 1, as OBJ counts) of vertex k around ring `ring` (0 = waist)."""
    return ring * AROUND + k % AROUND + 1


def main():
    lines = [
        "# tissu sample mesh: a flared skirt around the z axis (scripts/make_skirt.py), from a",
        f"# waist of radius {WAIST_RADIUS_M} m at z = {WAIST_HEIGHT_M} m to a hem of radius "
        f"{HEM_RADIUS_M} m at z = {HEM_HEIGHT_M} m;",
        f"# {AROUND} cells around, {DOWN} down, alternating diagonals, faces counter-clockwise seen "
        "from outside.",
        f"# {AROUND * (DOWN + 1)} vertices (the waist ring first), {2 * AROUND * DOWN} triangles.",
    ]
    for ring in range(DOWN + 1):
        s = ring / DOWN
        radius = WAIST_RADIUS_M + s * (HEM_RADIUS_M - WAIST_RADIUS_M)
        z = WAIST_HEIGHT_M + s * (HEM_HEIGHT_M - WAIST_HEIGHT_M)
        for k in range(AROUND):
            a = 2 * math.pi * k / AROUND
            lines.append(f"v {radius * math.cos(a):.6f} {radius * math.sin(a):.6f} {z:.6f}")
    for ring in range(DOWN):
        for k in range(AROUND):
            # upper ring: a (k), b (k + 1); lower ring: c (k), d (k + 1); outward normal is
            # counter-clockwise from outside: a, c, d, b
            a, b = vertex(ring, k), vertex(ring, k + 1)
            c, d = vertex(ring + 1, k), vertex(ring + 1, k + 1)
            if (ring + k) % 2 == 0:
                lines += [f"f {a} {c} {d}", f"f {a} {d} {b}"]
            else:
                lines += [f"f {a} {c} {b}", f"f {b} {c} {d}"]
    out = pathlib.Path(__file__).resolve().parent.parent / "data" / "meshes" / "skirt.obj"
    out.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
