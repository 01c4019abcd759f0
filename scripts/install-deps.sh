#!/usr/bin/env bash
# Installs the Debian 12 packages spifit builds with, only those that are missing
# (idempotent: a machine that has them all is not touched and needs no network).
# Why each package is needed: docs/design/dependencies.md.
set -euo pipefail

packages=(
  build-essential cmake
  libeigen3-dev libceres-dev libnlopt-cxx-dev libsuitesparse-dev libopenblas0-openmp libomp-dev
  libcli11-dev libtoml11-dev nlohmann-json3-dev libopenmpi-dev openmpi-bin
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox calculix-ccx
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "spifit: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "spifit: installing missing Debian packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "spifit: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
