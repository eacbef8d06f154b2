#!/usr/bin/env bash
# Installs the Debian packages plantsim builds with, only those that are missing; with
# `test`, also what the tests need (a single-node Slurm cluster, clang's libFuzzer, Chromium for
# the browser test of the reports, pytest and matplotlib for the Python module's tests).
# Safe to run again: it does nothing when everything is present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config lld
  libbox2d-dev libeigen3-dev libosmesa6-dev libpng-dev
  libgtest-dev libgmock-dev
  nlohmann-json3-dev libyaml-cpp-dev libcli11-dev
  libfreetype-dev fonts-dejavu-core libglpk-dev libcgal-dev libnlopt-dev
  libpcg-cpp-dev libboost-dev
  python3 python3-dev pybind11-dev python3-numpy
)
if [ "${1:-}" = test ]; then
  packages+=(slurm-wlm munge clang clang-format libclang-rt-14-dev chromium python3-pytest python3-matplotlib)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
