#!/usr/bin/env bash
# The parallel stages under ThreadSanitizer: the library and three tests
# (test_parallel_loops, test_parallel_stages, test_openmp_host) built with
# clang, -fsanitize=thread and clang's OpenMP runtime, whose Archer tool tells
# ThreadSanitizer how OpenMP orders threads (without it every region would
# report races inside the runtime). GCC's libgomp cannot be used: it is not
# built with ThreadSanitizer's annotations.
# Usage: scripts/tsan-parallel.sh [WORK_DIR]
# Exit 0: no race; 1: a race or a failed test; 77: clang, its OpenMP or Archer is missing.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$source_dir/build-tsan}

archer=$(ls /usr/lib/llvm-*/lib/libarcher.so 2>/dev/null | head -1 || true)
if ! command -v clang++ >/dev/null 2>&1 || ! ls /usr/lib/llvm-*/lib/libomp.so >/dev/null 2>&1 || [ -z "$archer" ]; then
  echo "SKIPPED: ThreadSanitizer over OpenMP needs clang, clang's OpenMP and its Archer tool; install clang and" \
       "libomp-dev (scripts/ensure-deps.sh clang libomp-dev)" >&2
  exit 77
fi

# Without line tables (a third less CPU time to build): a race's report names the
# functions on both stacks; rerun with -g1 in the flags for lines.
# Ninja where it is (the test command installs it): a tenth less CPU time than make.
generator=$(command -v ninja >/dev/null 2>&1 && echo "-G Ninja" || true)
CXX=clang++ cmake $generator -S "$source_dir" -B "$work" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g0" \
  -DCMAKE_UNITY_BUILD=ON -DPARTICLESIM_TSAN=ON -DPARTICLESIM_BUILD_APPS=OFF -DPARTICLESIM_BUILD_BENCH=OFF >/dev/null
tests=(test_parallel_loops test_parallel_stages test_openmp_host)
cmake --build "$work" --target "${tests[@]}" -j "$(nproc)" >/dev/null
for test in "${tests[@]}"; do
  OMP_TOOL_LIBRARIES="$archer" TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=1 exitcode=66" \
    "$work/tests/$test" || { echo "FAILED under ThreadSanitizer: $test" >&2; exit 1; }
done
