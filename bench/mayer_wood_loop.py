#!/usr/bin/env python3
"""Alder and Wainwright's 870 disks in a square periodic box, area fraction
0.670 to 0.714 in steps of 0.004, against Li, Nishikawa, Hoellmer, Maggs &
Krauth, J. Chem. Phys. 157, 234111 (2022) (their N = 870, aspect ratio 1:1
table, from jellyfysh/HistoricDisks, DigitizedData/ThisWork.csv)
(docs/physics.md, "The Mayer-Wood loop").

    bench/mayer_wood_loop.py BUILD_DIR OUT_DIR [STEPS] [JOBS]

Each density: simgen's periodic lattice (kT = r^2 / 4), STEPS steps of the
exact engine (default 40 000: about 100 000 collisions a disk), the
pressure's block average from a tenth of the run on; JOBS runs side by side
(default 2). Writes mayer_wood_loop.csv in OUT_DIR.
"""

import csv
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from equation_of_state import measure

PARTICLES = 870
# beta P (2r)^2 and its error, N = 870, square periodic box (Li et al. 2022).
LI_2022 = {
    0.670: (7.986779, 0.000025), 0.674: (8.199729, 0.000025), 0.678: (8.410215, 0.000027),
    0.682: (8.613949, 0.000068), 0.686: (8.804458, 0.000052), 0.690: (8.969898, 0.000075),
    0.694: (9.089054, 0.000083), 0.698: (9.13414, 0.00022), 0.702: (9.11472, 0.00016),
    0.706: (9.08175, 0.00031), 0.710: (9.06469, 0.00043), 0.714: (9.0310, 0.0032),
}


def main(build, out, steps, jobs):
    build, out = Path(build), Path(out)
    work = build / "mayer_wood_loop"
    work.mkdir(parents=True, exist_ok=True)
    densities = sorted(LI_2022)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda eta: measure(build, work, eta, steps, PARTICLES), densities))
    with open(out / "mayer_wood_loop.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["eta", "particles", "steps", "collisions_per_disk", "seconds", "betaP_d2", "betaP_d2_error",
                    "li_2022", "li_2022_error", "difference_in_sigma"])
        for eta, (betap, error, collisions, seconds) in zip(densities, results):
            reference, reference_error = LI_2022[eta]
            sigma = (error ** 2 + reference_error ** 2) ** 0.5
            w.writerow([f"{eta:.3f}", PARTICLES, steps, f"{collisions / PARTICLES:.0f}", f"{seconds:.1f}",
                        f"{betap:.5f}", f"{error:.2g}", reference, reference_error,
                        f"{(betap - reference) / sigma:+.2f}"])
            print(f"eta {eta:.3f}: {betap:.5f} +- {error:.2g} against {reference} "
                  f"({(betap - reference) / sigma:+.1f} sigma), {collisions / PARTICLES:.0f} collisions a disk")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 40000,
         int(sys.argv[4]) if len(sys.argv) > 4 else 2)
