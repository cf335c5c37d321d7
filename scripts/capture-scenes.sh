#!/usr/bin/env bash
# Captures the scenes under scenes/ that a GL driver can draw (the list below; displaced_pn and
# tagged_pn use tessref-only options) through the system's GL driver (Mesa llvmpipe here) into
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
for name in default displacement spider wuson_pn64; do
  scene=scenes/$name.json
  "$build/cli/tessref" capture "$scene" --out "$out/$name" --set image.width=256 --set image.height=256 \
    --tess-records 20000
done
du -sh "$out"/*
