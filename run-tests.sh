#!/usr/bin/env bash
# Builds tsf and runs the whole test suite (GoogleTest through ctest).
# Installs missing Debian packages first, like setup.sh.
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh --deps-only
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
