#!/usr/bin/env python3
"""simcli against the original team's sequential program on one scene file,
whole runs, the programs alternating run by run (the order flips every
round). The original (ariadn3/DiscreteParticleSimulator, openmp/sequential,
built with `gcc -O3 -fopenmp -o sim *.c -lm`) reads the scene on stdin.
Prints CSV: per program the median, lowest and highest time, and the
original's median over the program's. With --cpu=K, every run is pinned to
CPU K (simcli_runs.py), and only the one-thread programs run. With --busy,
one busy process (sh -c 'while :; do :; done') runs beside them throughout,
on another CPU than K.

    bench/against_original.py ORIGINAL_SIM BUILD_DIR [SCENE [ROUNDS]] [--cpu=K] [--busy] > bench/results/<machine>/against_original.csv
"""
import os
import statistics
import subprocess
import time

from simcli_runs import beside_busy_process, command_line, pin_to_cpu_option

arguments, options = command_line(__doc__, 2)
original = arguments[0]
build = arguments[1]
scene = arguments[2] if len(arguments) > 2 else os.path.join(os.path.dirname(__file__), "..", "examples", "default.in")
rounds = int(arguments[3]) if len(arguments) > 3 else 7
cpu = pin_to_cpu_option(options)
simcli = os.path.join(build, "apps", "simcli")
programs = {
    "original sequential": ([original], True),
    "simcli -t 1": ([simcli, "-t", "1", scene, "-o", os.devnull], False),
    "simcli -t 2": ([simcli, "-t", "2", scene, "-o", os.devnull], False),
    "simcli": ([simcli, scene, "-o", os.devnull], False),
}
if cpu is not None:
    del programs["simcli -t 2"], programs["simcli"]
times = {name: [] for name in programs}
with beside_busy_process("--busy" in options, cpu):
    for round_number in range(rounds):
        names = list(programs) if round_number % 2 == 0 else list(reversed(programs))
        for name in names:
            command, on_stdin = programs[name]
            with open(scene) as stdin:
                start = time.perf_counter()
                subprocess.run(command, stdin=stdin if on_stdin else subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, check=True)
                times[name].append(time.perf_counter() - start)
reference = statistics.median(times["original sequential"])
print("scene,program,rounds,median_s,min_s,max_s,original_over_this")
for name, values in times.items():
    median = statistics.median(values)
    print(f"{os.path.basename(scene)},{name},{rounds},{median:.4f},{min(values):.4f},{max(values):.4f},"
          f"{reference / median:.2f}")
