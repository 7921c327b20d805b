#!/usr/bin/env bash
# Quick start 2: installs what is missing, then builds and runs the whole test
# suite twice: a Release build (every test), and a build under
# AddressSanitizer and UndefinedBehaviorSanitizer (any report fails the run).
# About 8 minutes on a fresh 2-core machine, most of it compiling.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure-deps.sh clang-format
jobs=$(nproc)

echo "== Release build and tests"
cmake --preset release
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"

echo "== Sanitized build (address, undefined) and tests"
cmake --preset sanitize
cmake --build --preset sanitize -j "$jobs"
ctest --preset sanitize -j "$jobs"
