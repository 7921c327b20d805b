#!/usr/bin/env python3
"""The exact engine in a periodic box against the walled one, on the same
scene files: the gas at area fraction 0.3 (simgen gas) at 1e4, 1e5 and 1e6
disks, the two boundaries alternating run by run (the order flips every
round), the time being simcli --stats' step time. Prints CSV: per size the
median of the per-round ratios periodic / walls and their range.

    bench/exact_boundaries.py BUILD_DIR [ROUNDS] > bench/results/<machine>/exact_boundaries.csv
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

build = sys.argv[1] if len(sys.argv) > 1 else "build"
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
simgen = os.path.join(build, "apps", "simgen")
simcli = os.path.join(build, "apps", "simcli")
cases = [(10000, 200), (100000, 20), (1000000, 4)]  # about 5e5 to 1e6 collisions each


def step_time(scene, boundary):
    run = subprocess.run([simcli, "--engine", "exact", "--boundary", boundary, "--stats", scene, "-o", os.devnull],
                         capture_output=True, text=True, check=True)
    seconds = float(re.search(r"steps in ([0-9.e+-]+) s", run.stderr).group(1))
    collisions = int(re.search(r"stats: (\d+) particle collisions", run.stderr).group(1))
    return seconds, collisions


print("particles,steps,rounds,walls_median_s,periodic_median_s,walls_collisions,periodic_collisions,"
      "ratio_median,ratio_min,ratio_max")
with tempfile.TemporaryDirectory() as directory:
    for particles, steps in cases:
        scene = os.path.join(directory, f"gas{particles}.in")
        with open(scene, "w") as out:
            subprocess.run([simgen, "gas", "-n", str(particles), "-s", str(steps), "--mode", "perf", "--seed", "7"],
                           stdout=out, check=True)
        times = {"walls": [], "periodic": []}
        collisions = {}
        ratios = []
        for round_number in range(rounds):
            order = ["walls", "periodic"] if round_number % 2 == 0 else ["periodic", "walls"]
            this_round = {}
            for boundary in order:
                this_round[boundary], collisions[boundary] = step_time(scene, boundary)
                times[boundary].append(this_round[boundary])
            ratios.append(this_round["periodic"] / this_round["walls"])
        print(f"{particles},{steps},{rounds},{statistics.median(times['walls']):.4f},"
              f"{statistics.median(times['periodic']):.4f},{collisions['walls']},{collisions['periodic']},"
              f"{statistics.median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
