#!/usr/bin/env bash
# Sanitizers and fuzzers (docs/limits.md, "Sanitizers and fuzzing"). CI runs
# it after ./run-tests.sh. Needs clang 14 (setup.sh installs it).
#
#   build-asan/  clang, AddressSanitizer + UndefinedBehaviorSanitizer (+ the
#                libFuzzer coverage hooks): the fuzz targets and
#                test_library_asan, the library-level tests of the readers,
#                writers, Scene, mesher and haptics; LeakSanitizer on,
#                lib3mf/libzip leaks suppressed by name
#                (tests/sanitizers/lsan.supp); and test_verify_threads, the
#                verifier's threaded stages (column grid, self-intersection
#                predicates, printability rays, topology, the positions of the
#                model as written welded) on hand-drawn meshes, and the
#                binary STL writer's converting threads.
#   build-tsan/  clang, ThreadSanitizer: the haptic loop and Falcon driver
#                threads (test_haptics_threads) and the verifier's threaded
#                stages and the STL writer (test_verify_threads, the same
#                tests as under ASan).
#
# Every fuzz target runs TSF_FUZZ_SECONDS (default 5) from its seed corpus in
# tests/fuzz/corpus/<target>/ (new inputs go to a scratch folder, not the
# repository). Any sanitizer report, fuzzer crash or failed test fails the
# script. Options: --no-fuzz, --no-asan, --no-tsan leave a part out.
set -euo pipefail
cd "$(dirname "$0")"
fuzz=1 asan=1 tsan=1
for arg in "$@"; do
  case "$arg" in
    --no-fuzz) fuzz=0 ;;
    --no-asan) asan=0 ;;
    --no-tsan) tsan=0 ;;
    *) echo "run-sanitizers.sh: unknown option $arg" >&2; exit 2 ;;
  esac
done
CC=${CC_SANITIZE:-clang-14}
CXX=${CXX_SANITIZE:-clang++-14}
jobs=$(nproc)
root=$(pwd)
seconds=${TSF_FUZZ_SECONDS:-5}
stamp() { date +%s; }
t_start=$(stamp)

fuzzers=(csv_grid_fuzzer point_csv_fuzzer pgm_fuzzer png_fuzzer esri_ascii_fuzzer stl_fuzzer three_mf_fuzzer
         obj_fuzzer off_fuzzer scene_json_fuzzer openscad_messages_fuzzer replay_csv_fuzzer falcon_packet_fuzzer
         cf_time_fuzzer)

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export LSAN_OPTIONS=suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$root/tests/sanitizers/ubsan.supp
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1

if (( asan || fuzz )); then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Test -DCMAKE_CXX_FLAGS_TEST=-O0 \
        -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" -DTSF_SANITIZE=address,undefined \
        -DTSF_BUILD_FUZZERS=ON -DTSF_BUILD_BENCH=OFF >/dev/null
  targets=()
  (( fuzz )) && targets+=("${fuzzers[@]}")
  (( asan )) && targets+=(test_library_asan test_verify_threads)
  cmake --build build-asan -j"$jobs" --target "${targets[@]}"
  echo "run-sanitizers: ASan + UBSan build $(( $(stamp) - t_start )) s"
fi

if (( fuzz )); then
  t0=$(stamp)
  for f in "${fuzzers[@]}"; do
    name=${f%_fuzzer}
    seeds=$root/tests/fuzz/corpus/$name
    work=build-asan/fuzz-corpus/$name
    mkdir -p "$work" "build-asan/fuzz-artifacts/$name"
    echo "run-sanitizers: fuzzing $name for ${seconds} s"
    "build-asan/tests/$f" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -max_len=65536 \
        -artifact_prefix="build-asan/fuzz-artifacts/$name/" -print_final_stats=1 "$work" "$seeds" \
        2>"build-asan/fuzz-artifacts/$name/log.txt" || {
      tail -50 "build-asan/fuzz-artifacts/$name/log.txt" >&2
      echo "run-sanitizers: $name: the fuzzer found a failing input (build-asan/fuzz-artifacts/$name/)" >&2
      exit 1
    }
    grep -E "stat::number_of_executed_units" "build-asan/fuzz-artifacts/$name/log.txt" || true
  done
  echo "run-sanitizers: fuzzing $(( $(stamp) - t0 )) s"
fi

if (( asan )); then
  t0=$(stamp)
  # Left out: the 1000 x 1000 mesher test, the million-state force clamp and
  # the long energy sweeps take minutes each under ASan at -O0 and only repeat
  # arithmetic that the other tests of the same code run sanitized; ctest runs
  # them unsanitized.
  build-asan/tests/test_library_asan --gtest_brief=1 \
      --gtest_filter=-DirectMesher.ThousandByThousandGridIsSolid:Safety.ClampHoldsOverAMillionRandomStates:Energy.FingerPressingAndSlidingGainsNoEnergyFromTheSurface
  build-asan/tests/test_verify_threads --gtest_brief=1
  echo "run-sanitizers: ASan + UBSan tests $(( $(stamp) - t0 )) s"
fi

if (( tsan )); then
  t0=$(stamp)
  cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Test -DCMAKE_CXX_FLAGS_TEST=-O0 \
        -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" -DTSF_SANITIZE=thread -DTSF_BUILD_BENCH=OFF >/dev/null
  cmake --build build-tsan -j"$jobs" --target test_haptics_threads test_verify_threads
  build-tsan/tests/test_haptics_threads
  build-tsan/tests/test_verify_threads --gtest_brief=1
  echo "run-sanitizers: ThreadSanitizer build and tests $(( $(stamp) - t0 )) s"
fi
echo "run-sanitizers: all done in $(( $(stamp) - t_start )) s"
