#!/usr/bin/env bash
# Configures and builds tessref (Release) into build/.
#   scripts/build.sh [--target TARGET]... [extra cmake args]
# With --target, builds only those targets (and what they need), e.g. --target tessref_cli for the
# command alone; without, everything (the tests too).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
targets=()
while (( $# )) && [[ $1 == --target ]]; do
  (( $# >= 2 )) || { echo "build.sh: --target needs a target name" >&2; exit 2; }
  targets+=(--target "$2")
  shift 2
done
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j "$jobs" "${targets[@]}"
