#!/usr/bin/env bash
# Builds the benchmark harness (Release), runs it, and writes the CSVs and the
# plots under bench/results/<machine>/ (machine: first argument, or hostname).
# --quick runs a short version (smaller N, fewer repeats) for a smoke check.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure-deps.sh gnuplot-nox
machine=${1:-$(hostname)}
quick=${2:-}
out=bench/results/$machine
mkdir -p "$out"

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target particlesim_bench simcli -j "$(nproc)" >/dev/null

{
  echo "machine: $machine"
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores)"
  echo "memory: $(free -h | awk '/^Mem:/ {print $2}')"
  echo "compiler: $(g++ --version | head -1)"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
} > "$out/machine.txt"

build/bench/particlesim_bench steps $quick | tee "$out/steps.csv"
build/bench/particlesim_bench simcli $quick | tee "$out/simcli.csv"
gnuplot -e "results='$out'" bench/plot_steps.gp
echo "wrote $out/steps.csv, $out/simcli.csv, $out/time_per_step.png"
