#!/usr/bin/env bash
# Runs the libFuzzer harnesses (fuzz/*_fuzz.cpp) one after the other, each for SECONDS, and
# prints per harness the result, executions per second (runs / SECONDS), runs, the corpus size
# (inputs / kB) and the coverage (edges). Exits 1 when any harness crashed, hung, ran out of
# memory or broke an invariant in pound's code (the input that did it is kept under the work
# folder, and printed), 0 otherwise. A fault inside libhdf5 itself is counted ("ok,hdf5:N"),
# its input kept, and the harness runs on.
#   bash fuzz/run.sh 30                       # every harness for 30 s (CI)
#   bash fuzz/run.sh 3600 fuzz_journal        # one harness for an hour
# It installs clang (scripts/install-deps.sh --fuzz) and builds the harnesses with the preset
# 'fuzz' (build-fuzz/) unless FUZZ_BIN names a folder of built harnesses. The corpora grow
# under FUZZ_WORK (default build-fuzz/work), seeded from studies/, motions/, fuzz/seeds/ and
# the seeds each harness writes from the library itself (-pound_prepare).
# Environment: FUZZ_BIN, FUZZ_WORK, FUZZ_REPO (the repository for the seeds; default this
# one), FUZZ_TIMEOUT (seconds one input may take before it counts as a hang; default 20).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
if [[ $# -lt 1 || ! "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: bash fuzz/run.sh SECONDS [harness ...]" >&2
  exit 2
fi
seconds=$1
shift
all=(fuzz_study fuzz_motion_at2 fuzz_motion_columns fuzz_motion_fixed_width fuzz_motion_auto
     fuzz_journal fuzz_campaign_file fuzz_hazard)
harnesses=("$@")
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=("${all[@]}")
repo=${FUZZ_REPO:-$here}
timeout=${FUZZ_TIMEOUT:-20}

if [[ -z "${FUZZ_BIN:-}" ]]; then
  bash "$here/scripts/install-deps.sh" --fuzz
  (cd "$here" && cmake --preset fuzz >/dev/null && cmake --build --preset fuzz -j "$(nproc)")
  bin=$here/build-fuzz/fuzz
else
  bin=$FUZZ_BIN
fi
work=${FUZZ_WORK:-$here/build-fuzz/work}
mkdir -p "$work"

seed_dirs() {  # the repository's seeds of a harness
  case $1 in
    fuzz_study) echo "$repo/studies $repo/fuzz/seeds/study" ;;
    fuzz_motion_*) echo "$repo/motions $repo/fuzz/seeds/motion" ;;
    fuzz_hazard) echo "$repo/studies" ;;
  esac
}

failed=()
rows=()
for h in "${harnesses[@]}"; do
  [[ -x "$bin/$h" ]] || { echo "fuzz: $bin/$h not found" >&2; failed+=("$h (missing)"); continue; }
  w=$work/$h
  mkdir -p "$w/corpus" "$w/artifacts"
  rm -rf "$w/prepared"
  if ! "$bin/$h" -pound_prepare="$w/prepared" >"$w/prepare.log" 2>&1; then
    echo "fuzz: $h could not write its seeds:" >&2
    tail -n 20 "$w/prepare.log" >&2
    failed+=("$h (seeds)")
    continue
  fi
  dict=()
  [[ -s "$w/prepared/dict" ]] && dict=(-dict="$w/prepared/dict")
  # LeakSanitizer off where libhdf5 (not instrumented) loses blocks across inputs.
  [[ $h == fuzz_campaign_file ]] && dict+=(-detect_leaks=0)
  echo "== $h: ${seconds} s ($(date -u +%Y-%m-%dT%H:%M:%SZ)), log $w/fuzz.log"
  # A fault inside libhdf5 itself (a hang or crash on a damaged file that HDF5's own tools hit
  # too, docs/fuzzing.md) is not pound's: it is reported, its input kept, and the harness goes
  # on for the rest of its time. Any other fault fails the run.
  : >"$w/fuzz.log"
  start=$(date +%s)
  hdf5_faults=0
  runs=0
  result=ok
  while :; do
    left=$(( seconds - ($(date +%s) - start) ))
    (( left >= 1 )) || break
    rc=0
    # Inputs libFuzzer keeps for a fault; not the slow units it writes after a slow input
    # (-report_slow_units, 10 s: a loaded machine, not a fault of pound's).
    before=$(find "$w/artifacts" -type f ! -name 'slow-unit-*' | wc -l)
    "$bin/$h" -max_total_time="$left" -timeout="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$w/artifacts/" "${dict[@]}" \
      "$w/corpus" "$w/prepared/seeds" $(seed_dirs "$h") >"$w/last.log" 2>&1 || rc=$?
    cat "$w/last.log" >>"$w/fuzz.log"
    r=$(sed -n 's/^stat::number_of_executed_units: *//p' "$w/last.log" | tail -n 1)
    runs=$(( runs + ${r:-0} ))
    [[ $rc -eq 0 && $(find "$w/artifacts" -type f ! -name 'slow-unit-*' | wc -l) -eq $before ]] &&
      break
    # The first stack frame that is neither the sanitizers', libFuzzer's, the C library's nor
    # an allocator's (the caller of malloc or new decides).
    frame=$(sed -n '/ERROR: \(libFuzzer\|AddressSanitizer\|LeakSanitizer\)\|runtime error/,$p' "$w/last.log" |
      grep -E '^ +#[0-9]+ ' | grep -vE '__sanitizer|__interceptor_|fuzzer::|libc\.so|sysdeps/|raise|abort|pthread_kill|__asan|__ubsan| in (malloc|calloc|realloc|free|operator new|operator delete)' |
      head -n 1 || true)  # no frame (an exit without a fault report) must not end the script
    # Out of memory: libFuzzer lists the live allocations; HDF5's when libhdf5 holds them and
    # no frame of pound's code does (HDF5 itself grows to 10 GB reading some damaged files).
    if grep -q 'ERROR: libFuzzer: out-of-memory' "$w/last.log"; then
      frame=$(sed -n '/ERROR: libFuzzer: out-of-memory/,$p' "$w/last.log" | grep -E '^ +#[0-9]+ ' ||
        true)
      if grep -q libhdf5 <<<"$frame" && ! grep -q 'in pound::' <<<"$frame"; then
        frame="out of memory, live allocations in libhdf5"
      else
        frame="out of memory: $(grep 'in pound::' <<<"$frame" | head -n 1 || true)"
      fi
    fi
    if [[ $frame == *libhdf5* ]]; then
      hdf5_faults=$(( hdf5_faults + 1 ))
      echo "   fault inside libhdf5 (input kept, harness goes on): $frame" | cut -c1-160
      continue
    fi
    result="FAILED (exit $rc)"
    failed+=("$h")
    {
      echo "!! $h: a crash, hang, out-of-memory or broken invariant in pound; inputs kept in $w/artifacts"
      grep -E 'ERROR|invariant broken|runtime error|SUMMARY|deadly signal|timeout|out-of-memory' "$w/last.log" | head -n 20
      echo "   first frame: $frame"
      echo "   reproduce: $bin/$h $w/artifacts/<input>   (full log: $w/fuzz.log)"
    } >&2
    break
  done
  rate=$(( runs / (seconds > 0 ? seconds : 1) ))
  corp="$(ls "$w/corpus" | wc -l)/$(du -sk "$w/corpus" | cut -f1)kB"
  cov=$(grep -o 'cov: [0-9]*' "$w/fuzz.log" | tail -n 1 | cut -d' ' -f2 || true)
  [[ $result == ok && $hdf5_faults -gt 0 ]] && result="ok,hdf5:$hdf5_faults"
  rows+=("$(printf '%-26s %-12s %8s %10s %16s %7s' "$h" "${result%% *}" "$rate" "$runs" "$corp" "${cov:-?}")")
done

echo
echo "fuzz: ${seconds} s per harness, $(date -u +%Y-%m-%d), corpora in $work"
printf '%-26s %-12s %8s %10s %16s %7s\n' harness result execs/s runs "corpus (n/size)" cov
for r in "${rows[@]}"; do echo "$r"; done
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: every harness ran clean"
