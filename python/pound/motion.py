"""pound.motion: ground motions (docs/python.md, docs/motions.md).

Reading records, response spectra of arrays, design spectra and spectrum-compatible motions,
with the options, checks and numbers of ``pound motion spectrum|target|generate``. Arrays are
numpy arrays in SI units (s, m, m/s, m/s2); keys as the commands' (``ec8_type`` or
``**{"ec8-type": 1}`` is ``--ec8-type``).
"""

import os
from typing import NamedTuple

import numpy as np

from . import _engine
from ._options import Keys, arguments

_RECORD_KEYS = Keys(_engine.record_keys())
_TARGET_KEYS = Keys(_engine.target_keys())
_GENERATE_KEYS = Keys(_engine.generate_keys())
# `pound motion spectrum`'s keys that read and process a record file: response_spectrum takes
# the record as (dt, ag) and would otherwise leave them without effect.
_PROCESSED = ("the record is given as (dt, ag), already read: pound.motion.read_record(path, "
              "scale=..., truncate=..., baseline=...) reads and processes a file")
_SPECTRUM_REFUSED = {k: _PROCESSED for k in ("input", "format", "units", "dt", "truncate",
                                             "scale", "baseline")}
_SPECTRUM_REFUSED.update({"accept-any-pga": "use check_pga=False",
                          "json": "the result is returned"})


class Record(NamedTuple):
    """A ground-acceleration record: the motion=(dt, ag) of pound.simulate."""

    dt: float  #: sample spacing [s]
    accel: np.ndarray  #: ground acceleration at t = i dt [m/s2]


def read_record(path, format=None, units=None, dt=None, check_pga=True, truncate=None,
                scale=None, baseline=False):
    """Reads a record file: PEER .AT2, one or two columns, or fixed width (El Centro).

    format: "automatic" (default), "at2", "columns" or "fixed-width".
    units: "g", "m/s2" or "cm/s2" when the file does not state them (never guessed).
    dt: sample spacing [s] of a one-column file without a "# dt:" header.
    check_pga: refuse a peak above 10 g or below 1e-6 g (wrong units or values).
    truncate: keep only the first seconds [s]; scale: a factor; baseline: baseline-correct.

    Returns a Record (dt [s], accel [m/s2]), a pair that pound.simulate takes as motion=.
    Raises pound.Error naming the file and line.
    """
    keys = {"input": os.fspath(path), "format": format, "units": units, "dt": dt,
            "truncate": truncate, "scale": scale, "baseline": None}
    args = arguments(_RECORD_KEYS, None, keys)
    if not check_pga:
        args.append("--accept-any-pga")
    if baseline:
        args.append("--baseline")
    rec_dt, accel, _ = _engine.read_record(args, "check_pga=False")
    return Record(rec_dt, accel)


def response_spectrum(motion, periods=None, damping=None, substep=None, check_pga=True, **keys):
    """Elastic response spectra of a record by the exact piecewise-linear recurrence (Nigam &
    Jennings 1969), as ``pound motion spectrum``.

    motion: (dt, ag): sample spacing [s] and ground acceleration [m/s2] (a Record is one).
    periods: periods [s] (>= 0; T = 0 gives the peak ground acceleration); default 100
        log-spaced from t_min = 0.05 to t_max = 4 s (keys t_min, t_max, n_periods).
    damping: damping ratio in [0, 1), default 0.05.
    substep: largest step at which peaks are looked for, as a fraction of T (default 0.05; 0:
        at the samples only).
    check_pga: refuse a peak above 10 g or below 1e-6 g.

    Returns a dict of arrays: period_s, sd_m, psv_mps, psa_mps2, sa_abs_mps2, and damping.
    """
    dt, accel = motion[0], motion[1]
    keys = dict(keys, periods=periods, damping=damping, substep=substep)
    args = arguments(_RECORD_KEYS, None, keys, _SPECTRUM_REFUSED)
    if not check_pga:
        args.append("--accept-any-pga")
    return _engine.response_spectrum(args, float(dt), np.asarray(accel, dtype=float), "motion",
                                     "check_pga=False")


def design_spectrum(periods=None, **keys):
    """A design spectrum at a list of periods, as ``pound motion target``.

    keys: spectrum ("ec8", "nzs1170", "asce7", "japan", "table") and its parameters, e.g.
        spectrum="ec8", ec8_type=1, ground_type="C", ag=0.3 (g), damping; t_min, t_max,
        n_periods for the default periods (``pound motion target --help``).
    periods: periods [s]; default 100 log-spaced from 0.05 to 4 s.

    Returns a dict: period_s, psa_mps2 (= sa_abs_mps2, the spectrum's pseudo-acceleration),
    sd_m = Sa / w^2, psv_mps = Sa / w, damping, and "spectrum", the line describing it.
    """
    return _engine.design_spectrum(arguments(_TARGET_KEYS, None, dict(keys, periods=periods)))


def generate(**keys):
    """Spectrum-compatible motions (SIMQKE, Gasparini & Vanmarcke 1976), as ``pound motion
    generate`` without its files: the same motions, number for number.

    keys: the design spectrum's (spectrum="ec8", ec8_type=1, ground_type="C", ag=0.3, ...),
        count (1), duration (20 s), dt (0.01 s), seed (1: motion i is drawn from (seed, i)),
        envelope ("jennings" or "saragoni-hart") and its keys, t_min, t_max, n_periods (the
        matching periods), max_iterations; record-to-record variability: variability="spectral"
        with sigma_lnsa, sigma_table or sigma_model and correlation (docs/motions.md).

    Returns a dict: time_s [n], accel_mps2 [count, n], period_s [p] (report periods),
    design_psa_mps2 [p], target_psa_mps2 [count, p] (each motion's own target), psa_mps2
    [count, p], mean_psa_mps2, geomean_psa_mps2 [p], epsilon [count, p] and sigma_lnsa [p] (with
    variability, else None), pga_mps2, final_velocity_mps, final_displacement_m, min_ratio,
    max_ratio, mean_ratio (against each own target), iterations, phase_set [count], dt_s,
    spectrum and variability (descriptions).
    """
    refused = {"out": "the motions are returned, no files written", "json": "a dict is returned"}
    return _engine.generate(arguments(_GENERATE_KEYS, None, keys, refused))


def log_spaced_periods(t_min=0.05, t_max=4.0, n=100):
    """n periods [s] evenly spaced in log T from t_min to t_max, both included."""
    return _engine.log_spaced_periods(float(t_min), float(t_max), int(n))
