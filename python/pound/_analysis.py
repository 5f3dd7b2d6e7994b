"""pound.fragility and pound.risk: the commands ``pound fragility --json`` and ``pound risk
--json`` on a campaign result file, as function calls (docs/python.md, "Fragility and risk");
pound.lognormal_cdf, the form of their curves."""

import json
import os

from . import _engine
from ._options import Keys, arguments

_FRAGILITY_KEYS = Keys(_engine.fragility_keys())
_RISK_KEYS = Keys(_engine.risk_keys())
_REFUSED = {
    "input": "give the campaign file as the first argument",
    "json": "the result is returned",
    "help": "see help(pound.fragility), help(pound.risk) and the commands' --help",
    "out": "give the output folder as out=",
}


def lognormal_cdf(x, theta, beta):
    """P(X <= x) of a lognormal with median theta and logarithmic standard deviation beta:
    Phi(ln(x / theta) / beta), the fragility curves' form (theta and beta as pound fragility
    and pound risk give them; x in theta's unit). An array for an array, a float for a float.
    Needs scipy (Debian: python3-scipy)."""
    from scipy.stats import lognorm
    return lognorm.cdf(x, beta, scale=theta)


def _run(call, keys, extra, out, options):
    args = [f"--{k}={os.fspath(v)}" for k, v in extra.items()]
    if out is not None:
        args.append(f"--out={os.fspath(out)}")
    args += arguments(keys, None, options, _REFUSED)
    return json.loads(call(args, out is not None))


def fragility(campaign, out=None, **options):
    """Lognormal fragility curves with and without pounding from a campaign result file.

    Returns what ``pound fragility --input CAMPAIGN --json`` prints, parsed: "shift" (per
    building, EDP and limit the ratio of the median capacities with and without pounding, its
    90 % bootstrap band, both medians and whether the free one is fitted on the pounding
    curve's analyses), "curves" (theta [m/s2 of the intensity measure], beta, bands, counts,
    per contact model too where the study samples it), "sensitivity", "collapse", "models", ...
    (docs/fragility.md), number for number.

    campaign: the result file of ``pound campaign`` or ``pound merge``.
    out: a folder for the command's files (curves.csv, shift.csv, observations.csv,
        sensitivity.csv, fragility.h5; listed under "files"); None writes nothing.
    options: the command's options: drift_limits=[0.01, 0.02] (ratios), disp_limits (m),
        accel_limits (m/s2), force_limits (N), residual_drift_limits, ductility_limits,
        replicates=1000, seed=1; by default the limits of the study's [fragility] section.

    Raises pound.Error (a ValueError) on bad input, with the line the command prints after
    "pound fragility: error: ". Keeps the GIL (it reads HDF5, which is not thread-safe).
    """
    return _run(_engine.fragility, _FRAGILITY_KEYS, {"input": campaign}, out, options)


def risk(campaign, hazard, out=None, **options):
    """Pounding risk at every gap, the code rules, damage limits and collapse from a campaign
    result file and a site's hazard curve.

    Returns what ``pound risk --input CAMPAIGN --hazard HAZARD --json`` prints, parsed: per pair
    the gaps [m], the mean annual frequency [1/yr] and probability in T years of pounding at
    each, the gap for the target with its band, the code rules; "damage" (per building and
    limit the yearly rate with and without pounding and their ratio), "collapse" (rates,
    probabilities in T years, collapse margin ratios with design_im), "notes" (docs/risk.md).

    campaign: the result file of ``pound campaign`` or ``pound merge``.
    hazard: the hazard curve CSV (header 'pga [g], annual_rate [1/yr]', then points).
    out: a folder for the command's files (risk_gaps.csv, code_rules.csv, damage_maf.csv,
        risk.h5; listed under "files"); None writes nothing.
    options: the command's options: gaps=[...] (m), years=50, target_probability=0.02,
        design_im (g), replicates=1000, seed=1.

    Raises pound.Error on bad input. Keeps the GIL (it reads HDF5).
    """
    return _run(_engine.risk, _RISK_KEYS, {"input": campaign, "hazard": hazard}, out, options)
