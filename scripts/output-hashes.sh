#!/usr/bin/env bash
# Prints the SHA-256 of the PNG and --dump-tess output of 15 scene variants (every scheme, normal
# mode, spacing, winding, culling, adaptive levels, shading, 1 and all threads, the Wuson and spider
# meshes), so that a change meant to keep output bytes can be checked against the commit before it.
#   scripts/output-hashes.sh [TESSREF_BINARY] [OUT_DIR]    (default build/cli/tessref, a temp dir)
# Set TESSREF_SIMD=scalar to hash the scalar kernels' output (it must be the same).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/cli/tessref}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
wuson=scenes/wuson_pn64.json
run() {
  local name=$1
  shift
  "$bin" render "$@" -o "$out/$name.png" --dump-tess "$out/$name.tess" >/dev/null 2>"$out/$name.err" ||
    { echo "output-hashes: $name failed:" >&2; cat "$out/$name.err" >&2; exit 1; }
}
run default
run default_t1 --threads 1
run flat --set tessellation.scheme=flat
run linear --set tessellation.normal_mode=linear
run analytic --set tessellation.normal_mode=analytic
run corrected --set tessellation.normal_mode=quadratic_corrected
run even --set tessellation.spacing=fractional_even --set tessellation.inner=7.3 --set tessellation.outer=5.2
run equal_cw --set tessellation.spacing=equal --set tessellation.winding=cw --set cull_back_faces=true
run adaptive --set tessellation.adaptive.enabled=true
run normals --set shading=normals
run ico64 --set tessellation.inner=64 --set tessellation.outer=64 --set mesh.type=icosphere --set mesh.icosphere.refinements=1
run spider scenes/spider.json
if [[ -f /usr/share/assimp/models/OFF/Wuson.off ]]; then
  run wuson12 "$wuson" --set tessellation.inner=12 --set tessellation.outer=12
  run wuson64 "$wuson"
fi
"$bin" render --set tessellation.enabled=false -o "$out/notess.png" >/dev/null
(cd "$out" && sha256sum -- *.png *.tess | sort -k2)
