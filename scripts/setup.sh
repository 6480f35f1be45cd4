#!/usr/bin/env bash
# Installs everything desia needs on a fresh Debian bookworm machine, from Debian's packages and the
# npm registry only (see ../shared/toolchain.md). Safe to run again: every step checks first.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

log() { printf '[setup] %s\n' "$*"; }
sudo_if_needed() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

debian_packages=(
  build-essential cmake pkg-config
  libgtest-dev libbenchmark-dev
  libeigen3-dev nlohmann-json3-dev libglpk-dev zlib1g-dev
  emscripten chromium
  clang libclang-rt-14-dev
)
# Node.js: keep whatever node/npm the machine has (a newer nodejs package ships npm itself and
# conflicts with Debian's npm package); install Debian's only when the commands are missing.
command -v node >/dev/null 2>&1 || debian_packages+=(nodejs)
command -v npm >/dev/null 2>&1 || debian_packages+=(npm)

missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  sudo_if_needed apt-get update -qq
  DEBIAN_FRONTEND=noninteractive sudo_if_needed apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  log "Debian packages present"
fi

# Debian's source packages, by deriving a deb-src entry from the existing one (no host named).
enable_source_packages() {
  local src_list=/etc/apt/sources.list.d/debian-src.sources
  [ -f "$src_list" ] || [ -f /etc/apt/sources.list.d/debian-src.list ] && return 0
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | sudo_if_needed tee "$src_list" >/dev/null
  else
    grep -h '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | sudo_if_needed tee /etc/apt/sources.list.d/debian-src.list >/dev/null
  fi
  sudo_if_needed apt-get update -qq
}

# Downloads Debian's source package $1 into third_party/ (the unpacking differs per package).
fetch_source_package() {
  enable_source_packages
  mkdir -p "$root/third_party"
  (cd "$root/third_party" && apt-get source --download-only "$1" >/dev/null 2>&1 || apt-get source --download-only "$1")
}

# GLPK C sources for the WebAssembly build (the host libglpk cannot be linked into wasm).
glpk_dir="$root/third_party/glpk-5.0"
if [ ! -f "$glpk_dir/src/glpk.h" ]; then
  log "fetching GLPK 5.0 sources from Debian's source packages"
  fetch_source_package glpk
  (cd "$root/third_party" && tar xzf glpk_5.0.orig.tar.gz)
else
  log "GLPK sources present"
fi

# Clipper C++ sources, from Debian's source package (libpolyclipping): both builds compile them,
# with stable sorts, so that native and WebAssembly results are the same bytes (cmake/Clipper.cmake).
clipper_dir="$root/third_party/polyclipping-6.4.2"
if [ ! -f "$clipper_dir/cpp/clipper.cpp" ]; then
  log "fetching Clipper 6.4.2 sources from Debian's source packages"
  fetch_source_package libpolyclipping
  unpack="$(mktemp -d "$root/third_party/polyclipping.XXXXXX")"
  tar xjf "$root/third_party"/libpolyclipping_6.4.2.orig.tar.bz2 -C "$unpack"
  # The tarball's top folder has an arbitrary name: take the one that holds cpp/clipper.cpp.
  found="$(dirname "$(dirname "$(find "$unpack" -path '*/cpp/clipper.cpp' | head -n 1)")")"
  rm -rf "$clipper_dir"
  mv "$found" "$clipper_dir"
  rm -rf "$unpack"
else
  log "Clipper sources present"
fi

# zlib C sources for the WebAssembly build (inflate, for 3MF files), from Debian's source package;
# natively the core links Debian's zlib1g-dev of the same version (1.2.13).
zlib_dir="$root/third_party/zlib-1.2.13.dfsg"
if [ ! -f "$zlib_dir/inflate.c" ]; then
  log "fetching zlib 1.2.13 sources from Debian's source packages"
  fetch_source_package zlib
  (cd "$root/third_party" && tar xjf zlib_1.2.13.dfsg.orig.tar.bz2)
else
  log "zlib sources present"
fi

# npm packages (three, playwright-core, and manifold-3d for the tests); package-lock.json pins them.
if [ ! -d "$root/node_modules/three" ] || [ ! -d "$root/node_modules/playwright-core" ] ||
  [ ! -d "$root/node_modules/manifold-3d" ]; then
  log "installing npm packages"
  if [ -f package-lock.json ]; then npm ci --no-audit --no-fund; else npm install --no-audit --no-fund; fi
else
  log "npm packages present"
fi
log "done"
