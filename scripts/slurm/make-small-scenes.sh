#!/usr/bin/env bash
# A folder of small scenes for trying campaigns (docs/campaigns.md): the repository's scenes at
# 128 x 128 pixels and low levels, so that a whole campaign runs in a minute or two. Paths inside
# them are absolute, so the folder can live anywhere.
#
#   scripts/slurm/make-small-scenes.sh OUT_DIR
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 OUT_DIR" >&2; exit 2; }
repo="$(cd "$(dirname "$0")/../.." && pwd)"
out="$1"
mkdir -p "$out"
img='"image": { "width": 128, "height": 128 }'
cat >"$out/default_pn.json" <<JSON
{ $img, "tessellation": { "inner": 4, "outer": 4 } }
JSON
cat >"$out/default_even.json" <<JSON
{ $img, "tessellation": { "inner": 5, "outer": 3, "spacing": "fractional_even" } }
JSON
cat >"$out/default_flat.json" <<JSON
{ $img, "tessellation": { "scheme": "flat", "inner": 3, "outer": 6 }, "shading": "phong" }
JSON
cat >"$out/icosphere_pn.json" <<JSON
{ $img, "mesh": { "type": "icosphere" }, "tessellation": { "inner": 6, "outer": 6, "spacing": "equal" } }
JSON
cat >"$out/displacement.json" <<JSON
{ $img,
  "lights": [ { "position": [-3.0, 4.0, -8.0] } ],
  "material": { "color": [0.2, 0.6, 0.9], "shininess": 60.0 },
  "tessellation": { "scheme": "flat", "inner": 6, "outer": 6 },
  "shaders": { "program": "custom", "vertex": "twin:transform.vert", "tess_control": "twin:flat.tesc",
               "tess_evaluation": "$repo/scenes/glsl/displace.tese", "fragment": "twin:phong.frag",
               "uniforms": { "u_amplitude": 0.03, "u_frequency": 30.0 } } }
JSON
# The spider keeps its levels (12): at 3, capture stops with "vertex 13299 tagged with patch 0 out
# of order" (glref's transform-feedback ordering; reported, not a campaign matter).
cat >"$out/spider.json" <<JSON
{ $img,
  "mesh": { "type": "file", "path": "/usr/share/assimp/models/OBJ/spider.obj" },
  "transform": { "translate": [0.17, 0.02, 0.1], "rotate_deg": [0, 0, 0], "scale": 0.01 },
  "camera": { "fov_y_deg": 11.0 }, "cull_back_faces": false }
JSON
echo "make-small-scenes: $(ls "$out"/*.json | wc -l) scenes in $out"
