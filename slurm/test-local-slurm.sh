#!/usr/bin/env bash
# End-to-end test of the Slurm scripts in slurm/ on a real single-node Slurm started here.
#
#   bash slurm/test-local-slurm.sh          (from .ci/run; root, or sudo for apt-get)
#
# Installs Debian's slurm-wlm and munge when missing, starts a private munged, slurmctld and
# slurmd with a loopback-only configuration in a temporary folder (nothing under /etc is
# used or changed), submits the real scripts on a small study and checks:
#   1. campaign.sbatch (srun --mpi=pmix) runs a campaign to completion (the reference);
#   2. a campaign.sbatch job with a time limit shorter than the campaign (--time=1 with
#      --signal=B:USR1@58) is stopped by Slurm's signal, keeps its journal and exits 75, the
#      exit status of pound campaign itself, which the script passes on
#      (Slurm may send the signal in the job's first second: the script passes it on once
#      the campaign reports its start, so the outcome does not depend on the machine's speed);
#      campaign-mpirun.sbatch resumes it and is stopped again with
#      `scancel --signal=USR1 --batch`; a third submission completes it; the final file has
#      every sample exactly once and equals the reference (/samples, /response);
#   3. submit-array.sh splits the campaign over a 2-task job array and merges the parts;
#      the merged file equals the reference;
#   4. a job on a file that another job is writing (the same campaign submitted twice) finds it
#      in use: pound campaign exits 75 at once, changing nothing, and the script tries again
#      (POUND_LOCK_SLEEP=2) until the first job has ended, then finds the file complete and
#      exits 0; once campaign-mpirun.sbatch against campaign.sbatch, once an array chunk
#      submitted twice; both files equal a run of the same samples without Slurm.
# Exits 0 only when every check holds. Stops every daemon it started (by the process ids it
# recorded) and removes the temporary folder, also when a check fails (POUND_SLURM_KEEP=1
# keeps the folder for inspection).
#
# Environment: POUND (binary, default build/bin/pound); POUND_SLURM_TEST_SAMPLES (default: as
# many samples as 2 ranks of this machine simulate in about 60 s, measured before the jobs,
# at least 2400, so that the time-limited job surely outlives Slurm's signal, which Slurm's
# 30 s periodic check delivers at most about 30 s after the job starts).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
t0=$(date +%s)
say() { echo "test-local-slurm[$(( $(date +%s) - t0 ))s]: $*"; }

POUND=${POUND:-build/bin/pound}
[[ "$POUND" = /* ]] || POUND=$repo/$POUND
if [[ ! -x "$POUND" ]]; then
  echo "test-local-slurm: $POUND not found; build it first (cmake --preset release && cmake --build build)" >&2
  exit 1
fi
export POUND
study=$repo/studies/campaign-smoke.ini
PY=/usr/bin/python3
parts_py=$repo/slurm/pound_parts.py

# ---------------------------------------------------------------- packages
pkgs=(slurm-wlm munge openmpi-bin python3-h5py python3-numpy)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  SUDO=""
  [[ $(id -u) -ne 0 ]] && SUDO=sudo
  say "installing ${missing[*]}"
  # While installing, a policy-rc.d that forbids starting services keeps the packages from
  # starting the system's own munged, slurmctld and slurmd (this test starts private ones).
  policy=/usr/sbin/policy-rc.d
  made_policy=0
  if [[ ! -e $policy ]]; then
    printf '#!/bin/sh\nexit 101\n' | $SUDO tee "$policy" >/dev/null
    $SUDO chmod 755 "$policy"
    made_policy=1
  fi
  irc=0
  { $SUDO apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; } || irc=$?
  [[ $made_policy == 1 ]] && $SUDO rm -f "$policy"
  [[ $irc -eq 0 ]] || { echo "test-local-slurm: apt-get failed (exit status $irc)" >&2; exit 1; }
fi
say "packages present: ${pkgs[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "test-local-slurm: the Slurm daemons must run as root here; run the test as root" >&2
  exit 1
fi

# ---------------------------------------------------------------- daemons
T=$(mktemp -d /tmp/pound-slurm-test.XXXXXX)
chmod 700 "$T"
daemon_pids=()
daemon_names=()
cleanup() {
  local rc=$?
  set +e
  trap - EXIT INT TERM
  if [[ -n "${SLURM_CONF:-}" && ${#daemon_pids[@]} -ge 2 ]]; then
    # Cancel what is still queued or running and let slurmd end the job steps.
    if [[ -n "$(squeue -h -o %i 2>/dev/null)" ]]; then
      say "cleanup: cancelling jobs still in the queue"
      scancel --full $(squeue -h -o %i 2>/dev/null) 2>/dev/null
      for _ in $(seq 60); do [[ -z "$(squeue -h -o %i 2>/dev/null)" ]] && break; sleep 0.5; done
    fi
  fi
  local i
  for ((i = ${#daemon_pids[@]} - 1; i >= 0; --i)); do
    kill -TERM "${daemon_pids[$i]}" 2>/dev/null
  done
  for ((i = ${#daemon_pids[@]} - 1; i >= 0; --i)); do
    local pid=${daemon_pids[$i]}
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      say "cleanup: ${daemon_names[$i]} (pid $pid) did not stop on SIGTERM; SIGKILL"
      kill -KILL "$pid" 2>/dev/null
    fi
    wait "$pid" 2>/dev/null
    say "cleanup: stopped ${daemon_names[$i]} (pid $pid)"
  done
  if [[ $rc -ne 0 || "${POUND_SLURM_KEEP:-0}" == 1 ]] && [[ -d "$T" ]]; then
    say "logs of the daemons (last lines):"
    for f in "$T"/log/*.log; do [[ -f "$f" ]] && { echo "--- $f"; tail -n 15 "$f"; }; done
  fi
  if [[ "${POUND_SLURM_KEEP:-0}" == 1 ]]; then
    say "cleanup: kept $T"
  else
    rm -rf "$T"
  fi
  if [[ $rc -eq 0 ]]; then say "PASS (all checks hold) in $(( $(date +%s) - t0 )) s"; else say "FAIL (exit status $rc) after $(( $(date +%s) - t0 )) s"; fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

start_daemon() {  # name, command...
  local name=$1
  shift
  "$@" >"$T/log/$name.console" 2>&1 &
  daemon_pids+=($!)
  daemon_names+=("$name")
  say "started $name (pid $!)"
}

mkdir -p "$T"/{etc,munge,state,spool,log,run,jobs}
chmod 700 "$T/munge"
host=$(hostname -s)
read -r ctld_port slurmd_port < <("$PY" -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

# munge: a private key and socket; slurm.conf points at the socket.
dd if=/dev/urandom of="$T/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$T/munge/munge.key"
start_daemon munged munged -F --force --socket="$T/munge/munge.socket" \
  --key-file="$T/munge/munge.key" --pid-file="$T/run/munged.pid" \
  --log-file="$T/log/munged.log" --seed-file="$T/munge/munged.seed"
for _ in $(seq 100); do [[ -S "$T/munge/munge.socket" ]] && break; sleep 0.1; done
munge -S "$T/munge/munge.socket" -n | unmunge -S "$T/munge/munge.socket" >/dev/null
say "munged answers on $T/munge/munge.socket"

cat >"$T/etc/slurm.conf" <<EOF
# Test cluster of slurm/test-local-slurm.sh: one node, loopback only.
ClusterName=poundtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
CommunicationParameters=NoInAddrAny
AuthType=auth/munge
AuthInfo=socket=$T/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/run/slurmctld.pid
SlurmdPidFile=$T/run/slurmd.pid
SlurmctldLogFile=$T/log/slurmctld.log
SlurmdLogFile=$T/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SwitchType=switch/none
MpiDefault=none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MailProg=/bin/true
ReturnToService=2
MinJobAge=3600
KillWait=30
InactiveLimit=0
PlugStackConfig=$T/etc/plugstack.conf
NodeName=$host NodeAddr=127.0.0.1 NodeHostname=$host CPUs=2 RealMemory=4000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
: >"$T/etc/plugstack.conf"
export SLURM_CONF=$T/etc/slurm.conf
start_daemon slurmctld slurmctld -D -c -f "$SLURM_CONF"
start_daemon slurmd slurmd -D -f "$SLURM_CONF" -N "$host"
for _ in $(seq 120); do
  state=$(sinfo -h -N -o %T 2>/dev/null || true)
  [[ "$state" == idle ]] && break
  sleep 0.5
done
[[ "$state" == idle ]] || { echo "test-local-slurm: node state '$state', not idle" >&2; exit 1; }
say "slurm is up: node $host idle (slurmctld port $ctld_port, slurmd port $slurmd_port)"

# Jobs inherit this environment (sbatch --export=ALL): SLURM_CONF, POUND and, as root in CI,
# Open MPI's permission to run as root (the user-facing scripts do not set it).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export POUND_PYTHON=$PY

# ---------------------------------------------------------------- helpers
J=$T/jobs
checks=0
ok() { checks=$((checks + 1)); say "ok $checks - $*"; }
die() { say "not ok - $*"; exit 1; }

# job_field ID FIELD: FIELD=value from scontrol (first record).
job_field() { scontrol show job "$1" -o 2>/dev/null | head -n 1 | tr ' ' '\n' | sed -n "s/^$2=//p"; }
# wait_job ID TIMEOUT: waits until no record of the job (or its array tasks) is pending or running.
wait_job() {
  local id=$1 limit=$2 s=0
  while [[ -n "$(squeue -h -j "$id" -o %i 2>/dev/null)" ]]; do
    (( s >= limit )) && die "job $id still queued or running after $limit s"
    sleep 1
    s=$((s + 1))
  done
}
excerpt() {  # the scripts' own lines and the campaign's summary lines of a job output
  grep -E 'pound-slurm\[|campaign: (done|interrupted|stop requested|stopped: another|.*already complete)|pound_parts:|CANCELLED' "$1" \
    | sed 's/^/    | /' || true
}
show_log() { echo "----- $1"; cat "$1" 2>/dev/null || echo "(missing)"; echo "-----"; }
expect_job() {  # ID STATE EXIT LOG
  local st ec
  st=$(job_field "$1" JobState)
  ec=$(job_field "$1" ExitCode)
  if [[ "$st" != "$2" || "$ec" != "$3" ]]; then
    show_log "$4"
    die "job $1: JobState=$st ExitCode=$ec, expected $2 $3"
  fi
}

submit() { sbatch --parsable -D "$J" "$@" | cut -d';' -f1; }

# ---------------------------------------------------------------- 1. a complete run (srun)
if [[ -n "${POUND_SLURM_TEST_SAMPLES:-}" ]]; then
  samples=$POUND_SLURM_TEST_SAMPLES
else
  # One rank, 150 samples, timed here (not through Slurm): 2 ranks do about twice as many.
  ts=$(date +%s.%N)
  "$POUND" campaign --config "$study" --out "$T/calibrate.h5" --samples 150 --quiet 2>/dev/null \
    || die "calibration run of $POUND failed"
  te=$(date +%s.%N)
  rm -f "$T/calibrate.h5"
  samples=$("$PY" -c "import math; r = 150 / ($te - $ts); print(min(20000, max(2400, math.ceil(2 * r * 60 / 100) * 100)))")
  say "calibration: $(printf %.1f "$("$PY" -c "print(150 / ($te - $ts))")") samples/s on one rank -> $samples samples"
fi
say "study: $study with --samples $samples; binary $POUND"
ref=$J/ref.h5
a=$(submit --nodes=1 --ntasks-per-node=2 --time=10 -o "$J/ref.out" \
  slurm/campaign.sbatch "$study" "$ref" --samples "$samples")
say "job $a: campaign.sbatch, 2 ranks, full campaign (reference)"
wait_job "$a" 400
expect_job "$a" COMPLETED 0:0 "$J/ref.out"
excerpt "$J/ref.out"
[[ -f "$ref" && ! -e "$ref.journal" ]] || { show_log "$J/ref.out"; die "reference: no $ref or a journal left"; }
grep -q "campaign: done: $samples samples, 0 failed" "$J/ref.out" || { show_log "$J/ref.out"; die "reference: no 'done' line"; }
"$PY" "$parts_py" check "$ref" >/dev/null || die "reference: sample ids"
ok "campaign.sbatch (srun --mpi=pmix, 2 ranks) completed: JobState=COMPLETED ExitCode=0:0, $samples samples in $(job_field "$a" RunTime)"

# ---------------------------------------------------------------- 2. time limit, signal, resume
cut=$J/cut.h5
b=$(submit --nodes=1 --ntasks-per-node=2 --time=1 --signal=B:USR1@58 -o "$J/cut-1.out" \
  slurm/campaign.sbatch "$study" "$cut" --samples "$samples")
say "job $b: campaign.sbatch with --time=1 --signal=B:USR1@58 (shorter than the campaign)"
wait_job "$b" 200
[[ "$(job_field "$b" JobState)" == COMPLETED ]] && { show_log "$J/cut-1.out";
  die "job $b finished its campaign before Slurm's signal came; set POUND_SLURM_TEST_SAMPLES higher than $samples"; }
expect_job "$b" FAILED 75:0 "$J/cut-1.out"
excerpt "$J/cut-1.out"
grep -q "received SIGUSR1" "$J/cut-1.out" && grep -q "campaign: interrupted after" "$J/cut-1.out" \
  || { show_log "$J/cut-1.out"; die "job $b did not stop on SIGUSR1"; }
grep -q "the campaign stopped early (exit status 75)" "$J/cut-1.out" \
  || { show_log "$J/cut-1.out"; die "job $b: pound campaign itself did not exit 75"; }
grep -q "DUE TO TIME LIMIT" "$J/cut-1.out" && { show_log "$J/cut-1.out"; die "job $b reached its time limit"; }
[[ -f "$cut.journal" && ! -e "$cut" ]] || die "job $b: expected the journal and no result file"
ok "job $b stopped on Slurm's SIGUSR1 before its time limit: $(grep -o 'interrupted after [0-9]* of [0-9]* samples' "$J/cut-1.out"), pound campaign and the job exit 75, journal kept (RunTime $(job_field "$b" RunTime))"

c=$(submit --nodes=1 --ntasks-per-node=2 --time=10 -o "$J/cut-2.out" \
  slurm/campaign-mpirun.sbatch "$study" "$cut" --samples "$samples")
say "job $c: campaign-mpirun.sbatch, resubmitted; stopped with scancel --signal=USR1 --batch once it runs"
# Wait until the campaign reports that it has started (rank 0 creates $cut.started.JOBID when
# every rank runs with its stop handlers), however long the machine takes to start it.
for _ in $(seq 1500); do
  [[ -e "$cut.started.$c" ]] && break
  [[ -z "$(squeue -h -j "$c" -o %i)" ]] && break
  sleep 0.2
done
[[ -e "$cut.started.$c" ]] || { show_log "$J/cut-2.out"; die "job $c: the campaign did not report its start within 300 s"; }
scancel --signal=USR1 --batch "$c"
wait_job "$c" 200
expect_job "$c" FAILED 75:0 "$J/cut-2.out"
excerpt "$J/cut-2.out"
grep -q "found .* resuming" "$J/cut-2.out" && grep -q "(resuming)" "$J/cut-2.out" \
  && grep -q "received SIGUSR1" "$J/cut-2.out" && grep -q "campaign: interrupted after" "$J/cut-2.out" \
  || { show_log "$J/cut-2.out"; die "job $c did not resume and stop on SIGUSR1"; }
grep -q "the campaign stopped early (exit status 75)" "$J/cut-2.out" \
  || { show_log "$J/cut-2.out"; die "job $c: pound campaign (under mpirun) did not exit 75"; }
ok "job $c (mpirun) resumed the journal and stopped on scancel --signal=USR1 --batch: $(grep -o 'interrupted after [0-9]* of [0-9]* samples' "$J/cut-2.out"), pound campaign and the job exit 75"

done2=$(grep -o 'interrupted after [0-9]*' "$J/cut-2.out" | grep -o '[0-9]*$')
jinfo=$("$PY" "$parts_py" journal "$cut.journal") || die "journal of the stopped campaign: $jinfo"
[[ "$jinfo" == *": $done2 of $samples samples in $done2 valid records, 0 duplicate(s)" ]] \
  || die "journal after two stops: '$jinfo', expected $done2 samples, each once"
ok "the journal after two stops holds $done2 samples, each exactly once"

d=$(submit --nodes=1 --ntasks-per-node=2 --time=10 -o "$J/cut-3.out" \
  slurm/campaign-mpirun.sbatch "$study" "$cut" --samples "$samples")
say "job $d: campaign-mpirun.sbatch, resubmitted again to complete it"
wait_job "$d" 400
expect_job "$d" COMPLETED 0:0 "$J/cut-3.out"
excerpt "$J/cut-3.out"
[[ -f "$cut" && ! -e "$cut.journal" ]] || { show_log "$J/cut-3.out"; die "job $d: no complete $cut"; }
ok "job $d resumed and completed the campaign"
"$PY" "$parts_py" check "$cut" || die "resumed file: sample ids"
ok "resumed file holds every sample exactly once"
"$PY" "$parts_py" compare "$cut" "$ref" || die "the resumed file differs from the uninterrupted run"
ok "resumed file equals the uninterrupted run (/samples, /response)"

# ---------------------------------------------------------------- 3. job array + merge
merged=$J/merged.h5
ids=$(cd "$J" && "$repo/slurm/submit-array.sh" --ntasks=1 --time=10 -o "$J/chunk-%a.out" -- \
  2 "$study" "$merged" --samples "$samples")
read -r arr mrg <<<"$ids"
[[ -n "$arr" && -n "$mrg" ]] || die "submit-array.sh printed '$ids', not two job ids"
say "array job $arr (2 chunks, 1 rank each) and merge job $mrg submitted by submit-array.sh"
wait_job "$arr" 400
for k in 0 1; do
  expect_job "${arr}_$k" COMPLETED 0:0 "$J/chunk-$k.out"
  excerpt "$J/chunk-$k.out"
  lohi=$("$PY" "$parts_py" range --chunk "$k" --chunks 2 --samples "$samples")
  grep -q "chunk $k/2 = samples \[${lohi% *}, ${lohi#* })" "$J/chunk-$k.out" \
    || { show_log "$J/chunk-$k.out"; die "chunk $k: the engine did not report its sample range"; }
done
ok "array tasks ${arr}_0 and ${arr}_1 completed, each on its own half of the samples"
wait_job "$mrg" 200
expect_job "$mrg" COMPLETED 0:0 "$J/pound-merge-$mrg.out"
excerpt "$J/pound-merge-$mrg.out"
[[ -f "$merged" ]] || die "no merged file"
ok "merge job $mrg completed"
"$PY" "$parts_py" check "$merged" || die "merged file: sample ids"
"$PY" "$parts_py" compare "$merged" "$ref" || die "the merged file differs from the single run"
ok "merged file equals the single run (/samples, /response)"

# ---------------------------------------------------------------- 4. a file in use: 75, retried
# Two jobs on the same file at once, one rank each (the node has two cores): the second meets
# the file in use, pound campaign exits 75 before it starts, and the script tries again every
# 2 s until the first job has written the file, which the second then finds complete.
# wait_started PATTERN JOB LOG: waits until a file matches PATTERN (the job's campaign has
# started: RUN.h5.started.JOBID).
wait_started() {
  for _ in $(seq 1500); do
    compgen -G "$1" >/dev/null && return 0
    [[ -z "$(squeue -h -j "$2" -o %i)" ]] && break
    sleep 0.2
  done
  show_log "$3"
  die "job $2: the campaign did not report its start within 300 s"
}
# expect_retried ID LOG FILE: the job met FILE in use (exit 75), tried again and found it complete.
expect_retried() {
  grep -q "campaign: stopped: another campaign is writing $3 (pid" "$2" \
    && grep -q "exit status 75 before the start, try 1 of 100); trying again in 2 s" "$2" \
    && grep -q "$3 is already complete" "$2" \
    || { show_log "$2"; die "job $1 did not meet $3 in use, try again and find it complete"; }
}
busy_samples=$(( samples / 6 ))  # about 20 s on one rank
busy_ref=$J/busy-ref.h5
"$POUND" campaign --config "$study" --out "$busy_ref" --samples "$busy_samples" --quiet 2>/dev/null &
ref_pid=$!

in_use=$J/in-use.h5
e=$(submit --nodes=1 --ntasks-per-node=1 --time=10 -o "$J/in-use-1.out" \
  slurm/campaign.sbatch "$study" "$in_use" --samples "$busy_samples")
wait_started "$in_use.started.*" "$e" "$J/in-use-1.out"
f=$(POUND_LOCK_TRIES=100 POUND_LOCK_SLEEP=2 submit --nodes=1 --ntasks-per-node=1 --time=10 \
  -o "$J/in-use-2.out" slurm/campaign-mpirun.sbatch "$study" "$in_use" --samples "$busy_samples")
say "job $f: campaign-mpirun.sbatch on $in_use while job $e (campaign.sbatch, $busy_samples samples, 1 rank) writes it"
wait_job "$e" 400
wait_job "$f" 400
expect_job "$e" COMPLETED 0:0 "$J/in-use-1.out"
expect_job "$f" COMPLETED 0:0 "$J/in-use-2.out"
excerpt "$J/in-use-2.out"
expect_retried "$f" "$J/in-use-2.out" "$in_use"
ok "job $f met $in_use in use by job $e: pound campaign exited 75 $(grep -c 'trying again in' "$J/in-use-2.out") time(s), the script tried again and found the file complete (JobState=COMPLETED ExitCode=0:0)"

chunks_out=$J/in-use-array.h5
part=$chunks_out.parts/part-0000-of-0001.h5
g=$(submit --array=0 --ntasks=1 --time=10 -o "$J/in-use-chunk-1.out" \
  slurm/campaign-array.sbatch 1 "$study" "$chunks_out" --samples "$busy_samples")
wait_started "$part.started.*" "$g" "$J/in-use-chunk-1.out"
h=$(POUND_LOCK_TRIES=100 POUND_LOCK_SLEEP=2 submit --array=0 --ntasks=1 --time=10 \
  -o "$J/in-use-chunk-2.out" slurm/campaign-array.sbatch 1 "$study" "$chunks_out" --samples "$busy_samples")
say "array job $h: chunk 0 of 1 again while array job $g writes its part"
wait_job "$g" 400
wait_job "$h" 400
expect_job "${g}_0" COMPLETED 0:0 "$J/in-use-chunk-1.out"
expect_job "${h}_0" COMPLETED 0:0 "$J/in-use-chunk-2.out"
excerpt "$J/in-use-chunk-2.out"
expect_retried "${h}_0" "$J/in-use-chunk-2.out" "$part"
ok "array job $h met its part in use by array job $g: exit 75 $(grep -c 'trying again in' "$J/in-use-chunk-2.out") time(s), tried again, found the part complete"

wait "$ref_pid" || die "the run of $busy_samples samples without Slurm failed"
"$PY" "$parts_py" compare "$in_use" "$busy_ref" || die "$in_use differs from the same run without Slurm"
"$PY" "$parts_py" compare "$part" "$busy_ref" || die "$part differs from the same run without Slurm"
ok "both files written while a second job waited equal the run without Slurm (/samples, /response)"

say "$checks checks hold"
