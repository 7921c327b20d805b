#!/usr/bin/env bash
# Quick start 2: installs what is missing, then builds and runs the whole test
# suite twice: a Release build (every test), and a build under
# AddressSanitizer and UndefinedBehaviorSanitizer with the library's invariant
# checks compiled in (any report fails the run). The Release pass also
# cross-checks the bytes on aarch64 under qemu, runs the parallel stages under
# ThreadSanitizer (clang's OpenMP) and fuzzes for 10 seconds.
# 8 min 38 s to 10 min 57 s (four runs) from a clean clone on the project's 2-core machine with the tools
# already installed (OpenMPI's tests included), 16.1 to 20.6 min of CPU time, a quarter of it in the kernel (a first touch of memory is slow there);
# 8 min 42 s to 11 min 45 s (three runs; 16.2 to 22.0 min of CPU time) on a fresh machine, where it installs the tools.
set -euo pipefail
cd "$(dirname "$0")/.."
# OpenMPI decides the Release build's configuration (the distributed engine:
# PARTICLESIM_MPI on, and simcli runs under mpirun), so it comes first, in
# the one apt run that also brings what the build needs (Ninja, Eigen).
scripts/ensure-deps.sh --optional libopenmpi-dev openmpi-bin
jobs=$(nproc)
mpi=OFF
if command -v mpicxx >/dev/null 2>&1 && command -v mpirun >/dev/null 2>&1; then
  mpi=ON
else
  echo "OpenMPI is missing: the distributed engine is not built, and its tests will say SKIPPED"
fi
# The heavier test tools, which only the tests use: the aarch64 cross compiler
# and qemu (the same bytes on another architecture), clang with libFuzzer, its
# OpenMP and Archer (fuzzing, ThreadSanitizer over OpenMP), chromium (the
# animation page), python3-ase (simcli's trajectory files as ASE reads them),
# pkgconf (the installed pkg-config files), clang-format (the code's format,
# which code_format looks for when it runs). Installed while the Release build
# compiles: on a fresh machine apt alone took 107 s, with 118 CPU-s spread over
# both cores and waits on downloads and disk. Never stopped halfway: an
# interrupted dpkg leaves the machine's packages broken.
mkdir -p build
tools_log=build/test-tools-install.log
scripts/ensure-deps.sh --optional g++-aarch64-linux-gnu qemu-user clang libclang-rt-dev libomp-dev chromium \
  python3-ase pkgconf clang-format >"$tools_log" 2>&1 &
tools_install=$!

echo "== Release build (at ${SECONDS} s)"
cmake --preset release -DPARTICLESIM_MPI=$mpi
cmake --build --preset release -j "$jobs"
echo "== The test tools' install (at ${SECONDS} s)"
wait "$tools_install"
cat "$tools_log"

# The sanitized build compiles at the lowest priority while the release tests
# run: it takes only the CPU they leave idle (waiting on mpirun, Chromium,
# signals), and they keep their timing. Its log is shown once it ends.
echo "== Sanitized build (address, undefined) beside the release tests, at nice 19 (at ${SECONDS} s)"
cmake --preset sanitize
sanitize_log=build-sanitize/build.log
# In a process group of its own (setsid), so that a failing release test stops its compilers too.
# setsid also gives it a scheduling group of its own where Linux groups
# processes that way (autogroup, on in Debian's kernels), and groups share
# the CPU equally whatever their processes' nice: the group's own nice is set
# as well, or the build would take half the CPU from the tests.
setsid sh -c 'echo 19 >/proc/self/autogroup 2>/dev/null || true; exec nice -n 19 cmake --build --preset sanitize -j "$1"' \
  sanitize-build "$jobs" >"$sanitize_log" 2>&1 &
sanitize_build=$!
trap 'kill -- "-$sanitize_build" 2>/dev/null || true' EXIT

echo "== Release tests (at ${SECONDS} s)"
ctest --preset release -j "$jobs"

echo "== Sanitized build's log (release tests done at ${SECONDS} s)"
sanitize_status=0
wait "$sanitize_build" || sanitize_status=$?
trap - EXIT
cat "$sanitize_log"
if [ "$sanitize_status" -ne 0 ]; then
  echo "the sanitized build failed (status $sanitize_status)"
  exit "$sanitize_status"
fi
echo "== Sanitized tests (at ${SECONDS} s)"
ctest --preset sanitize -j "$jobs"
echo "== Done (at ${SECONDS} s)"
