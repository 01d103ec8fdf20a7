#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds and tests with.
# Does nothing when every package is already present; needs root otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libcli11-dev libglm-dev libtinygltf-dev nlohmann-json3-dev
  libopenimageio-dev libgtest-dev libgmock-dev
  povray
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=sudo
  else
    echo "install-deps: need root to install: ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
