#!/usr/bin/env python3
"""One simcli on each scene file with -t 1 and -t 2, alternating run by run
(the order flips every round), the time being simcli --stats' step time
(reading and set-up excluded). Prints one CSV row a scene: each thread
count's median and fastest time, the ratio of the fastest (on a machine
whose neighbours come and go, the fastest runs are the quiet ones), and
the median, quartiles and range of the per-round ratios two threads / one.
With --busy, one busy process (sh -c 'while :; do :; done') runs beside
them throughout.

    bench/two_threads.py SIMCLI ROUNDS SCENE... [--busy] [--header]
"""
import os

from simcli_runs import alternate, beside_busy_process, command_line, load_name, median, quartiles

arguments, options = command_line(__doc__, 3)
simcli, rounds, scenes = arguments[0], int(arguments[1]), arguments[2:]
busy = "--busy" in options

if "--header" in options:
    print("scene,load,rounds,one_thread_median_s,two_threads_median_s,one_thread_min_s,two_threads_min_s,"
          "ratio_of_mins,ratio_median,ratio_lower_quartile,ratio_upper_quartile,ratio_min,ratio_max")
with beside_busy_process(busy):
    for scene in scenes:
        commands = {threads: [simcli, "-t", threads, scene] for threads in ("1", "2")}
        times, _, ratios = alternate(commands, rounds)
        lower, upper = quartiles(ratios)
        print(f"{os.path.basename(scene)},{load_name(busy)},{rounds},"
              f"{median(times['1']):.4f},{median(times['2']):.4f},{min(times['1']):.4f},{min(times['2']):.4f},"
              f"{min(times['2']) / min(times['1']):.3f},"
              f"{median(ratios):.3f},{lower:.3f},{upper:.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
