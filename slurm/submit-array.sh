#!/bin/bash
# Submits a campaign split into CHUNKS array tasks plus the merge job that waits for them.
#
#   slurm/submit-array.sh [sbatch options for each chunk --] CHUNKS STUDY.ini RUN.h5 [campaign options]
#
# e.g.  slurm/submit-array.sh --ntasks=32 --time=02:00:00 -- 16 studies/fragility-default.ini \
#           frag.h5 --samples 400000
#
# Prints "ARRAYJOBID MERGEJOBID" on stdout. Each chunk job exits with pound campaign's status
# (0 complete, also when some samples failed: pound campaign's 4, logged; 75 stopped early with
# its journal kept, else an error); the merge runs only when every chunk exited 0 (afterok),
# otherwise Slurm cancels it. A chunk whose part another campaign is writing (an earlier
# submission still running) tries again (POUND_LOCK_TRIES, POUND_LOCK_SLEEP: see
# campaign-array.sbatch) and exits 0 once it finds the part complete, so that the merge reads
# only finished parts.
# Running the same command again after some chunks stopped early (time limit) or failed
# resumes them: finished chunks end at once (exit 0), the others continue from their journals,
# and a new merge job follows.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

sb=()
if [[ " $* " == *" -- "* ]]; then
  while [[ $1 != -- ]]; do sb+=("$1"); shift; done
  shift
fi
if [[ $# -lt 3 ]]; then
  sed -n '2,18p' "$0" >&2
  exit 2
fi
chunks=$1
study=$2
out=$3
shift 3
if ! [[ "$chunks" =~ ^[1-9][0-9]*$ ]]; then
  echo "submit-array: CHUNKS must be a whole number >= 1, not '$chunks'" >&2
  exit 2
fi
export POUND_SLURM_DIR=$here
array=$(sbatch --parsable --array=0-$((chunks - 1)) "${sb[@]}" \
  "$here/campaign-array.sbatch" "$chunks" "$study" "$out" "$@")
array=${array%%;*}
merge=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes \
  "$here/campaign-merge.sbatch" "$out" "$chunks")
merge=${merge%%;*}
echo "submit-array: chunks: array job $array (tasks 0-$((chunks - 1))); merge: job $merge (after all chunks succeed)" >&2
echo "$array $merge"
