#!/usr/bin/env bash
# Installs the Debian packages exactccd needs, skipping those already installed. Idempotent.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev
  libgtest-dev libbenchmark-dev libeigen3-dev doxygen
  libtbb-dev
  python3-matplotlib python3-setuptools python3-wheel python3-pip python3-venv
  pybind11-dev python3-dev python3-numpy python3-pytest python3-hypothesis
  clang clang-tidy libclang-rt-dev
  slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
