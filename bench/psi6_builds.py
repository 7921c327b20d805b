#!/usr/bin/env python3
"""Two builds' |psi6| (simcli --observables, which measures it every row)
on a crowded scene and a spread one: N disks touching in a triangular patch
in one corner of a box 20 000 wide, and simgen's gas of N disks (seed 7). Each build
runs each scene for S steps with and without --observables F
--observe-every 1, the runs alternating (the order flips every round); a
measurement's time is (with - without) / S within a round. Prints CSV: per
scene and build, the median measurement time, and the per-round ratio new /
old (median and range). With --busy, one busy process runs beside them;
with --cpu=K every run is pinned to CPU K (simcli_runs.py).

    bench/psi6_builds.py NEW_SIMCLI OLD_SIMCLI SIMGEN N S ROUNDS [--busy] [--cpu=K] > CSV
"""
import math
import os
import subprocess
import tempfile
import time

from simcli_runs import (alternating_rounds, beside_busy_process, command_line, load_name, median,
                         pin_to_cpu_option, write_gas)

arguments, options = command_line(__doc__, 6)
new_simcli, old_simcli, simgen = arguments[0], arguments[1], arguments[2]
particles, steps, rounds = int(arguments[3]), int(arguments[4]), int(arguments[5])
busy = "--busy" in options
cpu = pin_to_cpu_option(options)
simclis = {"new": new_simcli, "old": old_simcli}


def write_corner_patch(path):
    """N disks of radius 1, 2.05 apart in a triangular patch from (10, 10), in a box 20 000 wide."""
    side = math.ceil(math.sqrt(particles))
    with open(path, "w") as out:
        out.write(f"{particles}\n20000\n1\n{steps}\nperf\n")
        for k in range(particles):
            row, column = divmod(k, side)
            x = 10 + 2.05 * column + (1.025 if row % 2 else 0.0)
            y = 10 + 2.05 * math.sqrt(3) / 2 * row
            out.write(f"{k} {x!r} {y!r} 0.1 0.05\n")


def seconds(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


print("scene,particles,steps,load,rounds,new_psi6_s,old_psi6_s,ratio_median,ratio_min,ratio_max")
with tempfile.TemporaryDirectory() as directory, beside_busy_process(busy, cpu):
    scenes = {"corner patch": os.path.join(directory, "patch.in"),
              "gas": write_gas(simgen, directory, particles, steps)}
    write_corner_patch(scenes["corner patch"])
    observables = os.path.join(directory, "rows.csv")
    for name, scene in scenes.items():
        def measurement_time(build):
            simcli = simclis[build]
            plain = seconds([simcli, "--engine", "exact", "-o", os.devnull, scene])
            measured = seconds([simcli, "--engine", "exact", "-o", os.devnull, "--observables", observables,
                                "--observe-every", "1", scene])
            return (measured - plain) / steps

        times = alternating_rounds(measurement_time, ("new", "old"), rounds)
        ratios = [new / old for new, old in zip(times["new"], times["old"])]
        print(f"{name},{particles},{steps},{load_name(busy)},{rounds},{median(times['new']):.4f},"
              f"{median(times['old']):.4f},{median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
