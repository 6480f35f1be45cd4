#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# BurrTools as an outside judge of desia's voxel disassembly (test-only: not run by CI, not a
# dependency of the project, nothing of BurrTools is committed or shipped).
#
# BurrTools (https://github.com/burr-tools/burr-tools, GPL-2.0-or-later, (c) Andreas Roever et
# al.) is only used here as a second, independent program. This script
#   1. unpacks BurrTools from a given source (a checkout with src/burrTxt.cpp, or a bare git
#      directory, read at HEAD) into a work directory outside the project (default
#      /tmp/burrtools-judge);
#   2. builds its command-line tool burrTxt with g++ -O2, one file at a time (make -j1): the
#      sources are the lists tools_src, halfedge_src and libburr_src of BurrTools' meson.build.
#      Meson is not used because BurrTools' meson.build always wants the GUI's OpenGL/GLU/FLTK;
#      burrTxt itself only needs zlib and threads. About 30 s on one core;
#   3. builds btjudge, a small helper written here (below) and linked against the same BurrTools
#      objects: for each saved solution of an .xmpuzzle it prints the level of the saved plan as
#      BurrTools reads it, replays that plan voxel by voxel (no overlap in any state, each move one
#      set of parts along one axis with every unit step free, the removed group free to leave,
#      sub-trees consistent with their parent) and runs BurrTools' own disassembler
#      (disassembler_0_c) on the saved assembly;
#   4. for each .puz given: exports it with `desia export --format xmpuzzle`, runs `desia check`
#      and prints desia's level next to BurrTools' (burrTxt -x re-disassembles the saved assembly:
#      its first level must agree). With --solve, also `burrTxt -d -q -o all`, which searches every
#      assembly of the exported pieces in the result shape and prints each one's level (slow when
#      identical parts are exported as separate shapes: AlPackino takes about 35 s).
#
# Only the first number of a level is fully determined by the assembly: the later ones depend on
# which of several equally short move sequences a program picked (BurrTools and desia break such
# ties differently), so a difference there is printed, not treated as a failure.
#
# Usage:
#   scripts/burrtools-judge.sh --burrtools PATH [--work DIR] [--desia CLI] [--solve] FILE.puz...
# Exit status: 0 when BurrTools read every export, every saved plan replayed, BurrTools could take
# every assembly apart and the first levels agree; 1 otherwise; 2 on bad usage or a failed build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bt_src="" work="/tmp/burrtools-judge" desia="$root/build/native/core/cli/desia" solve=0
files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --burrtools) bt_src="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --desia) desia="$2"; shift 2 ;;
    --solve) solve=1; shift ;;
    -h|--help) sed -n '3,36p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) files+=("$1"); shift ;;
  esac
done
if [ -z "$bt_src" ] || [ ${#files[@]} -eq 0 ]; then
  echo "usage: $0 --burrtools PATH [--work DIR] [--desia CLI] [--solve] FILE.puz..." >&2
  exit 2
fi
[ -x "$desia" ] || { echo "desia CLI not found: $desia (build it, or pass --desia)" >&2; exit 2; }
case "$work" in "$root"|"$root"/*) echo "--work must be outside the project" >&2; exit 2 ;; esac

# --- 1. BurrTools' sources ----------------------------------------------------------------------
mkdir -p "$work"
if [ -f "$bt_src/src/burrTxt.cpp" ]; then
  tree="$(cd "$bt_src" && pwd)"
elif git -C "$bt_src" rev-parse --is-bare-repository >/dev/null 2>&1; then
  tree="$work/tree"
  rev="$(git -C "$bt_src" rev-parse HEAD)"
  if [ "$(cat "$work/tree.rev" 2>/dev/null)" != "$rev" ]; then
    rm -rf "$tree" && mkdir -p "$tree"
    git -C "$bt_src" archive HEAD | tar -x -C "$tree"
    echo "$rev" > "$work/tree.rev"
  fi
else
  echo "not a BurrTools checkout nor a git directory: $bt_src" >&2
  exit 2
fi

# --- 2./3. build burrTxt and btjudge with make -j1 -----------------------------------------------
cat > "$work/btjudge.cpp" <<'EOF'
// btjudge: level and replay of the saved disassembly plans of an .xmpuzzle, as BurrTools reads
// them, and BurrTools' own disassembler on the saved assemblies (scripts/burrtools-judge.sh).
#include "lib/puzzle.h"
#include "lib/problem.h"
#include "lib/assembly.h"
#include "lib/disassembler_0.h"
#include "lib/disassembly.h"
#include "lib/solution.h"
#include "lib/voxel.h"
#include "lib/gridtype.h"
#include "tools/xml.h"
#include "tools/gzstream.h"
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>
#include <vector>

typedef std::tuple<int, int, int> P;
static std::vector<std::vector<P> > cells;  // per piece: its voxels relative to its position
static int errors = 0, nodeCounter = 0;

static void err(const char *what, int node, int st) {
  if (errors < 20) printf("  plan error: %s (node %d, state %d)\n", what, node, st);
  errors++;
}
static bool removed(const state_c *s, unsigned int i) { return s->pieceRemoved(i); }
// positions of the node's parts: state b, the parts in `mv` shifted k units along (ux,uy,uz)
static bool overlapFree(const separation_c *s, const state_c *b, const std::vector<char> &mv,
                        int k, int ux, int uy, int uz) {
  std::set<P> used;
  for (unsigned int i = 0; i < s->getPieceNumber(); i++) {
    if (removed(b, i) && !mv[i]) continue;
    int x = b->getX(i), y = b->getY(i), z = b->getZ(i);
    if (mv[i]) { x += k * ux; y += k * uy; z += k * uz; }
    for (const P &c : cells[s->getPieceName(i)])
      if (!used.insert(P(std::get<0>(c) + x, std::get<1>(c) + y, std::get<2>(c) + z)).second) return false;
  }
  return true;
}
static int sgn(int v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

static void check(const separation_c *s) {
  const int node = nodeCounter++;
  const unsigned int n = s->getPieceNumber(), m = s->getMoves();
  const std::vector<char> none(n, 0);
  if (m == 0) { err("no moves", node, 0); return; }
  for (unsigned int i = 0; i < n; i++) if (removed(s->getState(0), i)) err("removed part in the first state", node, 0);
  if (!overlapFree(s, s->getState(0), none, 0, 0, 0, 0)) err("parts overlap", node, 0);
  for (unsigned int st = 1; st <= m; st++) {
    const state_c *a = s->getState(st), *b = s->getState(st - 1);
    const bool last = st == m;
    std::vector<char> mv(n, 0);
    int dx = 0, dy = 0, dz = 0;
    bool any = false, bad = false;
    for (unsigned int i = 0; i < n; i++) {
      int ex = a->getX(i) - b->getX(i), ey = a->getY(i) - b->getY(i), ez = a->getZ(i) - b->getZ(i);
      if (!ex && !ey && !ez) { if (last && removed(a, i)) bad = true; continue; }
      mv[i] = 1;
      if (last != removed(a, i) || removed(b, i)) bad = true;
      if (last) { ex = sgn(ex); ey = sgn(ey); ez = sgn(ez); }  // out: 20000 units, one direction
      if (!any) { dx = ex; dy = ey; dz = ez; any = true; }
      else if (ex != dx || ey != dy || ez != dz) bad = true;
    }
    if (!any) { err("a state repeats the previous one", node, st); continue; }
    if (bad) err(last ? "the last state does not move out exactly the removed parts, together"
                      : "the moved parts do not move alike", node, st);
    if ((dx != 0) + (dy != 0) + (dz != 0) != 1) { err("a move not along one axis", node, st); continue; }
    const int len = last ? 64 : abs(dx) + abs(dy) + abs(dz);  // out: slide 64 units, then gone
    for (int k = 1; k <= len; k++)
      if (!overlapFree(s, b, mv, k, sgn(dx), sgn(dy), sgn(dz))) {
        err(last ? "the removed group collides on its way out" : "parts collide during the move", node, st);
        break;
      }
  }
  // sub-trees: the removed group and the rest, each starting where it stood before leaving
  const state_c *fin = s->getState(m), *pre = s->getState(m - 1);
  std::set<unsigned int> rem, stay, covered;
  for (unsigned int i = 0; i < n; i++) (removed(fin, i) ? rem : stay).insert(s->getPieceName(i));
  const separation_c *subs[2] = {s->getLeft(), s->getRemoved()};
  for (const separation_c *c : subs) {
    if (!c) continue;
    std::set<unsigned int> ps;
    for (unsigned int j = 0; j < c->getPieceNumber(); j++) ps.insert(c->getPieceName(j));
    if (ps != rem && ps != stay) err("a sub-tree's parts are neither the removed group nor the rest", node, m);
    for (unsigned int p : ps) if (!covered.insert(p).second) err("two sub-trees share a part", node, m);
    const state_c *c0 = c->getState(0);
    int sx = 0, sy = 0, sz = 0;
    bool first = true, shifted = false;
    for (unsigned int j = 0; j < c->getPieceNumber(); j++)
      for (unsigned int i = 0; i < n; i++)
        if (s->getPieceName(i) == c->getPieceName(j)) {
          int ex = c0->getX(j) - pre->getX(i), ey = c0->getY(j) - pre->getY(i), ez = c0->getZ(j) - pre->getZ(i);
          if (first) { sx = ex; sy = ey; sz = ez; first = false; }
          else if (ex != sx || ey != sy || ez != sz) shifted = true;
        }
    if (shifted) err("a sub-tree does not start where its parts stood before the separation", node, m);
    check(c);
  }
  if (rem.size() > 1 && !covered.count(*rem.begin())) err("a removed group of several parts has no sub-tree", node, m);
  if (stay.size() > 1 && !covered.count(*stay.begin())) err("the rest (several parts) has no sub-tree", node, m);
}

static std::string level(const separation_c *s) {
  char buf[1000] = "";
  s->movesText(buf, sizeof buf);
  return std::string(buf) + " (" + std::to_string(s->sumMoves()) + " moves)";
}

int main(int argc, char **argv) {
  int rc = 0;
  for (int f = 1; f < argc; f++) {
    try {
      std::istream *str = openGzFile(argv[f]);
      xmlParser_c pars(*str);
      puzzle_c p(pars);
      delete str;
      for (unsigned int pr = 0; pr < p.getNumberOfProblems(); pr++) {
        problem_c *problem = p.getProblem(pr);
        const unsigned int np = problem->getNumberOfPieces();
        for (unsigned int sol = 0; sol < problem->getNumberOfSavedSolutions(); sol++) {
          const assembly_c *a = problem->getSavedSolution(sol)->getAssembly();
          cells.assign(np, std::vector<P>());
          for (unsigned int i = 0; i < np; i++) {
            if (!a->isPlaced(i)) continue;
            voxel_c *v = p.getGridType()->getVoxel(problem->getPartShape(problem->getPartIdToPieceId(i)));
            if (!v->transform(a->getTransformation(i))) { printf("  cannot transform part %u\n", i + 1); rc = 1; }
            for (unsigned int x = 0; x < v->getX(); x++)
              for (unsigned int y = 0; y < v->getY(); y++)
                for (unsigned int z = 0; z < v->getZ(); z++)
                  if (!v->isEmpty(x, y, z)) cells[i].push_back(P(x - v->getHx(), y - v->getHy(), z - v->getHz()));
            delete v;
          }
          const separation_c *saved = problem->getSavedSolution(sol)->getDisassembly();
          std::string savedText = "none", replay = "-", btText = "none";
          if (saved) {
            errors = 0; nodeCounter = 0;
            const state_c *s0 = saved->getState(0);
            for (unsigned int i = 0; i < saved->getPieceNumber(); i++) {
              const unsigned int pc = saved->getPieceName(i);
              if (s0->getX(i) != a->getX(pc) || s0->getY(i) != a->getY(pc) || s0->getZ(i) != a->getZ(pc))
                err("the first state is not the assembly", 0, 0);
            }
            check(saved);
            savedText = level(saved);
            replay = errors ? "FAILED" : "ok";
            if (errors) rc = 1;
          }
          disassembler_0_c d(*problem);
          separation_c *da = d.disassemble(a);
          if (da) { btText = level(da); delete da; } else rc = 1;
          printf("problem %u solution %u\n  saved plan: level %s, replay %s\n  BurrTools' disassembler: level %s\n",
                 pr, sol, savedText.c_str(), replay.c_str(), btText.c_str());
        }
      }
    } catch (std::exception &e) {
      printf("BurrTools could not read %s: %s\n", argv[f], e.what());
      rc = 1;
    }
  }
  return rc;
}
EOF

# source lists from meson.build: tools_src, halfedge_src, libburr_src (what burrTxt links)
srcs=$(awk '/^(tools_src|halfedge_src|libburr_src) *= *\[/{on=1; next} on && /\]/{on=0} on' "$tree/meson.build" \
       | grep -o "'[^']*'" | tr -d "'")
[ -n "$srcs" ] || { echo "no source lists found in $tree/meson.build" >&2; exit 2; }
{
  echo "CXX ?= g++"
  echo "CXXFLAGS = -O2 -std=c++11 -w -pthread -I$tree/src"
  objs=""
  for s in $srcs; do objs="$objs obj/$(echo "$s" | tr '/' '_' | sed 's/\.cpp$/.o/')"; done
  echo "LIB =$objs"
  echo "all: burrTxt btjudge"
  echo "burrTxt: \$(LIB) obj/burrTxt.o"
  printf '\t$(CXX) -o $@ $^ -lz -pthread\n'
  echo "btjudge: \$(LIB) obj/btjudge.o"
  printf '\t$(CXX) -o $@ $^ -lz -pthread\n'
  echo "obj/burrTxt.o: $tree/src/burrTxt.cpp"
  printf '\t@mkdir -p obj\n\t$(CXX) $(CXXFLAGS) -c $< -o $@\n'
  echo "obj/btjudge.o: btjudge.cpp"
  printf '\t@mkdir -p obj\n\t$(CXX) $(CXXFLAGS) -c $< -o $@\n'
  for s in $srcs; do
    echo "obj/$(echo "$s" | tr '/' '_' | sed 's/\.cpp$/.o/'): $tree/$s"
    printf '\t@mkdir -p obj\n\t$(CXX) $(CXXFLAGS) -c $< -o $@\n'
  done
} > "$work/Makefile"
echo "== building burrTxt and btjudge in $work (make -j1)"
if ! make -s -C "$work" -j1 all >"$work/build.log" 2>&1; then
  tail -20 "$work/build.log" >&2
  echo "build failed (log: $work/build.log)" >&2
  exit 2
fi

# --- 4. judge ------------------------------------------------------------------------------------
mkdir -p "$work/out"
status=0
for f in "${files[@]}"; do
  name="$(basename "$f" .puz)"
  x="$work/out/$name.xmpuzzle"
  echo
  echo "== $f"
  if ! "$desia" export "$f" --format xmpuzzle --output "$x" >/dev/null; then
    echo "  desia export failed"; status=1; continue
  fi
  desia_level="$("$desia" check "$f" 2>/dev/null | sed -n 's/^disassembly: level //p' | head -1 || true)"
  echo "  desia check: level ${desia_level:-none}"
  judge="$("$work/btjudge" "$x")" || status=1
  echo "$judge" | sed 's/^problem 0 solution 0$//; /^$/d'
  first_bt="$("$work/burrTxt" -x "$x" 2>/dev/null | sed -n 's/^level: //p' | head -1 || true)"
  echo "  burrTxt -x (first level): ${first_bt:-none}"
  first_desia="${desia_level%%[.,]*}"
  if [ -z "$first_bt" ] || [ "$first_bt" != "$first_desia" ]; then
    echo "  FIRST LEVEL DIFFERS"; status=1
  fi
  saved_level="$(echo "$judge" | sed -n "s/^  saved plan: level //p" | head -1)"
  if [ "${saved_level%% *}" != "${desia_level%%,*}" ]; then
    echo "  THE EXPORTED PLAN IS NOT THE ONE desia check PRINTS"; status=1
  fi
  bt_level="$(echo "$judge" | sed -n "s/^  BurrTools' disassembler: level //p" | head -1)"
  if [ "${bt_level%% *}" = "${desia_level%%,*}" ]; then echo "  levels: same"; else echo "  levels: differ after the first number (tie-breaking; see the header)"; fi
  if [ "$solve" = 1 ]; then
    echo "  burrTxt -d -q -o all (every assembly of these pieces, counts of levels):"
    "$work/burrTxt" -d -q -o all "$x" 2>/dev/null | sed -n 's/^level: //p' | sort | uniq -c | sed 's/^/   /'
  fi
done
exit $status
