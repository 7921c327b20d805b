#!/usr/bin/env python3
"""One simcli on each scene file with -t 1 and -t 2, alternating run by run
(the order flips every round), the time being simcli --stats' step time
(reading and set-up excluded). Prints one CSV row a scene: each thread
count's median and fastest time, the ratio of the fastest (on a machine
whose neighbours come and go, the fastest runs are the quiet ones), and
the median, quartiles and range of the per-round ratios two threads / one.
With --busy, one busy process (sh -c 'while :; do :; done') runs beside
them throughout.

A SCENE may also name a scene of the sizes benchmark's two families,
written by the simgen beside SIMCLI with steps for about 0.1 s:
default:N (the default scene's density and speeds, L = 20000 sqrt(N / 1000))
or gas:N (area fraction 0.3).

    bench/two_threads.py SIMCLI ROUNDS SCENE... [--busy] [--header]
    bench/two_threads.py build/apps/simcli 11 examples/default.in default:4096 gas:16384 --header
"""
import math
import os
import subprocess
import sys
import tempfile

from simcli_runs import alternate, beside_busy_process, command_line, load_name, median, quartiles

arguments, options = command_line(__doc__, 3)
simcli, rounds, scenes = arguments[0], int(arguments[1]), arguments[2:]
busy = "--busy" in options


def family_scene(spec, directory):
    """The scene file for SPEC: a path as it is, or default:N / gas:N written into DIRECTORY."""
    family, _, count = spec.partition(":")
    if family not in ("default", "gas") or not count.isdigit():
        if not os.path.isfile(spec):
            sys.exit(f"two_threads.py: {spec} is neither a scene file nor default:N or gas:N")
        return spec
    particles = int(count)
    steps = max(8, int(0.3 / (2e-7 * particles + 2e-6)))
    arguments = ["-n", count, "-s", str(steps), "--mode", "perf"]
    if family == "default":
        box = 20000 * math.sqrt(particles / 1000)
        arguments = ["random", *arguments, "-L", repr(box), "--speed-min", "2500", "--speed-max", "5000"]
    else:
        arguments = ["gas", *arguments]
    path = os.path.join(directory, f"{family}{particles}.in")
    with open(path, "w") as out:
        subprocess.run([os.path.join(os.path.dirname(simcli), "simgen"), *arguments], stdout=out, check=True)
    return path


if "--header" in options:
    print("scene,load,rounds,one_thread_median_s,two_threads_median_s,one_thread_min_s,two_threads_min_s,"
          "ratio_of_mins,ratio_median,ratio_lower_quartile,ratio_upper_quartile,ratio_min,ratio_max")
with beside_busy_process(busy), tempfile.TemporaryDirectory() as directory:
    for scene in (family_scene(spec, directory) for spec in scenes):
        commands = {threads: [simcli, "-t", threads, scene] for threads in ("1", "2")}
        times, _, ratios = alternate(commands, rounds)
        lower, upper = quartiles(ratios)
        print(f"{os.path.basename(scene)},{load_name(busy)},{rounds},"
              f"{median(times['1']):.4f},{median(times['2']):.4f},{min(times['1']):.4f},{min(times['2']):.4f},"
              f"{min(times['2']) / min(times['1']):.3f},"
              f"{median(ratios):.3f},{lower:.3f},{upper:.3f},{min(ratios):.3f},{max(ratios):.3f}", flush=True)
