#!/usr/bin/env python3
"""Two builds of the exact engine on the same scene files: the gas at area
fraction 0.3 (simgen gas, seed 7) at 1e4, 1e5 and 1e6 disks, the two simcli
binaries alternating run by run (the order flips every round), the time being
simcli --stats' step time (reading and set-up excluded). Prints CSV: per size
each build's median time and collisions a second (wall hits counted), and the
median and range of the per-round ratios new / old. With --busy, one busy
process (sh -c 'while :; do :; done') runs beside them throughout.

    bench/exact_builds.py NEW_SIMCLI OLD_SIMCLI SIMGEN [ROUNDS] [--busy] > bench/results/<machine>/<name>.csv
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

arguments = [a for a in sys.argv[1:] if a != "--busy"]
busy = "--busy" in sys.argv[1:]
if len(arguments) < 3:
    sys.exit(__doc__)
binaries = {"new": arguments[0], "old": arguments[1]}
simgen = arguments[2]
rounds = int(arguments[3]) if len(arguments) > 3 else 7
cases = [(10000, 200), (100000, 20), (1000000, 4)]  # about 5e5 to 1e6 collisions each


def step_time(simcli, scene):
    run = subprocess.run([simcli, "--engine", "exact", "-t", "1", "--stats", scene, "-o", os.devnull],
                         capture_output=True, text=True, check=True)
    seconds = float(re.search(r"steps in ([0-9.e+-]+) s", run.stderr).group(1))
    counts = re.search(r"stats: (\d+) particle collisions, (\d+) wall collisions", run.stderr)
    return seconds, int(counts.group(1)) + int(counts.group(2))


print("particles,steps,rounds,load,new_median_s,old_median_s,collisions,new_collisions_per_s,"
      "old_collisions_per_s,ratio_median,ratio_min,ratio_max")
load = subprocess.Popen(["sh", "-c", "while :; do :; done"]) if busy else None
try:
    with tempfile.TemporaryDirectory() as directory:
        for particles, steps in cases:
            scene = os.path.join(directory, f"gas{particles}.in")
            with open(scene, "w") as out:
                subprocess.run([simgen, "gas", "-n", str(particles), "-s", str(steps), "--mode", "perf", "--seed", "7"],
                               stdout=out, check=True)
            times = {"new": [], "old": []}
            collisions = {}
            ratios = []
            for round_number in range(rounds):
                order = ["new", "old"] if round_number % 2 == 0 else ["old", "new"]
                this_round = {}
                for build in order:
                    this_round[build], collisions[build] = step_time(binaries[build], scene)
                    times[build].append(this_round[build])
                ratios.append(this_round["new"] / this_round["old"])
            if collisions["new"] != collisions["old"]:
                sys.exit(f"the builds disagree at {particles} disks: {collisions['new']} and {collisions['old']} collisions")
            new_median = statistics.median(times["new"])
            old_median = statistics.median(times["old"])
            print(f"{particles},{steps},{rounds},{'one busy process' if busy else 'quiet'},{new_median:.4f},"
                  f"{old_median:.4f},{collisions['new']},{collisions['new'] / new_median:.4g},"
                  f"{collisions['old'] / old_median:.4g},{statistics.median(ratios):.3f},{min(ratios):.3f},"
                  f"{max(ratios):.3f}", flush=True)
finally:
    if load:
        load.kill()
