#!/usr/bin/env bash
# Runs every test: installs what is missing (scripts/setup.sh), builds both targets, then
#   1. the GoogleTest suite natively (CTest),
#   2. the same suite compiled to WebAssembly, run by node (CTest with node as emulator),
#   3. the node tests of the package API, native/WebAssembly parity and the CLI contract,
#   4. the headless-Chromium tests of the playground,
#   5. the GoogleTest suite again with AddressSanitizer and UndefinedBehaviorSanitizer (build/asan).
# Ends with one line "tests: N passed, M failed"; exit status non-zero when anything failed.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"
logs="$root/test-artifacts/logs"
mkdir -p "$logs"

bash scripts/setup.sh || { echo "setup failed"; exit 1; }
bash scripts/build.sh native || { echo "native build failed"; exit 1; }
bash scripts/build.sh wasm || { echo "WebAssembly build failed"; exit 1; }

passed=0
failed=0
status=0

# CTest prints "N% tests passed, F tests failed out of T".
count_ctest() {
  local line total fail
  line="$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -n 1)"
  if [ -z "$line" ]; then failed=$((failed + 1)); return; fi
  fail="$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")"
  total="$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$line")"
  passed=$((passed + total - fail))
  failed=$((failed + fail))
}

# node --test prints "# pass N" and "# fail N".
count_node() {
  local p f
  p="$(grep -E '^# pass [0-9]+' "$1" | tail -n 1 | awk '{print $3}')"
  f="$(grep -E '^# fail [0-9]+' "$1" | tail -n 1 | awk '{print $3}')"
  if [ -z "$p" ]; then failed=$((failed + 1)); return; fi
  passed=$((passed + p))
  failed=$((failed + ${f:-0}))
}

run_step() {
  local name="$1" counter="$2"
  shift 2
  echo "== $name"
  "$@" 2>&1 | tee "$logs/$name.log"
  local rc="${PIPESTATUS[0]}"
  "$counter" "$logs/$name.log"
  if [ "$rc" != 0 ]; then
    echo "== $name FAILED (exit $rc)"
    status=1
  fi
}

run_step native-ctest count_ctest ctest --test-dir build/native --output-on-failure -j "$jobs"
run_step wasm-ctest count_ctest ctest --test-dir build/wasm --output-on-failure -j "$jobs"
run_step node-tests count_node node --test --test-reporter=tap tests/node/
run_step browser-tests count_node node --test --test-reporter=tap tests/browser/

# The suite under ASan + UBSan (CMake option DESIA_SANITIZE; clang, RelWithDebInfo): an invalid
# access, a leak or undefined behaviour aborts the test that hit it. A failed build leaves no CTest
# summary, so count_ctest counts it as one failure. About 5 min of build and 1 min of tests on
# 2 cores, so nothing needs to be excluded to fit CI's 90 minutes.
sanitized_suite() {
  CC=clang CXX=clang++ cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDESIA_SANITIZE=ON \
    -DDESIA_TESTS=ON -DDESIA_CLI=OFF -DDESIA_BENCHMARKS=OFF >/dev/null || return 1
  cmake --build build/asan -j "$jobs" >"$logs/asan-build.log" 2>&1 || { tail -n 40 "$logs/asan-build.log"; return 1; }
  ctest --test-dir build/asan --output-on-failure -j "$jobs"
}
run_step asan-ctest count_ctest sanitized_suite

echo
echo "tests: $passed passed, $failed failed"
[ "$failed" = 0 ] || status=1
exit "$status"
