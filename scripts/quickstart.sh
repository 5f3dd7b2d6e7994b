#!/usr/bin/env bash
# Installs the Debian packages, builds pound (Release) and runs the default study: a Monte
# Carlo fragility campaign on two MPI ranks (studies/fragility-default.ini).
#   bash scripts/quickstart.sh               # the full default study (160 samples)
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
echo "== results: $out/campaign.h5 (schema: docs/campaign.md)"
