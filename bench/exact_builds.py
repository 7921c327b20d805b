#!/usr/bin/env python3
"""Two builds of the exact engine on the same scene files: the gas at area
fraction 0.3 (simgen gas, seed 7) at 1e4, 1e5 and 1e6 disks, the two simcli
binaries alternating run by run (the order flips every round), the time being
simcli --stats' step time (reading and set-up excluded). Prints CSV: per size
each build's median time and collisions a second (wall hits counted), and the
median and range of the per-round ratios new / old. With --busy, one busy
process (sh -c 'while :; do :; done') runs beside them throughout; with
--cpu=K, every run is pinned to CPU K (simcli_runs.py).

    bench/exact_builds.py NEW_SIMCLI OLD_SIMCLI SIMGEN [ROUNDS] [--busy] [--cpu=K] > bench/results/<machine>/<name>.csv
"""
import sys
import tempfile

from simcli_runs import alternate, beside_busy_process, cases, builds_and_simgen, load_name, median, write_gas

new_simcli, old_simcli, simgen, rounds, busy, cpu = builds_and_simgen(__doc__)

print("particles,steps,rounds,load,new_median_s,old_median_s,collisions,new_collisions_per_s,"
      "old_collisions_per_s,ratio_median,ratio_min,ratio_max")
with beside_busy_process(busy, cpu):
    with tempfile.TemporaryDirectory() as directory:
        for particles, steps in cases:
            scene = write_gas(simgen, directory, particles, steps)
            commands = {build: [simcli, "--engine", "exact", "-t", "1", scene]
                        for build, simcli in (("old", old_simcli), ("new", new_simcli))}
            times, counts, ratios = alternate(commands, rounds)
            collisions = {build: sum(counts[build]) for build in counts}
            if collisions["new"] != collisions["old"]:
                sys.exit(f"the builds disagree at {particles} disks: {collisions['new']} and {collisions['old']} collisions")
            new_median = median(times["new"])
            old_median = median(times["old"])
            print(f"{particles},{steps},{rounds},{load_name(busy)},{new_median:.4f},"
                  f"{old_median:.4f},{collisions['new']},{collisions['new'] / new_median:.4g},"
                  f"{collisions['old'] / old_median:.4g},{median(ratios):.3f},{min(ratios):.3f},"
                  f"{max(ratios):.3f}", flush=True)
