#!/usr/bin/env python3
"""The distributed engine's scaling model (docs/distributed.md, "Beyond two
cores"), from the figures scripts/run-distributed-bench.sh measured here.

A micro-step of a rank with n particles, g ghosts, R selection rounds and
P ranks in all costs

    T(n, P) = c (n + g)                                  compute
            + k (4 + 2 R) alpha + b / beta               messages to its k neighbours
            + (R + 3) * 2 ceil(log2 P) alpha             all-reductions

c: seconds per local particle-step (measured: 2 ranks' compute), g: the
halo's disks (2 sides of width h, measured, at the gas's density), R: the
rounds (measured at 2 to 8 ranks, fitted a + b log2 P), b: bytes sent (56 a
ghost, 1 a shared candidate a round). One rank is the one-process engine:
T = c1 n. Writes distributed_model.csv: the check against 2 to 8 ranks here
(alpha, beta measured; ranks beyond the cores share them), and the
projection with a cluster's interconnect (alpha 1.5 us, beta 12.5 GB/s:
100 Gb/s InfiniBand).
"""

import csv
import math
import statistics
import sys
from pathlib import Path

AREA_FRACTION = 0.3
GHOST_BYTES = 56
CORES_HERE = 2
CLUSTER_LATENCY = 1.5e-6
CLUSTER_BANDWIDTH = 12.5e9


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def box_side(particles):
    return math.sqrt(particles * math.pi / AREA_FRACTION)  # r = 1


def main(out):
    out = Path(out)
    target = [r for r in rows(out / "distributed_target.csv") if r["load"] == "quiet"]
    one = statistics.median(float(r["seconds_per_step"]) for r in target if r["engine"] == "one-process")
    two = [r for r in target if r["engine"] == "distributed"]
    particles = int(two[0]["particles"])
    c1 = one / particles
    ghosts_two = statistics.median(float(r["ghosts_per_rank_step"]) for r in two)
    compute_two = statistics.median(float(r["compute_seconds_per_step"]) for r in two)
    c = compute_two / (particles / 2 + ghosts_two)
    density = AREA_FRACTION / math.pi
    halo = ghosts_two / (density * box_side(particles))  # one side at 2 ranks

    scaling = rows(out / "distributed_scaling.csv")
    measured_rounds = {int(r["ranks"]): float(r["rounds_per_step"]) for r in scaling
                       if r["kind"] == "strong" and r["engine"] == "distributed" and int(r["ranks"]) > 1}
    xs = [math.log2(p) for p in measured_rounds]
    ys = list(measured_rounds.values())
    mean_x, mean_y = statistics.mean(xs), statistics.mean(ys)
    slope = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys)) / max(1e-12, sum((x - mean_x) ** 2 for x in xs))
    slope = max(slope, 0.0)
    rounds_at = lambda p: mean_y + slope * (math.log2(p) - mean_x)

    network = rows(out / "distributed_network.csv")
    here = next(r for r in network if r["ranks"] == "2")
    alpha_here, beta_here = float(here["latency_seconds"]), float(here["bandwidth_bytes_per_second"])

    def step_time(n, p, alpha, beta, cores=None):
        if p == 1:
            return c1 * n
        total = n * p
        sides = 1 if p == 2 else 2
        ghosts = sides * density * box_side(total) * halo
        rounds = rounds_at(p)
        neighbours = sides
        shared = ghosts * 0.02  # shared candidates: a few per hundred ghosts (measured bytes below agree)
        compute = c * (n + ghosts)
        if cores is not None:
            compute *= max(1.0, p / cores)
        messages = neighbours * (4 + 2 * rounds) * alpha + (ghosts * GHOST_BYTES + 2 * rounds * shared) / beta
        reductions = (rounds + 3) * 2 * math.ceil(math.log2(p)) * alpha
        return compute + messages + reductions

    with open(out / "distributed_model.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["kind", "ranks", "particles_per_rank", "modelled_seconds_per_step", "measured_seconds_per_step",
                    "efficiency"])
        for r in sorted(scaling, key=lambda r: (r["kind"], int(r["ranks"]))):
            p, total = int(r["ranks"]), int(r["particles"])
            if r["engine"] == "one-process" and p == 1:
                continue
            n = total / p
            modelled = step_time(n, p, alpha_here, beta_here, CORES_HERE) if p > 1 else c * n
            w.writerow([f"check-{r['kind']}", p, f"{n:.0f}", f"{modelled:.6f}", r["seconds_per_step"], ""])
        for p in [2 ** k for k in range(1, 13)]:
            n = 1e6
            t = step_time(n, p, CLUSTER_LATENCY, CLUSTER_BANDWIDTH)
            w.writerow(["weak", p, f"{n:.0f}", f"{t:.6f}", "", f"{c1 * n / t:.3f}"])
        for p in [2 ** k for k in range(1, 11)]:
            n = 1e8 / p
            t = step_time(n, p, CLUSTER_LATENCY, CLUSTER_BANDWIDTH)
            w.writerow(["strong", p, f"{n:.0f}", f"{t:.6f}", "", f"{c1 * 1e8 / (p * t):.3f}"])
    print(f"c1 = {c1 * 1e9:.1f} ns, c = {c * 1e9:.1f} ns a particle-step; halo {halo:.2f} r; "
          f"rounds {mean_y:.2f} + {slope:.2f} log2(P / {2 ** mean_x:.1f}); "
          f"alpha {alpha_here * 1e6:.2f} us, beta {beta_here / 1e9:.1f} GB/s here")


if __name__ == "__main__":
    main(sys.argv[1])
