#!/usr/bin/env bash
# Fuzzing campaign: builds the libFuzzer harnesses (tests/fuzz/, clang with ASan + UBSan, build/fuzz)
# and runs each one for SECONDS (default 60) from the seed corpus in tests/fuzz/corpus/<harness>/.
#   bash scripts/fuzz.sh [SECONDS] [HARNESS...]
# New inputs and findings go to a scratch folder, build/fuzz/campaign/<harness>/{corpus,findings}
# (FUZZ_OUT=DIR to move it), never into the repository: a finding worth keeping is copied by hand
# into tests/fuzz/regressions/<harness>/ once fixed, where the GoogleTest suite replays it.
# Prints executions and findings per harness; exit status 1 when anything was found.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
seconds="${1:-60}"
shift || true
harnesses=("$@")
[ "${#harnesses[@]}" -gt 0 ] || harnesses=(assembly_text mesh design_options check design)
out="${FUZZ_OUT:-$root/build/fuzz/campaign}"
jobs="$(nproc 2>/dev/null || echo 2)"

command -v clang++ >/dev/null || { echo "fuzz: clang++ is missing (bash scripts/setup.sh installs it)"; exit 2; }
CC=clang CXX=clang++ cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDESIA_FUZZ=ON \
  -DDESIA_TESTS=OFF -DDESIA_CLI=OFF -DDESIA_BENCHMARKS=OFF >/dev/null || { echo "fuzz: configure failed"; exit 2; }
cmake --build build/fuzz -j "$jobs" >/dev/null || { echo "fuzz: build failed"; exit 2; }

dictionary_of() {
  case "$1" in
    mesh | mesh_assembly) echo tests/fuzz/mesh.dict ;;
    design_options) echo tests/fuzz/design_options.dict ;;
    *) echo tests/fuzz/assembly.dict ;;
  esac
}

summary=()
total_findings=0
for h in "${harnesses[@]}"; do
  binary="build/fuzz/tests/fuzz/desia_fuzz_$h"
  [ -x "$binary" ] || { echo "fuzz: no harness '$h'"; exit 2; }
  mkdir -p "$out/$h/corpus" "$out/$h/findings"
  log="$out/$h/fuzz.log"
  start="$out/$h/.started"
  touch "$start"
  echo "== $h: ${seconds}s"
  # Fork mode keeps the campaign going after a crash (each finding is saved and counted) instead of
  # stopping at the first one. detect_leaks: a leak is a finding too.
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1" \
    "$binary" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -print_funcs=0 \
    -dict="$(dictionary_of "$h")" -artifact_prefix="$out/$h/findings/" \
    "$out/$h/corpus" "tests/fuzz/corpus/$h" >"$log" 2>&1
  # Fork mode reports "#EXECS: cov: ... corp: ..." after each job; the last one has the totals.
  execs="$(grep -oE '#[0-9]+: cov:' "$log" | tail -n 1 | tr -dc '0-9')"
  # Only this run's findings: the scratch folder keeps earlier campaigns' files.
  findings="$(find "$out/$h/findings" -type f -newer "$start" | wc -l)"
  total_findings=$((total_findings + findings))
  summary+=("$(printf '%-16s %12s executions %4d findings' "$h" "${execs:-?}" "$findings")")
  find "$out/$h/findings" -type f -newer "$start" | sed 's/^/   finding: /'
done

echo
echo "fuzz summary (${seconds}s per harness, scratch: $out)"
printf '%s\n' "${summary[@]}"
[ "$total_findings" = 0 ]
