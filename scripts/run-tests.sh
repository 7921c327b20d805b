#!/usr/bin/env bash
# Quick start 2: installs what is missing, then builds and runs the whole test
# suite twice: a Release build (every test), and a build under
# AddressSanitizer and UndefinedBehaviorSanitizer with the library's invariant
# checks compiled in (any report fails the run). The Release pass also
# cross-checks the bytes on aarch64 under qemu, runs the parallel stages under
# ThreadSanitizer (clang's OpenMP) and fuzzes for 10 seconds.
# 7 min 57 s to 10 min 8 s (twelve runs, the machine quiet; 16 min 36 s beside a busy process) from a clean clone on the project's 2-core machine with the tools
# already installed (OpenMPI's tests included), 14.3 to 18.5 min of CPU time, more than a quarter of it in the kernel (a first touch of memory
# and a switch between processes are slow in its virtual machine); on a fresh machine the tools' install
# adds what the Release build does not hide.
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

# One phase after another: the release tests keep both cores busy (96 % of
# the time), so a build beside them gains little idle CPU, and on the
# project's virtual machine the switches between the two cost more CPU than
# it gains (CHANGELOG.md has the runs). Nor do three tests at once instead of
# two, though some wait on mpirun or Chromium: the release tests took 240.8
# and 232.4 s at -j 3 against 232.6 and 231.5 s at -j 2, runs alternating.
echo "== Release tests (at ${SECONDS} s)"
ctest --preset release -j "$jobs"
echo "== Sanitized build (address, undefined) (at ${SECONDS} s)"
cmake --preset sanitize
cmake --build --preset sanitize -j "$jobs"
echo "== Sanitized tests (at ${SECONDS} s)"
ctest --preset sanitize -j "$jobs"
echo "== Done (at ${SECONDS} s)"
