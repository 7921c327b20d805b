#!/usr/bin/env bash
# The distributed engine's benchmark (docs/distributed.md): builds the mpi
# preset's benchmark, then writes under bench/results/<machine>/ (machine:
# first argument, or hostname):
#   distributed_target.csv   the dense gas of 1e6 disks, 10 steps: one rank
#                            (the one-process engine, as simcli under mpirun -np 1)
#                            against 2 ranks of one thread, in alternating
#                            rounds, quiet and beside a busy process
#   distributed_scaling.csv  1 to 8 ranks, weak (125 000 disks a rank) and
#                            strong (1e6 disks): the model's check
#   distributed_network.csv  ping-pong latency, bandwidth and an all-reduce
# then the model's projection (bench/distributed_model.py) and its plot.
# About 10 minutes on the project's 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure-deps.sh gnuplot-nox libopenmpi-dev openmpi-bin
machine=${1:-$(hostname)}
rounds=${ROUNDS:-5}
out=bench/results/$machine
mkdir -p "$out"
cmake --preset mpi -DPARTICLESIM_BUILD_BENCH=ON >/dev/null
cmake --build --preset mpi --target distributed_bench -j "$(nproc)" >/dev/null
bench=build-mpi/bench/distributed_bench
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_MCA_rmaps_base_oversubscribe=1
echo "$(date -u +%Y-%m-%dT%H:%MZ) commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown): distributed" >> "$out/runs.txt"

columns="ranks,particles,steps,engine,seconds_per_step,peak_mb_largest_rank,peak_mb_rank0,ghosts_per_rank_step,bytes_per_rank_step,messages_per_rank_step,rounds_per_step,exchange_seconds_per_step,compute_seconds_per_step"
gas() { mpirun -q -np "$1" "$bench" gas "$2" "$3" ${4:-}; }

echo "load,round,$columns" > "$out/distributed_target.csv"
for load in quiet busy; do
  busy_pid=""
  if [ "$load" = busy ]; then
    sh -c 'while :; do :; done' &
    busy_pid=$!
  fi
  for round in $(seq "$rounds"); do
    echo "$load,$round,$(gas 1 1000000 10)" >> "$out/distributed_target.csv"
    echo "$load,$round,$(gas 2 1000000 10)" >> "$out/distributed_target.csv"
  done
  [ -n "$busy_pid" ] && kill "$busy_pid"
done

echo "kind,$columns" > "$out/distributed_scaling.csv"
for ranks in 1 2 4 8; do
  echo "weak,$(gas "$ranks" $((125000 * ranks)) 10 distributed)" >> "$out/distributed_scaling.csv"
  echo "strong,$(gas "$ranks" 1000000 10 distributed)" >> "$out/distributed_scaling.csv"
done
echo "weak,$(gas 1 125000 10)" >> "$out/distributed_scaling.csv"
echo "strong,$(gas 1 1000000 10)" >> "$out/distributed_scaling.csv"

echo "ranks,latency_seconds,bandwidth_bytes_per_second,allreduce_seconds" > "$out/distributed_network.csv"
for ranks in 2 4 8; do mpirun -q -np "$ranks" "$bench" pingpong >> "$out/distributed_network.csv"; done

python3 bench/distributed_model.py "$out"
gnuplot -e "dir='$out'" bench/plot_distributed.gp
echo "written: $out/distributed_*.csv, $out/distributed.png"
