#!/usr/bin/env bash
# Installs every Debian package mistfall needs. Quick when all are present.
# Usage: scripts/install-deps.sh
# The render stage's packages are always installed: OpenVDB is needed to build (src/render/surface_mesh.cpp) and
# the tests of `mistfall render` run povray and ffmpeg; scripts/contact_sheet.sh labels images in the DejaVu font.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libhypre-dev libopenmpi-dev openmpi-bin
  libtomlplusplus-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libomp-dev
  python3 python3-numpy python3-matplotlib
  libopenvdb-dev povray ffmpeg fonts-dejavu-core
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "mistfall: installing missing Debian packages: ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "mistfall: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
