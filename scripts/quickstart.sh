#!/usr/bin/env bash
# Installs the Debian packages, builds pound (Release) and runs the default study end to end:
# a Monte Carlo campaign on two MPI ranks (studies/fragility-default.ini), the fragility
# analysis, and the figures.
#   bash scripts/quickstart.sh               # the full default study (960 samples)
#   bash scripts/quickstart.sh --samples 24  # a smoke run
set -euo pipefail
cd "$(dirname "$0")/.."
samples=()
if [ "${1:-}" = "--samples" ]; then samples=(--samples "$2"); fi
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
out=results/default
mkdir -p "$out"
mpi=(mpirun -np 2)
# Open MPI refuses to run as root unless told; containers and CI machines often are root.
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi
# Two ranks even on a machine that reports fewer cores.
mpi+=(--oversubscribe)
echo "== ${mpi[*]} build/bin/pound campaign --config studies/fragility-default.ini --out $out/campaign.h5 --force ${samples[*]}"
"${mpi[@]}" build/bin/pound campaign --config studies/fragility-default.ini \
  --out "$out/campaign.h5" --force "${samples[@]}"
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
/usr/bin/python3 scripts/plot_results.py --campaign "$out/campaign.h5" --fragility "$out/fragility" \
  --motions "$out/motions/motions.h5" --histories "$out/ch8-histories.h5" --out "$out/plots"
echo "== results:  $out/campaign.h5 (samples, schema in docs/campaign.md)"
echo "             $out/fragility/ (curves.csv, shift.csv, observations.csv, sensitivity.csv, fragility.h5)"
echo "== pictures: $out/plots/*.png"
