#!/usr/bin/env bash
# Issue 13: peak resident memory per rank after the first 300 samples of campaigns of 10^4,
# 10^6 and 10^8 samples (studies/campaign-smoke.ini on two ranks; --sample-range 0:300 runs the
# first 300 samples of the N-sample campaign, Latin hypercube strata and master bookkeeping
# sized for N). Target: within 10 % of each other.
# Usage: bash bench/campaign_memory.sh [pound binary]
set -euo pipefail
cd "$(dirname "$0")/.."
POUND=${1:-build/bin/pound}
mpi=(mpirun -np 2 --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%12s %12s\n' samples 'peak MB/rank'
for n in 10000 1000000 100000000; do
  line=$("${mpi[@]}" "$POUND" campaign --config studies/campaign-smoke.ini --samples "$n" \
           --sample-range 0:300 --out "$tmp/run.h5" --force --quiet 2>&1 | grep 'peak memory')
  mb=$(sed -E 's/.*peak memory per rank ([0-9.]+) MB.*/\1/' <<<"$line")
  printf '%12s %12s\n' "$n" "$mb"
done
