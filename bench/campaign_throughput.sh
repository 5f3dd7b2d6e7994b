#!/usr/bin/env bash
# Benchmark: campaign throughput on 1 and 2 MPI ranks (issue 5: 2 ranks >= 1.8 x 1 rank).
# Usage: bash bench/campaign_throughput.sh [SAMPLES] [STUDY]
# Prints samples per second for each rank count and the ratio. Run it on an idle machine, with
# enough samples that the fixed start-up (about 0.4 s per run) does not dominate.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-2400}
study=${2:-studies/campaign-smoke.ini}
pound=${POUND:-build/bin/pound}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpi=(mpirun --oversubscribe)
if [ "$(id -u)" -eq 0 ]; then mpi+=(--allow-run-as-root); fi
declare -A rate
for np in 1 2; do
  start=$(date +%s.%N)
  "${mpi[@]}" -np "$np" "$pound" campaign --config "$study" --samples "$n" --out "$tmp/r$np.h5" --quiet 2>"$tmp/log$np"
  end=$(date +%s.%N)
  secs=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
  rate[$np]=$(awk -v n="$n" -v s="$secs" 'BEGIN { print n / s }')
  tail -1 "$tmp/log$np"
  printf 'ranks %d: %d samples in %.2f s = %.2f samples/s\n' "$np" "$n" "$secs" "${rate[$np]}"
done
awk -v a="${rate[2]}" -v b="${rate[1]}" 'BEGIN { printf "speed-up 2 ranks / 1 rank: %.3f\n", a / b }' 
