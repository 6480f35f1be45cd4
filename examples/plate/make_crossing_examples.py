#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the plate examples whose plates cross at an angle (issue 26; the paper's halved joint,
Fig. 16c, at any angle): the TABLE of make_examples.py with its shelf tilted about the table's
length (its ends still square to the side panels) and a divider standing under the top (its top
edge square to it), turned in plan, passing through the shelf. The shelf and the divider cross at
`angle` degrees along a slanted line; the designer halves them there, each notch's walls in the
other plate's face planes. Run from anywhere: python3 examples/plate/make_crossing_examples.py
(`--angle A --out FILE` writes the table at another angle, as the tests do)."""
import argparse, json, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from make_examples import table  # noqa: E402


def rounded(p):
    return [round(c, 9) + 0.0 for c in p]


def slab(id_, name, corners, thickness):
    """A board given by its first face's corners (counter-clockwise about its thickness axis)."""
    return {"id": id_, "name": name, "outline": [rounded(p) for p in corners], "thickness": thickness}


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def table_with_slanted_crossing(angle, t=18.0, depth=440.0, centre=(500.0, 250.0, 300.0)):
    # The shelf is tilted by phi about x and the divider turned by alpha in plan, alpha = phi: the
    # angle between their planes is acos(sin(alpha) sin(phi)); 90 degrees: the divider alone turned.
    tilt = 0.0 if angle >= 90 else math.asin(math.sqrt(math.cos(math.radians(angle))))
    turn = math.radians(30.0) if angle >= 90 else tilt
    doc = table()
    plates = [p for p in doc["plates"] if p["name"] != "shelf"]
    shelf_normal = (0.0, -math.cos(tilt), math.sin(tilt))  # x cross (its depth direction)
    shelf_depth = (0.0, math.sin(tilt), math.cos(tilt))
    def on_shelf(x, s):
        return [x if k == 0 else centre[k] + s * shelf_depth[k] - t / 2 * shelf_normal[k] for k in range(3)]
    half = depth / 2
    plates.append(slab(6, "tilted shelf", [on_shelf(18, -half), on_shelf(982, -half), on_shelf(982, half),
                                           on_shelf(18, half)], t))
    divider_normal = (math.cos(turn), 0.0, math.sin(turn))
    along = (-math.sin(turn), 0.0, math.cos(turn))  # the divider in plan; along x y = -divider_normal
    def on_divider(s, y):
        return [centre[0] + s * along[0] - t / 2 * divider_normal[0], y,
                centre[2] + s * along[2] - t / 2 * divider_normal[2]]
    # Where the crossing line leaves the shelf at its back edge, seen along the divider: the
    # divider ends 5 mm before it (its slot opens there), and runs on past the front edge and below.
    line = cross(divider_normal, shelf_normal)
    back = abs(half / dot(line, shelf_depth) * dot(line, along)) - 5
    front = -(back + 5 + 2 * t)
    if dot(line, shelf_depth) * dot(line, along) < 0:
        back, front = -front, -back
    low = min(on_shelf(18, -half)[1], on_shelf(18, half)[1]) - 2 * t
    plates.append(slab(7, "divider", [on_divider(front, low), on_divider(front, 700.0), on_divider(back, 700.0),
                                      on_divider(back, low)], t))
    doc["plates"] = plates
    doc["name"] = (f"TABLE with a tilted shelf and a divider crossing it at {angle:g} degrees (7 plates): "
                   f"mortise-and-tenon joints and a halved joint whose notch walls follow the other plate's faces")
    return doc


def write(path, doc):
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--angle", type=float)
    parser.add_argument("--out")
    args = parser.parse_args()
    if args.angle is not None:
        write(args.out, table_with_slanted_crossing(args.angle))
        return
    write(os.path.join(HERE, "table_slanted_crossing.json"), table_with_slanted_crossing(60.0))


if __name__ == "__main__":
    main()
