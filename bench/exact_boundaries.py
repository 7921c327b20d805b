#!/usr/bin/env python3
"""The exact engine in a periodic box against the walled one, on the same
scene files: the gas at area fraction 0.3 (simgen gas) at 1e4, 1e5 and 1e6
disks, the two boundaries alternating run by run (the order flips every
round), the time being simcli --stats' step time. Prints CSV: per size the
median of the per-round ratios periodic / walls and their range. With
--cpu=K, every run is pinned to CPU K (simcli_runs.py).

    bench/exact_boundaries.py BUILD_DIR [ROUNDS] [--cpu=K] > bench/results/<machine>/exact_boundaries.csv
"""
import os
import tempfile

from simcli_runs import alternate, cases, command_line, pin_to_cpu_option, median, write_gas

arguments, options = command_line(__doc__, 0)
build = arguments[0] if arguments else "build"
rounds = int(arguments[1]) if len(arguments) > 1 else 7
cpu = pin_to_cpu_option(options)
simgen = os.path.join(build, "apps", "simgen")
simcli = os.path.join(build, "apps", "simcli")

print("particles,steps,rounds,walls_median_s,periodic_median_s,walls_collisions,periodic_collisions,"
      "ratio_median,ratio_min,ratio_max")
with tempfile.TemporaryDirectory() as directory:
    for particles, steps in cases:
        scene = write_gas(simgen, directory, particles, steps)
        commands = {boundary: [simcli, "--engine", "exact", "--boundary", boundary, scene]
                    for boundary in ("walls", "periodic")}
        times, counts, ratios = alternate(commands, rounds)
        print(f"{particles},{steps},{rounds},{median(times['walls']):.4f},"
              f"{median(times['periodic']):.4f},{counts['walls'][0]},{counts['periodic'][0]},"
              f"{median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
