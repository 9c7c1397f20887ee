#!/usr/bin/python3
"""Writes data/meshes/body.obj and data/meshes/body_arms.pc2: an upper body that lowers and raises
its arms, a deforming mesh obstacle for the T-shirt demo (data/meshes/tshirt.obj).

body.obj is a soup of three closed triangle parts, each turned about an axis (a "lathe": rings of
ellipses, a pole at each end), faces counter-clockwise seen from outside:
  - torso, neck and head: one part around the z axis, from a rounded bottom at z = 0.85 m through
    a trunk 0.34 m wide (x) and 0.22 m deep (y), rounded shoulders up to a neck of radius 0.06 m
    at z = 1.48 m, to a head (a ball of radius 0.11 m centred at z = 1.62 m);
  - two arms: tapered capsules of radius 0.05 m at the shoulder joint (+-0.22, 0, 1.40) m and
    0.04 m at the wrist, 0.55 m further, with round ends; each goes on 3 cm inwards past its
    joint (its round end 8 cm from the joint), into the torso, so that arm and torso overlap.
Its positions are the pose at t = 0, a T-pose: the arms point sideways, 10 degrees below
horizontal (80 degrees from hanging).

body_arms.pc2 is a point cache in Blender's PC2 format (little-endian: "POINTCACHE2\\0", version
1, point count, start frame 0.0, sample rate 1.0, sample count, then x y z float32 per point per
sample); point k is OBJ vertex k. 51 samples at 10 per second (sample k at t = k/10 s, 5 s;
scenarios interpolate linearly between them, and 10 per second keeps the file under 2 MB). The
arms hold the T-pose until 0.3 s, fall to 20 degrees from the body's side by 1.6 s, hold, rise
back to the T-pose by 3.4 s, fall again by 4.6 s and hold to 5 s, with cosine easing. Each arm
vertex is skinned (linear blend) between the still torso and the turned arm, with a weight that
goes smoothly from 0 at the arm's inner end to 1 8 cm further along the arm (at the joint), so
the shoulder bends and stretches; torso and head stay still.

Sizes in metres, z up, the body faces -y and stands on z = 0. numpy only:
/usr/bin/python3 scripts/make_body.py
/usr/bin/python3 scripts/make_body.py --resolution 4 --out /tmp/fine   # 16 times the triangles
(--resolution k puts k times the rings along each profile and k times the points around each
ring: a finer body of the same shape and motion, to measure what a body's size costs.)"""
import argparse
import math
import pathlib
import struct

import numpy as np

# torso, neck and head (around the z axis)
TRUNK_HALF_WIDTH_M, TRUNK_HALF_DEPTH_M = 0.17, 0.11
BOTTOM_Z_M, TRUNK_BOTTOM_Z_M, TRUNK_TOP_Z_M = 0.85, 0.93, 1.36
NECK_RADIUS_M, NECK_BOTTOM_Z_M = 0.06, 1.48
HEAD_RADIUS_M, HEAD_CENTRE_Z_M = 0.11, 1.62
SHOULDER_EXPONENT = 2.5  # superellipse exponent of the shoulders' profile (2: a quarter ellipse)
TORSO_AROUND = 40
# arms
SHOULDER_JOINT_M = (0.22, 0.0, 1.40)  # the right one (x > 0); the left one is its mirror image
ARM_LENGTH_M, SHOULDER_RADIUS_M, WRIST_RADIUS_M = 0.55, 0.05, 0.04
ARM_INNER_M = 0.03  # the arm's tube goes on this far past the joint, into the torso, before its end
T_POSE_DEGREES_BELOW_HORIZONTAL = 10.0
ARM_AROUND = 16
SKIN_RAMP_M = 0.08  # the skinning weight goes from 0 to 1 over this length from the arm's inner end
# mesh
RING_SPACING_M = 0.02  # along the profiles (arms: 0.025)
# animation
SAMPLES_PER_SECOND, DURATION_S = 10, 5.0
FALL_DEGREES = 60.0  # from 10 degrees below horizontal to 20 degrees from hanging
# (time s, fraction of the fall) keyframes, cosine easing between them
FALL_KEYS = [(0.0, 0.0), (0.3, 0.0), (1.6, 1.0), (2.0, 1.0), (3.4, 0.0), (4.6, 1.0), (5.0, 1.0)]

ROOT = pathlib.Path(__file__).resolve().parent.parent


def resample(profile, spacing):
    """Rings along a dense profile polyline of rows (s, a, b) (s along the axis, a and b the
    ellipse's half axes), evenly spaced by arc length in the (s, (a + b)/2) plane, about `spacing`
    apart; the first and last rows (the poles, a = b = 0) are kept."""
    step = np.hypot(np.diff(profile[:, 0]), np.diff(0.5 * (profile[:, 1] + profile[:, 2])))
    arc = np.concatenate([[0.0], np.cumsum(step)])
    count = max(2, round(arc[-1] / spacing))
    at = np.linspace(0.0, arc[-1], count + 1)
    return np.stack([np.interp(at, arc, profile[:, c]) for c in range(3)], axis=1)


def lathe(rings, around, origin, axis, e1, e2):
    """A closed surface of revolution: rings[k] = (s, a, b) is the ellipse
    origin + s axis + a cos(t) e1 + b sin(t) e2 (t = 2 pi i / around), rings[0] and rings[-1]
    single poles. (e1, e2, axis) is right-handed, so the faces below are counter-clockwise seen
    from outside. Returns (positions #V x 3, triangles #F x 3, 0-based)."""
    origin, axis, e1, e2 = (np.asarray(v, float) for v in (origin, axis, e1, e2))
    t = 2.0 * np.pi * np.arange(around) / around
    points = [origin + rings[0, 0] * axis]
    for s, a, b in rings[1:-1]:
        points += list(origin + s * axis + np.outer(a * np.cos(t), e1) + np.outer(b * np.sin(t), e2))
    points.append(origin + rings[-1, 0] * axis)
    ring_count = len(rings) - 2
    top = 1 + ring_count * around

    def ring(k, i):  # vertex i of inner ring k (0-based)
        return 1 + k * around + i % around

    faces = []
    for i in range(around):
        faces.append((0, ring(0, i + 1), ring(0, i)))  # bottom fan
        faces.append((top, ring(ring_count - 1, i), ring(ring_count - 1, i + 1)))  # top fan
        for k in range(ring_count - 1):
            # lower ring a (i), b (i + 1); upper ring c (i + 1), d (i): outward is a, b, c, d
            a, b = ring(k, i), ring(k, i + 1)
            c, d = ring(k + 1, i + 1), ring(k + 1, i)
            faces += [(a, b, c), (a, c, d)]
    return np.array(points), np.array(faces)


def torso_profile():
    """Dense (z, a, b) rows from the bottom pole to the top of the head."""
    rows = []
    # rounded bottom, a quarter ellipse: a = A sin p, b = B sin p, z = z1 - (z1 - z0) cos p
    for p in np.linspace(0.0, np.pi / 2, 40):
        rows.append((TRUNK_BOTTOM_Z_M - (TRUNK_BOTTOM_Z_M - BOTTOM_Z_M) * math.cos(p),
                     TRUNK_HALF_WIDTH_M * math.sin(p), TRUNK_HALF_DEPTH_M * math.sin(p)))
    # shoulders, a superellipse of exponent n from the trunk to the neck:
    # a = r + (A - r) cos(p)^(2/n), b = r + (B - r) cos(p)^(2/n), z = z1 + (z2 - z1) sin(p)^(2/n)
    n = SHOULDER_EXPONENT
    for p in np.linspace(0.0, np.pi / 2, 80):
        c, s = math.cos(p) ** (2 / n), math.sin(p) ** (2 / n)
        rows.append((TRUNK_TOP_Z_M + (NECK_BOTTOM_Z_M - TRUNK_TOP_Z_M) * s,
                     NECK_RADIUS_M + (TRUNK_HALF_WIDTH_M - NECK_RADIUS_M) * c,
                     NECK_RADIUS_M + (TRUNK_HALF_DEPTH_M - NECK_RADIUS_M) * c))
    # head: a ball from where its radius is the neck's, r sin q = neck radius, up to its top
    q0 = math.pi - math.asin(NECK_RADIUS_M / HEAD_RADIUS_M)
    for q in np.linspace(q0, 0.0, 80):
        r = HEAD_RADIUS_M * math.sin(q)
        rows.append((HEAD_CENTRE_Z_M + HEAD_RADIUS_M * math.cos(q), r, r))
    rows[-1] = (rows[-1][0], 0.0, 0.0)
    return np.array(rows)


def arm_profile():
    """Dense (s, r, r) rows along the arm from its inner pole; s from the shoulder joint."""
    rows = []
    r0, r1 = SHOULDER_RADIUS_M, WRIST_RADIUS_M
    s0 = -ARM_INNER_M
    for p in np.linspace(0.0, np.pi / 2, 30):  # inner end: a half ball of radius r0 about s0
        rows.append((s0 - r0 * math.cos(p), r0 * math.sin(p), r0 * math.sin(p)))
    for s in np.linspace(s0, ARM_LENGTH_M, 100)[1:]:  # a cone, r0 up to the joint, then to r1
        r = r0 + (r1 - r0) * max(s, 0.0) / ARM_LENGTH_M
        rows.append((s, r, r))
    for p in np.linspace(np.pi / 2, 0.0, 30)[1:]:  # wrist end: a half ball of radius r1
        rows.append((ARM_LENGTH_M + r1 * math.cos(p), r1 * math.sin(p), r1 * math.sin(p)))
    rows[0], rows[-1] = (rows[0][0], 0.0, 0.0), (rows[-1][0], 0.0, 0.0)
    return np.array(rows)


def arm_frame(side):
    """(joint, axis, e1, e2) of the right (side = +1) or left (side = -1) arm in the T-pose: the
    axis points from the shoulder to the hand, e1 is square to it and up, e2 = axis x e1."""
    down = math.radians(T_POSE_DEGREES_BELOW_HORIZONTAL)
    joint = np.array(SHOULDER_JOINT_M) * (side, 1, 1)
    axis = np.array([side * math.cos(down), 0.0, -math.sin(down)])
    e1 = np.array([side * math.sin(down), 0.0, math.cos(down)])
    return joint, axis, e1, np.cross(axis, e1)


def body(resolution=1):
    """(positions, triangles, parts): parts lists (name, first vertex, vertex count, first
    triangle, triangle count, side) with side 0 for the torso, +1 / -1 for the right / left arm.
    `resolution` multiplies the rings along each profile and the points around each ring."""
    spacing = RING_SPACING_M / resolution
    pieces = [("torso_neck_head", 0,
               lathe(resample(torso_profile(), spacing), TORSO_AROUND * resolution,
                     (0, 0, 0), (0, 0, 1), (1, 0, 0), (0, 1, 0)))]
    arm_rings = resample(arm_profile(), 1.25 * spacing)
    for name, side in (("arm_right", 1), ("arm_left", -1)):
        pieces.append((name, side, lathe(arm_rings, ARM_AROUND * resolution, *arm_frame(side))))
    positions, triangles, parts = [], [], []
    vertex_count = triangle_count = 0
    for name, side, (p, f) in pieces:
        parts.append((name, vertex_count, len(p), triangle_count, len(f), side))
        positions.append(p)
        triangles.append(f + vertex_count)
        vertex_count += len(p)
        triangle_count += len(f)
    # round to the 6 decimals the OBJ keeps, so that sample 0 of the cache is the OBJ to the bit
    return np.round(np.concatenate(positions), 6), np.concatenate(triangles), parts


def fall_fraction(t):
    """Fraction of the fall at time t: between keyframes (t0, f0) and (t1, f1),
    f = f0 + (f1 - f0) (1 - cos(pi u)) / 2 with u = (t - t0) / (t1 - t0)."""
    for (t0, f0), (t1, f1) in zip(FALL_KEYS, FALL_KEYS[1:]):
        if t <= t1:
            u = min(max((t - t0) / (t1 - t0), 0.0), 1.0)
            return f0 + (f1 - f0) * 0.5 * (1.0 - math.cos(math.pi * u))
    return FALL_KEYS[-1][1]


def skin_weight(s):
    """Linear blend skinning weight of an arm vertex at s along the arm from the shoulder joint:
    smoothstep 3x^2 - 2x^3 of x = (s - s0) / ramp, clamped to [0, 1], s0 the arm's inner end."""
    x = np.clip((s + ARM_INNER_M + SHOULDER_RADIUS_M) / SKIN_RAMP_M, 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


def pose(rest, parts, fraction):
    """Positions with the arms turned down by fraction x FALL_DEGREES about the y axis through
    each shoulder joint: p' = p + w (R - I)(p - joint), R the rotation, w the skinning weight
    ((R - I) is exactly 0 when the angle is, so the T-pose is the rest positions to the bit)."""
    out = rest.copy()
    for _, v0, count, _, _, side in parts:
        if side == 0:
            continue
        joint, axis, _, _ = arm_frame(side)
        p = rest[v0:v0 + count] - joint
        w = skin_weight(p @ axis)
        a = side * math.radians(FALL_DEGREES) * fraction  # about +y, x turns towards -z
        c, s = math.cos(a), math.sin(a)
        # R about y: x' = c x + s z, z' = -s x + c z; (R - I) p:
        d = np.stack([(c - 1.0) * p[:, 0] + s * p[:, 2], np.zeros(count),
                      -s * p[:, 0] + (c - 1.0) * p[:, 2]], axis=1)
        out[v0:v0 + count] += w[:, None] * d
    return out


def write_obj(path, positions, triangles, parts):
    lines = [
        "# tissu sample obstacle: an upper body in a T-pose (scripts/make_body.py), z up, facing -y;",
        "# three closed parts (a soup), faces counter-clockwise seen from outside;",
        f"# {len(positions)} vertices, {len(triangles)} triangles. Animated by body_arms.pc2 "
        "(point k = vertex k).",
    ]
    for name, v0, count, f0, fcount, _ in parts:
        lines.append(f"# {name}: vertices {v0 + 1} to {v0 + count}, {fcount} triangles")
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in positions]
    for name, _, _, f0, fcount, _ in parts:
        lines.append(f"o {name}")
        lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in triangles[f0:f0 + fcount]]
    path.write_text("\n".join(lines) + "\n")


def write_pc2(path, samples):
    """samples: #S x #V x 3. Blender's PC2: a 32-byte header, then float32 x y z per point."""
    header = struct.pack("<12siiffi", b"POINTCACHE2\0", 1, samples.shape[1], 0.0, 1.0,
                         samples.shape[0])
    path.write_bytes(header + samples.astype("<f4").tobytes())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--resolution", type=int, default=1,
                        help="rings along and points around each part, times this (default 1)")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "data" / "meshes",
                        help="folder for body.obj and body_arms.pc2 (default data/meshes)")
    arguments = parser.parse_args()
    if arguments.resolution < 1:
        parser.error(f"--resolution {arguments.resolution}: expected an integer of at least 1")
    rest, triangles, parts = body(arguments.resolution)
    count = round(DURATION_S * SAMPLES_PER_SECOND) + 1
    samples = np.stack([pose(rest, parts, fall_fraction(k / SAMPLES_PER_SECOND))
                        for k in range(count)])
    meshes = arguments.out
    meshes.mkdir(parents=True, exist_ok=True)
    write_obj(meshes / "body.obj", rest, triangles, parts)
    write_pc2(meshes / "body_arms.pc2", samples)
    speed = np.linalg.norm(np.diff(samples, axis=0), axis=2) * SAMPLES_PER_SECOND
    print(f"body.obj: {len(rest)} vertices, {len(triangles)} triangles in {len(parts)} parts; "
          f"body_arms.pc2: {count} samples; max vertex speed {speed.max():.3f} m/s "
          f"(between samples {np.unravel_index(speed.argmax(), speed.shape)[0]} and next)")


if __name__ == "__main__":
    main()
