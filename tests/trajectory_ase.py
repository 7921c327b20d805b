#!/usr/bin/env python3
"""simcli --trajectory read by ASE (python3-ase): every frame's positions,
velocities, radii, cell, pbc, step and time against the states simcli writes
with --exact-numbers for the same run. Exit 77 (skipped) without ASE.

usage: trajectory_ase.py SIMCLI WORK_DIR"""

import os
import subprocess
import sys

try:
    import ase.io
except ImportError:
    print("SKIPPED: python3-ase is not installed (scripts/ensure-deps.sh installs it as root)")
    sys.exit(77)

simcli, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
scene = os.path.join(work, "scene.in")
with open(scene, "w") as f:
    f.write("40 30 0.5 23 print\n")  # random: collisions with walls and pairs
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


for every, engine in ((1, "step"), (5, "step"), (4, "exact")):
    path = os.path.join(work, "run.xyz")
    states = subprocess.run(
        [simcli, scene, "--exact-numbers", "--engine", engine, "--trajectory", path, "--trajectory-every", str(every)],
        check=True, capture_output=True, text=True).stdout
    by_step = {}
    for line in states.splitlines():
        fields = line.split()
        by_step.setdefault(int(fields[0]), []).append([float(v) for v in fields[2:6]])
    frames = ase.io.read(path, index=":", format="extxyz")
    wanted = sorted(set(list(range(0, 24, every)) + [23]))
    check([a.info["step"] for a in frames] == wanted, f"every {every}: steps {[a.info['step'] for a in frames]}")
    for atoms in frames:
        step = atoms.info["step"]
        check(atoms.info["time"] == float(step), f"step {step}: time {atoms.info['time']}")
        check(len(atoms) == 40, f"step {step}: {len(atoms)} atoms")
        check(list(atoms.get_chemical_symbols()) == ["Ar"] * 40, "species")
        check(not any(atoms.pbc), f"pbc {atoms.pbc}")
        cell = atoms.cell.array
        check(cell[0][0] == 30 and cell[1][1] == 30 and cell[2][2] == 1.0, f"cell {cell}")
        check(all(r == 0.5 for r in atoms.arrays["radius"]), "radius")
        for i, (x, y, vx, vy) in enumerate(by_step[step]):
            p, v = atoms.positions[i], atoms.arrays["velo"][i]
            if (p[0], p[1], p[2], v[0], v[1], v[2]) != (x, y, 0.0, vx, vy, 0.0):
                failures.append(f"{engine}, step {step}, disk {i}: {p} {v} against {x} {y} {vx} {vy}")
                break

for failure in failures:
    print("FAILED:", failure)
print(f"trajectory_ase: {len(failures)} failed")
sys.exit(1 if failures else 0)
