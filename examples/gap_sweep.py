#!/usr/bin/env python3
"""Gap sweep of the thesis' chapter 8 pair (studies/ch8-five-three.ini: a 5-storey and a
3-storey building, the damped Sears model, the first 8 s of El Centro 1940 NS): how much
pounding amplifies the peak floor displacements as the gap between them grows, the simulations
run in parallel threads (pound.simulate releases the GIL while it simulates).

    PYTHONPATH=build/python /usr/bin/python3 examples/gap_sweep.py [--out results/examples]
        [--gaps 0:0.08:41] [--threads N]

Writes OUT/gap_sweep.png and OUT/gap_sweep.csv (one row per gap) and prints the table's first
and last rows with the time taken. docs/python.md explains the module.
"""

import argparse
import csv
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pound  # noqa: E402

STUDY = Path(__file__).resolve().parent.parent / "studies" / "ch8-five-three.ini"


def peaks(gap):
    """Per building: the largest displacement amplification over its floors and its top
    floor's; the number of impacts over all contact levels."""
    r = pound.simulate(STUDY, pair1__gap=gap)
    largest = [max(f["disp_amplification"] for f in b["floors"]) for b in r["buildings"]]
    top = [b["floors"][-1]["disp_amplification"] for b in r["buildings"]]
    names = [b["name"] for b in r["buildings"]]
    return names, largest, top, sum(c["impacts"] for c in r["contacts"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="results/examples")
    ap.add_argument("--gaps", default="0:0.08:41", help="first:last:count, in m")
    ap.add_argument("--threads", type=int, default=os.cpu_count())
    a = ap.parse_args()
    first, last, count = a.gaps.split(":")
    gaps = np.linspace(float(first), float(last), int(count))
    start = time.perf_counter()
    with ThreadPoolExecutor(max_workers=a.threads) as pool:
        rows = list(pool.map(peaks, gaps))
    seconds = time.perf_counter() - start
    names = rows[0][0]

    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "gap_sweep.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["gap_m"] + [f"{n} largest" for n in names] + [f"{n} top floor" for n in names]
                   + ["impacts"])
        for g, (_, largest, top, impacts) in zip(gaps, rows):
            w.writerow([f"{g:.4f}"] + [f"{x:.6f}" for x in largest + top] + [impacts])

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for b, name in enumerate(names):
        line, = ax.plot(gaps * 1e3, [r[1][b] for r in rows], marker="o", ms=3,
                        label=f"{name}: largest over its floors")
        ax.plot(gaps * 1e3, [r[2][b] for r in rows], ls="--", color=line.get_color(),
                label=f"{name}: top floor")
    no_contact = [g for g, r in zip(gaps, rows) if r[3] == 0]
    if no_contact:
        ax.axvline(no_contact[0] * 1e3, color="grey", lw=0.8)
        ax.text(no_contact[0] * 1e3, ax.get_ylim()[1], " no contact beyond", va="top",
                fontsize=8, color="grey")
    ax.axhline(1.0, color="black", lw=0.6)
    ax.set_xlabel("gap [mm]")
    ax.set_ylabel("peak displacement with / without pounding [-]")
    ax.set_title("Chapter 8 pair (damped Sears model), El Centro 1940 NS, 8 s")
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    fig.savefig(out / "gap_sweep.png", dpi=120)

    print(f"gap_sweep: {len(gaps)} gaps in {seconds:.2f} s on {a.threads} threads "
          f"(pound {pound.__version__} {pound.git_revision})")
    for g, r in (zip(gaps, rows)):
        if g in (gaps[0], gaps[-1]):
            print(f"  gap {g * 1e3:5.1f} mm: amplification "
                  + ", ".join(f"{n} {x:.3f}" for n, x in zip(names, r[1])) + f", {r[3]} impacts")
    print(f"gap_sweep: wrote {out / 'gap_sweep.png'} and {out / 'gap_sweep.csv'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
