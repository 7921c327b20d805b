#!/usr/bin/env python3
"""The run-queue wait that the default thread count watches, read from
outside: each scene file run by SIMCLI with -t 2 (every step on both
threads), quiet and then beside one busy process (sh -c 'while :; do :;
done'), ROUNDS times each. While a run lasts, every thread's
/proc/<pid>/task/<tid>/schedstat is sampled every 20 ms; a row gives the
run's threads' waits summed over the sampled span, as a share of that
span's wall time (what src/parallel/run_queue_wait.cpp reads from inside),
and the time the threads ran, likewise.

    bench/run_queue_waits.py SIMCLI ROUNDS SCENE... [--header]
"""
import os
import subprocess
import time

from simcli_runs import beside_busy_process, command_line

arguments, options = command_line(__doc__, 3)
simcli, rounds, scenes = arguments[0], int(arguments[1]), arguments[2:]


def schedstat_totals(pid):
    """(run ns, wait ns, threads listed) summed over the threads of PID, or None once it has ended."""
    run = wait = 0
    try:
        tasks = os.listdir(f"/proc/{pid}/task")
        for task in tasks:
            try:
                with open(f"/proc/{pid}/task/{task}/schedstat") as stat:
                    fields = stat.read().split()
            except (FileNotFoundError, ProcessLookupError):
                continue  # a thread that ended since the listing
            run += int(fields[0])
            wait += int(fields[1])
    except (FileNotFoundError, ProcessLookupError):
        return None
    return run, wait, len(tasks)


def measure(scene):
    """Runs simcli -t 2 on SCENE; returns (wait share, run share, span in s) over its sampled span."""
    child = subprocess.Popen([simcli, "-t", "2", "-o", os.devnull, scene])
    first = last = None
    while child.poll() is None:
        totals = schedstat_totals(child.pid)
        now = time.monotonic()
        if totals is not None and child.poll() is None:
            # The first sample after the second thread exists: reading the scene comes before it.
            if first is None and totals[2] >= 2:
                first = (now, totals)
            elif first is not None:
                last = (now, totals)
        time.sleep(0.02)
    if child.returncode != 0:
        raise SystemExit(f"run_queue_waits.py: simcli failed on {scene}")
    if first is None or last is None:
        raise SystemExit(f"run_queue_waits.py: {scene} ended before two samples; give it more steps")
    span = last[0] - first[0]
    return (1e-9 * (last[1][1] - first[1][1]) / span, 1e-9 * (last[1][0] - first[1][0]) / span, span)


if "--header" in options:
    print("scene,load,round,sampled_s,wait_share,run_share")
for busy in (False, True):
    with beside_busy_process(busy):
        for scene in scenes:
            for round_number in range(rounds):
                wait, run, span = measure(scene)
                load = "one busy process" if busy else "quiet"
                print(f"{os.path.basename(scene)},{load},{round_number},{span:.3f},{wait:.4f},{run:.4f}", flush=True)
