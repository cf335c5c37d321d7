#!/usr/bin/env bash
# Captures every scene under scenes/ through the system's GL driver (Mesa llvmpipe here) into
# tests/data/captures/<scene>/, the references the test suite verifies tessref against
# (tests/verify/committed_captures_test.cpp). Small enough to commit: 256 x 256 images and at
# most 12,000 emitted vertices' records in tess.bin (every k-th patch), every patch's digest.
#
#   scripts/capture-scenes.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=tests/data/captures
mkdir -p "$out"
for scene in scenes/*.json; do
  name=$(basename "$scene" .json)
  "$build/cli/tessref" capture "$scene" --out "$out/$name" --set image.width=256 --set image.height=256 \
    --tess-records 20000
done
du -sh "$out"/*
