#!/usr/bin/env bash
# Builds the benchmark harness (Release), runs it, and writes the CSVs and the
# plots under build/bench-results/<machine>/ (machine: first argument, or
# hostname); with --update, under bench/results/<machine>/, replacing the
# committed results. --quick runs a short version (smaller N, fewer repeats).
# Further arguments pick modes (default: all): steps simcli accuracy exact stress divergence loaded programs
# (programs and loaded read the other builds from the environment: bench/programs_benchmark.cpp).
# Installs gnuplot-nox (for the plots) when missing.
#   scripts/run-bench.sh cpp-2core                  # everything (about an hour)
#   scripts/run-bench.sh cpp-2core "" accuracy      # just run time against error
#   scripts/run-bench.sh --update cpp-2core         # everything, into the committed results
set -euo pipefail
cd "$(dirname "$0")/.."
results_root=build/bench-results
if [ "${1:-}" = "--update" ]; then
  results_root=bench/results
  shift
fi
scripts/ensure-deps.sh gnuplot-nox
machine=${1:-$(hostname)}
quick=${2:-}
shift $(( $# < 2 ? $# : 2 ))
modes=${*:-steps simcli accuracy exact stress divergence loaded programs}
out=$results_root/$machine
mkdir -p "$out"

cmake --preset release >/dev/null
cmake --build --preset release --target particlesim_bench simcli -j "$(nproc)" >/dev/null

{
  echo "machine: $machine"
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores)"
  # The widest lanes the searches may choose (x86-64): the same model name has come with and without AVX-512.
  echo "simd: $(grep -o -w -E 'avx2|fma|avx512f' /proc/cpuinfo 2>/dev/null | sort -u | tr '\n' ' ')"
  echo "memory: $(free -h | awk '/^Mem:/ {print $2}')"
  echo "compiler: $(g++ --version | head -1)"
} > "$out/machine.txt"
# Which commit wrote which CSVs: one line per run.
echo "$(date -u +%Y-%m-%dT%H:%MZ) commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown): $modes" >> "$out/runs.txt"

for mode in $modes; do
  build/bench/particlesim_bench "$mode" $quick | tee "$out/$mode.csv"
done
[[ " $modes " == *" steps "* ]] && gnuplot -e "results='$out'" bench/plot_steps.gp
[[ " $modes " == *" accuracy "* ]] && gnuplot -e "results='$out'" bench/plot_accuracy.gp
[[ " $modes " == *" divergence "* ]] && gnuplot -e "results='$out'" bench/plot_divergence.gp
[[ " $modes " == *" loaded "* ]] && gnuplot -e "results='$out'" bench/plot_loaded.gp
[[ " $modes " == *" loaded "* ]] && gnuplot -e "results='$out'" bench/plot_default_threads.gp
echo "wrote $(for mode in $modes; do printf '%s ' "$out/$mode.csv"; done)and the plots"
