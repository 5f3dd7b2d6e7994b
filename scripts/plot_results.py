#!/usr/bin/python3
"""Figures of a pound campaign and its fragility analysis (PNG, matplotlib Agg backend).

Run with Debian's python (python3-matplotlib, python3-h5py):

  /usr/bin/python3 scripts/plot_results.py --campaign RUN.h5 --fragility RUN-fragility \
      --out RUN-fragility/plots [--motions motions.h5] [--histories histories.h5] \
      [--risk RUN-risk]
  /usr/bin/python3 scripts/plot_results.py --histories histories.h5 --out plots  (alone)

Figures (one PNG each, units on every axis):
  fragility_<building>_<edp>.png  fitted curves with (solid) and without (dashed) pounding,
                                  90 % bootstrap bands, observed exceedance fractions; where a
                                  neighbour's collapse censored pounding analyses, the free
                                  curve of the same analyses dotted (shift.csv)
  amplification_<building>.png    pounding / free peak displacement and drift against each
                                  sampled parameter, with a running median
  spectra.png                     (--motions, from 'pound motion generate') response spectra of
                                  the generated motions, their mean and the target; motions
                                  with random targets (--variability spectral): median and
                                  16/84 % bands of the targets' and the motions' spectra
                                  against the design spectrum, and the motions scaled to the
                                  design PGA (as PGA stripes scale them)
  history.png                     (--histories, from 'pound simulate --histories') top-floor
                                  displacement of each building and the pounding force, and
                                  on spatially varying ground the ground under each building
  hysteresis.png                  (--histories holding /pounding/storey_shear) shear of the
                                  first storey of each building against its drift, with and
                                  without pounding (skipped when the file has no storey shears)
  amplification_im_<building>.png (campaign files with /amplification) median and 16-84 %
                                  band of the amplification of peak displacement, drift and
                                  acceleration against the intensity, one line per floor
  risk_fragility_pair<p>.png      (--risk, from 'pound risk --out DIR') P(pounding | IM) against
                                  the gap at several intensities: fitted curves and observed
                                  fractions
  risk_probability_pair<p>.png    (--risk) probability of pounding in T years against the gap,
                                  90 % bootstrap band, the target, the gap for it and the code
                                  rules' gaps
  hazard.png                      (--risk) the hazard curve used: its points and the
                                  log-log interpolation, extended beyond the ends (dashed)
  collapse_fragility[_<model>].png  (--fragility) collapse fragility with and without pounding
                                  per building, pooled and per contact model (plot_collapse.py)
  ida_<building>.png              peak storey drift against the intensity of every sample,
                                  collapsed samples marked (plot_collapse.py)
Inputs: the campaign file (schema src/campaign/result_file.hpp, read through the package
pound of build/python: pound.open_campaign), fragility.h5 of 'pound fragility'
(src/fragility/report_files.hpp), risk.h5 of 'pound risk' (src/risk/risk_files.hpp); all are
opened read-only.
"""
import argparse
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402
import numpy as np  # noqa: E402

from plot_collapse import (plot_collapse_fragility, plot_ida, read_csv,  # noqa: E402
                           same_analyses_fit)
from plot_common import (G, building_name, building_names, im_name, lognormal_cdf,  # noqa: E402
                         pound, save, text)

EDP_LABEL = {
    "drift": ("peak inter-storey drift ratio", lambda x: f"{100 * x:g} %"),
    "disp": ("peak floor displacement", lambda x: f"{1000 * x:g} mm"),
    "accel": ("peak floor acceleration", lambda x: f"{x / G:.3g} g"),
    "force": ("peak pounding force", lambda x: f"{x / 1000:g} kN"),
    "residual_drift": ("residual inter-storey drift ratio", lambda x: f"{100 * x:g} %"),
    "ductility": ("storey ductility demand (peak drift / yield drift)", lambda x: f"μ = {x:g}"),
}


def edp_label(edp):
    """(title, limit formatter) of an EDP; a name this script does not know is shown as is."""
    return EDP_LABEL.get(edp, (edp.replace("_", " "), lambda x: f"{x:g}"))
PARAM_UNITS = {"gap": "m", "e": "-", "k_factor": "-", "k": "N/m", "damping": "-", "chi": "-",
               "D": "-"}


def bound_text(bound):
    """Where the data put theta without a finite estimate (theta_bound_lo/hi, m/s^2)."""
    lo, hi = bound[0] / G, bound[1] / G
    if np.isnan(lo) or np.isnan(hi) or (lo <= 0 and np.isinf(hi)):
        return ""
    if np.isinf(hi):
        return f": θ > {lo:.3g} g"
    if lo <= 0:
        return f": θ < {hi:.3g} g"
    return f": {lo:.3g} g < θ < {hi:.3g} g"


def plot_fragility(frag_path, out):
    with h5py.File(frag_path, "r") as f:
        g = f["fragility"]
        grid = g["grid_im"][:] / G
        measure = text(g.attrs.get("intensity_measure", "pga"))
        names = building_names(g)
        design = text(g.attrs.get("design", "stripes"))
        curves = []
        for key in sorted(k for k in g if k.startswith("curve")):
            c = g[key]
            if text(c.attrs.get("model", "all")) != "all":
                continue  # a contact model's own curve: these figures show the pooled ones
            curves.append({
                "building": int(c.attrs["building"]), "edp": text(c.attrs["edp"]),
                "limit": float(c.attrs["limit"]), "pounding": text(c.attrs["pounding"]) == "true",
                "status": text(c.attrs["status"]), "theta": float(c.attrs["theta"]),
                "beta": float(c.attrs["beta"]),
                "bound": (float(c.attrs.get("theta_bound_lo", np.nan)),
                          float(c.attrs.get("theta_bound_hi", np.nan))),
                "im": c["observed_im"][:] / G, "n": c["observed_n"][:], "z": c["observed_z"][:],
                "p": c["probability"][:], "lo": c["band_lo"][:], "hi": c["band_hi"][:]})
    shifts = read_csv(os.path.join(os.path.dirname(frag_path), "shift.csv"))
    groups = {}
    for c in curves:
        groups.setdefault((c["building"], c["edp"]), []).append(c)
    for (b, edp), cs in groups.items():
        if all(c["status"] == "no_data" for c in cs):
            continue  # e.g. the ductility of a building without yield shears: nothing to show
        limits = sorted({c["limit"] for c in cs})
        colors = plt.cm.viridis(np.linspace(0.0, 0.85, len(limits)))
        fig, ax = plt.subplots(figsize=(11, 5))
        for c in cs:
            col = colors[limits.index(c["limit"])]
            style = "-" if c["pounding"] else "--"
            lab = edp_label(edp)[1](c["limit"]) + (", pounding" if c["pounding"] else ", no pounding")
            if c["status"] == "ok":
                lab += f": θ = {c['theta'] / G:.3f} g, β = {c['beta']:.2f}"
                ax.plot(grid, c["p"], style, color=col, lw=1.8, label=lab)
                ok = np.isfinite(c["lo"]) & np.isfinite(c["hi"])
                ax.fill_between(grid[ok], c["lo"][ok], c["hi"][ok], color=col,
                                alpha=0.18 if c["pounding"] else 0.08, lw=0)
            else:
                lab += f": no estimate ({c['status'].replace('_', ' ')}{bound_text(c['bound'])})"
                ax.plot([], [], style, color=col, lw=1.0, label=lab)
            same = None if c["pounding"] else same_analyses_fit(shifts, b, edp, c["limit"], "all")
            if same is not None:
                ax.plot(grid, lognormal_cdf(grid, *same), ":", color=col, lw=1.6,
                        label=edp_label(edp)[1](c["limit"]) + ", no pounding, the pounding "
                        f"curve's analyses: θ = {same[0]:.3f} g, β = {same[1]:.2f}")
            frac = np.where(c["n"] > 0, c["z"] / np.maximum(c["n"], 1), np.nan)
            ax.plot(c["im"], frac, "o" if c["pounding"] else "s", color=col, ms=6,
                    mfc=col if c["pounding"] else "none", mew=1.3, ls="none")
        ax.set_xscale("log")
        seen = np.concatenate([c["im"] for c in cs])
        if not seen.size:  # every analysis left out (continuous IM): the whole grid
            seen = grid[[0, -1]] * np.array([1.6, 1 / 1.6])
        ax.set_xlim(max(grid[0], seen.min() / 1.6), min(grid[-1], seen.max() * 1.6))
        ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(ticker.FuncFormatter(
            lambda x, _: f"{x:g}" if str(f"{x:.0e}")[0] in "2345" else ""))
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel(f"{im_name(measure)} [g]")
        ax.set_ylabel("P(EDP > limit) [-]")
        bname = building_name(names, b)
        pts = "stripes" if design == "stripes" else "IM bins"
        ax.set_title(f"Fragility of {bname}: {edp_label(edp)[0]}\n"
                     f"solid/filled: with pounding, dashed/open: without (dotted: without, on "
                     f"the analyses a neighbour's collapse left to the pounding curve); "
                     f"points: observed ({pts}), shading: 90 % bootstrap band", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False,
                  title="limit, case: fit", title_fontsize=8)
        save(fig, out, f"fragility_{b}_{edp}.png")


def running_median(x, y, window):
    order = np.argsort(x)
    xs, ys = x[order], y[order]
    half = max(1, window // 2)
    med = [np.median(ys[max(0, i - half):i + half + 1]) for i in range(len(xs))]
    return xs, np.array(med)


def plot_amplification(campaign_path, out):
    with pound.open_campaign(campaign_path) as c:
        ok = c.ok
        measure = c.intensity_measure
        names = building_names(c)
        params = {}
        for key, d in c.parameters.items():
            if d.dtype.kind not in "fiu":
                continue
            v = d[ok]
            if np.nanmin(v) < np.nanmax(v):
                params[key] = (v, PARAM_UNITS.get(key.split(".")[-1], "-"))
        im = c.im[ok] / G
        if np.nanmin(im) < np.nanmax(im):
            params[f"{im_name(measure)}"] = (im, "g")
        resp = {}
        for r, array in (("disp", "peak_disp"), ("drift", "peak_drift_ratio")):
            p = np.nanmax(c.response(f"{array}_pounding")[ok], axis=2)
            q = np.nanmax(c.response(f"{array}_free")[ok], axis=2)
            with np.errstate(divide="ignore", invalid="ignore"):
                resp[r] = np.where(q > 0, p / q, np.nan)
    if not params:
        return
    nb = resp["disp"].shape[1]
    keys = list(params)
    for b in range(nb):
        fig, axes = plt.subplots(2, len(keys), figsize=(3.3 * len(keys), 6.2), squeeze=False)
        for i, r in enumerate(("disp", "drift")):
            y = resp[r][:, b]
            for j, k in enumerate(keys):
                x, unit = params[k]
                good = np.isfinite(x) & np.isfinite(y)
                ax = axes[i][j]
                ax.scatter(x[good], y[good], s=8, alpha=0.45, color="tab:blue", lw=0)
                if good.sum() >= 5:
                    xs, med = running_median(x[good], y[good], max(5, good.sum() // 10))
                    ax.plot(xs, med, color="tab:red", lw=1.8, label="running median")
                ax.axhline(1.0, color="k", lw=0.8, ls=":")
                ax.set_xlabel(f"{k} [{unit}]")
                if j == 0:
                    label = "peak displacement" if r == "disp" else "peak drift"
                    ax.set_ylabel(f"{label}\npounding / free [-]")
                ax.grid(True, alpha=0.3)
        axes[0][0].legend(fontsize=8, loc="best")
        bname = building_name(names, b)
        fig.suptitle(f"Amplification of the peak response of {bname} by pounding "
                     f"against each sampled parameter (red: running median)", fontsize=11)
        fig.tight_layout()
        save(fig, out, f"amplification_{b}.png")


def plot_amplification_im(campaign_path, out):
    """Median and 16-84 % band of the amplification against the intensity (/amplification)."""
    with pound.open_campaign(campaign_path) as c:
        a = c.amplification
        if a is None:
            return
        measure = c.intensity_measure
        names = building_names(c)
    im = a["im"] / G
    design = text(a.attrs.get("design", "stripes"))
    stats = {m: {k: a[m][k] for k in ("median", "p16", "p84", "count")}
             for m in ("disp", "drift", "accel")}
    labels = {"disp": "peak displacement", "drift": "peak storey drift",
              "accel": "peak absolute acceleration"}
    nb, nf = stats["disp"]["median"].shape[1:]
    for b in range(nb):
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
        for ax, m in zip(axes, ("disp", "drift", "accel")):
            colors = plt.cm.viridis(np.linspace(0, 0.9, nf))
            for fl in range(nf):
                n = stats[m]["count"][:, b, fl]
                if not np.any(n > 0):
                    continue  # a floor the building does not have
                med, lo, hi = (stats[m][k][:, b, fl] for k in ("median", "p16", "p84"))
                ax.fill_between(im, lo, hi, color=colors[fl], alpha=0.15, lw=0)
                ax.plot(im, med, "o-", color=colors[fl], ms=3, lw=1.4,
                        label=("storey " if m == "drift" else "floor ") + str(fl + 1))
            ax.axhline(1.0, color="k", lw=0.8, ls=":")
            ax.set_xlabel(f"{im_name(measure)} [g]" + ("" if design == "stripes" else " (bin)"))
            ax.set_ylabel(f"{labels[m]}: pounding / free [-]")
            ax.grid(True, alpha=0.3)
        axes[0].legend(fontsize=8, loc="best")
        bname = building_name(names, b)
        fig.suptitle(f"Amplification by pounding of {bname}: median and 16-84 % band per "
                     f"{'stripe' if design == 'stripes' else 'intensity bin'}", fontsize=11)
        fig.tight_layout()
        save(fig, out, f"amplification_im_{b}.png")


def plot_risk(risk_path, out):
    """P(pounding) against the gap, probability in T years against the gap, the hazard used."""
    with h5py.File(risk_path, "r") as f:
        r = f["risk"]
        years = float(r.attrs["years"])
        target = float(r.attrs["target_probability"])
        measure = text(r.attrs.get("intensity_measure", "pga"))
        design_im = float(r.attrs["design_im_mps2"]) / G
        hz = {k: r["hazard"][k][:] for k in ("im", "rate", "curve_im", "curve_rate")}
        pairs = sorted(k for k in r if k.startswith("pair"))
        data = {}
        for k in pairs:
            g = r[k]
            data[k] = {n: g[n][:] for n in ("gap", "theta", "beta", "probability",
                                            "probability_lo", "probability_hi", "observed_im",
                                            "observed_n", "observed_z", "rule_gap",
                                            "rule_probability")}
            data[k]["rules"] = text(g.attrs.get("rules", "")).split(",")
            data[k]["target_gap"] = float(g.attrs["gap_for_target_m"])
            data[k]["band"] = (float(g.attrs["gap_band_lo_m"]), float(g.attrs["gap_band_hi_m"]))
    name = im_name(measure)
    # Hazard curve.
    fig, ax = plt.subplots(figsize=(6, 4.4))
    inside = (hz["curve_im"] >= hz["im"][0]) & (hz["curve_im"] <= hz["im"][-1])
    ax.loglog(hz["curve_im"][inside] / G, hz["curve_rate"][inside], "-", color="tab:blue",
              label="log-log interpolation")
    for part in (hz["curve_im"] < hz["im"][0], hz["curve_im"] > hz["im"][-1]):
        ax.loglog(hz["curve_im"][part] / G, hz["curve_rate"][part], "--", color="tab:blue")
    ax.loglog(hz["im"] / G, hz["rate"], "o", color="k", ms=4, label="points of the curve")
    ax.plot([], [], "--", color="tab:blue", label="end segments extended")
    ax.axvline(design_im, color="tab:red", lw=0.9, ls=":", label=f"design {name} {design_im:.3g} g")
    ax.set_xlabel(f"{name} [g]")
    ax.set_ylabel("annual rate of exceedance [1/yr]")
    ax.set_ylim(max(1e-7, np.min(hz["rate"]) / 10), None)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Hazard curve used by pound risk", fontsize=11)
    save(fig, out, "hazard.png")
    for k in pairs:
        d = data[k]
        p = k.replace("pair", "")
        # P(pounding | IM) against the gap at the observed intensities (fit: lines, data: dots).
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        ims = d["observed_im"]
        pick = np.unique(np.linspace(0, len(ims) - 1, min(6, len(ims))).round().astype(int))
        colors = plt.cm.plasma(np.linspace(0, 0.85, len(pick)))
        for c, j in zip(colors, pick):
            x = ims[j]
            fit = np.array([lognormal_cdf([x], t, b)[0] if np.isfinite(t) else np.nan
                            for t, b in zip(d["theta"], d["beta"])])
            ax.plot(d["gap"] * 1000, fit, "-", color=c, lw=1.5, label=f"{name} {x / G:.3g} g")
            n = d["observed_n"][:, j]
            with np.errstate(invalid="ignore", divide="ignore"):
                ax.plot(d["gap"] * 1000, d["observed_z"][:, j] / n, "o", color=c, ms=3)
        ax.set_xlabel("gap [mm]")
        ax.set_ylabel(f"P(pounding | {name}) [-]")
        ax.set_ylim(-0.02, 1.02)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, title="lines: lognormal fit per gap; dots: observed", title_fontsize=8)
        ax.set_title(f"Pair {p}: probability of pounding given the intensity", fontsize=11)
        save(fig, out, f"risk_fragility_pair{p}.png")
        # Probability in T years against the gap.
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        ok = np.isfinite(d["probability"])
        ax.fill_between(d["gap"][ok] * 1000, d["probability_lo"][ok], d["probability_hi"][ok],
                        color="tab:blue", alpha=0.2, lw=0, label="90 % bootstrap band")
        ax.semilogy(d["gap"][ok] * 1000, d["probability"][ok], "o-", color="tab:blue", ms=3,
                    label=f"P(pounding in {years:g} years)")
        ax.axhline(target, color="k", lw=0.9, ls="--", label=f"target {target:g}")
        if np.isfinite(d["target_gap"]):
            ax.axvline(d["target_gap"] * 1000, color="k", lw=1.2,
                       label=f"gap for the target {d['target_gap'] * 1000:.0f} mm")
            lo, hi = d["band"]
            if np.isfinite(lo) and np.isfinite(hi):
                ax.axvspan(lo * 1000, hi * 1000, color="k", alpha=0.08, lw=0)
        for rule, gap, prob, c in zip(d["rules"], d["rule_gap"], d["rule_probability"],
                                      ("tab:red", "tab:green", "tab:purple", "tab:orange")):
            ax.axvline(gap * 1000, color=c, lw=1.0, ls=":",
                       label=f"{rule} at {design_im:.3g} g: {gap * 1000:.0f} mm"
                             + (f", P = {prob:.3g}" if np.isfinite(prob) else ""))
        ax.set_xlabel("gap [mm]")
        ax.set_ylabel(f"probability of pounding in {years:g} years [-]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7.5, loc="best")
        ax.set_title(f"Pair {p}: pounding in {years:g} years against the gap", fontsize=11)
        save(fig, out, f"risk_probability_pair{p}.png")


def band(ax, tp, rows, color, label):
    """Median and 16/84 % band (percentiles over the rows at each period) of spectra [g]."""
    lo, med, hi = np.percentile(rows, [16, 50, 84], axis=0)
    ax.fill_between(tp, lo, hi, color=color, alpha=0.25, lw=0)
    ax.plot(tp, med, color=color, lw=2, label=f"{label}: median, 16-84 % band")


def plot_spectra_spread(f, out):
    """Motions with random targets: the spread of the targets' and the motions' spectra around
    the design spectrum; right, the same spectra scaled to the design PGA as PGA stripes scale
    them (the spread then shows at periods away from 0)."""
    tp = f["target/period"][:]
    design = f["target/psa"][:] / G
    psa = f["motions/psa"][:] / G
    targets = f["motions/target_psa"][:] / G
    pga = f["motions/pga"][:] / G
    sigma = f["target/sigma_lnsa"][:]
    describe = text(f.attrs.get("target", "target"))
    variability = text(f.attrs.get("variability", ""))
    damping = float(f.attrs.get("damping", 0.05))
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2), sharey=True)
    ax = axes[0]
    band(ax, tp, targets, "tab:orange", f"targets ({len(targets)})")
    band(ax, tp, psa, "tab:blue", f"motions ({len(psa)})")
    ax.plot(tp, design, color="k", lw=2, ls="--", label="design spectrum")
    ax.plot(tp, design * np.exp(sigma), color="k", lw=0.8, ls=":",
            label="design x exp(±sigma) (the model's 16/84 %)")
    ax.plot(tp, design * np.exp(-sigma), color="k", lw=0.8, ls=":")
    ax.set_title("Random targets and the spectra of the motions matched to them", fontsize=10)
    ax = axes[1]
    # Each motion scaled so that its PGA equals the design spectrum's Sa(0): the view of a
    # campaign with PGA stripes.
    ref = float(f.attrs["design_pga_mps2"]) / G
    scaled = psa * (ref / pga)[:, None]
    band(ax, tp, scaled, "tab:green", "motions scaled to one PGA")
    ax.plot(tp, design, color="k", lw=2, ls="--", label="design spectrum")
    ax.set_title(f"The same motions scaled to PGA = {ref:.3g} g (as a PGA stripe does)", fontsize=10)
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("period T [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="lower left")
    axes[0].set_ylabel(f"pseudo-spectral acceleration PSA [g] ({100 * damping:g} % damping)")
    fig.suptitle(textwrap.fill(describe, 140) + "\n" + textwrap.fill("variability: " + variability, 140),
                 fontsize=8)
    fig.tight_layout()
    save(fig, out, "spectra.png")


def plot_spectra(motions_path, out):
    with h5py.File(motions_path, "r") as f:
        if "motions/epsilon" in f:
            plot_spectra_spread(f, out)
            return
        tp = f["target/period"][:]
        target = f["target/psa"][:] / G
        psa = f["motions/psa"][:] / G
        mean = f["target/mean_psa"][:] / G if "target/mean_psa" in f else psa.mean(axis=0)
        describe = text(f.attrs.get("target", "target"))
        damping = float(f.attrs.get("damping", 0.05))
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for i, row in enumerate(psa):
        ax.plot(tp, row, color="0.6", lw=0.7, label="generated motions" if i == 0 else None)
    ax.plot(tp, mean, color="tab:blue", lw=2, label=f"mean of {len(psa)} motions")
    ax.plot(tp, target, color="tab:red", lw=2, ls="--", label="target")
    ax.set_xscale("log")
    ax.set_xlabel("period T [s]")
    ax.set_ylabel(f"pseudo-spectral acceleration PSA [g] ({100 * damping:g} % damping)")
    ax.set_title("Response spectra of the generated motions against the target\n"
                 + textwrap.fill(describe, 95), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=9)
    save(fig, out, "spectra.png")


def plot_history(hist_path, out, names):
    """Top-floor displacements and contact forces; with a third panel, the ground under each
    building (/ground/displacement) when the buildings do not all stand on the same motion."""
    with h5py.File(hist_path, "r") as f:
        bld = f["row/dof_building"][:]
        floor = f["row/dof_floor"][:]
        tp, xp = f["pounding/time"][:], f["pounding/displacement"]
        tf, xf = f["free/time"][:], f["free/displacement"]
        force = f["pounding/contact_force"][:]  # [steps, sites] on pounding/time
        pair = f["row/site_pair"][:]
        sfloor = f["row/site_floor"][:]
        tg = f["ground/time"][:] if "ground/time" in f else None
        ug = f["ground/displacement"][:] if "ground/displacement" in f else None
        varying = ug is not None and ug.shape[1] > 1 and np.any(ug != ug[:, :1])
        step = 1  # full resolution: thinning could clip the short impact peaks
        fig, axes = plt.subplots(3 if varying else 2, 1, figsize=(9, 9 if varying else 6.5),
                                 sharex=True)
        a1, a2 = axes[0], axes[1]
        colors = plt.cm.tab10.colors
        for b in np.unique(bld):
            top = np.where(bld == b)[0][np.argmax(floor[bld == b])]
            nm = building_name(names, b)
            c = colors[int(b) % 10]
            a1.plot(tp[::step], 1000 * xp[::step, top], color=c, lw=1.1,
                    label=f"{nm}, floor {floor[top]}, pounding")
            a1.plot(tf[::step], 1000 * xf[::step, top], color=c, lw=0.9, ls="--", alpha=0.8,
                    label=f"{nm}, floor {floor[top]}, no pounding")
        for s in range(force.shape[1]):
            if np.nanmax(np.abs(force[:, s])) > 0:
                a2.plot(tp, force[:, s] / 1000, lw=1.0,
                        label=f"pair {pair[s] + 1}, floor {sfloor[s]}")
    a1.set_ylabel("displacement relative to the ground [mm]")
    a1.legend(fontsize=8, ncol=2)
    a1.grid(True, alpha=0.3)
    a1.set_title("Top-floor displacement of each building with (solid) and without (dashed) pounding")
    a2.set_ylabel("pounding force [kN]")
    a2.set_title("Contact force at the colliding floors")
    if a2.lines:
        a2.legend(fontsize=8)
    a2.grid(True, alpha=0.3)
    if varying:  # spatially varying ground (docs/ground.md): what each base stands on
        a3 = axes[2]
        for b in range(ug.shape[1]):
            a3.plot(tg, 1000 * ug[:, b], color=colors[b % 10], lw=1.0,
                    label=f"under {building_name(names, b)}")
        for p in range(ug.shape[1] - 1):
            a3.plot(tg, 1000 * (ug[:, p] - ug[:, p + 1]), color="k", lw=0.8,
                    ls=":" if p else "-",
                    label=f"{building_name(names, p)} minus {building_name(names, p + 1)}")
        a3.set_ylabel("ground displacement [mm]")
        a3.set_title("The ground under each building and the relative ground displacement")
        a3.legend(fontsize=8, ncol=2)
        a3.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time t [s]")
    fig.tight_layout()
    save(fig, out, "history.png")


def storey_drift(u, bld, floor, dof):
    """Drift of the storey below floor `dof` [steps]: u of the floor minus u of the floor below
    in the same building (the ground, 0, below floor 1)."""
    below = np.where((bld == bld[dof]) & (floor == floor[dof] - 1))[0]
    return u[:, dof] - (u[:, below[0]] if floor[dof] > 1 and below.size else 0.0)


def plot_hysteresis(hist_path, out, names):
    """Storey shear against storey drift of the first storey of each building, with and without
    pounding; nothing when the file holds no storey shears."""
    with h5py.File(hist_path, "r") as f:
        if "pounding/storey_shear" not in f:
            return
        bld = f["row/dof_building"][:]
        floor = f["row/dof_floor"][:]
        # The storey's deformation as written (on a flexible foundation the chord minus h
        # theta); files written before it carry only the floors' displacements.
        runs = [(case, f[f"{case}/storey_drift"][:] if f"{case}/storey_drift" in f else None,
                 f[f"{case}/displacement"][:], f[f"{case}/storey_shear"][:])
                for case in ("pounding", "free")
                if f"{case}/storey_shear" in f and f"{case}/displacement" in f]
    buildings = np.unique(bld)
    fig, axes = plt.subplots(1, len(buildings), figsize=(5.2 * len(buildings), 4.6), squeeze=False)
    for ax, b in zip(axes[0], buildings):
        first = np.where((bld == b) & (floor == 1))[0]
        if not first.size:
            continue
        dof = first[0]
        for case, drift, u, shear in runs:
            pounding = case == "pounding"
            d = drift[:, dof] if drift is not None else storey_drift(u, bld, floor, dof)
            ax.plot(1000 * d, shear[:, dof] / 1000,
                    color="tab:red" if pounding else "tab:blue", lw=1.0 if pounding else 0.9,
                    ls="-" if pounding else "--", alpha=0.9 if pounding else 0.7,
                    label="pounding" if pounding else "no pounding")
        nm = building_name(names, b)
        ax.set_title(f"{nm}, storey 1", fontsize=10)
        ax.set_xlabel("storey drift [mm]")
        ax.set_ylabel("storey shear [kN]")
        ax.axhline(0.0, color="k", lw=0.5)
        ax.axvline(0.0, color="k", lw=0.5)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Hysteresis of the first storey of each building with (solid) and without "
                 "(dashed) pounding", fontsize=11)
    fig.tight_layout()
    save(fig, out, "hysteresis.png")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--campaign", help="campaign result file (HDF5); needed unless --histories or "
                   "--motions is given alone")
    p.add_argument("--fragility", help="output folder of 'pound fragility' (fragility.h5)")
    p.add_argument("--out", required=True, help="folder for the PNGs")
    p.add_argument("--motions", help="motions.h5 of 'pound motion generate'")
    p.add_argument("--histories", help="HDF5 of 'pound simulate --histories'")
    p.add_argument("--risk", help="output folder of 'pound risk' (risk.h5)")
    a = p.parse_args()
    if not (a.campaign or a.histories or a.motions):
        p.error("give --campaign, --histories or --motions")
    if (a.fragility or a.risk) and not a.campaign:
        p.error("--fragility and --risk need the --campaign they were computed from")
    os.makedirs(a.out, exist_ok=True)
    for path in [a.campaign, a.motions, a.histories] + (
            [os.path.join(a.fragility, "fragility.h5")] if a.fragility else []) + (
            [os.path.join(a.risk, "risk.h5")] if a.risk else []):
        if path and not os.path.isfile(path):
            sys.exit(f"plot_results.py: error: {path}: no such file")
    if a.fragility:
        plot_fragility(os.path.join(a.fragility, "fragility.h5"), a.out)
    if a.campaign:
        plot_amplification(a.campaign, a.out)
        plot_amplification_im(a.campaign, a.out)
    if a.fragility:
        with pound.open_campaign(a.campaign) as c:
            measure = c.intensity_measure
        plot_collapse_fragility(a.fragility, a.out, measure)
    if a.campaign:
        plot_ida(a.campaign, a.out)
    if a.risk:
        plot_risk(os.path.join(a.risk, "risk.h5"), a.out)
    if a.motions:
        plot_spectra(a.motions, a.out)
    if a.histories:
        names = []
        if a.campaign:
            with pound.open_campaign(a.campaign) as c:
                names = building_names(c)
        with h5py.File(a.histories, "r") as f:
            cfg = text(f.attrs.get("config", ""))
        hn = [l.split("=", 1)[1].strip() for l in cfg.splitlines()
              if l.strip().startswith("building") and ".name" in l.split("=")[0]]
        plot_history(a.histories, a.out, hn or names)
        plot_hysteresis(a.histories, a.out, hn or names)


if __name__ == "__main__":
    main()
