#!/usr/bin/env python3
"""Two simcli builds' whole runs (start, reading, set-up, steps and writing,
as a user waits for them) on large scenes and the default one, the two
binaries alternating run by run (the order flips every round): the gas at
area fraction 0.3 (simgen gas, seed 7) of a million disks for one step on
the stepped engine and for four on the exact engine, and examples/default.in.
Prints CSV: per scene each build's median time and the median and range of
the per-round ratios new / old. With --busy, one busy process (sh -c 'while
:; do :; done') runs beside them throughout; with --cpu=K, every run is
pinned to CPU K (simcli_runs.py).

    bench/whole_runs.py NEW_SIMCLI OLD_SIMCLI SIMGEN [ROUNDS] [--busy] [--cpu=K] > bench/results/<machine>/<name>.csv
"""
import os
import subprocess
import tempfile
import time

from simcli_runs import alternating_rounds, beside_busy_process, builds_and_simgen, load_name, median, write_gas

new_simcli, old_simcli, simgen, rounds, busy, cpu = builds_and_simgen(__doc__)
default_scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "default.in")


def whole_run(command):
    start = time.perf_counter()
    subprocess.run(command, check=True)
    return time.perf_counter() - start


print("scene,rounds,load,new_median_s,old_median_s,ratio_median,ratio_min,ratio_max")
with beside_busy_process(busy, cpu):
    with tempfile.TemporaryDirectory() as directory:
        cases = [("gas of 1e6 disks, 1 step", ["-t", "1"], write_gas(simgen, directory, 1000000, 1)),
                 ("gas of 1e6 disks, 4 steps, --engine exact", ["--engine", "exact"],
                  write_gas(simgen, directory, 1000000, 4)),
                 ("default scene", ["-t", "1"], default_scene)]
        for name, options_of_case, scene in cases:
            commands = {build: [simcli, *options_of_case, "-o", os.devnull, scene]
                        for build, simcli in (("old", old_simcli), ("new", new_simcli))}
            times = alternating_rounds(lambda build: whole_run(commands[build]), ("old", "new"), rounds)
            ratios = [new / old for old, new in zip(times["old"], times["new"])]
            print(f"{name},{rounds},{load_name(busy)},{median(times['new']):.4f},{median(times['old']):.4f},"
                  f"{median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
