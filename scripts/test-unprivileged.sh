#!/usr/bin/env bash
# Runs the README's test command (bash scripts/test.sh: build, then the whole ctest suite) as an
# unprivileged user, as a newcomer without root runs it (issue 24; CI runs this, .ci/run).
#
#   bash scripts/test-unprivileged.sh [USER]        (as root; USER defaults to nobody)
#
# The user gets a copy of the source tree of its own in a fresh folder under /tmp (the tracked
# and untracked files of this checkout, without .git, build folders and results/), builds it
# there and runs every test: nothing of this checkout is written, and nothing root-owned is
# rebuilt. Exits with the test command's status (non-zero when any test fails); the folder is
# removed at the end (POUND_UNPRIVILEGED_KEEP=1 keeps it).
set -euo pipefail
cd "$(dirname "$0")/.."
user=${1:-nobody}
say() { echo "test-unprivileged: $*"; }
if [[ $(id -u) -ne 0 ]]; then
  say "run as root: it switches to the user $user (runuser) and needs to hand it a copy"
  exit 1
fi
if ! id -u "$user" >/dev/null 2>&1; then
  say "no user '$user' on this machine; give an existing unprivileged user (e.g. nobody)"
  exit 1
fi
if [[ $(id -u "$user") -eq 0 ]]; then
  say "'$user' is root; give an unprivileged user"
  exit 1
fi
# Debian packages first, as root (scripts/test.sh then finds them all and installs nothing).
bash scripts/install-deps.sh

work=$(mktemp -d /tmp/pound-unprivileged.XXXXXX)
cleanup() {
  if [[ "${POUND_UNPRIVILEGED_KEEP:-0}" == 1 ]]; then say "kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT
mkdir "$work/src" "$work/home"
tar -cf - --exclude=./.git --exclude=./build --exclude='./build-*' --exclude=./results \
  --exclude=./out . | tar -xf - -C "$work/src"
chown -R "$user:$(id -gn "$user")" "$work"
chmod 755 "$work"
say "user $user (uid $(id -u "$user")), copy of the sources in $work/src"
# HOME: nobody's is /nonexistent. The tests' scratch folders and Open MPI's session folder go
# to /tmp as for any user.
rc=0
(cd "$work/src" &&
  runuser -u "$user" -- env HOME="$work/home" USER="$user" LOGNAME="$user" \
    bash scripts/test.sh) || rc=$?
if [[ $rc -eq 0 ]]; then
  say "PASS: bash scripts/test.sh as $user"
else
  say "FAIL: bash scripts/test.sh as $user exited $rc"
fi
exit "$rc"
