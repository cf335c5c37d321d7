#!/usr/bin/env bash
# Captures tests/replay/replay_app and fuzzes the importer on the capture (fuzz/fuzz_import.py):
# SECONDS of random inputs, or with --executions N a fixed, repeatable set. apitrace: the trace's
# calls, mutated and imported in process; --rdc: a RenderDoc capture's bytes, mutated and imported
# by TESSREF (the tessref binary) in its own process. Exit 77 (a skip) without the capture tool.
#
#   tests/replay/fuzz_import.sh REPLAY_APP (SECONDS | --executions N)
#   tests/replay/fuzz_import.sh --rdc TESSREF REPLAY_APP (SECONDS | --executions N)
set -euo pipefail
rdc=""
if [ "${1:-}" = --rdc ]; then rdc=$2; shift 2; fi
app=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fuzzer="$(dirname "$0")/../../fuzz/fuzz_import.py"
artifacts="${FUZZ_WORK:-$PWD/out/fuzz}/fuzz_import/artifacts"
if [ -n "$rdc" ]; then
  command -v renderdoccmd >/dev/null && /usr/bin/python3 -c 'import renderdoc' 2>/dev/null ||
    { echo "fuzz_import.sh: RenderDoc is not installed (Debian packages renderdoc, python3-renderdoc): skipped"; exit 77; }
  EGL_PLATFORM=surfaceless renderdoccmd capture -w -c "$work/app" "$app" "$work/app.ppm" >"$work/capture.log" 2>&1 ||
    { cat "$work/capture.log"; exit 1; }
  exec python3 "$fuzzer" --rdc "$work/app_capture.rdc" --tessref "$rdc" --timeout 30 "$@" --artifacts "$artifacts"
fi
command -v apitrace >/dev/null || { echo "fuzz_import.sh: apitrace is not installed (Debian package apitrace): skipped"; exit 77; }
apitrace trace --api egl -o "$work/app.trace" "$app" "$work/app.ppm" >"$work/trace.log" 2>&1 ||
  { cat "$work/trace.log"; exit 1; }
exec python3 "$fuzzer" "$work/app.trace" "$@" --artifacts "$artifacts"
