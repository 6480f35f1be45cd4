#!/usr/bin/env bash
# Starts the playground: installs what is missing, builds the WebAssembly module, and serves the
# repository on http://127.0.0.1:${PORT:-8080}/web/ (static files only; Ctrl-C stops it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup.sh
bash scripts/build.sh wasm
exec node scripts/serve.mjs --port "${PORT:-8080}"
