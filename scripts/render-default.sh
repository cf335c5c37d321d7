#!/usr/bin/env bash
# First README command: install what is missing, build the tessref command (only what it needs: the
# test suite is built by scripts/test.sh), render the default scene, print the image path.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target tessref_cli
mkdir -p out
build/cli/tessref render scenes/default.json -o out/default.png
echo "image: $(pwd)/out/default.png"
