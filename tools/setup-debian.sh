#!/usr/bin/env bash
# Installs the Debian 12 packages netsph needs to build, test and plot.
# Idempotent: packages already present are skipped, so running it twice costs one dpkg query.
# Why --no-install-recommends and munkres/unicodedata2: they keep matplotlib from pulling
# scipy + pythran + boost (~230 MB); see docs/ARCHITECTURE.md, "Dependencies".
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libtomlplusplus-dev libcli11-dev libfmt-dev libspdlog-dev nlohmann-json3-dev
  libhdf5-dev hdf5-tools
  libopenmpi-dev openmpi-bin
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-h5py python3-matplotlib python3-munkres python3-unicodedata2
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
