#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The interlocking-test benchmarks (paper Section 3.2): builds the native and WebAssembly
# targets, runs desia_bench (Google Benchmark; writes build/bench/native.json), then the same
# workloads in node (tests/benchmarks/wasm_bench.mjs), whose table puts the paper, native and
# WebAssembly side by side. About 2 to 3 minutes after the builds, on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

if [ "${1:-}" = "design" ]; then
  # The voxel designer against Table 1 (issue 3): native then WebAssembly; extra arguments go to
  # both (e.g. --seeds 3 --time-limit 60 --only bunny). Can take tens of minutes.
  shift
  bash scripts/build.sh native
  bash scripts/build.sh wasm
  echo "== voxel designer, native"
  build/native/tests/benchmarks/desia_design_bench "$@"
  echo
  echo "== voxel designer, WebAssembly (node)"
  node tests/benchmarks/wasm_design_bench.mjs "$@"
  exit 0
fi

if [ "${1:-}" = "plate" ]; then
  # The plate joint planner against Table 1 (issue 8), natively and in WebAssembly. Seconds.
  shift
  bash scripts/build.sh native
  bash scripts/build.sh wasm
  node tests/benchmarks/plate_bench.mjs "$@"
  exit 0
fi

if [ "${1:-}" = "frame" ]; then
  # The frame designer against Table 1 (issue 9), natively and in WebAssembly. Seconds.
  shift
  bash scripts/build.sh native
  bash scripts/build.sh wasm
  node tests/benchmarks/frame_bench.mjs "$@"
  exit 0
fi

if [ "${1:-}" = "package" ]; then
  # The npm package as a caller feels it (issue 4): worker start-up, calls through the worker,
  # abort latency, voxelize and export. About 10 seconds after the build.
  shift
  bash scripts/build.sh wasm
  node tests/benchmarks/package_bench.mjs "$@"
  exit 0
fi

echo "== building (native, wasm)"
bash scripts/build.sh native
bash scripts/build.sh wasm

echo
echo "== native (Google Benchmark)"
build/native/tests/benchmarks/desia_bench --desia_json="$root/build/bench/native.json"

echo
echo "== WebAssembly (node)"
node tests/benchmarks/wasm_bench.mjs --native="$root/build/bench/native.json" --json="$root/build/bench/wasm.json"
