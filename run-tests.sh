#!/usr/bin/env bash
# Builds tsf and runs the whole test suite (GoogleTest through ctest).
# Installs missing Debian packages first, like setup.sh.
#
# The tests get a build of their own in build-test/, of build type Test:
# optimised like Release but with assertions on, so that a broken invariant
# fails a test instead of passing unnoticed. (setup.sh's Release build in
# build/ has no assertions: there every bad input must end in a typed error,
# and the tests check that it does.)
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh --deps-only
cmake -S . -B build-test -G Ninja -DCMAKE_BUILD_TYPE=Test -DTSF_BUILD_BENCH=OFF >/dev/null
cmake --build build-test -j"$(nproc)"
ctest --test-dir build-test --output-on-failure -j"$(nproc)" "$@"
