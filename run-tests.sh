#!/usr/bin/env bash
# Builds tsf and runs the whole test suite (GoogleTest through ctest).
# Installs missing Debian packages first, like setup.sh.
#
# The tests are built in setup.sh's Release build, build/, so they run the
# very binary and libraries users run: there no assertion may stand between a
# bad input and its typed error, and the tests check that every bad input
# ends in one. (The library-level tests run again with assertions on, and
# under ASan + UBSan, in run-sanitizers.sh; docs/limits.md.)
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh --deps-only
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTSF_BUILD_TESTS=ON >/dev/null
cmake --build build -j"$(nproc)" --target tsf_tests
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
