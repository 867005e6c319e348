#!/usr/bin/env bash
# Installs boxcyl's dependencies from Debian's packages, only those that are missing (idempotent; safe
# to run on every invocation; uses sudo when not root).
# Usage: scripts/deps.sh [GROUP ...] [extra-package ...]
#   build   compiler, CMake, GMP, and the command-line tool's nlohmann-json and CLI11
#   python  the Python module's build (pip install ./python): Python headers, pybind11, numpy,
#           setuptools, pip, venv (with GMP and the compiler)
#   test    everything scripts/test.sh needs: build + python + GoogleTest, Google Benchmark,
#           pkg-config, pytest, Eigen (the Eigen adapter's test), and FLINT's Arb (the clearance
#           oracle's certified root isolation)
# With no group named, `test` (so `bash scripts/deps.sh` alone installs what the test command needs).
set -euo pipefail
build=(cmake g++ make libgmp-dev libflint-dev nlohmann-json3-dev libcli11-dev)
python=(g++ libgmp-dev libflint-dev python3-dev python3-pybind11 python3-numpy python3-setuptools python3-pip python3-venv)
test=("${build[@]}" "${python[@]}" libgtest-dev libgmock-dev libbenchmark-dev pkg-config python3-pytest
      python3-mypy python3-dask python3-distributed libeigen3-dev
      libflint-dev libflint-arb-dev)
packages=()
group=0
for a in "$@"; do
  case "$a" in
    build) packages+=("${build[@]}"); group=1 ;;
    python) packages+=("${python[@]}"); group=1 ;;
    test) packages+=("${test[@]}"); group=1 ;;
    *) packages+=("$a") ;;
  esac
done
((group)) || packages+=("${test[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  mapfile -t missing < <(printf '%s\n' "${missing[@]}" | sort -u)
  echo "deps: installing ${missing[*]} (apt-get)" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
