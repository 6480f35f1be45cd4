#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the plate sculptures of examples/plate/: closed low-poly meshes (.obj, millimetres) and the
mitred plate designs `desia plates-from-mesh` makes of them (.json, one plate per face):

  cube.obj, icosahedron.obj  - small test shapes (6 and 20 plates)
  dodecahedron.obj           - 12 pentagonal plates, three meeting at every corner
  lizard.obj                 - a LIZARD (after the paper's Fig. 1): a walking lizard's outline of 18
                               corners, bevelled above and below like a pebble; 38 plates

Run from anywhere after building the CLI (scripts/build.sh native):
    python3 examples/plate/make_sculptures.py [--desia path/to/desia]
The polygons of the convex solids are written as OBJ n-gons; the lizard is written as triangles
(ear-clipped), as Blender's "triangulate faces" export does: plates-from-mesh merges them back."""
import argparse, itertools, math, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..'))

# (mesh, thickness in mm)
THICKNESS = {'cube': 12.0, 'icosahedron': 6.0, 'dodecahedron': 6.0, 'lizard': 6.0}


def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def unit(a):
    n = math.sqrt(dot(a, a))
    return [c / n for c in a]


def convex_polyhedron(points):
    """The faces of the convex hull of `points` (each a plane through 3+ of them with all the others
    behind it), as vertex-index polygons counter-clockwise seen from outside."""
    centre = [sum(p[k] for p in points) / len(points) for k in range(3)]
    scale = max(math.sqrt(dot(sub(p, centre), sub(p, centre))) for p in points)
    eps = 1e-9 * scale
    faces, seen = [], set()
    for i, j, k in itertools.combinations(range(len(points)), 3):
        n = cross(sub(points[j], points[i]), sub(points[k], points[i]))
        if math.sqrt(dot(n, n)) < eps * scale:
            continue
        n = unit(n)
        if dot(n, sub(points[i], centre)) < 0:
            n = [-c for c in n]
        d = dot(n, points[i])
        if any(dot(n, p) > d + eps for p in points):
            continue
        on = tuple(sorted(m for m, p in enumerate(points) if abs(dot(n, p) - d) <= eps))
        if on in seen:
            continue
        seen.add(on)
        mid = [sum(points[m][c] for m in on) / len(on) for c in range(3)]
        u = unit(sub(points[on[0]], mid))
        v = cross(n, u)
        faces.append(sorted(on, key=lambda m: math.atan2(dot(sub(points[m], mid), v), dot(sub(points[m], mid), u))))
    return faces


def cube(size=200.0):
    h = size / 2
    return [[x, y, z] for x in (-h, h) for y in (-h, h) for z in (-h, h)]


def icosahedron(radius=150.0):
    phi = (1 + math.sqrt(5)) / 2
    pts = []
    for a, b in itertools.product((-1, 1), repeat=2):
        pts += [[0, a, b * phi], [a, b * phi, 0], [b * phi, 0, a]]
    s = radius / math.sqrt(1 + phi * phi)
    return [[c * s for c in p] for p in pts]


def dodecahedron(radius=150.0):
    phi = (1 + math.sqrt(5)) / 2
    pts = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    for a, b in itertools.product((-1, 1), repeat=2):
        pts += [[0, a / phi, b * phi], [a / phi, b * phi, 0], [b * phi, 0, a / phi]]
    s = radius / math.sqrt(3)
    return [[c * s for c in p] for p in pts]


# The lizard seen from above (mm, counter-clockwise, the head towards +x), walking: the left front
# and right hind feet reach forward, the others back; the tail swings a little to the right.
LIZARD_OUTLINE = [
    (250, 0),      # snout
    (205, 35),     # left cheek
    (140, 30),     # left shoulder
    (175, 110),    # left front foot
    (105, 45),     # left armpit
    (-20, 45),     # left hip
    (-5, 120),     # left hind foot
    (-60, 38),     # left groin
    (-110, 18),    # tail base, left
    (-300, -25),   # tail tip
    (-110, -22),   # tail base, right
    (-55, -40),    # right groin
    (-95, -120),   # right hind foot
    (-15, -45),    # right hip
    (95, -45),     # right armpit
    (120, -115),   # right front foot
    (150, -30),    # right shoulder
    (205, -35),    # right cheek
]
LIZARD_WAIST = 30.0   # mm from the belly (z = 0) to the widest outline, and on to the back
LIZARD_INSET = 15.0   # mm the back and the belly lie inside the widest outline


def inset_outline(outline, inset):
    """The outline's mitred offset inward: each corner where its two sides, moved `inset` inward,
    meet. The bevel faces between the outline and this one are then planar (each lies on one side
    line tilted about it)."""
    n = len(outline)
    lines = []
    for k in range(n):
        (x0, y0), (x1, y1) = outline[k], outline[(k + 1) % n]
        length = math.hypot(x1 - x0, y1 - y0)
        nx, ny = -(y1 - y0) / length, (x1 - x0) / length  # inward normal of a counter-clockwise side
        lines.append(((x0 + inset * nx, y0 + inset * ny), (x1 - x0, y1 - y0)))
    result = []
    for k in range(n):
        (p, d), (q, e) = lines[k - 1], lines[k]
        det = d[0] * -e[1] - d[1] * -e[0]
        t = ((q[0] - p[0]) * -e[1] - (q[1] - p[1]) * -e[0]) / det
        result.append((p[0] + t * d[0], p[1] + t * d[1]))
    return result


def lizard():
    """A pebble-like lizard: the outline at the waist, its inset at the belly (z = 0) and the back
    (z = 2 waist), a bevel face above and below every side; mirror-symmetric about the waist, so
    where four faces meet at the waist every plate's inner corner is the same point."""
    n = len(LIZARD_OUTLINE)
    inner = inset_outline(LIZARD_OUTLINE, LIZARD_INSET)
    points = [[x, y, 0.0] for x, y in inner] + [[x, y, LIZARD_WAIST] for x, y in LIZARD_OUTLINE] + \
             [[x, y, 2 * LIZARD_WAIST] for x, y in inner]
    belly, waist, back = 0, n, 2 * n
    faces = [list(range(back, back + n)), list(reversed(range(belly, belly + n)))]
    for k in range(n):
        m = (k + 1) % n
        faces.append([waist + k, waist + m, back + m, back + k])     # upper bevel
        faces.append([belly + k, belly + m, waist + m, waist + k])   # lower bevel
    return points, faces


def ear_clip(points, face):
    """Triangles of a planar simple polygon (counter-clockwise about its normal), by ear clipping."""
    normal = [0.0, 0.0, 0.0]
    for a, b in zip(face, face[1:] + face[:1]):
        normal = [normal[c] + v for c, v in enumerate(cross(points[a], points[b]))]
    normal = unit(normal)
    u = unit(sub(points[face[1]], points[face[0]]))
    v = cross(normal, u)
    flat = {m: (dot(points[m], u), dot(points[m], v)) for m in face}

    def turn(a, b, c):
        (ax, ay), (bx, by), (cx, cy) = flat[a], flat[b], flat[c]
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)

    rest, triangles = list(face), []
    while len(rest) > 3:
        for i in range(len(rest)):
            a, b, c = rest[i - 1], rest[i], rest[(i + 1) % len(rest)]
            if turn(a, b, c) <= 0:
                continue  # a reflex corner is no ear
            if any(m not in (a, b, c) and turn(a, b, m) >= 0 and turn(b, c, m) >= 0 and turn(c, a, m) >= 0 for m in rest):
                continue
            triangles.append([a, b, c])
            del rest[i]
            break
        else:
            raise ValueError('polygon is not simple')
    triangles.append(rest)
    return triangles


def write_obj(name, title, points, faces, triangulate):
    path = os.path.join(HERE, name + '.obj')
    with open(path, 'w') as out:
        out.write('# %s\n# written by examples/plate/make_sculptures.py; units: mm\n' % title)
        out.write('o %s\n' % name)
        for p in points:
            out.write('v %.6f %.6f %.6f\n' % tuple(p))
        for face in faces:
            for polygon in (ear_clip(points, face) if triangulate else [face]):
                out.write('f %s\n' % ' '.join(str(m + 1) for m in polygon))
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--desia', default=os.path.join(ROOT, 'build', 'native', 'core', 'cli', 'desia'))
    args = parser.parse_args()
    def convex(points):
        return points, convex_polyhedron(points)
    shapes = [
        ('cube', 'CUBE of 200 mm: 6 plates', *convex(cube()), False),
        ('icosahedron', 'ICOSAHEDRON (circumradius 150 mm): 20 triangular plates', *convex(icosahedron()), False),
        ('dodecahedron', 'DODECAHEDRON (circumradius 150 mm): 12 pentagonal plates', *convex(dodecahedron()), False),
        ('lizard', 'LIZARD (after Fig. 1): 18-corner outline bevelled above and below, 38 plates', *lizard(), True),
    ]
    for name, title, points, faces, triangulate in shapes:
        obj = write_obj(name, title, points, faces, triangulate)
        out = os.path.join(HERE, name + '.json')
        # Relative paths (from the repository): the messages name the files as a user would.
        result = subprocess.run([os.path.abspath(args.desia), 'plates-from-mesh', '--input', os.path.relpath(obj, ROOT),
                                 '--thickness', str(THICKNESS[name]), '--output', os.path.relpath(out, ROOT)],
                                cwd=ROOT, capture_output=True, text=True)
        sys.stdout.write(result.stdout)
        if result.returncode != 0:
            sys.stderr.write(result.stderr)
            sys.exit('plates-from-mesh failed on %s' % obj)


if __name__ == '__main__':
    main()
