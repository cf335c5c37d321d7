#!/usr/bin/env bash
# Installs the Debian 12 packages tessref builds, tests and compares against, or only the packages
# named as arguments. Idempotent: it asks apt only for what is missing. Needs root or sudo.
#
#   scripts/install-deps.sh [PACKAGE...]
set -euo pipefail
pkgs=("$@")
[ ${#pkgs[@]} -gt 0 ] || pkgs=(build-essential cmake pkg-config
      libglm-dev libpng-dev libopenimageio-dev openimageio-tools libembree-dev libtbb-dev libassimp-dev
      assimp-testmodels libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
      libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri time faketime apitrace python3
      renderdoc python3-renderdoc librenderdoc-dev
      glslang-dev glslang-tools spirv-tools spirv-headers chromium)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#pkgs[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
