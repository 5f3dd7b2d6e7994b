#!/usr/bin/python3
"""The lagged coherency a set of station motions achieves, against its model (issue 28).

Run with Debian's python (python3-matplotlib, python3-h5py) on the motions.h5 of
'pound motion generate --stations N --spacing D ...' (or --positions):

  /usr/bin/python3 scripts/plot_coherency.py --motions DIR/motions.h5 --out coherency.png

One panel per pair of stations (at most 6: the pairs of station 1 and of neighbours first): the
set's lagged coherency (/coherency/achieved, ensemble average of the cross-spectra, +- half_band
Hz around each frequency, the lag removed) and the model's (/coherency/model) against frequency,
with the separation, the model's lag d / v and the achieved lag in the title. docs/ground.md
describes the estimate.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    with h5py.File(path, "r") as f:
        if "coherency" not in f:
            sys.exit(f"{path}: no /coherency group; generate the motions with --stations or "
                     "--positions (pound motion generate)")
        c = f["coherency"]
        return {
            "frequency": c["frequency"][()],
            "pair": c["pair"][()],
            "separation": c["separation"][()],
            "lag": c["lag"][()],
            "model_lag": c["model_lag"][()],
            "model": c["model"][()],
            "achieved": c["achieved"][()],
            "half_band": float(c.attrs["half_band_hz"]),
            "coherency": str(f.attrs.get("coherency", "")),
            "velocity": float(f.attrs.get("apparent_velocity_mps", np.inf)),
            "count": f["motions/acceleration"].shape[0],
        }


def chosen_pairs(pair, limit=6):
    """Pairs of station 1 and of neighbours first, then the others, at most `limit`."""
    first = [i for i, (j, k) in enumerate(pair) if j == 1 or k == j + 1]
    rest = [i for i in range(len(pair)) if i not in first]
    return (first + rest)[:limit]


def plot(d, out):
    rows = chosen_pairs(d["pair"])
    n = len(rows)
    cols = min(n, 3)
    fig, axes = plt.subplots((n + cols - 1) // cols, cols, figsize=(4.2 * cols, 3.4 * ((n + cols - 1) // cols)),
                             squeeze=False, sharey=True)
    for ax, i in zip(axes.flat, rows):
        j, k = d["pair"][i]
        ax.plot(d["frequency"], d["model"][i], "k-", label="model")
        ax.plot(d["frequency"], d["achieved"][i], "o-", ms=3, color="tab:blue",
                label=f"achieved ({d['count']} motions)")
        ax.set_title(f"stations {j}-{k}, d = {d['separation'][i]:g} m\n"
                     f"lag d/v {d['model_lag'][i]:.4f} s, achieved {d['lag'][i]:.4f} s",
                     fontsize=9)
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylim(0, 1.05)
        ax.grid(alpha=0.3)
    for ax in axes[:, 0]:
        ax.set_ylabel("lagged coherency |gamma| [-]")
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=8, loc="lower left")
    v = d["velocity"]
    fig.suptitle(f"{d['coherency']}\napparent velocity "
                 f"{'inf' if not np.isfinite(v) else f'{v:g} m/s'}; +- {d['half_band']:g} Hz bands",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--motions", required=True, help="motions.h5 of pound motion generate")
    p.add_argument("--out", required=True, help="PNG file to write")
    a = p.parse_args()
    plot(read(a.motions), a.out)


if __name__ == "__main__":
    main()
