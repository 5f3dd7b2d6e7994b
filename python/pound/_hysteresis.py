"""pound.hysteresis: the storey-law tester ``pound hysteresis`` on an array of drifts."""

import numpy as np

from . import _engine
from ._options import Keys, arguments

_KEYS = Keys(_engine.hysteresis_keys())
_REFUSED = {
    "drifts": "give the drifts as the second argument",
    "json": "the shears are returned",
}


def hysteresis(law, drifts, **keys):
    """The shears [N] of one storey driven from rest through a drift history [m].

    Every drift is reached from the one before (from 0 for the first) along one monotone path
    by the law's incremental form, as ``pound hysteresis --law LAW --drifts FILE`` does.

    law: "elastic", "bilinear", "bouc-wen" or "imk".
    drifts: storey drifts in m (a sequence or a 1-D array).
    keys: k0 (N/m, required), fy (N, required by the inelastic laws), height (m, default 3) and
        the law's keys as in a study: hardening, bw_n, cap_strength_ratio, plastic_drift_ratio,
        post_cap_drift_ratio, ultimate_drift_ratio, residual_strength_ratio, energy_capacity,
        energy_exponent (docs/hysteresis.md).

    Returns a numpy array of the shears, one per drift. Raises pound.Error on bad input.
    """
    args = arguments(_KEYS, None, keys, _REFUSED)
    return _engine.hysteresis([f"--law={law}"] + args, np.asarray(drifts, dtype=float))
