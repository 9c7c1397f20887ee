#!/usr/bin/python3
"""Writes data/meshes/tshirt.obj: a loose T-shirt around the T-pose of data/meshes/body.obj
(scripts/make_body.py): short sleeves around the raised arms down to about the elbows, the body
of the shirt from the shoulders down to a hem at z = 1.0 m, at least 1.5 cm off the body.

The shirt is sewn from a front and a back T-shaped panel, each a grid of 2.5 cm cells in a flat
pattern (a torso block with a sleeve block on each side of its upper rows), cut along
alternating diagonals; the back mirrors the front but for its shallower neck notch. The panels
share their vertices along the shoulder and sleeve-top seams, the sleeve-bottom seams and the
side seams; the neck hole, the waist hem and the two cuffs stay open (four boundary loops).

The panels are laid onto a smooth closed surface g(p) = 0 around the body, the smooth union of
  - a torso: an elliptic cylinder of half axes 0.205 m (x) and 0.145 m (y) around the z axis,
    under a roof over the shoulders, z = 1.515 - x^2 m, their edge rounded with radius 6 cm;
  - two sleeves: capsules of radius 8.5 cm around the T-pose arms' axes from the shoulder
    joints (+-0.22, 0, 1.40) m, 10 degrees below horizontal;
cut by the hem plane z = 1.0 m, the cuff planes square to the arms 0.28 m from the joints and
the neck hole, a vertical elliptic cylinder of half axes 0.10 m (x) and 0.095 m (y) centred at
y = -0.015 m. The seams lie where the surface crosses y = 0. The panels' vertices start from a
rough layout and relax into an even mesh: each moves towards the mean of its neighbours, then
also along the pull of springs as long as the pattern's edges, and is put back onto the surface
(and onto its seam or cut) after each step.

Faces counter-clockwise seen from outside (normals away from the body). Rest shape = this
shape. Sizes in metres, z up, the body faces -y. numpy only (takes about 20 s):
/usr/bin/python3 scripts/make_tshirt.py"""
import math
import pathlib

import numpy as np

EDGE_M = 0.025  # target edge length
# torso of the shirt
HALF_WIDTH_M, HALF_DEPTH_M = 0.205, 0.145
ROOF_Z_M, ROOF_CURVATURE_PER_M = 1.515, 1.0  # shoulders: z = ROOF_Z_M - ROOF_CURVATURE_PER_M x^2
ROOF_ROUNDING_M = 0.06
HEM_Z_M = 1.0
# sleeves, around the T-pose arms of make_body.py
SHOULDER_JOINT_M = (0.22, 0.0, 1.40)  # the right one (x > 0); the left one is its mirror image
T_POSE_DEGREES_BELOW_HORIZONTAL = 10.0
SLEEVE_RADIUS_M, SLEEVE_LENGTH_M = 0.085, 0.28  # the cuff 0.28 m from the joint along the arm
ARMPIT_BLEND_M = 0.05  # width of the smooth union of torso and sleeves
# neck hole: (x / a)^2 + ((y - y0) / b)^2 < 1
NECK_HALF_X_M, NECK_HALF_Y_M, NECK_CENTRE_Y_M = 0.10, 0.095, -0.015
SMOOTH_ITERATIONS, SPRING_ITERATIONS, SMOOTH_SHARE = 400, 600, 0.3

# vertex kinds
INTERIOR, SEAM, HEM, CUFF_RIGHT, CUFF_LEFT, NECK, CORNER = range(7)


def arm_axis(side):
    """(joint, direction, up) of the right (side = +1) or left (side = -1) T-pose arm: the
    direction points to the hand, `up` is square to it, upwards."""
    down = math.radians(T_POSE_DEGREES_BELOW_HORIZONTAL)
    joint = np.array(SHOULDER_JOINT_M) * (side, 1.0, 1.0)
    return (joint, np.array([side * math.cos(down), 0.0, -math.sin(down)]),
            np.array([side * math.sin(down), 0.0, math.cos(down)]))


def smooth_min(a, b, k):
    """Polynomial smooth minimum: min(a, b) - k h^2 / 4, h = max(k - |a - b|, 0) / k."""
    h = np.maximum(k - np.abs(a - b), 0.0) / k
    return np.minimum(a, b) - 0.25 * k * h * h


def round_intersection(a, b, r):
    """Intersection of two regions a < 0 and b < 0 with its edge rounded to radius r:
    min(max(a, b), 0) + |(max(a + r, 0), max(b + r, 0))| - r."""
    return (np.minimum(np.maximum(a, b), 0.0)
            + np.hypot(np.maximum(a + r, 0.0), np.maximum(b + r, 0.0)) - r)


def torso_field(p):
    """About the signed distance to the shirt's torso: the ellipse's (q - 1) q / |grad q^2 / 2|
    with q^2 = (x/A)^2 + (y/B)^2, rounded-intersected with the roof's (z - roof(x)) / |grad|."""
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    q = np.hypot(x / HALF_WIDTH_M, y / HALF_DEPTH_M)
    grad = np.hypot(x / HALF_WIDTH_M ** 2, y / HALF_DEPTH_M ** 2)
    # q / grad lies between B and A; on the axis (0 / 0) take B
    ellipse = (q - 1.0) * np.where(grad > 1e-12, q / np.maximum(grad, 1e-12), HALF_DEPTH_M)
    roof = (z - ROOF_Z_M + ROOF_CURVATURE_PER_M * x * x) / np.hypot(1.0, 2 * ROOF_CURVATURE_PER_M * x)
    return round_intersection(ellipse, roof, ROOF_ROUNDING_M)


def sleeve_field(p, side):
    """Signed distance to a capsule of radius SLEEVE_RADIUS_M around the arm's axis, from the
    joint to well past the cuff: |p - joint - clamp(s) d| - radius."""
    joint, d, _ = arm_axis(side)
    s = np.clip((p - joint) @ d, 0.0, SLEEVE_LENGTH_M + 0.2)
    return np.linalg.norm(p - joint - s[..., None] * d, axis=-1) - SLEEVE_RADIUS_M


def field(p):
    """g(p): negative inside the shirt's closed surface, about the distance to it outside."""
    return smooth_min(torso_field(p),
                      smooth_min(sleeve_field(p, 1), sleeve_field(p, -1), ARMPIT_BLEND_M),
                      ARMPIT_BLEND_M)


def field_gradient(p, eps=1e-6):
    """Central differences of g."""
    out = np.empty_like(p)
    for axis in range(3):
        e = np.zeros(3)
        e[axis] = eps
        out[..., axis] = (field(p + e) - field(p - e)) / (2 * eps)
    return out


def constraint(p, kind):
    """Second constraint N(p) = 0 of each boundary vertex and its gradient (0 for the others)."""
    n, grad = np.zeros(len(p)), np.zeros_like(p)
    m = kind == SEAM  # the seams lie in y = 0
    n[m], grad[m, 1] = p[m, 1], 1.0
    m = kind == HEM
    n[m], grad[m, 2] = p[m, 2] - HEM_Z_M, 1.0
    for side, cuff in ((1, CUFF_RIGHT), (-1, CUFF_LEFT)):  # (p - joint) . d = cuff distance
        joint, d, _ = arm_axis(side)
        m = kind == cuff
        n[m], grad[m] = (p[m] - joint) @ d - SLEEVE_LENGTH_M, d
    m = kind == NECK  # (x / a)^2 + ((y - y0) / b)^2 - 1
    x, y = p[m, 0], p[m, 1] - NECK_CENTRE_Y_M
    n[m] = (x / NECK_HALF_X_M) ** 2 + (y / NECK_HALF_Y_M) ** 2 - 1.0
    grad[m, 0], grad[m, 1] = 2 * x / NECK_HALF_X_M ** 2, 2 * y / NECK_HALF_Y_M ** 2
    return n, grad


def project(p, kind, steps=4):
    """Newton steps onto g = 0 (and N = 0 for boundary vertices), the least-norm step
    -J^T (J J^T)^-1 F with J the constraints' gradients; corners do not move."""
    p = p.copy()
    one = (kind == INTERIOR)
    two = (kind != INTERIOR) & (kind != CORNER)
    for _ in range(steps):
        g, dg = field(p), field_gradient(p)
        p[one] -= (g[one] / np.einsum("ij,ij->i", dg[one], dg[one]))[:, None] * dg[one]
        n, dn = constraint(p, kind)
        a = np.einsum("ij,ij->i", dg, dg)
        b = np.einsum("ij,ij->i", dg, dn)
        c = np.einsum("ij,ij->i", dn, dn)
        det = a * c - b * b
        # (J J^T)^-1 F = [[c, -b], [-b, a]] (g, n) / det
        la = (c * g - b * n) / np.where(two, det, 1.0)
        ln = (a * n - b * g) / np.where(two, det, 1.0)
        p[two] -= la[two, None] * dg[two] + ln[two, None] * dn[two]
    return p


def bisect(inside, outside, iterations=60):
    """The point where g crosses 0 on each segment from `inside` (g < 0) to `outside`."""
    for _ in range(iterations):
        mid = 0.5 * (inside + outside)
        out = field(mid) > 0
        outside = np.where(out[:, None], mid, outside)
        inside = np.where(out[:, None], inside, mid)
    return 0.5 * (inside + outside)


def neck_arc_length(panel, steps=2000):
    """Length of the neck hole's ellipse on the front (panel = -1, y < 0) or back (+1)."""
    t = np.linspace(0.0, 2.0 * np.pi, steps + 1)
    x, y = NECK_HALF_X_M * np.cos(t), NECK_CENTRE_Y_M + NECK_HALF_Y_M * np.sin(t)
    step = np.hypot(np.diff(x), np.diff(y))
    return step[panel * (y[:-1] + y[1:]) > 0].sum()


class Pattern:
    """A panel's grid, the front (panel = -1) or the back (+1): vertex (i, j), i across (x grows
    with i), j up. Torso block: 0 <= i <= nx, 0 <= j <= top; sleeve blocks: -nl <= i <= 0 and
    nx <= i <= nx + nl, armpit <= j <= top. The neck is a notch in the top rows between its
    corners neck0 and neck1 on the top row, shaped as the neck hole seen from above: down
    straight from each corner, then in along 45 degree diagonals (cells cut in half), then
    across; deeper on the front than on the back."""

    def __init__(self):
        e = EDGE_M
        a, b = HALF_WIDTH_M, HALF_DEPTH_M
        # half the perimeter of the torso's ellipse, Ramanujan: pi (3 (a + b) - sqrt((3a + b)(a + 3b))) / 2
        half = 0.5 * math.pi * (3 * (a + b) - math.sqrt((3 * a + b) * (a + 3 * b)))
        self.nx = 2 * round(half / (2 * e))
        _, d, up = arm_axis(1)
        self.armpit_z = SHOULDER_JOINT_M[2] - SLEEVE_RADIUS_M / up[2] - 0.01
        self.armpit = round((self.armpit_z - HEM_Z_M) / e)
        # rows above the armpits: the torso's way from the armpits over the shoulder to the seam
        # at its middle, up the front, round the roof's edge and across the roof:
        # (roof - r - armpit) + pi r / 2 + (B - r); the sleeves' half round, pi R, is shorter
        over = (ROOF_Z_M - ROOF_ROUNDING_M - self.armpit_z) + 0.5 * math.pi * ROOF_ROUNDING_M \
            + HALF_DEPTH_M - ROOF_ROUNDING_M
        self.top = self.armpit + round(over / e)
        self.nl = round((SLEEVE_LENGTH_M + SHOULDER_JOINT_M[0] - HALF_WIDTH_M) / e)
        # the neck's corners, where the ellipse crosses y = 0: x = +-a sqrt(1 - (y0 / b)^2)
        corner = NECK_HALF_X_M * math.sqrt(1.0 - (NECK_CENTRE_Y_M / NECK_HALF_Y_M) ** 2)
        half_width = round(corner / e)
        self.neck0, self.neck1 = self.nx // 2 - half_width, self.nx // 2 + half_width
        self.notch = {panel: self.notch_path(panel, half_width) for panel in (-1, 1)}

    def notch_path(self, panel, half_width):
        """Vertices (i, j) along the notch from corner neck0 to corner neck1: `straight` rows
        down, `slant` diagonal steps, across, back up; depth = the neck hole's reach from the
        seam (y = 0) on the panel's side, b - panel y0, in cells; slant about 0.6 of the
        smaller of depth and half width."""
        depth = round((NECK_HALF_Y_M - panel * NECK_CENTRE_Y_M) / EDGE_M)
        slant = min(round(0.6 * min(depth, half_width)), depth, half_width)
        straight, i, j = depth - slant, self.neck0, self.top
        path = [(i, j)]
        steps = [(0, -1)] * straight + [(1, -1)] * slant + [(1, 0)] * (2 * (half_width - slant))
        steps += [(1, 1)] * slant + [(0, 1)] * straight
        for di, dj in steps:
            i, j = i + di, j + dj
            path.append((i, j))
        return path

    def triangles(self, panel):
        """The panel's triangles, (i, j) corners counter-clockwise in the (i, j) plane: each
        cell cut along alternating diagonals, but for the cells in the notch (left out) and
        those the notch's diagonals cut (their outer half kept)."""
        path = self.notch[panel]
        halves, inside = {}, set()
        for (i0, j0), (i1, j1) in zip(path, path[1:]):
            if i1 - i0 == 1 and j1 - j0 == -1:  # down-right: keep the lower left half
                halves[i0, j1] = [((i0, j1), (i1, j1), (i0, j0))]
            elif i1 - i0 == 1 and j1 - j0 == 1:  # up-right: keep the lower right half
                halves[i0, j0] = [((i0, j0), (i1, j0), (i1, j1))]
        for i in range(self.neck0, self.neck1):  # cells above the path, below the top row
            bottom = max(min(j0, j1) for (i0, j0), (i1, j1) in zip(path, path[1:])
                         if min(i0, i1) == i and max(i0, i1) == i + 1)
            inside |= {(i, j) for j in range(bottom, self.top) if (i, j) not in halves}
        cells = [(i, j) for j in range(self.top) for i in range(self.nx)]
        cells += [(i, j) for j in range(self.armpit, self.top)
                  for i in list(range(-self.nl, 0)) + list(range(self.nx, self.nx + self.nl))]
        out = []
        for i, j in cells:
            if (i, j) in inside:
                continue
            if (i, j) in halves:
                out += halves[i, j]
                continue
            a, b, c, d = (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
            out += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
        return out

    def kind(self, i, j, panel):
        nx, nl, top, armpit = self.nx, self.nl, self.top, self.armpit
        if (j == 0 and i in (0, nx)) or (j in (armpit, top) and i in (-nl, nx + nl)) or \
                (j == top and i in (self.neck0, self.neck1)):
            return CORNER
        if i == -nl:
            return CUFF_LEFT
        if i == nx + nl:
            return CUFF_RIGHT
        if j == 0:
            return HEM
        if (i, j) in self.notch[panel]:
            return NECK
        if j == top or (i in (0, nx) and j <= armpit) or (j == armpit and (i < 0 or i > nx)):
            return SEAM
        return INTERIOR

    def neck_point(self, i, j, panel):
        """A place on the neck hole's ellipse x = a cos t, y = y0 + b sin t for a vertex of the
        notch, by its share u of the notch's length from corner neck0."""
        path = np.array(self.notch[panel], float)
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(path, axis=0), axis=1))])
        u = arc[self.notch[panel].index((i, j))] / arc[-1]
        t1 = math.asin(-NECK_CENTRE_Y_M / NECK_HALF_Y_M)  # the right corner; the left: pi - t1
        # front: t from pi - t1 up to 2 pi + t1; back: from pi - t1 down to t1
        t = math.pi - t1 + u * (math.pi + 2 * t1 if panel < 0 else 2 * t1 - math.pi)
        roof = ROOF_Z_M - ROOF_CURVATURE_PER_M * (NECK_HALF_X_M * math.cos(t)) ** 2
        return np.array([NECK_HALF_X_M * math.cos(t),
                         NECK_CENTRE_Y_M + NECK_HALF_Y_M * math.sin(t), roof - 0.01])

    def layout(self, i, j, panel):
        """A rough place of vertex (i, j) of the front (panel = -1) or back (+1) in the plane
        y = 0, or on the neck hole, refined later by relaxing."""
        nx, nl, top, armpit = self.nx, self.nl, self.top, self.armpit
        if self.kind(i, j, panel) == NECK:
            return self.neck_point(i, j, panel)
        if 0 <= i <= nx:  # torso block: x across, z up to the armpits, then up to the roof
            x = HALF_WIDTH_M * (2.0 * i / nx - 1.0)
            roof = ROOF_Z_M - ROOF_CURVATURE_PER_M * x * x
            if j <= armpit:
                z = HEM_Z_M + (self.armpit_z - HEM_Z_M) * j / armpit
            else:
                z = self.armpit_z + (roof - self.armpit_z) * (j - armpit) / (top - armpit)
            return np.array([x, 0.0, z])
        side = 1 if i > nx else -1
        joint, d, up = arm_axis(side)
        k = i - nx if side > 0 else -i  # cells out from the armhole
        # along the arm from where it meets the torso's side (x = A) to the cuff, across it
        # from the bottom seam to the top one
        s0 = (HALF_WIDTH_M - SHOULDER_JOINT_M[0]) / abs(d[0])
        s = s0 + (SLEEVE_LENGTH_M - s0) * k / nl
        across = SLEEVE_RADIUS_M * (2.0 * (j - armpit) / (top - armpit) - 1.0)
        return joint + s * d + across * up


def build():
    """(positions #V x 3, triangles #F x 3 0-based, kinds #V)."""
    pattern = Pattern()
    index, positions, kinds, grid = {}, [], [], []
    for panel in (-1, 1):  # front (y < 0), then back
        corners = {ij for triangle in pattern.triangles(panel) for ij in triangle}
        for i, j in sorted(corners, key=lambda ij: (ij[1], ij[0])):
            kind = pattern.kind(i, j, panel)
            if panel > 0 and kind in (SEAM, CORNER):
                index[panel, i, j] = index[-1, i, j]  # sewn: shared with the front
                continue
            index[panel, i, j] = len(positions)
            p = pattern.layout(i, j, panel)
            if kind not in (SEAM, CORNER, NECK):
                # along y from the plane y = 0 to the surface, where g(x, panel t, z) = 0
                inside = np.array([p[0], 0.0, p[2]])
                if field(inside[None])[0] < 0:
                    p = bisect(inside[None], (inside + (0.0, panel * 0.5, 0.0))[None])[0]
            positions.append(p)
            grid.append((i, j))
            kinds.append(kind)
    positions, kinds = np.array(positions), np.array(kinds)
    triangles = []
    for panel in (-1, 1):
        for triangle in pattern.triangles(panel):
            # counter-clockwise in (i, j) faces -y: outwards on the front, reversed on the back
            t = [index[panel, i, j] for i, j in triangle]
            triangles.append(t if panel < 0 else t[::-1])
    triangles = np.array(triangles)
    positions = place_corners(positions, kinds, pattern, index)
    return relax(positions, triangles, kinds, np.array(grid, float)), triangles, kinds


def place_corners(positions, kinds, pattern, index):
    """Puts the fixed corners where their seams meet the cuts, on g = 0 in y = 0."""
    p = positions.copy()
    nx, nl, top, armpit = pattern.nx, pattern.nl, pattern.top, pattern.armpit
    for i, side in ((0, -1), (nx, 1)):  # hem: z = HEM_Z_M
        p[index[-1, i, 0]] = bisect(np.array([[0.0, 0.0, HEM_Z_M]]),
                                    np.array([[0.5 * side, 0.0, HEM_Z_M]]))[0]
    for i, side in ((-nl, -1), (nx + nl, 1)):  # cuffs: around the arm's axis, up and down
        joint, d, up = arm_axis(side)
        centre = joint + SLEEVE_LENGTH_M * d
        for j, sign in ((armpit, -1), (top, 1)):
            p[index[-1, i, j]] = bisect(centre[None], (centre + 0.3 * sign * up)[None])[0]
    # neck: y = 0, x where the neck's ellipse crosses y = 0, z where g crosses 0 going up
    x = NECK_HALF_X_M * math.sqrt(1.0 - (NECK_CENTRE_Y_M / NECK_HALF_Y_M) ** 2)
    for i, side in ((pattern.neck0, -1), (pattern.neck1, 1)):
        p[index[-1, i, top]] = bisect(np.array([[side * x, 0.0, 1.2]]),
                                      np.array([[side * x, 0.0, 1.8]]))[0]
    return p


def relax(positions, triangles, kinds, grid):
    """Evens the mesh out on the surface, every vertex but the corners moving, then put back onto
    the surface (and its seam or cut) at each iteration: SMOOTH_ITERATIONS times half way to the
    mean of its neighbours (dp = 0.5 (mean - p)), then SPRING_ITERATIONS times also pulled by
    springs of rest length the edge's length in the pattern (grid: each vertex's (i, j)) scaled
    to the mesh's total edge length:
    dp = 0.5 (SMOOTH_SHARE (mean - p) + (1 - SMOOTH_SHARE) sum (|e| - rest) e / |e| / degree)."""
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    edges = np.unique(np.sort(edges, axis=1), axis=0)
    degree = np.bincount(edges.ravel(), minlength=len(positions)).astype(float)
    fixed = kinds == CORNER
    p = project(positions, kinds)
    for _ in range(SMOOTH_ITERATIONS):
        total = np.zeros_like(p)
        np.add.at(total, edges[:, 0], p[edges[:, 1]])
        np.add.at(total, edges[:, 1], p[edges[:, 0]])
        moved = p + 0.5 * (total / degree[:, None] - p)
        moved[fixed] = p[fixed]
        p = project(moved, kinds, steps=2)
    pattern_length = np.linalg.norm(grid[edges[:, 0]] - grid[edges[:, 1]], axis=1)
    for _ in range(SPRING_ITERATIONS):
        e = p[edges[:, 1]] - p[edges[:, 0]]
        length = np.linalg.norm(e, axis=1)
        rest = pattern_length * length.sum() / pattern_length.sum()
        pull = ((length - rest) / length)[:, None] * e
        total, mean = np.zeros_like(p), np.zeros_like(p)
        np.add.at(total, edges[:, 0], pull)
        np.add.at(total, edges[:, 1], -pull)
        np.add.at(mean, edges[:, 0], p[edges[:, 1]])
        np.add.at(mean, edges[:, 1], p[edges[:, 0]])
        mean /= degree[:, None]
        moved = p + 0.5 * (SMOOTH_SHARE * (mean - p) + (1.0 - SMOOTH_SHARE) * total / degree[:, None])
        moved[fixed] = p[fixed]
        p = project(moved, kinds, steps=2)
    return project(p, kinds)


def main():
    positions, triangles, kinds = build()
    lines = [
        "# tissu sample mesh: a T-shirt around the T-pose of body.obj (scripts/make_tshirt.py),",
        "# z up, facing -y; a front and a back panel sewn at the shoulders, under the sleeves and",
        "# at the sides; open at the neck, the hem (z = 1.0 m) and the two cuffs; faces",
        "# counter-clockwise seen from outside.",
        f"# {len(positions)} vertices, {len(triangles)} triangles.",
    ]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in positions]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in triangles]
    out = pathlib.Path(__file__).resolve().parent.parent / "data" / "meshes" / "tshirt.obj"
    out.write_text("\n".join(lines) + "\n")
    print(f"tshirt.obj: {len(positions)} vertices, {len(triangles)} triangles")


if __name__ == "__main__":
    main()
