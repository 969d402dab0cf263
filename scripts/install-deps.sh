#!/usr/bin/env bash
# Installs the Debian packages the course needs; does nothing when they are all present.
set -euo pipefail

packages=(
  cmake pkg-config gcc clang make
  libglfw3-dev libegl-dev libegl-mesa0 libosmesa6-dev libgl1-mesa-dri
  python3-glad libstb-dev libcglm-dev libcmocka-dev libassimp-dev libcjson-dev
  glslang-tools xvfb xauth twm x11-utils gnuplot-nox
  assimp-testmodels
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
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "install-deps: missing ${missing[*]}; run this script as root or install sudo" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
