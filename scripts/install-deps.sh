#!/usr/bin/env bash
# Installs the Debian packages zraster needs to build, test and benchmark. Idempotent and quiet:
# does nothing (and needs no root) when everything is already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  clang clang-format clang-tidy libclang-rt-14-dev
  libglm-dev libassimp-dev libminizip-dev libstb-dev libdeflate-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libhwy-dev libtbb-dev libgtest-dev libgmock-dev libbenchmark-dev
  libegl-dev libgles-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-distributed
  libsdl2-dev xvfb xauth xdotool
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  if [[ "$status" != *"install ok installed"* ]]; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "zraster: installing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
