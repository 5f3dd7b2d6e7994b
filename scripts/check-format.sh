#!/usr/bin/env bash
# Fails when a C++ file differs from .clang-format (run by ctest as FormatCheck).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "clang-format not installed (Debian package clang-format)"; exit 1; }
bad=0
while IFS= read -r f; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f (run: clang-format -i $f)"
    bad=1
  fi
done < <(find src tests bench fuzz python -name '*.cpp' -o -name '*.hpp' | sort)
exit $bad
