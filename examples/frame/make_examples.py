#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the frame examples of examples/frame/ (input frames in millimetres, modelled after the
paper's Fig. 19, Fig. 20, the SCAFFOLD inset and the FLOWER of Fig. 1, Section 5.3).
Run from anywhere: python3 examples/frame/make_examples.py [--results]
With --results it also designs the stored results (*_result.json: seed 1, the default) with the
native CLI (build/native/core/cli/desia; scripts/build.sh native first)."""
import json, math, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))


def document(name, joints, beams, **extra):
    doc = {"format": "desia-assembly", "version": 1, "kind": "frame", "name": name}
    doc.update(extra)
    doc["joints"] = [{"id": k + 1, "position": [round(c, 3) for c in p]} for k, p in enumerate(joints)]
    doc["beams"] = []
    for k, beam in enumerate(beams):
        if isinstance(beam, dict):
            entry = {"id": k + 1, "joints": beam["joints"]}
            entry["path"] = [[round(c, 3) for c in p] for p in beam["path"]]
            doc["beams"].append(entry)
        else:
            doc["beams"].append({"id": k + 1, "joints": list(beam)})
    return doc


def write(file_name, doc):
    with open(os.path.join(HERE, file_name), "w") as out:
        json.dump(doc, out, indent=1)
        out.write("\n")


def cube():
    # Fig. 19: the 12 edges of a cube, every corner a three-way voxel joint.
    s = 600
    joints = [[x, y, z] for y in (0, s) for z in (0, s) for x in (0, s)]
    index = {tuple(p): k + 1 for k, p in enumerate(joints)}
    beams = []
    for p in joints:
        for axis in range(3):
            if p[axis] == 0:
                q = list(p)
                q[axis] = s
                beams.append((index[tuple(p)], index[tuple(q)]))
    return document("FRAME CUBE (Fig. 19): the 12 edges of a 600 mm cube", joints, beams)


def chair():
    # Fig. 20: 1.0 m x 0.5 m x 0.5 m. Four legs; the feet joined in pairs by floor rails (front,
    # back); side seat rails; the back legs go on up as the back posts under a top rail.
    # 11 beams, joints of valence 2 and 3 (the paper's chair has 2 to 4; it does not give its exact
    # beams).
    w, d, seat, top = 500, 500, 450, 1000
    joints = [
        [0, 0, 0], [w, 0, 0], [w, 0, d], [0, 0, d],              # feet 1-4 (front: z = 0)
        [0, seat, 0], [w, seat, 0], [w, seat, d], [0, seat, d],  # seat corners 5-8
        [0, top, d], [w, top, d],                                # back top 9-10
    ]
    beams = [(1, 5), (2, 6), (3, 7), (4, 8),  # legs
             (1, 2), (4, 3),                  # floor rails, front and back
             (5, 8), (6, 7),                  # side seat rails
             (8, 9), (7, 10), (9, 10)]        # back posts and top rail
    return document("FRAME CHAIR (after Fig. 20): 1.0 m x 0.5 m x 0.5 m, 11 beams", joints, beams)


def cut_point():
    # Two square frames joined by one beam: that beam is a cut point of the parts-graph, and no
    # joints can make such a frame interlocking (paper Fig. 18).
    s = 400
    joints = [[0, 0, 0], [s, 0, 0], [s, 0, s], [0, 0, s],
              [2 * s, 0, 0], [3 * s, 0, 0], [3 * s, 0, s], [2 * s, 0, s]]
    beams = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5), (2, 5)]
    return document("TWO SQUARES joined by one beam (refused: beam 9 is a cut point)", joints, beams)


def lattice(name, cells, spacing, skip=()):
    nx, ny, nz = cells
    joints, index = [], {}
    for y in range(ny + 1):
        for z in range(nz + 1):
            for x in range(nx + 1):
                index[(x, y, z)] = len(joints) + 1
                joints.append([x * spacing, y * spacing, z * spacing])
    beams = []
    for (x, y, z), a in sorted(index.items(), key=lambda item: item[1]):
        for axis, step in enumerate([(1, 0, 0), (0, 1, 0), (0, 0, 1)]):
            q = (x + step[0], y + step[1], z + step[2])
            if q in index and ((x, y, z), axis) not in skip:
                beams.append((a, index[q]))
    return document(name, joints, beams)


def scaffold():
    # The SCAFFOLD inset of Section 5.3 (92 beams): a 4 x 2 x 2-cell lattice (96 beams) without the
    # four beams along z of the middle row at the lower middle level.
    skip = {((x, 1, 1), 0) for x in range(4)}
    doc = lattice("SCAFFOLD (Section 5.3 inset): a 4 x 2 x 2-cell lattice of 1 m cells, 92 beams", (4, 2, 2), 1000, skip)
    assert len(doc["beams"]) == 92, len(doc["beams"])
    return doc


def scaffold_300():
    doc = lattice("SCAFFOLD 4 x 4 x 4 cells (benchmark), 300 beams", (4, 4, 4), 1000)
    assert len(doc["beams"]) == 300, len(doc["beams"])
    return doc


def scaffold_882():
    # A 6 x 6 x 6-cell lattice: a long design (seconds), for progress and cancellation.
    doc = lattice("SCAFFOLD 6 x 6 x 6 cells, 882 beams", (6, 6, 6), 1000)
    assert len(doc["beams"]) == 882, len(doc["beams"])
    return doc


def flower():
    # After the FLOWER of Fig. 1: 23 curved beams. The topology of a 2 x 1 x 1-cell lattice (20
    # beams) with a stem loop below its middle (3 beams); the upper joints spread out and up like
    # an opening flower, and every beam bows outwards through a path: it leaves each joint straight
    # out of the face the lattice gives it (so the face is never in doubt), then arcs.
    cell = 500
    grid = [(x, y, z) for y in (0, 1) for z in (0, 1) for x in (0, 1, 2)]
    centre = [cell, 0, cell / 2]

    def place(x, y, z):
        p = [x * cell, y * cell, z * cell]
        if y == 1:  # the upper ring opens: farther from the axis, and higher
            p = [centre[0] + 1.3 * (p[0] - centre[0]), 650, centre[2] + 1.6 * (p[2] - centre[2])]
        return p

    joints = [place(*g) for g in grid]
    index = {g: k for k, g in enumerate(grid)}
    ends = []  # (joint a, face normal a, joint b, face normal b)
    for g in grid:
        for axis in range(3):
            q = list(g)
            q[axis] += 1
            if tuple(q) in index:
                n = [0, 0, 0]
                n[axis] = 1
                ends.append((index[g], n, index[tuple(q)], [-c for c in n]))
    joints.append([cell, -400, 0])     # stem joints below the middle of the lower ring
    joints.append([cell, -400, cell])
    s1, s2 = len(joints) - 2, len(joints) - 1
    ends.append((index[(1, 0, 0)], [0, -1, 0], s1, [0, 1, 0]))
    ends.append((index[(1, 0, 1)], [0, -1, 0], s2, [0, 1, 0]))
    ends.append((s1, [0, 0, 1], s2, [0, 0, -1]))
    beams = []
    for a, na, b, nb in ends:
        pa, pb = joints[a], joints[b]
        length = math.dist(pa, pb)
        out = 0.3 * length
        start = [pa[k] + out * na[k] for k in range(3)]
        end = [pb[k] + out * nb[k] for k in range(3)]
        mid = [(start[k] + end[k]) / 2 for k in range(3)]
        radial = [mid[0] - centre[0], 0, mid[2] - centre[2]]
        r = math.hypot(radial[0], radial[2]) or 1
        bow = [0.15 * length * radial[0] / r, 0.08 * length, 0.15 * length * radial[2] / r]
        beams.append({"joints": [a + 1, b + 1], "path": [start, [mid[k] + bow[k] for k in range(3)], end]})
    assert len(beams) == 23, len(beams)
    return document("FLOWER (after Fig. 1): 23 curved beams", joints, beams)


def main():
    write("frame_cube.json", cube())
    write("frame_chair.json", chair())
    write("cut_point.json", cut_point())
    write("scaffold_92.json", scaffold())
    write("scaffold_300.json", scaffold_300())
    write("scaffold_882.json", scaffold_882())
    write("flower.json", flower())
    if "--results" in sys.argv[1:]:
        cli = os.path.join(HERE, "..", "..", "build", "native", "core", "cli", "desia")
        for name in ("frame_cube", "frame_chair", "flower", "scaffold_92"):
            subprocess.run([cli, "design", "frame", "--input", os.path.join(HERE, name + ".json"), "--output",
                            os.path.join(HERE, name + "_result.json"), "--seed", "1", "--quiet"], check=True)


if __name__ == "__main__":
    main()
