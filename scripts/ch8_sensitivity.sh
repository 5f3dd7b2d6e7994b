#!/usr/bin/env bash
# Sensitivity of the thesis' chapter 8 practical example (studies/ch8-five-three.ini) to the
# wave-speed factor chi (1/4, 1/8, 1/16; D = 1) and the contact stiffness factor D (1, 2, 5;
# chi = 1/8), as in Khatiwada's Figures 8.31-8.33, plus the building damping the thesis does not
# state (2 %, 10 %). Prints one table (docs/sears.md, "Validation: thesis chapter 8").
# Every sensitivity case runs with the thesis' N = 100 modes and again with N = 400, because
# at N = 100 the stiffer contacts (D = 2, 5) and the slower wave (chi = 1/16) leave the force
# rise time Z / (2 k) unresolved (docs/sears.md, "Modal truncation"). About 5 s.
#
#   POUND=build-s8/bin/pound scripts/ch8_sensitivity.sh
#
# Columns: peak pounding force at floors 1-3 [kN]; peak absolute acceleration of the 5-storey's
# third floor (rigid floor DOF, slab centre, contact face) and of the 3-storey's third floor
# (slab centre, contact face) [g]; displacement amplification (with / without pounding) of
# both roofs and of the 5-storey's third floor; impacts per floor (raw contact phases, and the
# thresholded count when `pound simulate --json` reports it as "significant_impacts").
set -euo pipefail
cd "$(dirname "$0")/.."
POUND=${POUND:-build/bin/pound}
STUDY=studies/ch8-five-three.ini

run() {  # label, modes, extra options...
  local label=$1 modes=$2
  shift 2
  "$POUND" simulate --config "$STUDY" --json --sears.modes "$modes" "$@" 2>/dev/null |
    python3 -c '
import json, sys
g = 9.80665
label = sys.argv[1]
d = json.load(sys.stdin)
b5, b3 = d["buildings"][0]["floors"], d["buildings"][1]["floors"]
slab = {(s["building"], s["floor"]): s for s in d["slabs"]}
F = [c["peak_force_N"] / 1e3 for c in d["contacts"]]
imp = "/".join(str(c["impacts"]) for c in d["contacts"])
if all("significant_impacts" in c for c in d["contacts"]):
    imp += " (" + "/".join(str(c["significant_impacts"]) for c in d["contacts"]) + ")"
print("| %s | %s | %.0f | %.0f | %.0f | %.2f | %.2f | %.1f | %.2f | %.1f | %.3f | %.3f | %.3f | %s |" % (
    label, sys.argv[2], F[0], F[1], F[2],
    b5[2]["peak_abs_accel_pounding_mps2"] / g,
    slab[(0, 3)]["peak_centre_accel_mps2"] / g, slab[(0, 3)]["peak_face_accel_mps2"] / g,
    slab[(1, 3)]["peak_centre_accel_mps2"] / g, slab[(1, 3)]["peak_face_accel_mps2"] / g,
    b5[-1]["disp_amplification"], b3[-1]["disp_amplification"], b5[2]["disp_amplification"],
    imp))
' "$label" "$modes"
}

echo "| case | N | F1 [kN] | F2 [kN] | F3 [kN] | 5-st fl3 floor [g] | 5-st fl3 centre [g] | 5-st fl3 face [g] | 3-st fl3 centre [g] | 3-st fl3 face [g] | roof amp 5-st | roof amp 3-st | fl3 amp 5-st | impacts fl1/2/3 |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for modes in 100 400; do
  run "chi = 1/8, D = 1 (study)" $modes
  run "chi = 1/4, D = 1" $modes --sears.chi 0.25
  run "chi = 1/16, D = 1" $modes --sears.chi 0.0625
  run "chi = 1/8, D = 2" $modes --sears.D 2
  run "chi = 1/8, D = 5" $modes --sears.D 5
done
run "building damping 2 %" 100 --building1.damping 0.02 --building2.damping 0.02
run "building damping 10 %" 100 --building1.damping 0.10 --building2.damping 0.10
