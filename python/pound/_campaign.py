"""pound.open_campaign and pound.read_campaign: a campaign result file (``pound campaign``,
``pound merge``) as an object (its samples, sampled parameters, buildings and their floors,
intensity levels, responses and amplification statistics) or as a pandas DataFrame. The schema
is docs/campaign.md's (src/campaign/result_file.hpp); the file is read with h5py, the engine is
not involved. Every script of the repository reads campaign files through this module."""

import os
from functools import cached_property

import numpy as np

from ._engine import Error

# /samples datasets that are not sampled parameters.
_SAMPLE_FIELDS = ("id", "status", "message", "im", "scale")
# Per building and floor ([samples, buildings, floors]): a building's value is the largest over
# its floors, but for the energies, which add up over its storeys.
_SUMMED = ("hysteretic_energy_",)
# Per pair and level ([samples, pairs, levels]): the impacts add up over the levels, the rest
# is the largest.
_PAIR_DATASETS = ("peak_force", "impacts", "approach_free")
_PAIR_SUMMED = ("impacts",)
# Files without the root attribute `floors` (written before 2026-11-26): a building's floors are
# the floor columns of these per-floor datasets with a finite value in some sample (the arrays
# are as wide as the tallest building, NaN beyond a building's floors). The free run gives
# every floor of every successful sample a finite peak displacement.
_FLOOR_EVIDENCE = ("peak_disp_free", "peak_disp_pounding")
# Per-floor datasets renamed since (issue 31, src/campaign/floor_arrays.hpp): their current name
# and the one files written before hold them under. response() reads either.
_FORMER_NAMES = {"peak_drift_ratio_pounding": "peak_drift_pounding",
                 "peak_drift_ratio_free": "peak_drift_free"}
_CURRENT_NAMES = {former: name for name, former in _FORMER_NAMES.items()}
_BLOCK = 65536  # rows read at a time where a whole dataset is not needed


def _text(value):
    """An HDF5 value as Python: bytes decoded, arrays as lists, numpy scalars as numbers."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray):
        return [_text(v) for v in value.tolist()]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _labels(data):
    """A dataset of variable-length strings as an array of str (dtype object)."""
    return np.array([_text(v) for v in data.tolist()], dtype=object)


class Group(dict):
    """An HDF5 group read whole: its datasets (numpy arrays) and subgroups (Group) by name,
    its attributes (decoded) in ``attrs``."""

    def __init__(self, items=(), attrs=None):
        super().__init__(items)
        self.attrs = dict(attrs or {})


def _read_group(g):
    import h5py
    items = {name: (_read_group(obj) if isinstance(obj, h5py.Group) else obj[()])
             for name, obj in g.items()}
    return Group(items, {k: _text(v) for k, v in g.attrs.items()})


class CampaignFile:
    """A campaign result file open for reading (``pound.open_campaign(path)``; a context
    manager: ``with pound.open_campaign(path) as c: ...``). Arrays are numpy arrays in SI units
    (m, m/s2, N, J, s), one row per sample as stored; datasets are read when asked for.

    Samples: ids, status (0 ok, 1 numerical failure, 2 input failure), ok (status == 0),
    messages, im (the scaled motion's intensity measure, m/s2), scale, parameters (every
    sampled parameter by its study key, labels as str), len(c) (rows), sample_count (the
    campaign's samples; a part of a split campaign holds fewer rows).
    Intensity: intensity_measure ("pga" or "sa"), im_levels (the stripes, m/s2; empty for a
    sampled scale factor), stripes (sample id mod the number of levels, or None).
    Buildings: buildings, building_names, floors (one count per building), pairs.
    Study: study (the resolved text), study_value(key).
    Results: response(name) (/response/<name>), amplification (/amplification as a Group, or
    None), datasets(...) and dataset(name) (any dataset as stored).
    attrs: the root attributes, decoded (study, seed, samples, intensity_measure,
    im_levels_mps2, building_names, floors, engine_version, git_revision, ...).

    Raises pound.Error when the file cannot be opened or is not a campaign result file.
    """

    def __init__(self, path):
        import h5py
        self.path = os.fspath(path)
        try:
            self._file = h5py.File(self.path, "r")
        except (OSError, ValueError) as e:
            raise Error(f"{self.path}: cannot open the campaign file ({e}); give a result file "
                        "of pound campaign or pound merge") from None
        if "samples/id" not in self._file or "response" not in self._file:
            self._file.close()
            raise Error(f"{self.path}: not a campaign result file (no /samples/id or /response); "
                        "give a result file of pound campaign or pound merge")
        self.attrs = {k: _text(v) for k, v in self._file.attrs.items()}

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return f"pound.open_campaign({self.path!r})"

    # Samples.
    def __len__(self):
        return len(self._file["samples/id"])

    @cached_property
    def ids(self):
        return self._file["samples/id"][()]

    @cached_property
    def status(self):
        return self._file["samples/status"][()]

    @property
    def ok(self):
        """True for the samples that succeeded (status 0)."""
        return self.status == 0

    @cached_property
    def messages(self):
        return _labels(self._file["samples/message"][()])

    @cached_property
    def im(self):
        return self._file["samples/im"][()]

    @cached_property
    def scale(self):
        return self._file["samples/scale"][()]

    @property
    def sample_count(self):
        return int(self.attrs["samples"])

    @cached_property
    def parameters(self):
        """Every sampled parameter, {study key: array}, in the file's order; labels (model) as
        str."""
        out = {}
        for name, ds in self._file["samples"].items():
            if name not in _SAMPLE_FIELDS:
                data = ds[()]
                out[name] = _labels(data) if data.dtype.kind in "OS" else data
        return out

    # Intensity.
    @property
    def intensity_measure(self):
        return str(self.attrs.get("intensity_measure", "pga"))

    @cached_property
    def im_levels(self):
        """The intensity levels of a multiple-stripe campaign [m/s2]; empty without stripes."""
        text = str(self.attrs.get("im_levels_mps2", ""))
        return np.array([float(x) for x in text.split(",") if x.strip()])

    @property
    def stripes(self):
        """The 0-based stripe of each sample (sample id mod the number of levels), or None for
        a campaign without stripes (a sampled scale factor)."""
        return self.ids % len(self.im_levels) if len(self.im_levels) else None

    # Buildings.
    @cached_property
    def buildings(self):
        r = self._file["response"]
        for name in _FLOOR_EVIDENCE:
            if name in r and r[name].ndim == 3:
                return int(r[name].shape[1])
        return len(str(self.attrs.get("building_names", "")).split(","))

    @property
    def pairs(self):
        return max(0, self.buildings - 1)

    @cached_property
    def building_names(self):
        """One name per building, from the attribute building_names ("a, b"); "building<b>"
        where it gives none (as pound fragility names them)."""
        names = [n.strip() for n in str(self.attrs.get("building_names", "")).split(",")]
        return [names[b] if b < len(names) and names[b] else f"building{b + 1}"
                for b in range(self.buildings)]

    @cached_property
    def floors(self):
        """The number of floors of each building: the root attribute `floors`; for a file
        written before it existed (2026-11-26), the floor columns of /response/peak_disp_free
        (and _pounding) that hold a finite value in some sample. Raises pound.Error when the
        attribute does not fit the file, or when an older file has no successful sample to
        count a building's floors from."""
        width = self._floor_width()
        if "floors" in self.attrs:
            counts = self.attrs["floors"]
            counts = counts if isinstance(counts, list) else [counts]
            if (len(counts) != self.buildings or
                    not all(isinstance(n, int) and 1 <= n <= width for n in counts)):
                raise Error(f"{self.path}: attribute floors = {counts} does not fit the file "
                            f"({self.buildings} buildings of at most {width} floors in "
                            "/response); a damaged file?")
            return counts
        return self._floors_from_data(width)

    def _floor_width(self):
        r = self._file["response"]
        for name in _FLOOR_EVIDENCE:
            if name in r and r[name].ndim == 3:
                return int(r[name].shape[2])
        raise Error(f"{self.path}: no /response/peak_disp_free of shape [samples, buildings, "
                    "floors]; not a campaign result file of pound campaign or pound merge")

    def _floors_from_data(self, width):
        r = self._file["response"]
        seen = np.zeros((self.buildings, width), dtype=bool)
        for name in _FLOOR_EVIDENCE:
            if name in r and r[name].shape[1:] == seen.shape:
                for start in range(0, len(r[name]), _BLOCK):
                    seen |= np.isfinite(r[name][start:start + _BLOCK]).any(axis=0)
        counts = []
        for b in range(self.buildings):
            finite = np.flatnonzero(seen[b])
            if not finite.size:
                raise Error(f"{self.path}: no attribute floors (a file of pound before "
                            "2026-11-26) and no successful sample from which to count the "
                            f"floors of building {b + 1}; run the campaign again with this "
                            "pound")
            counts.append(int(finite[-1]) + 1)
        return counts

    # Study.
    @property
    def study(self):
        """The resolved study text (``key = value`` lines)."""
        return str(self.attrs.get("study", ""))

    def study_value(self, key):
        """The resolved study's value of `key` (``simulation.collapse_drift_ratio``,
        ``fragility.drift_limits``, ...) as text; None when the study does not give it."""
        for line in self.study.splitlines():
            k, sep, v = line.partition("=")
            if sep and k.strip() == key:
                return v.strip()
        return None

    # Results.
    def response(self, name):
        """/response/<name> as stored ([samples, buildings, floors], [samples, buildings] or
        [samples, pairs, levels]; NaN where a building has fewer floors, a pair fewer levels
        or the sample failed); None when the file has no such dataset (collapse arrays before
        issue 23). A dataset renamed since is found under its former name in a file written
        before (peak_drift_ratio_pounding: peak_drift_pounding)."""
        r = self._file["response"]
        if name not in r:
            name = _FORMER_NAMES.get(name, name)
        return r[name][()] if name in r else None

    @property
    def response_names(self):
        """The names of the datasets under /response, by their current names (a dataset that
        a file written before its renaming holds under its former name by its new one)."""
        return [_CURRENT_NAMES.get(name, name) for name in self._file["response"]]

    @cached_property
    def amplification(self):
        """/amplification (docs/campaign.md) read whole: a Group of arrays ("im", "samples",
        "disp": {"median": ...}, ...) with its attributes in .attrs; None when the file has
        none."""
        return _read_group(self._file["amplification"]) if "amplification" in self._file else None

    def datasets(self, groups=("samples", "response", "run")):
        """The paths ("samples/id", ...) of every dataset under these groups, sorted."""
        import h5py
        out = []
        for g in groups:
            if g in self._file:
                self._file[g].visititems(
                    lambda name, obj, g=g: out.append(f"{g}/{name}")
                    if isinstance(obj, h5py.Dataset) else None)
        return sorted(out)

    def dataset(self, path):
        """A dataset by its path in the file ("samples/id"), as stored (bytes undecoded)."""
        return self._file[path][()]

    def to_dataframe(self, floors=False):
        """The campaign as a pandas DataFrame (pound.read_campaign)."""
        import pandas as pd
        cols = {}
        for name in ("status", "message", "im", "scale"):
            if f"samples/{name}" in self._file:
                cols[name] = list(self.messages) if name == "message" else self.dataset(
                    f"samples/{name}")
        if len(self.im_levels):
            cols["stripe"] = self.stripes
        cols.update(self.parameters)
        cols.update(_response_columns(self, floors))
        df = pd.DataFrame(cols, index=pd.Index(self.ids, name="id"))
        df.attrs.update(self.attrs)
        return df


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


def _response_columns(c, floors):
    """The /response datasets as columns (see read_campaign)."""
    cols = {}
    for name in c.response_names:
        data = c.response(name)
        if data.ndim < 2:
            continue
        # A dataset of a pair has one column fewer than there are buildings.
        per_building = name not in _PAIR_DATASETS and data.shape[1] == c.buildings
        label = "building" if per_building else "pair"
        if data.ndim == 2:  # one value per building or pair (collapse, ...)
            for b in range(data.shape[1]):
                cols[f"{label}{b + 1}.{name}"] = data[:, b]
            continue
        if data.ndim != 3:
            continue
        summed = name.startswith(_SUMMED) if per_building else name in _PAIR_SUMMED
        for b in range(data.shape[1]):
            n = c.floors[b] if per_building else data.shape[2]
            cols[f"{label}{b + 1}.{name}"] = _reduce(data[:, b, :n], summed)
            if floors:
                part = "floor" if per_building else "level"
                for j in range(n):
                    cols[f"{label}{b + 1}.{part}{j + 1}.{name}"] = data[:, b, j]
    return cols


def open_campaign(path):
    """A campaign result file (``pound campaign``, ``pound merge``) open for reading: a
    CampaignFile (help(pound.CampaignFile)), best used as a context manager:

        with pound.open_campaign("results/default/campaign.h5") as c:
            c.building_names, c.floors, c.im_levels        # ['5-storey', '3-storey'], [5, 3], ...
            drift = c.response("peak_drift_ratio_pounding")[c.ok]  # [samples, buildings, floors]

    Raises pound.Error when the file cannot be opened or is not a campaign result file.
    """
    return CampaignFile(path)


def read_campaign(path, floors=False):
    """A campaign result file as a pandas DataFrame, one row per sample (index: the sample id).

    Columns: status (0 ok, 1 numerical failure, 2 input failure), message, im (the scaled
    motion's intensity measure, m/s2), scale, stripe (0-based: sample id mod the number of
    levels, when the campaign has intensity levels), every sampled parameter by its study key
    (e, gap, k_factor, building1.mass_scale, model, ...), and per building b and run (pounding,
    free) its peak demands: building<b>.peak_disp_<run> (m), .peak_drift_ratio_<run>,
    .peak_accel_<run> (m/s2), .residual_drift_<run>, .ductility_<run>: the largest over the
    building's floors; .hysteretic_energy_<run> (J): the sum over its storeys; per pair p:
    pair<p>.peak_force (N) and pair<p>.approach_free (m), the largest over the levels, and
    pair<p>.impacts, their sum. Datasets of one value per building (such as
    /response/collapsed_pounding, where the file has it) become building<b>.<name> as stored.
    NaN where a sample failed.

    floors: also one column per floor (building<b>.floor<j>.<name>) and level
    (pair<p>.level<l>.<name>). A building's floors are the file's attribute floors (for older
    files see CampaignFile.floors).

    The file's root attributes (study, seed, samples, intensity_measure, im_levels_mps2,
    building_names, floors, engine_version, git_revision, ...) are in DataFrame.attrs. Raises
    pound.Error when the file cannot be read or is not a campaign result file.
    """
    with CampaignFile(path) as c:
        return c.to_dataframe(floors)
