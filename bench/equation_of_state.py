#!/usr/bin/env python3
"""The hard-disk equation of state in a periodic box against the virial
series (docs/physics.md, "The equation of state").

    bench/equation_of_state.py BUILD_DIR OUT_DIR [STEPS]

For each area fraction eta from 0.10 to 0.50: simgen's periodic lattice of
400 disks (kT = r^2 / 4), melted and measured by the exact engine
(simcli --engine exact --boundary periodic --observables, the pressure's
block average from a tenth of the run on), Z = beta P A / N = beta P (2r)^2
* pi / (4 eta). Against Z = 1 + sum_{k=2..10} (B_k / B_2^(k-1)) (2 eta)^(k-1)
with Clisby & McCoy's coefficients (J. Stat. Phys. 122, 15 (2006), table 1,
D = 2); the series' tail beyond B10 is estimated as geometric with the
ratio B10 B_2 / B9 and given as its uncertainty. Writes
equation_of_state.csv in OUT_DIR; and equation_of_state_sizes.csv: eta 0.3
at 100, 400, 1600 and 6400 disks (the same collisions a disk), the finite
box's 1/N correction measured.
"""

import csv
import math
import re
import subprocess
import sys
from pathlib import Path

# B_k / B_2^(k-1) for hard disks, k = 2 .. 10 (Clisby & McCoy 2006).
REDUCED_VIRIAL = [1.0, 0.782004, 0.53223180, 0.33355604, 0.1988425, 0.1148728, 0.0649930, 0.0362193, 0.0199537]
PARTICLES = 400


def virial_series(eta):
    x = 2.0 * eta
    z = 1.0 + sum(b * x ** (k + 1) for k, b in enumerate(REDUCED_VIRIAL))
    ratio = REDUCED_VIRIAL[-1] / REDUCED_VIRIAL[-2]
    next_term = REDUCED_VIRIAL[-1] * ratio * x ** 10
    tail = next_term / (1.0 - ratio * x)
    return z, tail


def measure(build, work, eta, steps, particles=PARTICLES):
    scene = work / f"eos-{eta:.3f}-{particles}.in"
    with open(scene, "w") as f:
        subprocess.run([str(build / "apps/simgen"), "crystal", "-n", str(particles), "--fraction", f"{eta}",
                        "--boundary", "periodic", "-s", str(steps), "--mode", "perf"], stdout=f, check=True)
    run = subprocess.run([str(build / "apps/simcli"), "--engine", "exact", "--boundary", "periodic", str(scene),
                          "-o", "/dev/null", "--observables", str(work / f"eos-{eta:.3f}-{particles}.csv"), "--observe-every",
                          "10", "--measure-from", str(steps // 10), "--stats"],
                         capture_output=True, text=True, check=True)
    pressure = re.search(r"beta P \(2r\)\^2 = ([0-9.e+-]+) \+- ([0-9.e+-]+)", run.stderr)
    collisions = re.search(r"stats: (\d+) particle collisions", run.stderr)
    seconds = re.search(r"steps in ([0-9.]+) s", run.stderr)
    return float(pressure.group(1)), float(pressure.group(2)), int(collisions.group(1)), float(seconds.group(1))


def main(build, out, steps):
    build, out = Path(build), Path(out)
    work = build / "equation_of_state"
    work.mkdir(parents=True, exist_ok=True)
    with open(out / "equation_of_state.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["eta", "particles", "steps", "collisions_per_disk", "seconds", "betaP_d2", "betaP_d2_error", "Z",
                    "Z_error", "Z_virial_B10", "Z_virial_tail", "difference_in_sigma"])
        for k in range(9):
            eta = 0.10 + 0.05 * k
            betap, error, collisions, seconds = measure(build, work, eta, steps)
            scale = math.pi / (4.0 * eta)
            z, z_error = betap * scale, error * scale
            series, tail = virial_series(eta)
            sigma = math.hypot(z_error, tail)
            w.writerow([f"{eta:.2f}", PARTICLES, steps, f"{collisions / PARTICLES:.0f}", f"{seconds:.2f}",
                        f"{betap:.6f}", f"{error:.2g}", f"{z:.5f}", f"{z_error:.2g}", f"{series:.5f}", f"{tail:.2g}",
                        f"{(z - series) / sigma:+.2f}"])
            print(f"eta {eta:.2f}: Z = {z:.5f} +- {z_error:.2g}, series {series:.5f} (+{tail:.1g}), "
                  f"{collisions / PARTICLES:.0f} collisions a disk, {seconds:.1f} s", flush=True)
    with open(out / "equation_of_state_sizes.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["eta", "particles", "steps", "collisions_per_disk", "Z", "Z_error", "Z_virial_B10"])
        eta = 0.3
        for particles in [100, 400, 1600, 6400]:
            sized_steps = steps * PARTICLES // particles
            betap, error, collisions, _ = measure(build, work, eta, sized_steps, particles)
            scale = math.pi / (4.0 * eta)
            w.writerow([f"{eta:.2f}", particles, sized_steps, f"{collisions / particles:.0f}", f"{betap * scale:.5f}",
                        f"{error * scale:.2g}", f"{virial_series(eta)[0]:.5f}"])
            print(f"N {particles}: Z = {betap * scale:.5f} +- {error * scale:.2g}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 40000)
