"""Helpers shared by the figure scripts (plot_results.py, plot_collapse.py): units, names, saving."""
import os
from math import erf, log, sqrt

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

G = 9.80665  # m/s^2 per g


def text(attr):
    return attr.decode() if isinstance(attr, bytes) else str(attr)


def im_name(measure):
    return "Sa(T1)" if measure == "sa" else "PGA"


def building_names(f):
    """The building names of a campaign file's root attribute (a list, possibly short)."""
    return [n.strip() for n in text(f.attrs.get("building_names", "")).split(",")]


def building_name(names, b):
    return names[b] if b < len(names) and names[b] else f"building {b + 1}"


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    print(path)


def lognormal_cdf(x, theta, beta):
    """P(X <= x) of a lognormal with median theta and log standard deviation beta."""
    return np.array([0.5 * (1 + erf(log(v / theta) / (beta * sqrt(2)))) for v in x])
