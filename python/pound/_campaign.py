"""pound.read_campaign: a campaign result file (``pound campaign``, ``pound merge``) as a pandas
DataFrame. The schema is docs/campaign.md's (src/campaign/result_file.hpp); the file is read with
h5py, the engine is not involved."""

import os
import re

import numpy as np

from ._engine import Error

# Per building and floor ([samples, buildings, floors]): a building's value is the largest over
# its floors, but for the energies, which add up over its storeys.
_SUMMED = ("hysteretic_energy_",)
# Per pair and level ([samples, pairs, levels]): the impacts add up over the levels, the rest
# is the largest.
_PAIR_DATASETS = ("peak_force", "impacts", "approach_free")
_PAIR_SUMMED = ("impacts",)


def _text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.dtype.kind in "OS":
        return [_text(v) for v in value.tolist()]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _reduce(values, summed):
    """Over the last axis: nansum or nanmax, NaN where every value is NaN."""
    values = np.asarray(values, dtype=float)
    nan = np.isnan(values)
    if summed:
        out = np.where(nan, 0.0, values).sum(axis=-1)
    else:
        out = np.where(nan, -np.inf, values).max(axis=-1)
    out[np.all(nan, axis=-1)] = np.nan
    return out


def _floor_counts(study_text, buildings):
    """Floors of each building from the resolved study (building<b>.masses), else None."""
    counts = []
    for b in range(1, buildings + 1):
        m = re.search(rf"^building{b}\.masses\s*=\s*(.+)$", study_text or "", re.M)
        if not m:
            return None
        counts.append(len([x for x in re.split(r"[,\s]+", m.group(1).strip()) if x]))
    return counts


def _response_columns(group, attrs, floors):
    """The /response datasets as columns (see read_campaign)."""
    cols = {}
    counts = None
    buildings = len(str(attrs.get("building_names", "")).split(","))
    for name, ds in group.items():
        data = ds[()]
        if data.ndim < 2:
            continue
        # A dataset of a pair has one column fewer than there are buildings.
        per_building = name not in _PAIR_DATASETS and data.shape[1] == buildings
        label = "building" if per_building else "pair"
        if data.ndim == 2:  # one value per building or pair (collapse, ...)
            for b in range(data.shape[1]):
                cols[f"{label}{b + 1}.{name}"] = data[:, b]
            continue
        if data.ndim != 3:
            continue
        summed = name.startswith(_SUMMED) if per_building else name in _PAIR_SUMMED
        if per_building and counts is None:
            counts = _floor_counts(attrs.get("study"), data.shape[1])
            counts = counts or [data.shape[2]] * data.shape[1]
        for b in range(data.shape[1]):
            n = counts[b] if per_building else data.shape[2]
            cols[f"{label}{b + 1}.{name}"] = _reduce(data[:, b, :n], summed)
            if floors:
                part = "floor" if per_building else "level"
                for j in range(n):
                    cols[f"{label}{b + 1}.{part}{j + 1}.{name}"] = data[:, b, j]
    return cols


def read_campaign(path, floors=False):
    """A campaign result file as a pandas DataFrame, one row per sample (index: the sample id).

    Columns: status (0 ok, 1 numerical failure, 2 input failure), message, im (the scaled
    motion's intensity measure, m/s2), scale, stripe (0-based: sample id mod the number of
    levels, when the campaign has intensity levels), every sampled parameter by its study key
    (e, gap, k_factor, building1.mass_scale, model, ...), and per building b and run (pounding,
    free) its peak demands: building<b>.peak_disp_<run> (m), .peak_drift_<run> (drift ratio),
    .peak_accel_<run> (m/s2), .residual_drift_<run>, .ductility_<run>: the largest over the
    building's floors; .hysteretic_energy_<run> (J): the sum over its storeys; per pair p:
    pair<p>.peak_force (N) and pair<p>.approach_free (m), the largest over the levels, and
    pair<p>.impacts, their sum. Datasets of one value per building (such as
    /response/collapsed_pounding, where the file has it) become building<b>.<name> as stored.
    NaN where a sample failed.

    floors: also one column per floor (building<b>.floor<j>.<name>) and level
    (pair<p>.level<l>.<name>).

    The file's root attributes (study, seed, samples, intensity_measure, im_levels_mps2,
    building_names, engine_version, git_revision, ...) are in DataFrame.attrs. Raises
    pound.Error when the file cannot be read or is not a campaign result file.
    """
    import h5py
    import pandas as pd

    path = os.fspath(path)
    try:
        f = h5py.File(path, "r")
    except (OSError, ValueError) as e:
        raise Error(f"{path}: cannot open the campaign file ({e}); give a result file of "
                    "pound campaign or pound merge") from None
    with f:
        if "samples/id" not in f or "response" not in f:
            raise Error(f"{path}: not a campaign result file (no /samples/id or /response); "
                        "give a result file of pound campaign or pound merge")
        attrs = {k: _text(v) for k, v in f.attrs.items()}
        samples = f["samples"]
        ids = samples["id"][()]
        cols = {}
        for name in ("status", "message", "im", "scale"):
            if name in samples:
                cols[name] = _text(samples[name][()]) if name == "message" else samples[name][()]
        levels = [x for x in str(attrs.get("im_levels_mps2", "")).split(",") if x.strip()]
        if levels:
            cols["stripe"] = ids % len(levels)
        for name, ds in samples.items():
            if name not in ("id", "status", "message", "im", "scale"):
                data = ds[()]
                cols[name] = _text(data) if data.dtype.kind in "OS" else data
        cols.update(_response_columns(f["response"], attrs, floors))
    df = pd.DataFrame(cols, index=pd.Index(ids, name="id"))
    df.attrs.update(attrs)
    return df
