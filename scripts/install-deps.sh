#!/usr/bin/env bash
# Installs the Debian 12 packages HLOD Studio needs to build, run and test.
# Idempotent: when everything is present it only runs one dpkg query and exits.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git file help2man
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-tools-dev qt6-tools-dev-tools
  qt6-l10n-tools qt6-translations-l10n
  libvtk9-dev
  libopenmesh-dev libtinygltf-dev libstb-dev libdeflate-dev libglm-dev libmeshoptimizer-dev libassimp-dev
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
  libocct-foundation-dev libocct-ocaf-dev libocct-visualization-dev
  libopenvdb-dev libboost-iostreams-dev libtbb-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang-14 libfuzzer-14-dev
  xvfb xauth libgl1-mesa-dri mesa-utils
  chromium
  slurmctld slurmd slurm-client munge
)
# npm: the machine may ship Node.js from another Debian-format repo that bundles npm;
# only ask Debian for it when no npm command exists at all.
if ! command -v npm >/dev/null 2>&1; then PACKAGES+=(nodejs npm); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing package(s): ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
