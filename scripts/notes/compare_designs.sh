#!/usr/bin/env bash
# Byte-identity check for the scale-1500 work (issue 10): the same seeds and options must give the
# same bytes before and after. usage: scripts/notes/compare_designs.sh BASE_DESIA NEW_DESIA [BASE_PARTIAL NEW_PARTIAL]
# BASE_/NEW_PARTIAL: scripts/notes/partial_design.cpp built against each build's libdesia_core.a
#   g++ -O2 -std=c++17 -Icore/include scripts/notes/partial_design.cpp build/native/core/libdesia_core.a -lglpk -lpolyclipping -o partial
# (35^3 N=1500 cut at a node limit, compared by the hash of the deepest node).
set -u
base="$1" new="$2"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${TMPDIR:-/tmp}/desia-compare"
mkdir -p "$out"
cube() {  # a solid cube of side $1 as a .puz
  python3 -c "
n=$1
print(n,n,n)
for z in range(n):
    for y in range(n): print('1 '*n)
    print()" >"$out/cube$1.puz"
  echo "$out/cube$1.puz"
}
ex="$root/examples/voxel"
cases=(
  "$ex/Cube_4x4x4_origin.puz 9 1" "$ex/Cube_4x4x4_origin.puz 9 2" "$ex/Cube_4x4x4_origin.puz 8 3"
  "$ex/Cube_hollow_4x4x4_origin.puz 7 1" "$ex/Cube_hollow_4x4x4_origin.puz 7 2"
  "$ex/bunny_origin.puz 80 1" "$ex/bunny_origin.puz 40 2" "$ex/dog_origin.puz 14 1"
  "$(cube 10) 60 1" "$(cube 10) 60 2" "$(cube 6) 30 1" "$(cube 20) 300 1" "$(cube 20) 300 2"
)
fail=0
for c in "${cases[@]}"; do
  set -- $c
  for extra in "" "--rank x --node-limit 400" "--mode recursive --node-limit 400"; do
    [ "$extra" != "" ] && [ "$2" -gt 60 ] && continue
    "$base" design voxel --input "$1" --parts "$2" --seed "$3" --jobs 1 $extra --output "$out/a.json" >"$out/a.txt" 2>&1
    "$new" design voxel --input "$1" --parts "$2" --seed "$3" --jobs 1 $extra --output "$out/b.json" >"$out/b.txt" 2>&1
    if [ -f "$out/a.json" ] && cmp -s "$out/a.json" "$out/b.json"; then r=same; else r=DIFFERENT; fail=1; fi
    if [ ! -f "$out/a.json" ]; then  # no puzzle within the node limit: compare the report instead
      if [ ! -f "$out/b.json" ] && [ "$(tail -1 "$out/a.txt")" = "$(tail -1 "$out/b.txt")" ]; then r="same report: $(tail -1 "$out/a.txt")"; else r=DIFFERENT; fail=1; fi
    fi
    echo "$(basename "$1") N=$2 seed $3 $extra: $r"
    rm -f "$out/a.json" "$out/b.json"
  done
done
if [ -n "${BASE_PARTIAL:-}" ]; then
  for limit in ${PARTIAL_LIMITS:-40}; do
    a="$("$BASE_PARTIAL" "$(cube 35)" 1500 1 $limit 2>/dev/null)"; b="$("$NEW_PARTIAL" "$out/cube35.puz" 1500 1 $limit 2>/dev/null)"
    echo "35^3 N=1500 node limit $limit: ${a% time*} | ${b% time*}"
    [ "${a% time*}" = "${b% time*}" ] || fail=1
  done
fi
exit $fail
