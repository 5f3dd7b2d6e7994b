#!/usr/bin/env bash
# Installs the Debian packages, builds pound (Release) and runs the default study end to end:
# a Monte Carlo campaign on two MPI ranks (studies/fragility-default.ini), the fragility
# analysis, the amplification summary, the figures, and last the pounding risk on the example
# hazard curve of studies/hazard-los-angeles-pga.csv: the gap a 2 % probability of pounding in
# 50 years needs, and the code rules' gaps with their probabilities.
#   bash scripts/quickstart.sh               # the full default study (1200 samples)
#   bash scripts/quickstart.sh --samples 24  # a smoke run
set -euo pipefail
cd "$(dirname "$0")/.."
samples=()
if [ "${1:-}" = "--samples" ]; then samples=(--samples "$2"); fi
# Each stage prints its wall time; the build makes the program and the Python module the
# figures use (the tests and the benchmarks are built by scripts/test.sh, which runs them).
t_stage=$(date +%s)
stage_done() {
  local now
  now=$(date +%s)
  echo "== [$1: $((now - t_stage)) s]"
  t_stage=$now
}
bash scripts/install-deps.sh
stage_done "packages"
cmake --preset release >/dev/null
stage_done "configure"
cmake --build --preset release -j "$(nproc)" --target pound _engine
stage_done "build (pound and its Python module)"
out=results/default
mkdir -p "$out"
mpi=(mpirun -np 2)
# Open MPI refuses to run as root unless told; containers and CI machines often are root.
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi
# Two ranks even on a machine that reports fewer cores.
mpi+=(--oversubscribe)
echo "== ${mpi[*]} build/bin/pound campaign --config studies/fragility-default.ini --out $out/campaign.h5 --force ${samples[*]}"
# Exit status 4: finished, some samples failed (listed in the file): the analyses go on.
rc=0
"${mpi[@]}" build/bin/pound campaign --config studies/fragility-default.ini \
  --out "$out/campaign.h5" --force "${samples[@]}" || rc=$?
if [[ $rc -eq 4 ]]; then
  echo "== the campaign finished with failed samples (exit status 4; /samples/message in $out/campaign.h5 says why); the analyses leave them out"
elif [[ $rc -ne 0 ]]; then
  exit "$rc"
fi
stage_done "campaign"
echo "== build/bin/pound fragility --input $out/campaign.h5 --out $out/fragility"
build/bin/pound fragility --input "$out/campaign.h5" --out "$out/fragility"
# Inputs of the figures that the campaign file does not hold: 100 motions like the default
# study's (its target, each matched to its own random target: Boore-Atkinson 2008 sigma,
# Baker-Jayaram 2008 correlation), for the spread of their spectra, and the time histories of
# the chapter 8 example.
build/bin/pound motion generate --spectrum ec8 --ec8-type 1 --ground-type C --ag 0.3 \
  --count 100 --duration 10 --dt 0.01 --seed 2026 --variability spectral \
  --sigma-model boore-atkinson-2008 --correlation baker-jayaram-2008 --out "$out/motions" >/dev/null
build/bin/pound simulate --config studies/ch8-yielding.ini --histories "$out/ch8-histories.h5" >/dev/null
echo "== build/bin/pound summary --input $out/campaign.h5"
build/bin/pound summary --input "$out/campaign.h5" > "$out/summary.txt"
head -n 12 "$out/summary.txt"
echo "   (the whole table: $out/summary.txt)"
# The risk run writes its files first and its table last, so that the answer ends the output.
build/bin/pound risk --input "$out/campaign.h5" --hazard studies/hazard-los-angeles-pga.csv \
  --out "$out/risk" > "$out/risk.txt"
stage_done "analyses"
/usr/bin/python3 scripts/plot_results.py --campaign "$out/campaign.h5" --fragility "$out/fragility" \
  --motions "$out/motions/motions.h5" --histories "$out/ch8-histories.h5" --risk "$out/risk" \
  --out "$out/plots"
stage_done "figures"
echo "== results:  $out/campaign.h5 (samples, /amplification; schema in docs/campaign.md)"
echo "             $out/fragility/ (curves.csv, shift.csv, observations.csv, sensitivity.csv, fragility.h5)"
echo "             $out/risk/ (risk_gaps.csv, code_rules.csv, damage_maf.csv, risk.h5; docs/risk.md)"
echo "== pictures: $out/plots/*.png"
echo "== build/bin/pound risk --input $out/campaign.h5 --hazard studies/hazard-los-angeles-pga.csv --out $out/risk"
sed -n '1,/^Pounding at each gap/p' "$out/risk.txt" | sed '$d'
sed -n '/^Damage limits/,$p' "$out/risk.txt"
