#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A box whose long sides lean out from upright (issue 26, slanted mortise-and-tenon joints).

A level base and lid, two long sides leaning out by `lean` degrees (15: their planes 75 degrees
from the base's and the lid's), and an upright end between them (the other end open). Each side's bottom and top are
bevelled to lie on the base's top face and the lid's bottom face (as IBOIS's hexboxes' sides lie
on their neighbours' faces): no square edge stands on a face at a right angle there, slanted
tenons join them. The end's slanted sides stand square on the sides' inner faces, its bottom and
top on the base and the lid. (With a second end the designer needs no slanted tenon: the base
slides out first on dovetails.)

    python3 examples/plate/make_leaning_box.py [--lean DEGREES --out FILE]
"""
import argparse
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def rounded(points):
    return [[round(v, 6) for v in p] for p in points]


def board(id_, name, face, offset):
    """A board by its first face and the second one, `offset` away."""
    return {"id": id_, "name": name,
            "faces": [rounded(face), rounded([[p[k] + offset[k] for k in range(3)] for p in face])]}


def leaning_box(lean=15.0, length=400.0, depth=260.0, height=200.0, t=18.0, margin=25.0, end_inset=40.0):
    s, c = math.sin(math.radians(lean)), math.cos(math.radians(lean))
    floor, ceiling = t, t + height  # the base's top face, the lid's bottom face
    reach = height * s / c  # how far a side leans out over its height
    near, far = margin + reach, margin + reach + depth  # the sides' outer faces at the floor

    def side(id_, name, y, outwards):
        up = [0.0, outwards * s / c, 1.0]  # per mm of height
        inwards = [0.0, -outwards * c, s]
        xs = [0.0, length] if outwards < 0 else [length, 0.0]
        outer = [[xs[0], y, floor], [xs[1], y, floor], [xs[1], y + up[1] * height, ceiling],
                 [xs[0], y + up[1] * height, ceiling]]
        # The inner face: moved in by t and slid along the side's plane back onto the levels,
        # which is the outer face moved t / cos(lean) level across.
        inner = [[p[0], p[1] - outwards * t / c, p[2]] for p in outer]
        return {"id": id_, "name": name, "faces": [rounded(outer), rounded(inner)]}

    def end(id_, name, x):
        inner_near = near + t / c  # the near side's inner face at the floor, along y
        inner_far = far - t / c
        face = [[x, inner_near, floor], [x, inner_far, floor], [x, inner_far + reach, ceiling],
                [x, inner_near - reach, ceiling]]
        return board(id_, name, face, [t, 0.0, 0.0])

    width = depth + 2 * (reach + margin)
    plates = [
        board(1, "base", [[0.0, 0.0, 0.0], [length, 0.0, 0.0], [length, width, 0.0], [0.0, width, 0.0]],
              [0.0, 0.0, t]),
        side(2, "front side", near, -1),
        side(3, "back side", far, 1),
        end(4, "left end", end_inset),
        board(5, "lid", [[0.0, 0.0, ceiling], [length, 0.0, ceiling], [length, width, ceiling],
                         [0.0, width, ceiling]], [0.0, 0.0, t]),
    ]
    return {"format": "desia-assembly", "version": 1, "kind": "plate",
            "name": f"leaning box: a base, a lid, an end and two sides leaning out {lean:g} degrees, {t:g} mm",
            "plates": plates}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lean", type=float, default=15.0)
    parser.add_argument("--out", default=os.path.join(HERE, "leaning_box.json"))
    args = parser.parse_args()
    with open(args.out, "w") as f:
        json.dump(leaning_box(args.lean), f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
