#!/usr/bin/env python3
"""Two builds of the exact engine on simgen's families: for each family, a
scene of N disks and S steps (simgen FAMILY -n N -s S --mode perf), the two
simcli binaries alternating run by run (the order flips every round). Prints
CSV: per family and build, the median whole run (start included: a crowded
start's first predictions are part of the cost) and the median step time
(simcli --stats), the cells a side each build chose, and the per-round
ratio new / old of the whole runs (median and range). With --busy, one busy
process runs beside them; with --cpu=K every run is pinned to CPU K
(simcli_runs.py).

    bench/exact_families_builds.py NEW_SIMCLI OLD_SIMCLI SIMGEN N S ROUNDS [--busy] [--cpu=K] > CSV
"""
import os
import re
import subprocess
import tempfile
import time

from simcli_runs import alternating_rounds, beside_busy_process, command_line, load_name, median, pin_to_cpu_option

arguments, options = command_line(__doc__, 6)
new_simcli, old_simcli, simgen = arguments[0], arguments[1], arguments[2]
particles, steps, rounds = arguments[3], arguments[4], int(arguments[5])
busy = "--busy" in options
cpu = pin_to_cpu_option(options)
simclis = {"new": new_simcli, "old": old_simcli}
families = ["cradle", "line", "walls", "clusters", "gas", "crystal", "random"]


def run(simcli, scene):
    """The whole run's seconds, the step time and the cells a side of simcli --engine exact --stats."""
    start = time.perf_counter()
    done = subprocess.run([simcli, "--engine", "exact", "--stats", "-o", os.devnull, scene], capture_output=True,
                          text=True, check=True)
    whole = time.perf_counter() - start
    step = float(re.search(r"steps in ([0-9.e+-]+) s", done.stderr).group(1))
    cells = re.search(r"neighbours by (\d+) x", done.stderr)
    return whole, step, cells.group(1) if cells else "lines"


print("family,particles,steps,load,rounds,new_whole_s,old_whole_s,new_step_s,old_step_s,new_cells,old_cells,"
      "ratio_median,ratio_min,ratio_max")
with tempfile.TemporaryDirectory() as directory, beside_busy_process(busy, cpu):
    for family in families:
        scene = os.path.join(directory, family + ".in")
        with open(scene, "w") as out:
            subprocess.run([simgen, family, "-n", particles, "-s", steps, "--mode", "perf"], stdout=out, check=True)
        results = alternating_rounds(lambda build: run(simclis[build], scene), ("new", "old"), rounds)
        ratios = [new[0] / old[0] for new, old in zip(results["new"], results["old"])]
        whole = {name: median([r[0] for r in results[name]]) for name in results}
        step = {name: median([r[1] for r in results[name]]) for name in results}
        print(f"{family},{particles},{steps},{load_name(busy)},{rounds},{whole['new']:.4f},{whole['old']:.4f},"
              f"{step['new']:.4f},{step['old']:.4f},{results['new'][0][2]},{results['old'][0][2]},"
              f"{median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
