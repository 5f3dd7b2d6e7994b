"""Collapse figures of a pound campaign (issue 23), drawn by plot_results.py:

  collapse_fragility.png          (--fragility, CSV files of 'pound fragility' with collapse
                                  rows) P(collapse | IM) with and without pounding, one panel per
                                  building: the fitted lognormal curves (theta_mps2, beta of
                                  curves.csv) and the observed fractions per stripe or IM bin
                                  (observations.csv); skipped, with a note, when the CSV files
                                  have no collapse rows (a pound fragility before issue 23)
  collapse_fragility_<model>.png  the same for each contact model where curves.csv has rows of
                                  that model (column model; 'all' is the pooled curve), the
                                  pooled curves in grey for reference
  ida_<building>.png              the peak storey drift ratio (largest over the storeys) of every
                                  successful sample against its intensity, with and without
                                  pounding side by side, coloured by contact model where the
                                  study samples it; collapsed samples (/response/collapsed_*) as
                                  crosses in a row at the top, and in the pounding run, the
                                  buildings still standing when the other collapsed (the run
                                  stops there) as open circles; a file without the collapse
                                  arrays has no marks
"""
import csv
import os
import re
import warnings

import matplotlib.pyplot as plt
import matplotlib.ticker as ticker
import numpy as np

from plot_common import G, building_name, building_names, im_name, lognormal_cdf, pound, save


def read_csv(path):
    """The rows of a CSV file as dicts; [] when there is no such file."""
    if not os.path.isfile(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(field):
    """A CSV number; NaN for an empty field (no finite estimate) or anything else."""
    try:
        return float(field)
    except (TypeError, ValueError):
        return float("nan")


def model_of(row):
    """The model column of a row; 'all' (pooled) for CSV files written before it existed."""
    return (row.get("model") or "all").strip() or "all"


def log_axis(ax, which="x"):
    """A logarithmic axis ("x" or "y") labelled with plain numbers."""
    getattr(ax, f"set_{which}scale")("log")
    axis = ax.xaxis if which == "x" else ax.yaxis
    axis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    axis.set_minor_formatter(ticker.FuncFormatter(
        lambda x, _: f"{x:g}" if f"{x:.0e}"[0] in "235" else ""))


def same_analyses_fit(shifts, building, edp, limit, model):
    """(theta [g], beta) of the free runs of the analyses the pounding curve keeps, when a
    neighbour's collapse censored some of them (shift.csv's free_same_analyses = 1), else None."""
    for s in shifts:
        if (int(s["building"]) == building and s["edp"] == edp and model_of(s) == model
                and abs(number(s["limit"]) - limit) <= 1e-12 * max(1.0, abs(limit))
                and s.get("free_same_analyses") == "1"):
            th, be = number(s.get("theta_free_mps2")) / G, number(s.get("beta_free"))
            if np.isfinite(th) and np.isfinite(be) and th > 0 and be > 0:
                return th, be
    return None


def fragility_panel(ax, curves, obs, pooled, xs, same=None):
    """One building: the curves with (solid, red) and without (dashed, blue) pounding, their
    observed fractions, and the pooled curves in grey when this is a model's panel; `same`,
    (theta, beta) of the free runs of the pounding curve's analyses (dotted blue), where a
    neighbour's collapse censored some: the curve to compare the pounding one with."""
    for r in pooled:
        th, be = number(r["theta_mps2"]) / G, number(r["beta"])
        if np.isfinite(th) and np.isfinite(be) and th > 0 and be > 0:
            ax.plot(xs, lognormal_cdf(xs, th, be), "-" if r["pounding"] == "true" else "--",
                    color="0.6", lw=1.0)
    if pooled:
        ax.plot([], [], "-", color="0.6", lw=1.0, label="all samples (fit)")
    for pounding, color, style in ((True, "tab:red", "-"), (False, "tab:blue", "--")):
        case = "with pounding" if pounding else "without pounding"
        for r in (r for r in curves if (r["pounding"] == "true") == pounding):
            th, be = number(r["theta_mps2"]) / G, number(r["beta"])
            if r.get("status") == "ok" and np.isfinite(th) and np.isfinite(be) and th > 0 and be > 0:
                ax.plot(xs, lognormal_cdf(xs, th, be), style, color=color, lw=1.8,
                        label=f"{case}: θ = {th:.3g} g, β = {be:.2f}")
            else:
                ax.plot([], [], style, color=color, lw=1.0,
                        label=f"{case}: no estimate ({r.get('status', '?').replace('_', ' ')})")
        if not pounding and same is not None:
            ax.plot(xs, lognormal_cdf(xs, *same), ":", color=color, lw=1.8,
                    label=f"without, the pounding curve's analyses: θ = {same[0]:.3g} g, "
                          f"β = {same[1]:.2f}")
        key = "exceed_pounding" if pounding else "exceed_free"
        # The free runs' own count (n_free; a file before it had the pounding count only).
        n_key = "n" if pounding or not obs or "n_free" not in obs[0] else "n_free"
        pts = [(number(o["im_mps2"]) / G, number(o[key]) / number(o[n_key])) for o in obs
               if number(o[n_key]) > 0 and o.get(key, "") != ""]
        if pts:
            x, y = zip(*pts)
            ax.plot(x, y, "o" if pounding else "s", color=color, ms=5, ls="none",
                    mfc=color if pounding else "none", mew=1.2, label=f"observed, {case}")


def plot_collapse_fragility(frag_dir, out, measure):
    """collapse_fragility.png and one per contact model, from curves.csv and observations.csv."""
    path = os.path.join(frag_dir, "curves.csv")
    rows = [r for r in read_csv(path) if r.get("edp") == "collapse"]
    if not rows:
        print(f"plot_results.py: note: {path} has no collapse rows (a pound fragility without the "
              "collapse limit): no collapse_fragility.png")
        return
    obs_path = os.path.join(frag_dir, "observations.csv")
    observed = [o for o in read_csv(obs_path) if o.get("edp") == "collapse"]
    design = "IM bins" if observed and "bin" in observed[0] else "stripes"
    shifts = read_csv(os.path.join(frag_dir, "shift.csv"))
    models = ["all"] + sorted({model_of(r) for r in rows} - {"all"})
    buildings = sorted({int(r["building"]) for r in rows})
    names = {int(r["building"]): r.get("building_name", "") for r in rows}
    ims = [number(o["im_mps2"]) / G for o in observed if number(o["im_mps2"]) > 0]
    lo, hi = (min(ims) / 1.6, max(ims) * 1.6) if ims else (0.01, 10.0)
    xs = np.exp(np.linspace(np.log(lo), np.log(hi), 200))
    for m in models:
        mine = [r for r in rows if model_of(r) == m]
        if not mine:
            continue
        fig, axes = plt.subplots(1, len(buildings), figsize=(5.6 * len(buildings), 4.4),
                                 squeeze=False, sharey=True)
        for ax, b in zip(axes[0], buildings):
            fragility_panel(ax, [r for r in mine if int(r["building"]) == b],
                            [o for o in observed if int(o["building"]) == b and model_of(o) == m],
                            [] if m == "all" else
                            [r for r in rows if int(r["building"]) == b and model_of(r) == "all"],
                            xs, same_analyses_fit(shifts, b, "collapse", 1.0, m))
            log_axis(ax)
            ax.set_xlim(lo, hi)
            ax.set_ylim(-0.02, 1.02)
            ax.set_xlabel(f"{im_name(measure)} [g]")
            ax.set_title(f"{names[b] or f'building {b + 1}'}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7.5, loc="upper left")
        axes[0][0].set_ylabel("P(collapse | IM) [-]")
        who = "all samples" if m == "all" else f"contact model {m}"
        fig.suptitle(f"Collapse fragility with and without pounding ({who}): lognormal fits and "
                     f"observed fractions per {design[:-1]}", fontsize=11)
        fig.tight_layout()
        save(fig, out, "collapse_fragility.png" if m == "all" else
             f"collapse_fragility_{re.sub(r'[^A-Za-z0-9_.-]', '_', m)}.png")


def peak_over_floors(a):
    """Largest finite value over the last axis; NaN where there is none."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return np.nanmax(a, axis=-1)


def read_ida(campaign_path):
    with pound.open_campaign(campaign_path) as c:
        ok = c.ok
        limit = c.study_value("simulation.collapse_drift_ratio")  # [simulation] of the study
        d = {"measure": c.intensity_measure,
             "names": building_names(c),
             "limit": float(limit) if limit else None,
             "stripes": len(c.im_levels) > 0,
             "im": c.im[ok] / G,
             "stripe": (c.stripes if c.stripes is not None else np.zeros_like(c.ids))[ok]}
        for case in ("pounding", "free"):
            d[case] = peak_over_floors(c.response(f"peak_drift_ratio_{case}")[ok])
            collapsed = c.response(f"collapsed_{case}")
            d[f"collapsed_{case}"] = collapsed[ok] > 0.5 if collapsed is not None else None
        model = c.parameters.get("model")
        d["model"] = np.array(list(model), dtype=str)[ok] if model is not None else None
    return d


def ida_panel(ax, d, b, case, colors, top, jitter):
    """One building and one run: standing samples as dots, collapsed ones as crosses at `top`,
    and the median peak drift per stripe and model (collapsed samples above every other)."""
    drift = 100 * d[case][:, b]
    gone = d[f"collapsed_{case}"][:, b] if d[f"collapsed_{case}"] is not None else None
    # In the pounding run, a building standing when the other one collapsed: the run stopped.
    stopped = None
    if case == "pounding" and gone is not None:
        stopped = ~gone & d["collapsed_pounding"].any(axis=1)
    x = d["im"] * jitter
    for label, color in colors.items():
        sel = np.ones(len(x), bool) if label == "" else d["model"] == label
        stand = sel & (~gone if gone is not None else True)
        tag = f" ({label})" if label else ""
        def named(mask, name):  # a legend entry only for marks that are drawn
            return name if np.any(mask) else None

        if stopped is not None:
            ax.scatter(x[stand & ~stopped], drift[stand & ~stopped], s=9, color=color, lw=0,
                       alpha=0.6, label=named(stand & ~stopped, f"standing{tag}"))
            ax.scatter(x[stand & stopped], drift[stand & stopped], s=16, facecolors="none",
                       edgecolors=color, lw=0.9,
                       label=named(stand & stopped, f"standing when the other collapsed{tag}"))
        else:
            ax.scatter(x[stand], drift[stand], s=9, color=color, lw=0, alpha=0.6,
                       label=named(stand, f"standing{tag}" if gone is not None else label))
        if gone is not None:
            ax.scatter(x[sel & gone], np.full(int((sel & gone).sum()), top), marker="x", s=22,
                       color=color, lw=1.1, label=named(sel & gone, f"collapsed{tag}"))
        if d["stripes"]:
            med_x, med_y = [], []
            for j in np.unique(d["stripe"][sel]):
                s = sel & (d["stripe"] == j)
                y = np.where(gone[s], np.inf, drift[s]) if gone is not None else drift[s]
                y = y[~np.isnan(y)]
                if y.size:
                    med_x.append(np.exp(np.mean(np.log(d["im"][s]))))
                    med_y.append(np.median(y))
            med_y = np.array(med_y)
            ax.plot(np.array(med_x)[np.isfinite(med_y)], med_y[np.isfinite(med_y)], "-",
                    color=color, lw=1.6, label=f"median per stripe{tag}")
    if gone is not None:
        ax.axhline(top, color="k", lw=0.6, ls=":")
        n = int(gone.sum())
        ax.set_title(f"{'with' if case == 'pounding' else 'without'} pounding: {n} of "
                     f"{len(gone)} collapsed", fontsize=10)
    else:
        ax.set_title(f"{'with' if case == 'pounding' else 'without'} pounding", fontsize=10)


def plot_ida(campaign_path, out):
    """ida_<building>.png: peak storey drift ratio against the intensity, collapses marked."""
    d = read_ida(campaign_path)
    if not d["im"].size:
        return
    labels = sorted(set(d["model"])) if d["model"] is not None else [""]
    colors = {label: plt.cm.tab10(i % 10) for i, label in enumerate(labels)}
    # Stripes put every sample of a stripe at one IM: spread them a little (+-4 %), the same
    # spread in both panels, so that the dots can be told apart.
    jitter = (np.exp(np.random.default_rng(0).uniform(-0.04, 0.04, d["im"].size))
              if d["stripes"] else np.ones(d["im"].size))
    for b in range(d["pounding"].shape[1]):
        drift = 100 * np.concatenate([d["pounding"][:, b], d["free"][:, b]])
        drift = drift[np.isfinite(drift) & (drift > 0)]
        if not drift.size:
            continue
        limit = 100 * d["limit"] if d["limit"] else None
        top = 1.8 * max(np.max(drift), limit or 0)
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
        for ax, case in zip(axes, ("pounding", "free")):
            ida_panel(ax, d, b, case, colors, top, jitter)
            log_axis(ax)
            log_axis(ax, "y")
            ax.set_ylim(max(np.min(drift) / 1.5, top / 1e4), top * 1.5)
            if limit:
                ax.axhline(limit, color="tab:red", lw=0.9, ls="--",
                           label=f"collapse drift ratio {limit:g} %")
            if d["collapsed_pounding"] is not None:
                ax.text(1.0, top, " collapsed", transform=ax.get_yaxis_transform(),
                        va="center", ha="left", fontsize=8)
            ax.set_xlabel(f"{im_name(d['measure'])} [g]" + (" (dots spread ±4 % about their "
                                                            "stripe)" if d["stripes"] else ""))
            ax.grid(True, which="both", alpha=0.3)
        axes[0].set_ylabel("peak storey drift ratio, largest over the storeys [%]")
        fig.suptitle(f"{building_name(d['names'], b)}: peak storey drift against the intensity "
                     "(IDA-style, every successful sample)", fontsize=11)
        fig.tight_layout()
        handles, names = axes[0].get_legend_handles_labels()
        if handles:
            fig.legend(handles, names, fontsize=8, loc="center left", bbox_to_anchor=(1.0, 0.5),
                       frameon=False,
                       title="median per stripe: a collapsed\nsample above every other"
                       if d["stripes"] and d["collapsed_pounding"] is not None else None,
                       title_fontsize=8)
        save(fig, out, f"ida_{b}.png")
