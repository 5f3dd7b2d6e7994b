"""pound.simulate and pound.impact: the commands ``pound simulate --json`` and ``pound impact
--json`` as function calls (docs/python.md)."""

import json
import os
import warnings

import numpy as np

from . import _engine
from ._options import Keys, arguments

_SIMULATE_KEYS = Keys(_engine.simulate_keys())
_IMPACT_KEYS = Keys(_engine.impact_keys())
_SIMULATE_REFUSED = {
    "json": "the result is returned",
    "histories": "histories=True returns the time histories as arrays",
    "config": "give the study file as the first argument",
    "help": "see help(pound.simulate) and pound simulate --help",
}
_IMPACT_REFUSED = {
    "json": "the result is returned",
    "config": "give the file as config=",
    "help": "see help(pound.impact) and pound impact --help",
}
# How a message about an implausible peak of a given motion says to accept it.
_CHECK_PGA_KEY = "motion__check_pga=False (or [motion] check_pga = false in the study)"


class UnusedKeyWarning(UserWarning):
    """A given key that the chosen contact model does not read (``pound simulate``'s note)."""


def _motion_arrays(motion):
    try:
        dt, accel = motion
    except (TypeError, ValueError):
        raise TypeError("motion: give (dt, ag): the sample spacing in s and the ground "
                        "acceleration in m/s2 (a pound.motion.Record is one)") from None
    return float(dt), np.asarray(accel, dtype=float)


def _simulate(study, motion, histories, overrides):
    """The engine's answer: (result dict, notes, timing)."""
    args = arguments(_SIMULATE_KEYS, study, overrides, _SIMULATE_REFUSED)
    dt, accel = _motion_arrays(motion) if motion is not None else (None, None)
    text, notes, hist, timing = _engine.simulate(args, dt, accel, bool(histories), "motion",
                                                 _CHECK_PGA_KEY)
    result = json.loads(text)
    if hist is not None:
        result["histories"] = hist
    return result, notes, timing


def simulate(study, motion=None, histories=False, **overrides):
    """Simulates a row of buildings under a ground motion, with and without pounding.

    Returns what ``pound simulate --config STUDY --json`` prints, parsed (a dict: "buildings"
    with per floor the peaks with and without pounding, "contacts", "energy_pounding", ...; SI
    units, named in the keys: m, m/s2, N, J, s), number for number.

    study: the path of a study file (INI), or a dict of sections, e.g.
        {"building1": {"masses": [48e3] * 3, "stiffnesses": [8.4e7] * 3},
         "building2": {...}, "pair1": {"gap": 0.01}, "motion": {"file": "record.AT2"}};
        relative paths in a dict are taken from the current directory, in a file from the
        file's folder (as the command does).
    motion: (dt, ag) to use instead of the study's record: the sample spacing [s] and the ground
        acceleration [m/s2] (a numpy array or a list; pound.motion.read_record returns one).
        The study's [motion] keys duration, scale, baseline and check_pga still act on it.
    histories: also return, under "histories", numpy arrays of both runs ("pounding", "free":
        "time" [s], "displacement" [m], "storey_drift" [m], "storey_shear" [N],
        "abs_acceleration" [m/s2] with a column per floor, "contact_force" [N] with a column
        per contact site, "foundation_sway" [m] and "foundation_rotation" [rad] with a column
        per building, 0 on a fixed base), the columns' "dof_building", "dof_floor",
        "site_pair", "site_floor", the "motion" ("time", "acceleration": the study's record)
        and the "ground" under each building ("time" [s], "acceleration" [m/s2] and
        "displacement" [m], a column per building): what ``--histories FILE.h5`` writes.
    overrides: study keys as on the command line, winning over the study: contact__e=0.5 or
        **{"contact.e": 0.5}, building1__hysteresis="imk", dt=1e-5, ...

    Raises pound.Error (a ValueError) on bad input, with the line the command prints after
    "pound simulate: error: ", and pound.NumericalError on a numerical failure. Writes no file.
    Warns (UnusedKeyWarning) about given keys the contact model does not read. Releases the GIL
    while it simulates: threads run simulations in parallel.
    """
    result, notes, _ = _simulate(study, motion, histories, overrides)
    for note in notes:
        warnings.warn(note, UnusedKeyWarning, stacklevel=2)
    return result


def impact(config=None, **keys):
    """Two free bodies (no springs, no ground motion) colliding once through a contact model.

    Returns what ``pound impact --json`` prints, parsed: e_eff, contact_duration_s, impulse_Ns,
    peak_force_N, max_penetration_m, v1_after, v2_after (m/s), contact_phases,
    internal_energy1_J, internal_energy2_J (None for the lumped models).

    config: an options file (e.g. studies/ch7-pendulums.ini), or None.
    keys: the command's options, e.g. model="hc-hertz", e=0.6, k=3.21e9 (N/m or N/m^1.5), m1=109,
        m2=108 (kg), v0=0.2 (m/s), v0_min, rtol, dt; the damped Sears model's length1, E, rho,
        xi_s, chi, contact, ... (``pound impact --help``).

    Raises pound.Error on bad input, pound.NumericalError on a numerical failure.
    """
    args = arguments(_IMPACT_KEYS, os.fspath(config) if config is not None else None, keys,
                     _IMPACT_REFUSED)
    return json.loads(_engine.impact(args))
