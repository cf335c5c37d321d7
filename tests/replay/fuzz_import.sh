#!/usr/bin/env bash
# Captures tests/replay/replay_app with apitrace and fuzzes the importer on its calls
# (fuzz/fuzz_import.py): SECONDS of random inputs, or with --executions N a fixed, repeatable set.
# Exit 77 (a skip) without apitrace.
#
#   tests/replay/fuzz_import.sh REPLAY_APP (SECONDS | --executions N)
set -euo pipefail
app=$1
shift
command -v apitrace >/dev/null || { echo "fuzz_import.sh: apitrace is not installed (Debian package apitrace): skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
apitrace trace --api egl -o "$work/app.trace" "$app" "$work/app.ppm" >"$work/trace.log" 2>&1 ||
  { cat "$work/trace.log"; exit 1; }
exec python3 "$(dirname "$0")/../../fuzz/fuzz_import.py" "$work/app.trace" "$@" --artifacts "${FUZZ_WORK:-$PWD/out/fuzz}/fuzz_import/artifacts"
