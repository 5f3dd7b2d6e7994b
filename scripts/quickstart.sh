#!/usr/bin/env bash
# Installs the Debian packages, builds pound (Release) and runs the default study.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
echo "== pound simulate --config studies/ch3-steel-frames.ini"
./build/bin/pound simulate --config studies/ch3-steel-frames.ini
echo "== done: the program is build/bin/pound; studies are in studies/"
