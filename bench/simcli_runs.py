"""What the comparison scripts share (exact_boundaries.py, exact_builds.py, whole_runs.py,
stepped_builds.py, two_threads.py, against_original.py): simcli's step time,
two commands run alternately, the order flipping every round, the command
line, the pinning to one CPU (--cpu=K), the busy process beside them, and the
exact engine's gas scenes.

Pinning: on a virtual machine whose CPUs are shared with other guests, one
CPU can run the same program 1.35 times slower than another for minutes,
and runs left to the scheduler land on either, so a ratio of two runs picks
that up at random (one build against itself on the 2-core benchmark host:
single rounds from 0.66 to 1.53 unpinned, nearly all within 0.93 to 1.08
pinned; benchmarks.md). With --cpu=K the script pins itself to CPU K, so that every
run it starts stays there, and the busy process to another. (The script
pins itself rather than each child, so that a child is still started the
fast way, without a fork of the Python process: whole-run timings such as
against_original.py's count the start.)"""
import contextlib
import os
import re
import statistics
import subprocess
import sys

cases = [(10000, 200), (100000, 20), (1000000, 4)]  # the gas at area fraction 0.3: about 5e5 to 1e6 collisions each


def write_gas(simgen, directory, particles, steps):
    """simgen gas -n PARTICLES -s STEPS --mode perf --seed 7, into DIRECTORY; returns its path."""
    scene = os.path.join(directory, f"gas{particles}_{steps}.in")
    with open(scene, "w") as out:
        subprocess.run([simgen, "gas", "-n", str(particles), "-s", str(steps), "--mode", "perf", "--seed", "7"],
                       stdout=out, check=True)
    return scene


def step_time(command):
    """simcli's --stats step time and its collisions (pairs and walls) for COMMAND (a list ending in the scene)."""
    run = subprocess.run(command + ["--stats", "-o", os.devnull], capture_output=True, text=True, check=True)
    seconds = float(re.search(r"steps in ([0-9.e+-]+) s", run.stderr).group(1))
    counts = re.search(r"stats: (\d+) particle collisions, (\d+) wall collisions", run.stderr)
    return seconds, int(counts.group(1)), int(counts.group(2))


def alternating_rounds(measure, names, rounds):
    """MEASURE(name) for each of the two NAMES, alternately: the first name first in even rounds, the
    second in odd ones. Returns {name: [its result in each round]}."""
    first, second = names
    results = {first: [], second: []}
    for round_number in range(rounds):
        for name in [first, second] if round_number % 2 == 0 else [second, first]:
            results[name].append(measure(name))
    return results


def alternate(commands, rounds):
    """Runs the two commands {name: command} alternately; returns each one's times, its last
    step_time() counts, and the per-round ratios second / first."""
    first, second = commands
    results = alternating_rounds(lambda name: step_time(commands[name]), (first, second), rounds)
    times = {name: [r[0] for r in results[name]] for name in results}
    counts = {name: list(results[name][-1][1:]) for name in results}
    ratios = [b / a for a, b in zip(times[first], times[second])]
    return times, counts, ratios


def median(values):
    return statistics.median(values)


def quartiles(values):
    """The lower and upper quartiles."""
    cuts = statistics.quantiles(values, n=4)
    return cuts[0], cuts[2]


def command_line(usage, at_least):
    """sys.argv's arguments that are not options (exits with USAGE when fewer than AT_LEAST), and its options."""
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(arguments) < at_least:
        sys.exit(usage)
    return arguments, {a for a in sys.argv[1:] if a.startswith("--")}


def pin_to_cpu_option(options):
    """With --cpu=K among OPTIONS, pins this process (and so every child it starts) to CPU K and
    returns K (exits unless K is a CPU this process may use); else returns None."""
    values = [option.partition("=")[2] for option in options if option.startswith("--cpu=")]
    if not values:
        return None
    allowed = os.sched_getaffinity(0)
    if not values[-1].isdigit() or int(values[-1]) not in allowed:
        sys.exit(f"--cpu=K: K must be one of the CPUs this process may use: {sorted(allowed)}")
    cpu = int(values[-1])
    os.sched_setaffinity(0, {cpu})
    return cpu


def builds_and_simgen(usage):
    """The command line NEW_SIMCLI OLD_SIMCLI SIMGEN [ROUNDS] [--busy] [--cpu=K] (ROUNDS 7 unless
    given), pinning as pin_to_cpu_option() does; returns (new, old, simgen, rounds, busy, cpu)."""
    arguments, options = command_line(usage, 3)
    cpu = pin_to_cpu_option(options)
    rounds = int(arguments[3]) if len(arguments) > 3 else 7
    return arguments[0], arguments[1], arguments[2], rounds, "--busy" in options, cpu


def load_name(busy):
    return "one busy process" if busy else "quiet"


@contextlib.contextmanager
def beside_busy_process(busy, cpu=None):
    """With BUSY, one busy process (sh -c 'while :; do :; done') runs while inside; with CPU (the
    one this process is pinned to), on another CPU, where there is another."""
    others = sorted(set(range(os.cpu_count() or 1)) - {cpu}) if cpu is not None else []
    pin = (lambda: os.sched_setaffinity(0, {others[0]})) if others else None
    load = subprocess.Popen(["sh", "-c", "while :; do :; done"], preexec_fn=pin) if busy else None
    try:
        yield
    finally:
        if load:
            load.kill()
