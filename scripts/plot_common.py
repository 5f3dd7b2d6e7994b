"""Helpers shared by the figure scripts (plot_results.py, plot_collapse.py): the package pound
(which reads the campaign files and holds g and the lognormal CDF), names, saving."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The package pound: from PYTHONPATH when it names one, else this tree's build (build/python,
# docs/python.md; the scripts run as `/usr/bin/python3 scripts/plot_results.py ...`), else an
# installed one. sys.path holds the script's folder, then PYTHONPATH's, then the installed ones.
_BUILD = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                                       "python"))
if os.path.isdir(os.path.join(_BUILD, "pound")):
    sys.path.insert(1 + len([p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]),
                    _BUILD)
try:
    import pound  # noqa: E402
except ImportError as e:
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: cannot import the Python package pound "
             f"({e}); build it (cmake --preset release && cmake --build --preset release makes "
             "build/python/pound) or put it on PYTHONPATH")

G = pound.G  # m/s^2 per g
lognormal_cdf = pound.lognormal_cdf  # P(X <= x) of a lognormal with median theta and beta


def text(attr):
    return attr.decode() if isinstance(attr, bytes) else str(attr)


def im_name(measure):
    return "Sa(T1)" if measure == "sa" else "PGA"


def building_names(f):
    """The building names of a campaign (pound.open_campaign) or of an HDF5 object's attribute
    building_names (fragility.h5's /fragility): a list, possibly short."""
    if isinstance(f, pound.CampaignFile):
        return f.building_names
    return [n.strip() for n in text(f.attrs.get("building_names", "")).split(",")]


def building_name(names, b):
    return names[b] if b < len(names) and names[b] else f"building {b + 1}"


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    print(path)
