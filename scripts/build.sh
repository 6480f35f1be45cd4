#!/usr/bin/env bash
# Builds desia. `build.sh native` (CLI, tests, benchmarks in build/native), `build.sh wasm` (the
# two embind modules in dist/, the full desia_wasm and the light desia_light the package's worker
# loads first (docs/architecture.md), and the WebAssembly test suite in build/wasm), `build.sh` (both),
# `build.sh site` (the WebAssembly module, then the playground as a self-contained static site in
# dist/site/, relative URLs only: scripts/build-site.mjs; docs/playground.md).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"
what="${1:-all}"

build_native() {
  cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DDESIA_TESTS=ON -DDESIA_BENCHMARKS=ON -DDESIA_CLI=ON >/dev/null
  cmake --build build/native -j "$jobs"
}

build_wasm() {
  # Debian's Emscripten needs node to find Debian's acorn module (toolchain.md #1).
  export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
  # node is the emulator for the test suite; its fetch breaks Emscripten 3.1.6 (toolchain.md #3/#7).
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DDESIA_TESTS=ON \
    "-DCMAKE_CROSSCOMPILING_EMULATOR=$(command -v node);--no-experimental-fetch" >/dev/null
  cmake --build build/wasm -j "$jobs"
}

case "$what" in
  native) build_native ;;
  wasm) build_wasm ;;
  site) build_wasm; node scripts/build-site.mjs ;;
  all) build_native; build_wasm ;;
  *) echo "usage: scripts/build.sh [native|wasm|site|all]" >&2; exit 2 ;;
esac
