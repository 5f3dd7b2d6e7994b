#!/usr/bin/env bash
# Installs the Debian 12 packages pound needs. Idempotent: when everything is present it
# returns in about a second without touching apt.
#   bash scripts/install-deps.sh          # build, tests, figures
#   bash scripts/install-deps.sh --fuzz   # and clang 14 with its libFuzzer and sanitizer
#                                         # runtimes (fuzz/run.sh, docs/fuzzing.md)
set -euo pipefail
PKGS=(build-essential cmake pkg-config
      libopenmpi-dev openmpi-bin
      libeigen3-dev libhdf5-dev libboost-program-options-dev libfftw3-dev
      libgtest-dev librandom123-dev clang-format
      python3 python3-numpy python3-matplotlib python3-h5py
      pybind11-dev python3-dev python3-pandas python3-scipy python3-pytest
      locales)
# pybind11-dev and python3-dev build the Python module (docs/python.md), python3-pandas is its
# read_campaign, python3-scipy its lognormal_cdf (the figures' fragility curves),
# python3-pytest runs its tests, locales lets a test compile a comma locale.
# clang-14 is the compiler; libclang-rt-14-dev holds libclang_rt.fuzzer, .asan and .ubsan.
if [ "${1:-}" = "--fuzz" ]; then PKGS+=(clang-14 libclang-rt-14-dev); fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} Debian packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
