#!/usr/bin/env bash
# Installs exactly the Debian packages shadowvol needs that are missing on this machine.
# Safe to run again: it asks dpkg first and calls apt-get only for what is absent.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libglm-dev libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libembree-dev libtbb-dev
  libegl-dev libgl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libstb-dev libassimp-dev
  pybind11-dev python3-dev python3-numpy python3-pytest libtinygltf-dev
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
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
