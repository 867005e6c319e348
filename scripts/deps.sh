#!/usr/bin/env bash
# Installs boxcyl's build and test dependencies from Debian's packages, only those that are missing
# (idempotent; safe to run on every invocation). Usage: scripts/deps.sh [extra-package ...]
set -euo pipefail
packages=(cmake g++ make libgmp-dev nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
          pkg-config python3-dev python3-pybind11 python3-numpy python3-pytest python3-setuptools python3-pip
          python3-mypy python3-dask python3-distributed "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "deps: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
