#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A closed box with slanted sides (a frustum of a square pyramid) of mitred plates (issue 26).

Each plate is given by its two faces: its outer face is a face of the frustum, its inner face the
same face plane moved in by the thickness, each vertex where three such planes meet, so that
neighbouring plates meet edge to edge along the planes that halve their angles (mitres). The
sides lean out from upright by `lean` degrees (55: a shallow tray with a lid): bottom and lid meet the
sides with their planes 90 - lean degrees apart, neighbouring sides 47.9 degrees (step tenons).

    python3 examples/plate/make_slanted_box.py [--lean DEGREES --out FILE]
"""
import argparse
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def solve3(planes):
    """The point on three planes (n, d): n . p = d (Cramer's rule)."""
    (a, da), (b, db), (c, dc) = planes

    def det(u, v, w):
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                + u[2] * (v[0] * w[1] - v[1] * w[0]))

    cols = [[a[i], b[i], c[i]] for i in range(3)]
    rhs = [da, db, dc]
    whole = det(*cols)
    point = []
    for i in range(3):
        replaced = [rhs if j == i else cols[j] for j in range(3)]
        point.append(det(*replaced) / whole)
    return point


def slanted_box(lean=55.0, width=400.0, height=220.0, t=18.0):
    """Outer planes: bottom z = 0, lid z = height, four sides leaning out by `lean` from vertical."""
    s, c = math.sin(math.radians(lean)), math.cos(math.radians(lean))
    half = width / 2
    planes = {"bottom": ([0.0, 0.0, -1.0], 0.0), "lid": ([0.0, 0.0, 1.0], height)}
    sides = {"front": (0.0, -1.0), "right": (1.0, 0.0), "back": (0.0, 1.0), "left": (-1.0, 0.0)}
    for name, (x, y) in sides.items():
        n = [x * c, y * c, -s]  # outward, tilted down: the box widens upwards
        planes[name] = (n, half * c)  # through the bottom's edge at z = 0
    around = ["front", "right", "back", "left"]
    faces = {"bottom": [(name, around[(k + 1) % 4]) for k, name in enumerate(around)][::-1],
             "lid": [(name, around[(k + 1) % 4]) for k, name in enumerate(around)]}
    for k, name in enumerate(around):
        prev, nxt = around[k - 1], around[(k + 1) % 4]
        faces[name] = [("bottom", prev), ("bottom", nxt), ("lid", nxt), ("lid", prev)]

    def corner(name, pair, inset):
        chosen = [planes[name], planes[pair[0]], planes[pair[1]]]
        return [round(v, 6) for v in solve3([(n, d - inset) for n, d in chosen])]

    plates = []
    for index, name in enumerate(["bottom", "front", "right", "back", "left", "lid"], start=1):
        outer = [corner(name, pair, 0.0) for pair in faces[name]]
        inner = [corner(name, pair, t) for pair in faces[name]]
        plates.append({"id": index, "name": name, "faces": [inner, outer]})
    return {"format": "desia-assembly", "version": 1, "kind": "plate",
            "name": f"slanted box: 6 mitred plates, {t:g} mm, sides leaning out {lean:g} degrees",
            "plates": plates}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lean", type=float, default=55.0)
    parser.add_argument("--out", default=os.path.join(HERE, "slanted_box.json"))
    args = parser.parse_args()
    with open(args.out, "w") as f:
        json.dump(slanted_box(args.lean), f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
