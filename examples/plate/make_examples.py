#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the plate examples of examples/plate/ (input designs, in millimetres, modelled after the
paper's Fig. 13, 17, 18 and 1). Run from anywhere: python3 examples/plate/make_examples.py"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))


def box(id_, name, lo, hi):
    """An axis-aligned board: the face at the smallest extent's low side, extruded along it."""
    size = [hi[k] - lo[k] for k in range(3)]
    axis = min(range(3), key=lambda k: size[k])
    u, v = [k for k in range(3) if k != axis]
    # Counter-clockwise about +axis, so the right-hand normal points into the board.
    corners = []
    for a, b in [(lo[u], lo[v]), (hi[u], lo[v]), (hi[u], hi[v]), (lo[u], hi[v])]:
        p = [0.0, 0.0, 0.0]
        p[axis], p[u], p[v] = lo[axis], a, b
        corners.append(p)
    if (u, v, axis) not in [(0, 1, 2), (1, 2, 0), (2, 0, 1)]:
        corners.reverse()
    return {"id": id_, "name": name, "outline": corners, "thickness": size[axis]}


def document(name, plates, **extra):
    doc = {"format": "desia-assembly", "version": 1, "kind": "plate", "name": name}
    doc.update(extra)
    doc["plates"] = plates
    return doc


def table():
    # Fig. 17: a top, two side panels as legs, front and back aprons, a shelf. 18 mm boards. The
    # top overhangs by 25 mm and the aprons stand 20 mm in from the edges, so every joint is a
    # through mortise-and-tenon (a board flush with an edge would get an open mortise, which lets
    # it slide out sideways).
    t = 18
    return document("TABLE (after Fig. 17): top, two side panels, two aprons and a shelf; orthogonal butt joints", [
        box(1, "top", [-25, 700, -25], [1025, 700 + t, 625]),
        box(2, "left side", [0, 0, 0], [t, 700, 600]),
        box(3, "right side", [1000 - t, 0, 0], [1000, 700, 600]),
        box(4, "front apron", [t, 550, 20], [1000 - t, 700, 20 + t]),
        box(5, "back apron", [t, 550, 580 - t], [1000 - t, 700, 580]),
        box(6, "shelf", [t, 150, 40], [1000 - t, 150 + t, 560]),
    ])


def table_with_divider():
    # The TABLE with a divider standing through a slot in its shelf (the two boards cross): a halved
    # joint (paper Fig. 2) beside the mortise-and-tenon joints.
    doc = table()
    t = 18
    doc["plates"].append(box(7, "divider", [491, 100, 40], [491 + t, 700, 560]))
    doc["name"] = "TABLE with a divider crossing its shelf (7 plates): mortise-and-tenon and halved joints"
    return doc


def table_with_split_side():
    # The TABLE with its left side panel in two halves, front and back, meeting edge to edge at
    # z = 300 in the plane x = 0..18 (as IBOIS's VDA corner's hexagons meet): an in-plane dovetail
    # joins the halves beside the mortise-and-tenon joints.
    doc = table()
    t = 18
    doc["plates"][1] = box(2, "left side, front half", [0, 0, 0], [t, 700, 300])
    doc["plates"].append(box(7, "left side, back half", [0, 0, 300], [t, 700, 600]))
    doc["name"] = "TABLE with its left side in two halves meeting edge to edge (7 plates): an in-plane dovetail and mortise-and-tenon joints"
    return doc


def long_table(bays, bay=600.0, t=18.0, depth=600.0, height=700.0):
    """A long table of `bays` bays, 4 bays + 2 plates: a top over a row of side panels, a front and
    a back apron and a shelf in each bay. The middle panels carry aprons and shelves from both
    sides at the same place: their tenons take turns (staggered) so the mortises never meet."""
    length = bays * (bay + t) + t
    plates = [box(1, "top", [-25, height, -25], [length + 25, height + t, depth + 25])]
    for i in range(bays + 1):
        x = i * (bay + t)
        plates.append(box(len(plates) + 1, f"side {i + 1}", [x, 0, 0], [x + t, height, depth]))
    for i in range(bays):
        x0 = i * (bay + t) + t
        plates.append(box(len(plates) + 1, f"front apron {i + 1}", [x0, 550, 20], [x0 + bay, height, 20 + t]))
        plates.append(box(len(plates) + 1, f"back apron {i + 1}", [x0, 550, depth - 20 - t], [x0 + bay, height, depth - 20]))
        plates.append(box(len(plates) + 1, f"shelf {i + 1}", [x0, 150, 40], [x0 + bay, 150 + t, depth - 40]))
    return document(f"LONG TABLE of {bays} bays ({len(plates)} plates): through mortise-and-tenon joints everywhere", plates)


def chair(with_bar):
    # Fig. 18: a seat on two legs with a back; the back panel touches only the seat, so the seat
    # is a cut point. The repaired chair adds a bar joining the back to the legs.
    t = 18
    plates = [
        box(1, "left leg", [0, 0, 0], [t, 450 - t, 450]),
        box(2, "right leg", [450 - t, 0, 0], [450, 450 - t, 450]),
        box(3, "front rail", [t, 300, 0], [450 - t, 450 - 2 * t, t]),
        box(4, "back rail", [t, 300, 450 - t], [450 - t, 450 - 2 * t, 450]),
        box(5, "seat", [0, 450 - t, 0], [450, 450, 450]),
        box(6, "back", [0, 450, 450 - t], [450, 900, 450]),
        box(7, "low stretcher", [t, 100, 200], [450 - t, 100 + t, 250]),
        box(8, "middle stretcher", [t, 200, 200], [450 - t, 200 + t, 250]),
    ]
    name = "CHAIR (after Fig. 18): the back rests on the seat alone, so the seat is a cut point"
    if with_bar:
        # Two side bars from the legs up to the back bypass the seat (the paper adds one part).
        plates.append(box(9, "left back bar", [-t, 300, 450 - 3 * t], [0, 900, 450]))
        plates.append(box(10, "right back bar", [450, 300, 450 - 3 * t], [450 + t, 900, 450]))
        name = "CHAIR repaired (after Fig. 18): side bars join the back to the legs, no cut point"
    return document(name, plates)


def mitred_box(side=300.0, t=12.0):
    # A closed cube of six plates meeting at 45-degree mitres: every contact is edge to edge, with a
    # normal at 45 degrees to the plates (non-orthogonal contacts, judged by the LP test).
    plates = []
    for index, (axis, sign) in enumerate([(0, -1), (0, 1), (1, -1), (1, 1), (2, -1), (2, 1)]):
        u, v = [k for k in range(3) if k != axis]
        outer_level = 0.0 if sign < 0 else side
        inner_level = outer_level - sign * t
        def corner(level, lo, hi, a, b):
            p = [0.0, 0.0, 0.0]
            p[axis] = level
            p[u] = lo if a == 0 else hi
            p[v] = lo if b == 0 else hi
            return p
        order = [(0, 0), (1, 0), (1, 1), (0, 1)]
        outer = [corner(outer_level, 0.0, side, a, b) for a, b in order]
        inner = [corner(inner_level, t, side - t, a, b) for a, b in order]
        plates.append({"id": index + 1, "name": "xyz"[axis] + ("-" if sign < 0 else "+") + " face", "faces": [outer, inner]})
    return document("MITRED BOX: a closed cube of six 12 mm plates with 45-degree mitres", plates)


def shelf(rows, columns, name, cell=300.0, t=18.0, depth=300.0):
    """A bookcase of `rows` x `columns` cells: two full-height sides, shelves between them, and
    uprights between each pair of shelves at the inner column boundaries (every cell is a cycle)."""
    width = columns * (cell + t) + t
    height = rows * (cell + t) + t
    plates = [box(1, "left side", [0, 0, 0], [t, height, depth]), box(2, "right side", [width - t, 0, 0], [width, height, depth])]
    for r in range(rows + 1):
        y = r * (cell + t)
        plates.append(box(len(plates) + 1, f"shelf {r + 1}", [t, y, 0], [width - t, y + t, depth]))
    for r in range(rows):
        y0 = r * (cell + t) + t
        for c in range(1, columns):
            x = c * (cell + t)
            plates.append(box(len(plates) + 1, f"upright {r + 1}.{c}", [x, y0, 0], [x + t, y0 + cell, depth]))
    return document(name, plates)


def cabinet(width=600.0, depth=400.0, wall=600.0, ridge=115.0, t=18.0):
    # After Fig. 13: a cabinet under a gable roof. Two pentagonal sides, a bottom, a back and a
    # shelf between them, and two roof boards resting on the sides' sloped edges and meeting at the
    # ridge in a vertical mitre: the roof's contacts are not orthogonal (judged by the LP test).
    half = depth / 2
    def side(id_, name, x0):
        # The outline in the plane x = x0 (counter-clockwise about +x, so it extrudes towards +x).
        outline = [[x0, 0, 0], [x0, wall, 0], [x0, wall + ridge, half], [x0, wall, depth], [x0, 0, depth]]
        return {"id": id_, "name": name, "outline": outline, "thickness": t}
    slope = math.hypot(half, ridge)
    up = [0.0, half / slope, -ridge / slope]  # the front roof board's outward normal in (x, y, z)
    def roof(id_, name, front):
        sign = 1 if front else -1
        eave_z = 0.0 if front else depth
        n = [0.0, up[1], sign * up[2]]
        bottom = [[-t, wall, eave_z], [width + t, wall, eave_z], [width + t, wall + ridge, half], [-t, wall + ridge, half]]
        # The top face: the eave edge moved out along the normal; the ridge edge where the top
        # plane meets the vertical mitre plane z = half.
        eave_top = [[p[k] + t * n[k] for k in range(3)] for p in bottom[:2]]
        # On the top plane, from the eave going up the slope to z = half.
        along = [0.0, ridge / slope, sign * half / slope]
        run = (half - eave_top[0][2]) / along[2]
        ridge_top = [[p[k] + run * along[k] for k in range(3)] for p in reversed(eave_top)]
        top = eave_top + ridge_top
        if not front:
            bottom = [bottom[1], bottom[0], bottom[3], bottom[2]]
            top = [top[1], top[0], top[3], top[2]]
        return {"id": id_, "name": name, "faces": [bottom, top]}
    plates = [
        side(1, "left side", -t),
        side(2, "right side", width),
        box(3, "bottom", [0, 0, 0], [width, t, depth]),
        box(4, "back", [0, t, depth - t], [width, wall, depth]),
        box(5, "shelf", [0, 300, 0], [width, 300 + t, depth - t]),
        roof(6, "front roof", True),
        roof(7, "back roof", False),
    ]
    return document("CABINET (after Fig. 13): a cabinet under a gable roof; the roof boards meet at a mitred ridge", plates)


def main():
    examples = {
        "cabinet.json": cabinet(),
        "bookshelf.json": shelf(3, 3, "BOOKSHELF (after Fig. 1): 3 x 3 cells, two sides, 4 shelves and 6 uprights (12 plates)"),
        "bookcase_123.json": shelf(10, 12, "BOOKCASE of 10 x 12 cells: two sides, 11 shelves and 110 uprights (123 plates)"),
        "table.json": table(),
        "table_divider.json": table_with_divider(),
        "table_split_side.json": table_with_split_side(),
        "bench_2_bays.json": long_table(2),
        "long_table_102.json": long_table(25),
        "chair_cut_point.json": chair(False),
        "chair_repaired.json": chair(True),
        "mitred_box.json": mitred_box(),
    }
    for name, doc in examples.items():
        with open(os.path.join(HERE, name), "w") as out:
            json.dump(doc, out, indent=1)
            out.write("\n")


if __name__ == "__main__":
    main()
