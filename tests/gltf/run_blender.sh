#!/usr/bin/env bash
# Runs a Blender check script headless: run_blender.sh SCRIPT ARGS...
# Exits 77 (skipped) when Blender, or the numpy its glTF add-on needs, is
# not installed (scripts/install-deps.sh installs both).
set -euo pipefail
script=$1; shift
if ! command -v blender >/dev/null 2>&1; then
  echo "SKIP: blender is not installed (scripts/install-deps.sh installs it)"; exit 77
fi
if ! python3 -c 'import numpy' >/dev/null 2>&1 && ! dpkg-query -W python3-numpy >/dev/null 2>&1; then
  echo "SKIP: python3-numpy, which Blender's glTF add-on needs, is not installed"; exit 77
fi
exec blender -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
