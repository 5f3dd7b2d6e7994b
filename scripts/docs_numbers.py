#!/usr/bin/python3
"""Regenerates the numbers of docs/fragility.md ("Example"), docs/risk.md ("The default
study") and docs/hysteresis.md ("Damping near collapse") from runs of the default study, and
prints each table in the Markdown form those pages use, so that a page's numbers never outlive
the study (issue 24):

    /usr/bin/python3 scripts/docs_numbers.py [--work DIR] [--ranks 2] [--reuse]

Runs, with build/bin/pound, three campaigns of studies/fragility-default.ini into DIR (default
results/docs-numbers/): the study as it is (default.h5), with --generator.variability none
(no-variability.h5: every motion matched to the design spectrum) and with Rayleigh damping on
the initial stiffness (initial-damping.h5: --buildingN.damping_stiffness initial), each on
--ranks MPI ranks, and studies/campaign-smoke.ini with a sampled scale factor
(smoke-continuous.h5, 200 samples); then pound fragility on each and pound risk on the first
(the example hazard curve), once as the README runs it and once with --design-im at the
hazard's 2475-year PGA (the collapse margin ratio, FEMA P695). A few minutes on two cores.
--reuse keeps campaign and analysis files already in DIR (after a change of the study or the
code, run without it). Paste each printed block over the table its heading names. The campaign
files are read with the package pound of the same build (build/python: pound.open_campaign).
"""
import argparse
import csv
import os
import re
import subprocess
import sys

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
POUND = os.path.join(ROOT, "build", "bin", "pound")
# The package pound the same build makes (build/python; after PYTHONPATH's folders, before the
# installed packages): it reads the campaign files and holds g.
if os.path.isdir(os.path.join(ROOT, "build", "python", "pound")):
    sys.path.insert(1 + len([p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]),
                    os.path.join(ROOT, "build", "python"))
try:
    import pound  # noqa: E402
except ImportError as e:
    sys.exit(f"docs_numbers: cannot import the Python package pound ({e}); build first (cmake "
             "--preset release && cmake --build --preset release)")

G = pound.G  # m/s^2 per g
STUDY = os.path.join(ROOT, "studies", "fragility-default.ini")
HAZARD = os.path.join(ROOT, "studies", "hazard-los-angeles-pga.csv")

SMOKE = os.path.join(ROOT, "studies", "campaign-smoke.ini")

# name: (study, campaign options, fragility options)
CAMPAIGNS = {
    "default": (STUDY, [], []),
    "no-variability": (STUDY, ["--generator.variability", "none"], []),
    "initial-damping": (STUDY, ["--building1.damping_stiffness", "initial",
                                "--building2.damping_stiffness", "initial"], []),
    # The smoke study with a sampled scale factor instead of its stripes (its `levels` line
    # left out: a study gives one or the other).
    "smoke-continuous": (None, ["--intensity.scale", "lognormal(1,0.6,0.1,5)", "--samples", "200"],
                         ["--drift-limits", "0.02", "--replicates", "300"]),
}


def run(cmd, out=None):
    """Runs cmd (a list), stdout to the file `out` or returned; stops on failure."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print("docs_numbers: " + " ".join(cmd), file=sys.stderr)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"docs_numbers: exit status {r.returncode}: {' '.join(cmd)}\n{r.stderr}")
    if out:
        with open(out, "w") as f:
            f.write(r.stdout)
    return r.stdout


def make_runs(work, ranks, reuse):
    os.makedirs(work, exist_ok=True)
    mpi = ["mpirun", "-np", str(ranks), "--oversubscribe"]
    if os.geteuid() == 0:
        mpi.append("--allow-run-as-root")
    smoke = os.path.join(work, "smoke-continuous.ini")
    with open(SMOKE) as f, open(smoke, "w") as g:
        g.write("".join(line for line in f if not line.lstrip().startswith("levels")))
    for name, (study, extra, frag_extra) in CAMPAIGNS.items():
        h5 = os.path.join(work, name + ".h5")
        if not (reuse and os.path.exists(h5)):
            run(mpi + [POUND, "campaign", "--config", study or smoke, "--out", h5, "--force",
                       "--quiet"] + extra)
        frag = os.path.join(work, name + "-fragility")
        if not (reuse and os.path.exists(os.path.join(frag, "curves.csv"))):
            run([POUND, "fragility", "--input", h5, "--out", frag] + frag_extra,
                out=os.path.join(work, name + "-fragility.txt"))
    risk = os.path.join(work, "default-risk")
    if not (reuse and os.path.exists(os.path.join(risk, "risk_gaps.csv"))):
        run([POUND, "risk", "--input", os.path.join(work, "default.h5"), "--hazard", HAZARD,
             "--out", risk], out=os.path.join(work, "default-risk.txt"))
    mce = os.path.join(work, "default-risk-mce")
    if not (reuse and os.path.exists(os.path.join(mce, "risk_gaps.csv"))):
        run([POUND, "risk", "--input", os.path.join(work, "default.h5"), "--hazard", HAZARD,
             "--out", mce, "--design-im", f"{mce_pga():.4f}"],
            out=os.path.join(work, "default-risk-mce.txt"))


def mce_pga(return_period=2475.0):
    """The hazard curve's PGA [g] at 1 / return_period per year, by log-log interpolation
    between its points (as pound risk reads a hazard curve: src/risk/hazard_curve.hpp)."""
    import math
    pts = []
    with open(HAZARD) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line[0].isalpha():
                continue
            x, y = (float(v) for v in line.split(","))
            pts.append((x, y))
    target = math.log(1.0 / return_period)
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        l0, l1 = math.log(y0), math.log(y1)
        if l0 >= target >= l1:
            t = (target - l0) / (l1 - l0)
            return math.exp(math.log(x0) + t * (math.log(x1) - math.log(x0)))
    raise SystemExit("docs_numbers: the hazard curve does not reach the 2475-year rate")


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def curves(work, name, model="all"):
    """(building name, edp, limit, pounding) -> the row of curves.csv (the pooled curves, or
    those of one sampled contact model)."""
    out = {}
    for r in read_csv(os.path.join(work, name + "-fragility", "curves.csv")):
        if r.get("model", "all") == model:
            out[(r["building_name"], r["edp"], float(r["limit"]), r["pounding"] == "true")] = r
    return out


def theta_g(row):
    return float(row["theta_mps2"]) / G


def headline(work):
    """The shift block of pound fragility's output, as docs/fragility.md shows it."""
    text = open(os.path.join(work, "default-fragility.txt")).read().splitlines()
    lines = []
    for line in text[1:]:
        if not line.strip():
            break
        lines.append(line)
    return "```\n" + "\n".join(lines) + "\n```"


def headline_facts(work):
    """The numbers the prose below the headline quotes."""
    c = curves(work, "default")
    finite = sum(r["status"] == "ok" for r in c.values())
    drift = {b: [theta_g(c[(b, "drift", lim, True)]) for lim in (0.01, 0.02, 0.04)]
             for b in ("5-storey", "3-storey")}
    yield_g = [theta_g(c[(b, "ductility", 1.0, p)]) for b in ("5-storey", "3-storey")
               for p in (True, False)]
    coll = {b: (c[(b, "collapse", 1.0, True)], c[(b, "collapse", 1.0, False)])
            for b in ("5-storey", "3-storey")}
    return "\n".join([
        f"- finite curves: {finite} of {len(c)}",
        "- collapse, theta [g] / beta with and without pounding: " + "; ".join(
            f"{b} {theta_beta(p)} and {theta_beta(f)}" for b, (p, f) in coll.items()),
        "- peak-drift limits 1/2/4 % with pounding [g]: 5-storey "
        + ", ".join(f"{x:.2f}" for x in drift["5-storey"]) + "; 3-storey "
        + ", ".join(f"{x:.2f}" for x in drift["3-storey"]),
        f"- ductility 1 (yield), both buildings, with and without pounding: "
        f"{min(yield_g):.2f}-{max(yield_g):.2f} g",
    ])


BETA_ROWS = [("5-storey", "collapse", 1.0), ("3-storey", "collapse", 1.0),
             ("5-storey", "drift", 0.01), ("5-storey", "drift", 0.02), ("5-storey", "drift", 0.04),
             ("3-storey", "drift", 0.01), ("3-storey", "drift", 0.02), ("3-storey", "drift", 0.04),
             ("5-storey", "ductility", 1.0), ("5-storey", "ductility", 2.0),
             ("5-storey", "ductility", 4.0), ("3-storey", "ductility", 1.0),
             ("3-storey", "ductility", 2.0), ("3-storey", "ductility", 4.0),
             ("5-storey", "residual_drift", 0.002), ("3-storey", "residual_drift", 0.002)]


def limit_text(edp, limit):
    if edp == "collapse":
        return "collapse"
    if edp in ("drift", "residual_drift"):
        return f"{edp.replace('_', ' ')} {100 * limit:g} %"
    return f"{edp} {limit:g}"


def theta_beta(row):
    if row is None:
        return ""
    if row["status"] != "ok":
        return row["status"]
    return f"{theta_g(row):.3f} / {float(row['beta']):.2f}"


def betas_table(work):
    before, after = curves(work, "no-variability"), curves(work, "default")
    out = ["| building | EDP, limit | before: pounding | before: free | after: pounding | after: free |",
           "|---|---|---|---|---|---|"]
    for b, edp, lim in BETA_ROWS:
        cells = [theta_beta(t.get((b, edp, lim, p))) for t in (before, after) for p in (True, False)]
        out.append(f"| {b} | {limit_text(edp, lim)} | " + " | ".join(cells) + " |")
    # The pounding force of the pair (listed under building 1).
    force = [theta_beta(t.get(("5-storey", "force", 1e5, True))) for t in (before, after)]
    out.append(f"| both | force 100 kN | {force[0]} | | {force[1]} | |")
    return "\n".join(out)


def collapse_table(work):
    """Collapse fragility per building with and without pounding, pooled and per model: the
    pounding curve (its censored analyses left out), the free curve of all the analyses, the
    free median of the pounding curve's analyses, and the shift (like for like)."""
    out = ["| building | analyses with pounding (censored) | with pounding: theta [g] / beta | "
           "without, all: theta [g] / beta | without, same analyses: theta [g] | "
           "shift [90 % band] | collapsed with / without |",
           "|---|---|---|---|---|---|---|"]
    shifts = {(r["building_name"], r.get("model", "all")): r
              for r in read_csv(os.path.join(work, "default-fragility", "shift.csv"))
              if r["edp"] == "collapse"}
    for model in ("all", "sears", "hc-linear"):
        c = curves(work, "default", model)
        for b in ("5-storey", "3-storey"):
            p, f = c.get((b, "collapse", 1.0, True)), c.get((b, "collapse", 1.0, False))
            if p is None:
                continue
            sh = shifts[(b, model)]
            ratio = (f"{float(sh['ratio']):.3f} [{float(sh['ratio_ci90_lo']):.3f}, "
                     f"{float(sh['ratio_ci90_hi']):.3f}]" if sh["ratio"] else "-")
            who = b if model == "all" else f"{b} ({model})"
            same = (f"{float(sh['theta_free_mps2']) / G:.3f}" if sh.get("theta_free_mps2")
                    else "-")
            out.append(f"| {who} | {p['analyses']} ({p['left_out']}) | {theta_beta(p)} | "
                       f"{theta_beta(f)} | {same} | {ratio} | "
                       f"{p['exceedances']} / {f['exceedances']} |")
    return "\n".join(out)


def damping_table(work):
    """How the collapse and 4 % drift curves move from initial- to tangent-stiffness damping."""
    initial, tangent = curves(work, "initial-damping"), curves(work, "default")
    out = ["| building | limit | initial: pounding | initial: free | tangent: pounding | "
           "tangent: free | tangent / initial (free) |",
           "|---|---|---|---|---|---|---|"]
    for b in ("5-storey", "3-storey"):
        for edp, lim in (("collapse", 1.0), ("drift", 0.04), ("drift", 0.02)):
            cells = [theta_beta(t.get((b, edp, lim, p))) for t in (initial, tangent)
                     for p in (True, False)]
            fi, ft = initial.get((b, edp, lim, False)), tangent.get((b, edp, lim, False))
            r = (f"{theta_g(ft) / theta_g(fi):.3f}" if fi and ft and fi["status"] == "ok"
                 and ft["status"] == "ok" else "-")
            out.append(f"| {b} | {limit_text(edp, lim)} | " + " | ".join(cells) + f" | {r} |")
    return "\n".join(out)


def model_facts(work):
    """What the two sampled contact models do differently: the median acceleration amplification
    of the 5-storey's third floor per stripe, per model (from the campaign file), over the
    samples in which the building's pounding run was not stopped by the other's collapse (as
    /amplification and pound summary)."""
    out = []
    with pound.open_campaign(os.path.join(work, "default.h5")) as c:
        im = np.round(c.im / G, 4)
        model = c.parameters["model"]
        ok = c.ok
        ap, af = c.response("peak_accel_pounding"), c.response("peak_accel_free")
        cp = c.response("collapsed_pounding")
        # standing[:, b]: building b's pounding run was not stopped by the other's collapse
        standing = np.stack([~((cp[:, b] != 1) & (cp[:, 1 - b] == 1)) for b in (0, 1)], axis=1)
        amp = ap[:, 0, 2] / af[:, 0, 2]
        for m in ("sears", "hc-linear", None):
            cells = []
            for level in np.unique(im[ok]):
                sel = ok & standing[:, 0] & (im == level) & ((model == m) if m else True)
                cells.append(f"{np.nanmedian(amp[sel]):.2f}" if sel.any() else "-")
            out.append(f"- 5-storey floor 3 acceleration amplification, median per stripe "
                       f"({m or 'pooled'}): " + ", ".join(cells))
        for m in ("sears", "hc-linear"):
            sel = ok & (model == m) & (im >= 0.3) & (im <= 0.6)
            for b, f in ((0, 2), (1, 2)):
                r = ap[sel & standing[:, b], b, f] / af[sel & standing[:, b], b, f]
                out.append(f"- {m}, 0.3-0.6 g, building {b + 1} floor {f + 1}: acceleration "
                           f"amplification median {np.nanmedian(r):.2f}, 16/84 % "
                           f"{np.nanpercentile(r, 16):.2f}/{np.nanpercentile(r, 84):.2f}")
    return "\n".join(out)


def span(values, fmt="{:.2f}"):
    """'lo-hi' of a list of numbers ('lo to hi' when signed)."""
    sep = " to " if "+" in fmt else "-"
    return fmt.format(min(values)) + sep + fmt.format(max(values))


def betas(c, edp, building=None):
    return [float(r["beta"]) for (b, e, _, _), r in c.items()
            if e == edp and r["status"] == "ok" and (building is None or b == building)]


def shift_ratios(work, name, edp):
    return [float(r["ratio"]) for r in read_csv(os.path.join(work, name + "-fragility", "shift.csv"))
            if r["edp"] == edp and r["ratio"] and r.get("model", "all") == "all"]


def prcc_top(work, name, building, response, n=3):
    rows = [r for r in read_csv(os.path.join(work, name + "-fragility", "sensitivity.csv"))
            if r["building_name"] == building and r["response"] == response]
    rows.sort(key=lambda r: int(r["rank"]))
    return ", ".join(f"{r['parameter']} {float(r['prcc']):+.2f}" for r in rows[:n])


def betas_facts(work):
    """The numbers the prose around the betas table quotes."""
    before, after = curves(work, "no-variability"), curves(work, "default")
    med = {}
    for edp in ("drift", "ductility"):
        med[edp] = [100 * (theta_g(after[k]) / theta_g(before[k]) - 1) for k in after
                    if k[1] == edp and after[k]["status"] == "ok" and k in before
                    and before[k]["status"] == "ok"]
    out = []
    for edp in ("drift", "ductility", "residual_drift"):
        out.append(f"- {edp} betas, before: {span(betas(before, edp))} (5-storey "
                   f"{span(betas(before, edp, '5-storey'))}, 3-storey "
                   f"{span(betas(before, edp, '3-storey'))}); after: {span(betas(after, edp))} "
                   f"(5-storey {span(betas(after, edp, '5-storey'))}, 3-storey "
                   f"{span(betas(after, edp, '3-storey'))})")
    for edp in ("drift", "ductility"):
        out.append(f"- {edp} medians, after / before - 1: {span(med[edp], '{:+.0f}')} %")
    for edp in ("drift", "ductility", "residual_drift"):
        out.append(f"- shift ratios of {edp}: after {span(shift_ratios(work, 'default', edp))}, "
                   f"before {span(shift_ratios(work, 'no-variability', edp))}")
    for name, when in (("default", "after"), ("no-variability", "before")):
        out.append(f"- 3-storey disp_amplification, largest |PRCC| {when}: "
                   + prcc_top(work, name, "3-storey", "disp_amplification"))
    return "\n".join(out)


def elastic_facts(work):
    elastic, yielding = curves(work, "elastic"), curves(work, "no-variability")
    ok = lambda r: r is not None and r["status"] == "ok"
    lower = [100 * (1 - theta_g(yielding[k]) / theta_g(elastic[k])) for k in elastic
             if k[1] == "drift" and ok(elastic[k]) and ok(yielding.get(k))]
    out = [f"- yielding lowers the drift limits' median PGA by {span(lower, '{:.0f}')} % "
           "(the limits with a finite fit in both)"]
    for name, c in (("elastic", elastic), ("yielding", yielding)):
        p, f = c[("3-storey", "drift", 0.01, True)], c[("3-storey", "drift", 0.01, False)]
        if ok(p) and ok(f):
            out.append(f"- 3-storey, 1 % drift, {name}: reached at "
                       f"{100 * (1 - theta_g(p) / theta_g(f)):.0f} % lower PGA with pounding")
    return "\n".join(out)


def pounding_facts(work):
    """Where pounding shows in the default study: the storeys next to the contact."""
    c = curves(work, "default")
    shifts = {(r["building_name"], r["edp"], float(r["limit"])): float(r["ratio"])
              for r in read_csv(os.path.join(work, "default-fragility", "shift.csv"))
              if r.get("model", "all") == "all" and r["ratio"]}
    out = []
    for edp, lim in (("residual_drift", 0.002), ("ductility", 2.0)):
        for b in ("5-storey", "3-storey"):
            out.append(f"- {b}, {limit_text(edp, lim)}: median PGA "
                       f"{100 * (1 - shifts[(b, edp, lim)]):.0f} % lower with pounding (the shift, "
                       "like for like)")
    with pound.open_campaign(os.path.join(work, "default.h5")) as h:
        im = h.im / G
        band = (im > 0.3 - 1e-9) & (im < 0.6 + 1e-9)
        for name, key in (("ductility", "ductility"), ("residual drift", "residual_drift")):
            pnd = h.response(f"{key}_pounding")[band]
            free = h.response(f"{key}_free")[band]
            out.append(f"- {name}, 0.3-0.6 g ({int(band.sum())} samples), median with pounding / "
                       "median without: " + "; ".join(
                           f"{h.building_names[b]} storeys 1-{floors} " + ", ".join(
                               f"{np.nanmedian(pnd[:, b, s]) / np.nanmedian(free[:, b, s]):.2f}"
                               for s in range(floors))
                           for b, floors in enumerate(h.floors)))
        n = len(im)
        for run in ("pounding", "free"):
            d = h.response(f"ductility_{run}")[:, 0, :]
            top = np.nanargmax(d, axis=1)
            out.append(f"- 5-storey's largest ductility in its 4th or 5th storey, {run}: "
                       f"{int(np.sum(top >= 3))} of {n} samples")
    force = c[("5-storey", "force", 1e5, True)]
    out.append(f"- peak pounding force 100 kN: median PGA {theta_g(force):.3f} g, beta "
               f"{float(force['beta']):.2f}")
    return "\n".join(out)


def continuous_facts(work):
    c = curves(work, "smoke-continuous")
    p, f = c[("T0.75", "drift", 0.02, True)], c[("T0.75", "drift", 0.02, False)]
    shift = [r for r in read_csv(os.path.join(work, "smoke-continuous-fragility", "shift.csv"))
             if r["building_name"] == "T0.75" and r["edp"] == "drift"][0]
    return (f"- T0.75 at 2 % drift: theta {theta_g(p):.3f} g with pounding against "
            f"{theta_g(f):.3f} g without, ratio {float(shift['ratio']):.3f} "
            f"[{float(shift['ratio_ci90_lo']):.3f}, {float(shift['ratio_ci90_hi']):.3f}]")


def risk_block(work):
    """The first two blocks of pound risk's table: the gap for the target and the code rules."""
    text = open(os.path.join(work, "default-risk.txt")).read()
    start = text.index("Gap needed for the target")
    end = text.index("Pounding at each gap")
    return "```\n" + text[start:end].rstrip("\n") + "\n```"


def e2(x):
    """1.37e-2 as docs/risk.md writes it."""
    m, e = f"{x:.2e}".split("e")
    return f"{m}e{int(e)}"


def prob(x, p=None):
    """A probability as docs/risk.md writes it: 4 decimals when the estimate p is below 0.01."""
    return f"{x:.4f}" if (x if p is None else p) < 0.01 else f"{x:.3f}"


# The grid points docs/risk.md shows: the first five above 0 and the seventh.
RISK_GAP_ROWS = [1, 2, 3, 4, 5, 7]


def risk_gaps_table(work):
    rows = [r for r in read_csv(os.path.join(work, "default-risk", "risk_gaps.csv"))
            if r["pair"] == "1"]
    out = ["| gap [m] | samples pounding | theta [g] | beta | nu [1/yr] | P(50 years) |",
           "|---|---|---|---|---|---|"]
    for k in RISK_GAP_ROWS:
        if k >= len(rows) or rows[k]["status"] != "ok":
            continue
        r = rows[k]
        p, lo, hi = (float(r[x]) for x in ("probability", "probability_ci90_lo",
                                            "probability_ci90_hi"))
        out.append(f"| {float(r['gap_m']):.3f} | {r['pounding']} / {r['analyses']} | "
                   f"{float(r['theta_mps2']) / G:.3f} | {float(r['beta']):.2f} | "
                   f"{e2(float(r['maf_per_year']))} | {prob(p)} [{prob(lo, p)}, {prob(hi, p)}] |")
    return "\n".join(out)


def risk_damage_table(work):
    rows = read_csv(os.path.join(work, "default-risk", "damage_maf.csv"))
    by = {(r["building_name"], r["edp"], float(r["limit"])): r for r in rows}
    by = {k: r for k, r in by.items()}
    rows = [r for r in rows if r.get("model", "all") == "all"]
    by = {(r["building_name"], r["edp"], float(r["limit"])): r for r in rows}
    groups = [("collapse", "collapse", (1.0,)),
              ("drift", "drift 1 % / 2 % / 4 %", (0.01, 0.02, 0.04)),
              ("residual_drift", "residual drift 0.2 / 0.5 / 1 %", (0.002, 0.005, 0.01)),
              ("ductility", "ductility 1 / 2 / 4", (1.0, 2.0, 4.0))]
    out = ["| building | limit | nu with pounding | nu without | ratio |", "|---|---|---|---|---|"]
    for b in ("5-storey", "3-storey"):
        for edp, label, limits in groups:
            rs = [by.get((b, edp, lim)) for lim in limits]
            if None in rs:
                continue

            def col(key, fmt):
                return " / ".join(fmt(float(r[key])) if r[key] else "-" for r in rs)

            out.append(f"| {b} | {label} | {col('maf_pounding_per_year', e2)} | "
                       f"{col('maf_free_per_year', e2)} | {col('ratio', lambda x: f'{x:.2f}')} |")
    return "\n".join(out)


def collapse_risk_table(work):
    """Collapse in 50 years on the example hazard curve and the collapse margin ratio at its
    2475-year PGA (pound risk --design-im), per building, pooled and per model."""
    out = ["| building | model | nu with pounding [1/yr] | nu without | ratio | P(50 years) with / "
           "without | CMR with / without |", "|---|---|---|---|---|---|---|"]
    text = open(os.path.join(work, "default-risk-mce.txt")).read().splitlines()
    start = next(i for i, line in enumerate(text) if line.startswith("Collapse:"))
    for line in text[start + 2:]:
        # * like for like (a neighbour's collapse censored); the probabilities' bootstrap bands
        # ([lo, hi] after each) are not in this table.
        f = re.sub(r"\s*\[[^\]]*\]", "", line.replace(" *", "")).split()
        if len(f) != 9:
            break
        out.append(f"| {f[0]} | {f[1]} | {f[2]} | {f[3]} | {f[4]} | {f[5]} / {f[6]} | "
                   f"{f[7]} / {f[8]} |")
    return f"(2475-year PGA {mce_pga():.4f} g)\n\n" + "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", default=os.path.join(ROOT, "results", "docs-numbers"))
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--reuse", action="store_true")
    a = ap.parse_args()
    if not os.access(POUND, os.X_OK):
        sys.exit(f"docs_numbers: {POUND} not found; build first (cmake --preset release && "
                 "cmake --build --preset release)")
    make_runs(a.work, a.ranks, a.reuse)
    sections = [
        ("docs/fragility.md, Example: the headline (pound fragility --input default.h5)",
         headline(a.work)),
        ("docs/fragility.md, Example: numbers the prose below the headline quotes",
         headline_facts(a.work)),
        ("docs/fragility.md, Example: the betas before and after issue 12", betas_table(a.work)),
        ("docs/fragility.md, Example: numbers the prose around the betas table quotes",
         betas_facts(a.work)),
        ("docs/fragility.md, Example: collapse with and without pounding", collapse_table(a.work)),
        ("docs/fragility.md, Example: the two contact models", model_facts(a.work)),
        ("docs/hysteresis.md, Damping near collapse: initial against tangent stiffness",
         damping_table(a.work)),
        ("docs/fragility.md, Example: where pounding shows (the default study)",
         pounding_facts(a.work)),
        ("docs/fragility.md, Example: the continuous-IM variant of the smoke study",
         continuous_facts(a.work)),
        ("docs/risk.md, The default study: pound risk's first blocks", risk_block(a.work)),
        ("docs/risk.md, The default study: pounding in 50 years against the gap",
         risk_gaps_table(a.work)),
        ("docs/risk.md, The default study: damage limits", risk_damage_table(a.work)),
        ("docs/risk.md, The default study: collapse", collapse_risk_table(a.work)),
    ]
    for title, body in sections:
        print(f"== {title}\n\n{body}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
