#!/usr/bin/env bash
# Regenerates every image of docs/gallery.md with the built CLI, and prints the figures the page
# quotes (tessref's own summary lines). Builds nothing: run scripts/build.sh first. Needs the
# package assimp-testmodels (Wuson, the spider). Takes under a minute.
#
#   scripts/gallery.sh [BUILD_DIR]     (default: build)
#
# Images: docs/images/gallery/<mesh>-<scheme>-{curvature,highlights}.png for the seed 004 sphere
# (i = 1), torus (j = 10), rounded cube and vase and Wuson, and <scene>-{fake,real,difference}.png
# for the fake-versus-real normals of the default scene, seed 000's cube and the spider.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
tessref="$build/cli/tessref"
out=docs/images/gallery
[[ -x "$tessref" ]] || { echo "gallery: $tessref not found (run scripts/build.sh)" >&2; exit 2; }
for f in /usr/share/assimp/models/OFF/Wuson.off /usr/share/assimp/models/OBJ/spider.obj; do
  [[ -r "$f" ]] || { echo "gallery: $f missing (apt-get install assimp-testmodels)" >&2; exit 2; }
done
mkdir -p "$out"
small=(--set image.width=256 --set image.height=256)

# One row of the page: NAME, the curvature range (empty: tessref's 2/r^2), the highlight lines'
# spacing (in mesh radii), then the scene arguments. Nagata's eps as seed 004 used it: 0 on its sphere, torus and rounded cube, 0.06 on
# the vase; 0.03 (its Bunny's) on Wuson.
row() {
  local name=$1 range=$2 spacing=$3
  shift 3
  local range_arg=()
  [[ -n "$range" ]] && range_arg=(--curvature-range "$range")
  for scheme in pn phong nlsa nagata; do
    "$tessref" stats "$@" "${small[@]}" --set tessellation.scheme=$scheme \
      --image gaussian_curvature "${range_arg[@]}" -o "$out/$name-$scheme-curvature.png" 2>/dev/null
    "$tessref" stats "$@" "${small[@]}" --set tessellation.scheme=$scheme \
      --image highlight_lines --highlight-spacing "$spacing" -o "$out/$name-$scheme-highlights.png" 2>/dev/null
  done
}
# seed 004's meshes: the default scene's view direction, the camera fitted to the mesh.
fitted=(--set camera.fit=true --set tessellation.inner=16 --set tessellation.outer=16)
row sphere 2.5 0.5 --set mesh.type=icosphere --set mesh.icosphere.refinements=1 --set tessellation.nagata_eps=0 "${fitted[@]}"
row torus 4 0.5 --set mesh.type=seed004_torus --set tessellation.nagata_eps=0 "${fitted[@]}"
row rounded_cube 4 0.5 --set mesh.type=rounded_cube --set tessellation.nagata_eps=0 "${fitted[@]}"
row vase "" 0.5 --set mesh.type=vase --set tessellation.nagata_eps=0.06 "${fitted[@]}"
# Wuson (3,732 triangles) in its scene's own view; wider light lines: its small features bend
# the normals fast.
row wuson 4 1.0 scenes/wuson_pn64.json --set tessellation.nagata_eps=0.03 \
  --set tessellation.inner=8 --set tessellation.outer=8

# Seed 000, Figure 13: 'fake' (quadratic) against 'real' (analytic) normals, PN triangles. The
# figures at the scene's own size (1024x1024), the images at 256x256.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
compare() {
  local name=$1
  shift
  echo "== $name, 1024x1024"
  "$tessref" stats "$@" --image normal_mode_difference -o "$tmp/d.png" 2>/dev/null
  # How many of those differences an unscaled difference image would show (over 8/255).
  "$tessref" render "$@" --set tessellation.normal_mode=quadratic -o "$tmp/fake.png" >/dev/null 2>&1
  "$tessref" render "$@" --set tessellation.normal_mode=analytic -o "$tmp/real.png" >/dev/null 2>&1
  "$tessref" diff "$tmp/fake.png" "$tmp/real.png" --tolerance 8/255 | tail -1 || true
  "$tessref" stats "$@" "${small[@]}" --image normal_mode_difference -o "$out/$name-difference.png" >/dev/null 2>&1
  "$tessref" render "$@" "${small[@]}" --set tessellation.normal_mode=quadratic -o "$out/$name-fake.png" >/dev/null 2>&1
  "$tessref" render "$@" "${small[@]}" --set tessellation.normal_mode=analytic -o "$out/$name-real.png" >/dev/null 2>&1
}
compare default
compare cube --set mesh.type=cube
compare spider scenes/spider.json
du -ch "$out"/*.png | tail -1
