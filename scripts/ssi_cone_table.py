#!/usr/bin/python3
"""The numbers of docs/ssi.md ("How large an error"): Wolf's cone under the buildings of the
default study, the frequency-dependent cone against its frequency-independent constants
K + i omega C (issue 29):

    /usr/bin/python3 scripts/ssi_cone_table.py [--study studies/fragility-default.ini]

Reads each building's floor masses, storey stiffnesses and heights and its slab_length (taken as
the side B of a square footprint) from the study; its fixed-base modes; the cone's constants
for a circular footing of the equivalent radius (sway: equal area, r = B / sqrt(pi); rocking:
equal moment of inertia of the area, r = (4 I / pi)^(1/4) = B (3 pi)^(-1/4)) on soft soil
(Vs 100, 150, 200 m/s; nu 0.3, 0.4, 0.45; rho 1800 and 2000 kg/m^3, which changes K and C but
none of the ratios); and prints, in the Markdown of docs/ssi.md, the cone's dynamic stiffness
against a0 = omega r / Vs and, per building and soil, at the fixed-base fundamental frequency
the ratio of the cone's rocking stiffness and damping coefficient to the constants', and the
flexible-base period and damping ratio of the first mode's oscillator (Veletsos & Meek 1974)
with the constants and with the cone. numpy only.
"""
import argparse
import configparser
import math
import os

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def cone(r, vs, rho, nu):
    """The cone's constants (src/structure/foundation.cpp; Wolf 1994, Wolf & Deeks 2004)."""
    G = rho * vs * vs
    capped = nu > 1.0 / 3.0
    vp = 2.0 * vs if capped else vs * math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))
    i0 = math.pi * r**4 / 4.0
    return {
        "Kx": 8.0 * G * r / (2.0 - nu),
        "Cx": rho * vs * math.pi * r * r,
        "Kt": 8.0 * G * r**3 / (3.0 * (1.0 - nu)),
        "Ct": rho * vp * i0,
        "dM": 0.3 * math.pi * (nu - 1.0 / 3.0) * rho * r**5 if capped else 0.0,
        "zx": math.pi * (2.0 - nu) / 8.0 * r,
        "zt": 9.0 * math.pi * (1.0 - nu) * (vp / vs) ** 2 / 32.0 * r,
        "c": vp,
    }


def rocking_ratios(c, omega):
    """The rocking cone's Re S / K and (Im S / omega) / C at omega, and b0 = omega z0 / c: the
    trapped inertia (-omega^2 dM in both models) left out."""
    b0 = omega * c["zt"] / c["c"]
    return 1.0 - b0 * b0 / (3.0 * (1.0 + b0 * b0)), b0 * b0 / (1.0 + b0 * b0), b0


def read_buildings(path):
    ini = configparser.ConfigParser(inline_comment_prefixes=("#",))
    ini.read(path)
    out = []
    n = 1
    while ini.has_section(f"building{n}"):
        s = ini[f"building{n}"]
        floats = lambda key: [float(x) for x in s[key].replace(",", " ").split()]  # noqa: E731
        m = np.array(floats("masses"))
        k = np.array(floats("stiffnesses"))
        h = np.array(floats("storey_heights") if "storey_heights" in s else [3.0])
        k = np.resize(k, m.size)
        h = np.resize(h, m.size)
        out.append({"name": s.get("name", f"building{n}"), "m": m, "k": k, "h": h,
                    "B": floats("slab_length")[0]})
        n += 1
    return out


def first_mode(b):
    """Fixed-base first mode: omega1, the equivalent SDOF's stiffness k* = omega1^2 M* and height
    h* = sum m phi z / sum m phi (the height of the resultant of the first mode's forces)."""
    n = b["m"].size
    K = np.zeros((n, n))
    for j in range(n):
        K[j, j] += b["k"][j]
        if j > 0:
            K[j - 1, j - 1] += b["k"][j]
            K[j - 1, j] -= b["k"][j]
            K[j, j - 1] -= b["k"][j]
    s = 1.0 / np.sqrt(b["m"])
    w2, v = np.linalg.eigh(s[:, None] * K * s[None, :])
    phi = s * v[:, 0]
    phi /= phi[-1]
    z = np.cumsum(b["h"])
    L = np.sum(b["m"] * phi)
    M = L * L / np.sum(b["m"] * phi * phi)
    return math.sqrt(w2[0]), w2[0] * M, np.sum(b["m"] * phi * z) / L


def flexible_base(w1, k, h, cx, ct, cone_model, zeta=0.05):
    """The first mode's single-degree-of-freedom system (mass k / w1^2, stiffness k with the
    structure's damping as 2 i zeta k, at height h) on a massless foundation: its complex
    stiffness k~ in series with the sway and rocking impedances, 1 / k~ = 1 / (k (1 + 2 i zeta))
    + 1 / S_x + h^2 / S_t (the replacement oscillator of Veletsos & Meek 1974), at the frequency
    w~ where k / w1^2 w~^2 = Re k~ (iterated, the impedances at w~): returns T~ = 2 pi / w~ and
    the system's damping ratio zeta~ = Im k~ / (2 Re k~)."""
    m = k / (w1 * w1)
    w = w1
    for _ in range(200):
        sx = cx["Kx"] + 1j * w * cx["Cx"]
        kr, cr = rocking_ratios(ct, w)[:2] if cone_model else (1.0, 1.0)
        st = ct["Kt"] * kr + 1j * w * ct["Ct"] * cr
        ks = 1.0 / (1.0 / (k * (1.0 + 2j * zeta)) + 1.0 / sx + h * h / st)
        new = math.sqrt(ks.real / m)
        if abs(new - w) < 1e-12 * w1:
            w = new
            break
        w = new
    return 2.0 * math.pi / w, ks.imag / (2.0 * ks.real)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--study", default=os.path.join(ROOT, "studies", "fragility-default.ini"))
    a = ap.parse_args()
    buildings = read_buildings(a.study)

    print("Cone dynamic stiffness against a0 = omega r / Vs (r the footing's radius): sway is "
          "K + i omega C at every a0; rocking, Re S / K and (Im S / omega) / C (the trapped "
          "inertia left out):\n")
    a0s = [0.25, 0.5, 1.0, 1.5, 2.0, 3.0]
    print("| nu | | " + " | ".join(f"a0 = {x:g}" for x in a0s) + " |")
    print("|---|---|" + "---|" * len(a0s))
    for nu in (0.3, 0.4, 0.45):
        c = cone(1.0, 1.0, 1.0, nu)  # r = Vs = 1: omega = a0
        ks = [rocking_ratios(c, x)[0] for x in a0s]
        cs = [rocking_ratios(c, x)[1] for x in a0s]
        print(f"| {nu:g} | Re S / K | " + " | ".join(f"{v:.3f}" for v in ks) + " |")
        print(f"| | (Im S / omega) / C | " + " | ".join(f"{v:.3f}" for v in cs) + " |")

    print("\nThe buildings (fixed base; square footprints of side B = slab_length):\n")
    print("| building | T1 [s] | k* [N/m] | h* [m] | B [m] | r sway [m] | r rocking [m] |")
    print("|---|---|---|---|---|---|---|")
    modes = []
    for b in buildings:
        w1, k, h = first_mode(b)
        rx, rt = b["B"] / math.sqrt(math.pi), b["B"] * (3.0 * math.pi) ** -0.25
        modes.append((w1, k, h, rx, rt))
        print(f"| {b['name']} | {2 * math.pi / w1:.3f} | {k:.3e} | {h:.2f} | {b['B']:g} | "
              f"{rx:.2f} | {rt:.2f} |")

    print("\nThe constants (rho = 1800 / 2000 kg/m^3; K and C scale with rho):\n")
    print("| building | Vs [m/s] | nu | Kx [N/m] | Cx [N s/m] | Kt [N m/rad] | Ct [N m s/rad] "
          "| dM_t [kg m^2] |")
    print("|---|---|---|---|---|---|---|---|")
    for b, (w1, k, h, rx, rt) in zip(buildings, modes):
        for vs in (100.0, 200.0):
            for nu in (0.3, 0.45):
                lo = (cone(rx, vs, 1800.0, nu), cone(rt, vs, 1800.0, nu))
                hi = (cone(rx, vs, 2000.0, nu), cone(rt, vs, 2000.0, nu))
                f = lambda key, i: f"{lo[i][key]:.3g} / {hi[i][key]:.3g}"  # noqa: E731
                print(f"| {b['name']} | {vs:g} | {nu:g} | {f('Kx', 0)} | {f('Cx', 0)} | "
                      f"{f('Kt', 1)} | {f('Ct', 1)} | {f('dM', 1)} |")

    print("\nAt the fundamental frequencies (rho = 1900 kg/m^3; no ratio depends on it): a0 of "
          "the rocking radius at the fixed-base T1, the rocking cone's Re S / K and "
          "(Im S / omega) / C there (sway: 1 and 1); the flexible-base period T~ and damping "
          "ratio zeta~ of the first mode's oscillator (5 % structural damping) with the "
          "constants and with the cone:\n")
    print("| building | Vs [m/s] | nu | a0 | Re S_t / K_t | (Im S_t / omega) / C_t | T~ [s] "
          "constants | T~ [s] cone | zeta~ constants | zeta~ cone |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for b, (w1, k, h, rx, rt) in zip(buildings, modes):
        for vs in (100.0, 150.0, 200.0):
            for nu in (0.3, 0.4, 0.45):
                cx, ct = cone(rx, vs, 1900.0, nu), cone(rt, vs, 1900.0, nu)
                re1, d1, _ = rocking_ratios(ct, w1)
                tc, zc = flexible_base(w1, k, h, cx, ct, False)
                tw, zw = flexible_base(w1, k, h, cx, ct, True)
                print(f"| {b['name']} | {vs:g} | {nu:g} | {w1 * rt / vs:.2f} | {re1:.3f} | "
                      f"{d1:.3f} | {tc:.3f} | {tw:.3f} | {zc:.4f} | {zw:.4f} |")


if __name__ == "__main__":
    main()
