#!/usr/bin/env bash
# The full sampling sweep against llvmpipe (issue 20; tests/glref/sampling_sweep_test.cpp): every
# texture format x minification filter x magnification filter x wrap mode x lookup function, 16,384
# lookups each, drawn by tessref and by Mesa's llvmpipe and compared bit for bit. Prints each case
# that differs with its count and first difference, then the totals; exits 1 if a case exceeds
# what docs/textures.md states. Builds build/ first if needed.
#
#   scripts/sampling-sweep.sh           # about 21,700 cases, 356 million lookups, 90 minutes on 2 cores
#   scripts/sampling-sweep.sh lookup_1d # the cases whose keys contain "lookup_1d" (1D textures; lookup_cube: cube maps)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/tests/test_glref ] || { cmake -S . -B build >/dev/null && cmake --build build -j"$(nproc)" --target test_glref; }
if [ $# -gt 0 ]; then export TESSREF_SAMPLING_SWEEP_MATCH="$1"; fi
TESSREF_SAMPLING_SWEEP=full build/tests/test_glref --gtest_filter='SamplingSweepVsLlvmpipe.*'
