#!/usr/bin/env bash
# Installs every Debian 12 package Hypergarden needs to build, test and run.
# Idempotent: packages already present are skipped, and `apt-get update` runs
# at most once per invocation (only when something is missing).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config
  libopenvdb-dev libboost-iostreams-dev libtbb-dev libopenvdb-tools
  libglfw3-dev libglm-dev libepoxy-dev libgl-dev libegl-dev
  libopenxr-dev libopenxr-loader1
  libimgui-dev libstb-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtinygltf-dev libmeshoptimizer-dev
  xvfb xauth libgl1-mesa-dri mesa-utils admesh clang
  openxr-layer-corevalidation
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
