#!/usr/bin/env python3
"""A campaign file in pandas: per intensity stripe and building, the fraction of samples whose
peak storey drift ratio exceeds a limit, with and without pounding, and the fraction that
collapsed where the file records collapse (/response/collapsed_pounding, collapsed_free).

    PYTHONPATH=build/python /usr/bin/python3 examples/campaign_fractions.py
        [--campaign results/default/campaign.h5] [--drift-limit R] [--out results/examples]

The drift limit defaults to the first of the study's [fragility] drift_limits (0.01 in
studies/fragility-default.ini), else 0.01. The default campaign is the one
`bash scripts/quickstart.sh` writes. Writes OUT/campaign_fractions.png and .csv and prints the
table. docs/python.md explains pound.open_campaign and its DataFrame (pound.read_campaign).
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

import pound  # noqa: E402

G = pound.G  # m/s2 per g


def drift_limit_of(campaign):
    """The first [fragility] drift_limits value of the campaign's resolved study, if any."""
    limits = campaign.study_value("fragility.drift_limits")
    return float(limits.replace(",", " ").split()[0]) if limits else None


def groups_of(df, levels):
    """Stripe of each sample and the stripe's intensity in g (levels: the stripes' intensities
    in m/s2); with a sampled scale instead of stripes, eight bins of equal count in IM."""
    if "stripe" in df.columns:
        return df["stripe"], pd.Series(levels / G)
    bins = pd.qcut(df["im"], 8, labels=False, duplicates="drop")
    return bins, (df["im"] / G).groupby(bins).median()


def fractions(df, names, levels, limit):
    ok = df[df["status"] == 0]
    group, intensity = groups_of(ok, levels)
    rows = []
    for b, name in enumerate(names, start=1):
        for run in ("pounding", "free"):
            exceeds = ok[f"building{b}.peak_drift_ratio_{run}"] > limit
            collapsed = ok.get(f"building{b}.collapsed_{run}")
            for g, part in exceeds.groupby(group):
                row = {"building": name, "run": run, "stripe": int(g),
                       "im_g": float(intensity[g]), "samples": int(part.size),
                       "drift_exceeded": float(part.mean())}
                if collapsed is not None:
                    row["collapsed"] = float(collapsed[part.index].astype(float).mean())
                rows.append(row)
    return pd.DataFrame(rows)


def plot(table, names, limit, has_collapse, path, im_label="PGA"):
    measures = ["drift_exceeded"] + (["collapsed"] if has_collapse else [])
    fig, axes = plt.subplots(len(measures), len(names), figsize=(5 * len(names),
                                                                  3.6 * len(measures)),
                             squeeze=False)
    for i, measure in enumerate(measures):
        for j, name in enumerate(names):
            ax = axes[i][j]
            for run, style in (("pounding", "-o"), ("free", "--s")):
                t = table[(table["building"] == name) & (table["run"] == run)]
                ax.plot(t["im_g"], t[measure], style, ms=4, label=f"{run}")
            ax.set_ylim(-0.02, 1.02)
            ax.set_xlabel(f"{im_label} [g]")
            what = (f"P(peak drift ratio > {limit:g})" if measure == "drift_exceeded"
                    else "P(collapse)")
            ax.set_ylabel(what)
            ax.set_title(name)
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--campaign", default="results/default/campaign.h5")
    ap.add_argument("--drift-limit", type=float)
    ap.add_argument("--out", default="results/examples")
    a = ap.parse_args()
    with pound.open_campaign(a.campaign) as c:
        df = c.to_dataframe()  # one row per sample, as pound.read_campaign(a.campaign)
        names = c.building_names
        limit = a.drift_limit or drift_limit_of(c) or 0.01
        table = fractions(df, names, c.im_levels, limit)
        im_label = "Sa(T1)" if c.intensity_measure == "sa" else "PGA"
    has_collapse = "collapsed" in table.columns
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    table.to_csv(out / "campaign_fractions.csv", index=False)
    plot(table, names, limit, has_collapse, out / "campaign_fractions.png", im_label)
    failed = int((df["status"] != 0).sum())
    print(f"campaign_fractions: {a.campaign}: {len(df)} samples ({failed} failed), drift limit "
          f"{limit:g}; collapse: "
          + ("per building and run" if has_collapse else
             "not in this file (no /response/collapsed_pounding)"))
    wide = table.pivot_table(index=["building", "im_g"], columns="run",
                             values=["drift_exceeded"] + (["collapsed"] if has_collapse else []))
    with pd.option_context("display.width", 120, "display.max_rows", 200):
        print(wide.round(3))
    print(f"campaign_fractions: wrote {out / 'campaign_fractions.png'} and "
          f"{out / 'campaign_fractions.csv'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
