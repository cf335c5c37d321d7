#!/usr/bin/env bash
# Peak resident memory of one heavy tessellated frame: Wuson (assimp-testmodels, 3,732 triangles)
# with PN triangles at inner = outer = 64 at 1024x1024 (scenes/wuson_pn64.json), then the same frame
# at level 12 for comparison. Builds nothing: run scripts/build.sh first.
#
#   scripts/bench-memory.sh [BUILD_DIR]     (default: build)
#
# Prints peak RSS (from /usr/bin/time -v, package `time`), tessellated triangles (patches x the
# triangles `tessref tpg` emits for one patch at that level, checked against the count tessref
# render prints where it does) and the frame time (vertex +
# tessellation + raster+fs as tessref reports them; wall time includes loading and PNG writing).
# Exit status: 0 if the level-64 frame peaked below 1 GiB, 1 if not, 2 if it could not run.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
tessref="$build/cli/tessref"
scene=scenes/wuson_pn64.json
limit_kib=$((1024 * 1024))

[[ -x "$tessref" ]] || { echo "bench-memory: $tessref not found (run scripts/build.sh)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "bench-memory: /usr/bin/time missing (apt-get install time)" >&2; exit 2; }
mesh=$(sed -n 's/.*"path": *"\([^"]*\)".*/\1/p' "$scene")
[[ -r "$mesh" ]] || { echo "bench-memory: $mesh missing (apt-get install assimp-testmodels)" >&2; exit 2; }

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Milliseconds of one "<name> X ms" field of tessref's render line.
field_ms() { sed -n "s/.*$1 \([0-9.]*\) ms.*/\1/p" <<<"$2"; }

# render LEVEL: runs one frame, prints its figures; sets peak_kib.
render() {
  local level=$1 log line patches per_patch rc
  log="$out/time-$level.txt"
  line=$(/usr/bin/time -v -o "$log" "$tessref" render "$scene" -o "$out/wuson-$level.png" \
           --set tessellation.inner="$level" --set tessellation.outer="$level")
  rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "bench-memory: tessref render failed (exit $rc) at level $level" >&2
    cat "$log" >&2
    exit 2
  fi
  peak_kib=$(sed -n 's/.*Maximum resident set size (kbytes): *//p' "$log")
  patches=$(sed -n 's/.*: \([0-9]*\) triangles in,.*/\1/p' <<<"$line")
  per_patch=$(( $("$tessref" tpg --domain triangles --spacing fractional_odd \
                   --outer "$level,$level,$level" --inner "$level" | wc -l) / 3 ))
  # Newer tessref prints the count itself; it must agree with the generator's per-patch count.
  local reported
  reported=$(sed -n 's/.* \([0-9]*\) after tessellation,.*/\1/p' <<<"$line")
  if [[ -n "$reported" && "$reported" != $((patches * per_patch)) ]]; then
    echo "bench-memory: tessref reports $reported triangles, expected $patches x $per_patch" >&2
    exit 2
  fi
  local vertex tess raster wall
  vertex=$(field_ms vertex "$line")
  tess=$(field_ms tessellation "$line")
  raster=$(field_ms raster+fs "$line")
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): *//p' "$log")
  awk -v l="$level" -v kib="$peak_kib" -v p="$patches" -v pp="$per_patch" -v vx="$vertex" \
      -v ts="$tess" -v rs="$raster" -v wall="$wall" 'BEGIN {
    printf "level %2d: peak RSS %7.1f MiB, %d patches x %d = %d tessellated triangles, frame %.0f ms (vertex %s + tessellation %s + raster+fs %s ms), wall %s\n",
           l, kib / 1024, p, pp, p * pp, vx + ts + rs, vx, ts, rs, wall }'
}

echo "$scene, 1024x1024, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
render 64
peak64=$peak_kib
render 12
if (( peak64 >= limit_kib )); then
  echo "bench-memory: FAIL: level-64 peak RSS $peak64 KiB >= 1 GiB" >&2
  exit 1
fi
echo "bench-memory: ok: level-64 peak RSS below 1 GiB"
