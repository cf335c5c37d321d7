#!/usr/bin/env bash
# First README command: install what is missing, build, render the default scene, print the image path.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/cli/tessref render scenes/default.json -o out/default.png
echo "image: $(pwd)/out/default.png"
