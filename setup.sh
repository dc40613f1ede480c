#!/usr/bin/env bash
# tsf set-up: installs what is missing (Debian 12 packages), builds a Release
# tsf into build/, and runs the main job on a bundled example:
#   field -> OpenSCAD file + direct STL -> rendered by openscad -> verified.
#
#   ./setup.sh              everything above
#   ./setup.sh --deps-only  only install the Debian packages
#   ./setup.sh --no-demo    install and build, skip the example
set -euo pipefail
cd "$(dirname "$0")"

# Everything tsf builds and tests with. Debian packages only. (clang-14 and
# its runtimes: the sanitizer and fuzzer builds of run-sanitizers.sh.)
DEPS=(
  build-essential cmake ninja-build pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  libglm-dev libusb-1.0-0-dev libpng-dev lib3mf-dev libzip-dev
  libcli11-dev nlohmann-json3-dev libgdal-dev liblouis-dev libxxhash-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  openscad admesh xvfb xauth prusa-slicer unzip
  clang-14 libclang-rt-14-dev
)

mode="${1:-all}"

missing=()
for p in "${DEPS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Node.js runs the second OpenSCAD engine (OpenSCAD 2025 compiled to
# WebAssembly, `tsf render --engine wasm`). Debian's nodejs and npm unless a
# Node.js with npm is already installed.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends nodejs npm
fi
# The engine's npm package, pinned by package-lock.json, into the project
# (never global; nothing is fetched when tsf runs).
wasm=runners/openscad/wasm
if [ ! -f "$wasm/node_modules/.package-lock.json" ] || [ "$wasm/package-lock.json" -nt "$wasm/node_modules/.package-lock.json" ]; then
  (cd "$wasm" && npm ci --no-audit --no-fund --loglevel=error)
fi
[ "$mode" = "--deps-only" ] && exit 0

# Release: no assertions (run-tests.sh builds the tests apart, with them).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target tsf
[ "$mode" = "--no-demo" ] && exit 0

# The main job on a bundled example (European airports, OpenFlights data).
mkdir -p out
set -x
./build/tsf gen examples/airports-europe.csv --points x=lon,y=lat --bins 40 --mirror \
    -o out/airports-europe.stl --scad out/airports-europe.scad --preview out/airports-europe.png
./build/tsf render out/airports-europe.scad -o out/airports-europe.openscad.stl
./build/tsf verify out/airports-europe.openscad.stl --scene out/airports-europe.stl.scene.json \
    --reference out/airports-europe.stl
