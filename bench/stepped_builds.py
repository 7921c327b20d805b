#!/usr/bin/env python3
"""Two builds of the stepped engine on one scene file: the two simcli
binaries alternating run by run (the order flips every round), the time
being simcli --stats' step time (reading and set-up excluded). Prints one CSV
row: each build's median time, and the median, quartiles and range of the
per-round ratios new / old. THREADS "default" leaves -t out (the
thread count each build chooses). With --busy, one busy process
(sh -c 'while :; do :; done') runs beside them throughout; with --cpu=K,
every run is pinned to CPU K (simcli_runs.py; one thread then).

    bench/stepped_builds.py NEW_SIMCLI OLD_SIMCLI SCENE THREADS ROUNDS [--busy] [--header] [--cpu=K]
"""
import os
import sys

from simcli_runs import alternate, beside_busy_process, command_line, pin_to_cpu_option, load_name, median, quartiles

arguments, options = command_line(__doc__, 5)
new_simcli, old_simcli, scene, threads, rounds = arguments[0], arguments[1], arguments[2], arguments[3], int(arguments[4])
busy = "--busy" in options
cpu = pin_to_cpu_option(options)
if cpu is not None and threads != "1":
    sys.exit("stepped_builds.py: --cpu=K pins every run to one CPU, so THREADS must be 1")

if "--header" in options:
    print("scene,threads,load,rounds,new_median_s,old_median_s,ratio_median,ratio_lower_quartile,"
          "ratio_upper_quartile,ratio_min,ratio_max")
with beside_busy_process(busy, cpu):
    thread_option = [] if threads == "default" else ["-t", threads]
    commands = {build: [simcli, *thread_option, scene] for build, simcli in (("old", old_simcli), ("new", new_simcli))}
    times, _, ratios = alternate(commands, rounds)
    lower, upper = quartiles(ratios)
    print(f"{os.path.basename(scene)},{threads},{load_name(busy)},{rounds},"
          f"{median(times['new']):.4f},{median(times['old']):.4f},"
          f"{median(ratios):.3f},{lower:.3f},{upper:.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
