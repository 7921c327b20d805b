#!/usr/bin/env bash
# Coverage-guided fuzzing of the reader and both engines (fuzz/fuzz_scene.cpp)
# with clang's libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer.
# Usage: scripts/fuzz.sh SECONDS [WORK_DIR]
# The corpus grows in WORK_DIR/corpus (fuzz/corpus is the committed seed set);
# a finding is written to WORK_DIR/crash-* (or timeout-*, oom-*) and fails the run.
# Exit 0: no finding; 1: a finding; 2: SECONDS not a whole number; 77: clang or libFuzzer is missing.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:?usage: scripts/fuzz.sh SECONDS [WORK_DIR]}
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "scripts/fuzz.sh: SECONDS must be a whole number, not '$seconds' (usage: scripts/fuzz.sh SECONDS [WORK_DIR])" >&2
  exit 2
fi
work=${2:-$source_dir/build-fuzz}

if ! command -v clang++ >/dev/null 2>&1 ||
   ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 ||
   ! ls /usr/lib/llvm-*/lib/libomp.so >/dev/null 2>&1; then
  echo "SKIPPED: fuzzing needs clang, libFuzzer and clang's OpenMP; install clang, libclang-rt-dev and libomp-dev" \
       "(scripts/ensure-deps.sh clang libclang-rt-dev libomp-dev)" >&2
  exit 77
fi

# Without line tables (0.67 of the build's CPU time): a finding's report names
# the functions, and its artifact reproduces it in a build with -g.
# A run of a minute or less spends most of its time compiling: -O0 builds in
# 26 CPU-s against -O1's 46 (19 s against 29 s on two cores) and runs half as
# many inputs (625 against 1167 in 10 s); a longer run gains more from -O1.
optimization=$([ "$seconds" -le 60 ] && echo "-O0" || echo "-O1")
# Ninja where it is (the test command installs it): a tenth less CPU time than make.
generator=$(command -v ninja >/dev/null 2>&1 && echo "-G Ninja" || true)
CXX=clang++ cmake $generator -S "$source_dir" -B "$work" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$optimization -g0" \
  -DCMAKE_UNITY_BUILD=ON -DPARTICLESIM_FUZZ=ON \
  -DPARTICLESIM_BUILD_APPS=OFF -DPARTICLESIM_BUILD_TESTS=OFF -DPARTICLESIM_BUILD_BENCH=OFF >/dev/null
cmake --build "$work" --target fuzz_scene -j "$(nproc)" >/dev/null
mkdir -p "$work/corpus"
# One thread per OpenMP team is enough to reach every code path; more only slows the runs.
OMP_WAIT_POLICY=passive "$work/fuzz_scene" "$work/corpus" "$source_dir/fuzz/corpus" \
  -dict="$source_dir/fuzz/scene.dict" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/" 2>"$work/fuzz.log" || {
  tail -40 "$work/fuzz.log" >&2
  echo "FINDING: see $work/fuzz.log and the artifact it names" >&2
  exit 1
}
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|cov: [0-9]+ ft: [0-9]+" "$work/fuzz.log" | tail -4
