#!/usr/bin/env python3
"""Two builds of the stepped engine on one scene file: the two simcli
binaries alternating run by run (the order flips every round), the time
being simcli --stats' step time (reading and set-up excluded). Prints one CSV
row: each build's median time, and the median, quartiles and range of the
per-round ratios new / old. With --busy, one busy process
(sh -c 'while :; do :; done') runs beside them throughout.

    bench/stepped_builds.py NEW_SIMCLI OLD_SIMCLI SCENE THREADS ROUNDS [--busy] [--header]
"""
import os
import re
import statistics
import subprocess
import sys

arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
if len(arguments) < 5:
    sys.exit(__doc__)
new_simcli, old_simcli, scene, threads, rounds = arguments[0], arguments[1], arguments[2], arguments[3], int(arguments[4])
busy = "--busy" in sys.argv[1:]


def step_time(simcli):
    run = subprocess.run([simcli, "--stats", "-t", threads, scene, "-o", os.devnull], capture_output=True, text=True,
                         check=True)
    return float(re.search(r"steps in ([0-9.e+-]+) s", run.stderr).group(1))


if "--header" in sys.argv[1:]:
    print("scene,threads,load,rounds,new_median_s,old_median_s,ratio_median,ratio_lower_quartile,"
          "ratio_upper_quartile,ratio_min,ratio_max")
load = subprocess.Popen(["sh", "-c", "while :; do :; done"]) if busy else None
try:
    times = {"new": [], "old": []}
    ratios = []
    for round_number in range(rounds):
        order = ["new", "old"] if round_number % 2 == 0 else ["old", "new"]
        this_round = {}
        for build in order:
            this_round[build] = step_time(new_simcli if build == "new" else old_simcli)
            times[build].append(this_round[build])
        ratios.append(this_round["new"] / this_round["old"])
    ratios.sort()
    quartiles = statistics.quantiles(ratios, n=4)
    print(f"{os.path.basename(scene)},{threads},{'one busy process' if busy else 'quiet'},{rounds},"
          f"{statistics.median(times['new']):.4f},{statistics.median(times['old']):.4f},"
          f"{statistics.median(ratios):.3f},{quartiles[0]:.3f},{quartiles[2]:.3f},{ratios[0]:.3f},{ratios[-1]:.3f}",
          flush=True)
finally:
    if load:
        load.kill()
