#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Convert BurrTools' example puzzles (cubic grid) into desia test data.

For every examples/*.xmpuzzle of BurrTools whose grid is cubic (<gridType type="0"/>), for every
problem and every stored solution (at most MAX_SOLUTIONS per file, chosen deterministically), this
script places every piece of the solution's assembly in the result shape's voxel space, checks the
placement (no two pieces overlap; the union covers every filled '#' voxel of the result, may use its
variable '+' voxels and nothing else), writes the assembly as a desia .puz file and records the
disassembly that BurrTools stored with the solution: its level in BurrTools' notation (what
BurrTools' movesText prints, split at the dots) and its total number of moves (sumMoves).

Only facts about BurrTools' file format are taken from BurrTools' sources (src/lib/voxel.cpp,
voxel_0.cpp, tabs_0/rotmatrix.inc, assembly.cpp, assembler_0.cpp, problem.cpp, solution.cpp,
disassembly.cpp); the code here is written for desia.

Usage:
  python3 scripts/burrtools-solutions.py --burrtools PATH [--output tests/data/burrtools] [--desia CLI]

PATH is a BurrTools checkout (a directory with examples/) or a bare git directory of BurrTools
(read at HEAD, or at --rev). Standard library only.
"""

import argparse
import gzip
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

MAX_SOLUTIONS = 40  # per example file

# ---------------------------------------------------------------------------------------------
# BurrTools' 24 rotations of the cubic grid, in BurrTools' order (transformation numbers 0..23,
# src/lib/tabs_0/rotmatrix.inc). Each entry gives the three rows of the matrix M as signed axes:
# "x -z y" means  x' = x,  y' = -z,  z' = y  (BurrTools computes x' = M[0]x + M[1]y + M[2]z, ...).
# Assemblies only use these 24 (assembly_c's reader refuses 24..47, the mirror images).
ROTATIONS = [
    "x y z", "x -z y", "x -y -z", "x z -y",
    "-z y x", "-y -z x", "z -y x", "y z x",
    "-x y -z", "-x -z -y", "-x -y z", "-x z y",
    "z y -x", "y -z -x", "-z -y -x", "-y z -x",
    "-y x z", "z x y", "y x -z", "-z x -y",
    "y -x z", "-z -x y", "-y -x -z", "z -x -y",
]


def rotation_matrix(text):
    rows = []
    for token in text.split():
        sign = -1 if token.startswith("-") else 1
        axis = "xyz".index(token[-1])
        row = [0, 0, 0]
        row[axis] = sign
        rows.append(row)
    return rows


MATRICES = [rotation_matrix(r) for r in ROTATIONS]


def apply(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] for i in range(3))


# ---------------------------------------------------------------------------------------------
# Shapes (voxel spaces)

EMPTY, FILLED, VARIABLE = 0, 1, 2


class Shape:
    """A BurrTools voxel space: size, hotspot and per-voxel state (x fastest, then y, then z)."""

    def __init__(self, element, index):
        self.index = index
        self.name = element.get("name", "")
        self.size = tuple(int(element.get(a)) for a in ("x", "y", "z"))
        # A missing hotspot attribute is 0 (voxel.cpp uses atoi of the empty string).
        self.hotspot = tuple(int(element.get(a) or 0) for a in ("hx", "hy", "hz"))
        if element.get("type") != "0":
            raise ValueError("shape %d: unknown voxel type %r" % (index, element.get("type")))
        self.states = []
        for c in element.text or "":
            if c == "#":
                self.states.append(FILLED)
            elif c == "+":
                self.states.append(VARIABLE)
            elif c == "_":
                self.states.append(EMPTY)
            elif c.isdigit():
                pass  # colour of the voxel before it (colour constraints do not change geometry)
            elif c.isspace():
                pass
            else:
                raise ValueError("shape %d: unexpected character %r" % (index, c))
        sx, sy, sz = self.size
        if len(self.states) != sx * sy * sz:
            raise ValueError("shape %d: %d voxels for a %dx%dx%d space" % (index, len(self.states), sx, sy, sz))

    def voxels(self, state):
        sx, sy, _ = self.size
        out = []
        for i, s in enumerate(self.states):
            if s == state:
                out.append((i % sx, (i // sx) % sy, i // (sx * sy)))
        return out

    def placed_voxels(self, trans, position):
        """The FILLED voxels of this shape in orientation trans, placed at position.

        BurrTools rotates the whole voxel space with M and shifts it so that its corner (0,0,0)
        stays the minimum corner (voxel_0_c::transform); the hotspot goes along. The assembler
        (assembler_0_c) records a piece whose rotated space starts at offset o in the result as
        position o + rotated hotspot. So a voxel p of the rotated space lies at
        position - rotated hotspot + p. Only FILLED voxels of a piece are placed.
        """
        m = MATRICES[trans]
        sx, sy, sz = self.size
        corner = apply(m, (sx - 1, sy - 1, sz - 1))
        shift = tuple(-c if c < 0 else 0 for c in corner)
        hot = apply(m, self.hotspot)
        hot = tuple(hot[k] + shift[k] for k in range(3))
        out = []
        for v in self.voxels(FILLED):
            r = apply(m, v)
            out.append(tuple(position[k] - hot[k] + r[k] + shift[k] for k in range(3)))
        return out


# ---------------------------------------------------------------------------------------------
# Disassemblies: both stored forms are reduced to BurrTools' separationInfo list (pre-order:
# for each separation the number of its states, then its 'left' subtree, then its 'removed'
# subtree; 0 for a missing subtree). A separation's moves are states - 1, the last one being the
# move that takes the removed group out.


def separation_to_info(element, out):
    states = element.findall("state")
    if not states:
        raise ValueError("separation without states")
    out.append(len(states))
    subs = {s.get("type"): s for s in element.findall("separation")}
    for kind in ("left", "removed"):
        if kind in subs:
            separation_to_info(subs[kind], out)
        else:
            out.append(0)
    return out


def subtree_end(values, idx):
    """Index just after the subtree starting at idx."""
    open_ends = 1
    while open_ends:
        open_ends += 1 if values[idx] else -1
        idx += 1
    return idx


def has_multi_moves(values, idx):
    """True when the subtree at idx has a separation of more than one move (states > 2)."""
    return any(v > 2 for v in values[idx:subtree_end(values, idx)])


def level_list(values, idx=0):
    """BurrTools' movesText split at the dots: moves of this separation, then (pre-order) the
    left and removed subtrees, each only when it contains a separation of more than one move."""
    out = [values[idx] - 1]
    left = idx + 1
    removed = subtree_end(values, left)
    for child in (left, removed):
        if values[child] and has_multi_moves(values, child):
            out += level_list(values, child)
    return out


def sum_moves(values):
    return sum(v - 1 for v in values if v)


def unseparated_groups(element, out):
    """Groups of more than one piece that a full <separation> leaves together (BurrTools' piece
    numbers): the pieces left in, or removed by, the last state when no sub-separation follows."""
    pieces = [int(t) for t in element.find("pieces").text.split()]
    last = element.findall("state")[-1]
    d = [[int(t) for t in last.find(a).text.split()] for a in ("dx", "dy", "dz")]
    removed = [p for i, p in enumerate(pieces) if max(abs(d[0][i]), abs(d[1][i]), abs(d[2][i])) > 10000]
    left = [p for p in pieces if p not in removed]
    subs = {s.get("type"): s for s in element.findall("separation")}
    for kind, group in (("left", left), ("removed", removed)):
        if kind in subs:
            unseparated_groups(subs[kind], out)
        elif len(group) > 1:
            out.append(sorted(group))
    return out


def check_separation_states(element, piece_voxels, positions, problems, where):
    """Replays a full <separation>: every state must be free of overlaps among the pieces still
    in it, and consecutive states must differ by one translation of a set of pieces along one
    axis. Checks that the placement conversion agrees with BurrTools' own coordinates.

    A state holds each piece's position in the assembly's coordinates (the disassembler starts
    from the assembly's placements; disassemblernode.cpp), so a piece has moved by its state
    position minus its assembly position. A removed piece is more than 10000 away."""
    pieces = [int(t) for t in element.find("pieces").text.split()]
    states = []
    for st in element.findall("state"):
        d = [[int(t) for t in st.find(a).text.split()] for a in ("dx", "dy", "dz")]
        states.append([(d[0][i], d[1][i], d[2][i]) for i in range(len(pieces))])
    for si, offsets in enumerate(states):
        seen = {}
        for i, p in enumerate(pieces):
            if any(abs(c) > 10000 for c in offsets[i]):
                continue  # removed
            shift = tuple(offsets[i][k] - positions[p][k] for k in range(3))
            for v in piece_voxels[p]:
                w = (v[0] + shift[0], v[1] + shift[1], v[2] + shift[2])
                if w in seen:
                    problems.append("state %d of a separation: pieces %d and %d overlap" % (si, seen[w], p))
                    return
                seen[w] = p
    for si in range(1, len(states)):
        moved = [i for i in range(len(pieces)) if states[si][i] != states[si - 1][i]]
        deltas = set()
        for i in moved:
            a, b = states[si - 1][i], states[si][i]
            deltas.add(tuple(b[k] - a[k] for k in range(3)) if max(abs(c) for c in b) <= 10000 else "out")
        if not moved:
            problems.append("state %d repeats the previous state" % si)
        else:
            d = [x for x in deltas if x != "out"]
            if len(set(d)) > 1 or any(sum(1 for c in x if c) != 1 for x in d):
                problems.append("state %d is not one translation along one axis: %s" % (si, deltas))
    for sub in element.findall("separation"):
        check_separation_states(sub, piece_voxels, positions, problems, where)


# ---------------------------------------------------------------------------------------------
# Problems and solutions


def problem_pieces(problem):
    """Shape id of every piece of the problem, in BurrTools' piece order (each <shape> entry in
    turn, as many pieces as its count, or its max for a min/max range)."""
    out = []
    shapes = problem.find("shapes")
    for entry in shapes.findall("shape") if shapes is not None else []:
        sid = int(entry.get("id"))
        if entry.get("count"):
            n = int(entry.get("count"))
        elif entry.get("min") and entry.get("max"):
            n = int(entry.get("max"))
        else:
            n = 1
        out += [sid] * n
    return out


def parse_assembly(text):
    """List of (x, y, z, trans) per piece, None for an unplaced piece ('x')."""
    tokens = text.split()
    out = []
    i = 0
    while i < len(tokens):
        if tokens[i] == "x":
            out.append(None)
            i += 1
        else:
            x, y, z, t = (int(v) for v in tokens[i:i + 4])
            if not 0 <= t < 24:
                raise ValueError("transformation %d outside 0..23" % t)
            out.append((x, y, z, t))
            i += 4
    return out


def level_key(solution):
    """The stored level of a <solution> element as text ('' when none is stored)."""
    sep = solution.find("separation")
    info = solution.find("separationInfo")
    if sep is not None:
        values = separation_to_info(sep, [])
    elif info is not None:
        values = [int(t) for t in info.text.split()]
    else:
        return ""
    return ".".join(str(v) for v in level_list(values))


def choose_solutions(solutions):
    """Indices of at most MAX_SOLUTIONS solutions, deterministically and for variety: the
    solutions are grouped by their stored level (groups in order of first appearance, each in
    file order) and taken round-robin, one from each group in turn, until the cap is reached.
    Below the cap every solution is taken."""
    if len(solutions) <= MAX_SOLUTIONS:
        return list(range(len(solutions)))
    groups = {}
    for i, (_, _, sol) in enumerate(solutions):
        groups.setdefault(level_key(sol), []).append(i)
    queues = list(groups.values())
    chosen = []
    while len(chosen) < MAX_SOLUTIONS:
        for q in queues:
            if q and len(chosen) < MAX_SOLUTIONS:
                chosen.append(q.pop(0))
    return sorted(chosen)


def format_puz(size, labels):
    nx, ny, nz = size
    lines = ["%d %d %d" % size]
    for z in range(nz):
        for y in range(ny):
            lines.append(" ".join(str(labels.get((x, y, z), 0)) for x in range(nx)))
        lines.append("")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# Reading BurrTools


class Source:
    def __init__(self, path, rev):
        self.path = path
        self.rev = rev
        self.checkout = os.path.isdir(os.path.join(path, "examples"))
        self.commit = self._git("rev-parse", rev).strip() if not self.checkout else self._checkout_commit()

    def _git(self, *args, binary=False):
        out = subprocess.run(["git", "--git-dir", self.path] + list(args), check=True, stdout=subprocess.PIPE)
        return out.stdout if binary else out.stdout.decode()

    def _checkout_commit(self):
        try:
            return subprocess.run(["git", "-C", self.path, "rev-parse", "HEAD"], check=True,
                                  stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout.decode().strip()
        except (subprocess.CalledProcessError, OSError):
            return None

    def examples(self):
        if self.checkout:
            names = sorted(os.listdir(os.path.join(self.path, "examples")))
        else:
            names = [n.split("/")[-1] for n in self._git("ls-tree", "--name-only", self.rev, "examples/").split("\n")]
            names = sorted(n for n in names if n)
        return [n for n in names if n.endswith(".xmpuzzle")]

    def read(self, name):
        if self.checkout:
            with open(os.path.join(self.path, "examples", name), "rb") as f:
                data = f.read()
        else:
            data = self._git("show", "%s:examples/%s" % (self.rev, name), binary=True)
        if data[:2] == b"\x1f\x8b":
            data = gzip.decompress(data)
        return data


# ---------------------------------------------------------------------------------------------


def convert_example(name, data, outdir, entries, report):
    try:
        root = ET.fromstring(data)
    except ET.ParseError:
        # BurrTools reads bytes; some examples carry Latin-1 text (e.g. a designer's name).
        root = ET.fromstring(data.decode("latin-1"))
    base = name[:-len(".xmpuzzle")]
    grid = root.find("gridType")
    if grid is None or grid.get("type") != "0":
        report["skipped_grid"].append("%s (gridType %s)" % (name, grid.get("type") if grid is not None else "?"))
        return
    shapes = [Shape(e, i) for i, e in enumerate(root.find("shapes").findall("voxel"))]
    problems_el = root.find("problems")
    problems = problems_el.findall("problem") if problems_el is not None else []
    # All solutions of the file, in file order, then the cap.
    all_solutions = []
    for pi, problem in enumerate(problems):
        sols = problem.find("solutions")
        for si, sol in enumerate(sols.findall("solution") if sols is not None else []):
            all_solutions.append((pi, si, sol))
    if not all_solutions:
        report["no_solutions"].append(name)
        return
    chosen = [all_solutions[i] for i in choose_solutions(all_solutions)]
    if len(chosen) < len(all_solutions):
        report["capped"].append("%s: %d of %d solutions" % (name, len(chosen), len(all_solutions)))
    for pi, si, sol in chosen:
        problem = problems[pi]
        where = "%s problem %d solution %d" % (name, pi, si)
        piece_shapes = problem_pieces(problem)
        result = shapes[int(problem.find("result").get("id"))]
        placements = parse_assembly(sol.find("assembly").text or "")
        if len(placements) != len(piece_shapes):
            report["failures"].append("%s: %d placements for %d pieces" % (where, len(placements), len(piece_shapes)))
            continue
        # Place every piece; label placed pieces 1..n in BurrTools' piece order.
        labels = {}
        piece_voxels = {}
        placed = []  # BurrTools piece index of each label
        errors = []
        for p, (sid, pl) in enumerate(zip(piece_shapes, placements)):
            if pl is None:
                continue
            placed.append(p)
            label = len(placed)
            voxels = shapes[sid].placed_voxels(pl[3], pl[:3])
            piece_voxels[p] = voxels
            for v in voxels:
                if v in labels:
                    errors.append("piece %d overlaps piece %d at %s" % (p, placed[labels[v] - 1], v))
                labels[v] = label
        # Union against the result: every voxel inside the result space and not EMPTY there;
        # every FILLED voxel of the result covered; VARIABLE voxels may stay empty.
        rx, ry, rz = result.size
        for v in labels:
            inside = 0 <= v[0] < rx and 0 <= v[1] < ry and 0 <= v[2] < rz
            if not inside or result.states[v[0] + rx * (v[1] + ry * v[2])] == EMPTY:
                errors.append("voxel %s is outside the result shape" % (v,))
        missing = [v for v in result.voxels(FILLED) if v not in labels]
        if missing:
            errors.append("%d filled result voxels uncovered, e.g. %s" % (len(missing), missing[0]))
        sep = sol.find("separation")
        info = sol.find("separationInfo")
        if sep is not None:
            check_separation_states(sep, piece_voxels, {p: placements[p][:3] for p in placed}, errors, where)
        if errors:
            report["failures"].append("%s: %s" % (where, "; ".join(errors[:3])))
            continue
        if sep is not None:
            values = separation_to_info(sep, [])
            kind = "separation"
        elif info is not None:
            values = [int(t) for t in info.text.split()]
            kind = "separationInfo"
        else:
            values = None
            kind = "none"
        # Whether the stored disassembly takes every piece apart: a tree with k separations has
        # k + 1 leaves, so it separates all n pieces exactly when it has n - 1 separations.
        # BurrTools leaves a group of pieces together when the problem groups their shapes
        # (e.g. CubeInCage's cage) or when the disassembler was told to stop.
        complete = (sum(1 for v in values if v) == len(placed) - 1) if values else None
        groups = None
        if sep is not None:
            label_of = {p: i + 1 for i, p in enumerate(placed)}
            groups = [[label_of[p] for p in g] for g in unseparated_groups(sep, [])]
        fname = "%s-p%d-s%d.puz" % (base, pi, si)
        with open(os.path.join(outdir, fname), "w") as f:
            f.write(format_puz(result.size, labels))
        entries.append({
            "file": fname,
            "example": name,
            "problem": pi,
            "problem_name": problem.get("name", ""),
            "solution": si,
            "pieces": len(placed),
            "level": level_list(values) if values else None,
            "moves": sum_moves(values) if values else None,
            "disassembly": kind,
            "complete": complete,
            "unseparated_groups": groups,
            "grid": list(result.size),
            "variable_voxels": len(result.voxels(VARIABLE)),
            "burrtools_pieces": placed,
            "shapes": [piece_shapes[p] for p in placed],
        })


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--burrtools", required=True, help="BurrTools checkout or bare git directory")
    ap.add_argument("--rev", default="HEAD", help="revision to read from a bare git directory")
    ap.add_argument("--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests",
                                                     "data", "burrtools"))
    ap.add_argument("--desia", help="also run 'DESIA check' on every written file (path of the desia CLI)")
    ap.add_argument("--only", action="append", help="convert only these examples (name without .xmpuzzle)")
    args = ap.parse_args()

    src = Source(args.burrtools, args.rev)
    os.makedirs(args.output, exist_ok=True)
    for old in os.listdir(args.output):
        if old.endswith(".puz"):
            os.remove(os.path.join(args.output, old))
    entries = []
    report = {"skipped_grid": [], "no_solutions": [], "capped": [], "failures": []}
    for name in src.examples():
        if args.only and name[:-len(".xmpuzzle")] not in args.only:
            continue
        convert_example(name, src.read(name), args.output, entries, report)

    doc = {
        "source": "BurrTools examples/*.xmpuzzle (https://github.com/burr-tools/burr-tools), GPL-2.0-or-later, "
                  "(c) Andreas Roever et al.",
        "burrtools_commit": src.commit,
        "generator": "scripts/burrtools-solutions.py",
        "max_solutions_per_example": MAX_SOLUTIONS,
        "solutions": entries,
    }
    # One solution per line: readable and diff-friendly.
    head = json.dumps({k: v for k, v in doc.items() if k != "solutions"}, indent=1)
    body = ",\n".join("  " + json.dumps(e) for e in entries)
    with open(os.path.join(args.output, "levels.json"), "w") as f:
        f.write(head[:-2] + ',\n "solutions": [\n' + body + "\n ]\n}\n")

    cli_failures = []
    if args.desia:
        # The desia CLI must read every file (exit 0 or 1: a verdict, not 2: bad input) and find
        # the right number of parts in the right grid. Its verdict is not checked here.
        for e in entries:
            path = os.path.join(args.output, e["file"])
            r = subprocess.run([args.desia, "check", path], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
            head = r.stdout.decode().split("\n")[0]
            want = "parts: %d (voxel grid %s)" % (e["pieces"], "x".join(str(n) for n in e["grid"]))
            if r.returncode not in (0, 1) or head != want:
                cli_failures.append("%s: exit %d, %r (expected %r) %s" % (e["file"], r.returncode, head, want,
                                                                        r.stderr.decode().strip()))
        print("desia check read %d of %d files as expected" % (len(entries) - len(cli_failures), len(entries)))
        for line in cli_failures:
            print("DESIA READ FAILED: %s" % line)

    print("converted %d solutions from %d examples" % (len(entries), len({e["example"] for e in entries})))
    for key, label in (("skipped_grid", "not cubic"), ("no_solutions", "cubic, no stored solution"),
                       ("capped", "capped"), ("failures", "SELF-CHECK FAILED")):
        for line in report[key]:
            print("%s: %s" % (label, line))
    print("self-check failures: %d" % len(report["failures"]))
    return 1 if report["failures"] or cli_failures else 0


if __name__ == "__main__":
    sys.exit(main())
