#!/usr/bin/env bash
# Whole processes, start to exit, as a user runs them (issue 21's start-up figures):
#   tessref render of the default scene to a PNG, against tessref-glref-render --fair doing the
#   same on Mesa llvmpipe (EGL surfaceless, the twins specialized for the scene, RGBA8 colour and
#   24-bit depth, an RGBA8 read-back, the PNG written by the same libpng writer);
#   tessref's fixed cost: tessref render of a 16x16 one-triangle scene (bench/startup/).
# Rounds alternate the programs; medians and minima are printed as a Markdown table. The two
# PNGs are compared first (tessref diff, tolerance 1/255): if they differ, nothing is timed.
#
#   scripts/bench-startup.sh [BUILD_DIR] [ROUNDS]    (default build-bench, 11 rounds)
#
# llvmpipe keeps compiled shaders in Mesa's disk cache (~/.cache/mesa_shader_cache), as it does
# for any application: the table's llvmpipe figure is with that cache warm (a warm-up run fills
# it), and one row gives the run with the cache off (MESA_SHADER_CACHE_DISABLE=true).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-bench}
rounds=${2:-11}
tessref=$build/cli/tessref
glref=$build/glref/tessref-glref-render
[[ -x $tessref ]] || { echo "bench-startup: $tessref missing (build tessref_cli)" >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench-startup: ROUNDS must be a positive integer" >&2; exit 2; }
have_glref=1
[[ -x $glref ]] || { have_glref=0; echo "bench-startup: $glref missing: llvmpipe rows skipped" >&2; }
scene=scenes/default.json
tiny=bench/startup/one_triangle.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Milliseconds of one whole process (its output kept in $tmp/last.log).
timed() {
  local t0 t1
  t0=$(date +%s%N)
  "$@" >"$tmp/last.log" 2>&1 || { echo "bench-startup: failed: $*" >&2; cat "$tmp/last.log" >&2; exit 1; }
  t1=$(date +%s%N)
  echo $(( (t1 - t0) / 1000 ))
}
# median and minimum in ms of microsecond samples
stats() { printf '%s\n' "$@" | sort -n | awk '{v[NR] = $1} END {printf "%.1f %.1f", v[int((NR + 1) / 2)] / 1000, v[1] / 1000}'; }

t_render=(); t_glref=(); t_cold=(); t_tiny=(); t_help=(); t_glref_help=()
timed "$tessref" render "$scene" -o "$tmp/tessref.png" >/dev/null  # warm-up: page cache
if (( have_glref )); then
  timed "$glref" --fair "$scene" -o "$tmp/llvmpipe.png" >/dev/null  # warm-up: page and shader caches
  if ! "$tessref" diff --tolerance 1/255 "$tmp/tessref.png" "$tmp/llvmpipe.png" >"$tmp/diff.log" 2>&1; then
    echo "bench-startup: the two images differ by more than 1/255; nothing timed:" >&2
    cat "$tmp/diff.log" >&2
    exit 1
  fi
  check=$(sed -n 's/.*: \([0-9]*\) pixels (.*/\1/p' "$tmp/diff.log")
fi
for ((r = 0; r < rounds; ++r)); do
  t_render+=("$(timed "$tessref" render "$scene" -o "$tmp/tessref.png")")
  t_tiny+=("$(timed "$tessref" render "$tiny" -o "$tmp/tiny.png")")
  t_help+=("$(timed "$tessref" --help)")
  if (( have_glref )); then
    t_glref+=("$(timed "$glref" --fair "$scene" -o "$tmp/llvmpipe.png")")
    t_glref_help+=("$(timed "$glref" --help)")
    if (( r < 3 )); then
      t_cold+=("$(MESA_SHADER_CACHE_DISABLE=true timed "$glref" --fair "$scene" -o "$tmp/llvmpipe.png")")
    fi
  fi
done
read -r render_med render_min <<<"$(stats "${t_render[@]}")"
read -r tiny_med tiny_min <<<"$(stats "${t_tiny[@]}")"
read -r help_med help_min <<<"$(stats "${t_help[@]}")"
write_ms=$("$tessref" render "$scene" -o "$tmp/tessref.png" | sed -n 's/.*write \([0-9.]*\) ms.*/\1/p')

echo "Whole processes, $rounds alternating rounds (medians, minima in brackets), $(nproc) hardware threads:"
echo
echo "| process | ms | target |"
echo "| --- | --- | --- |"
echo "| \`tessref render\` default scene -> PNG | $render_med ($render_min) | - |"
if (( have_glref )); then
  read -r glref_med glref_min <<<"$(stats "${t_glref[@]}")"
  read -r cold_med cold_min <<<"$(stats "${t_cold[@]}")"
  read -r gh_med gh_min <<<"$(stats "${t_glref_help[@]}")"
  ratio=$(awk -v a="$render_med" -v b="$glref_med" 'BEGIN {printf "%.2f", a / b}')
  met=$(awk -v r="$ratio" 'BEGIN {print (r <= 0.5) ? "met" : "not met"}')
  echo "| \`tessref-glref-render --fair\` default scene -> PNG (llvmpipe, shader cache warm) | $glref_med ($glref_min) | - |"
  echo "| the same, shader cache off (${#t_cold[@]} rounds) | $cold_med ($cold_min) | - |"
  echo "| **tessref / llvmpipe**, whole process | **$ratio** | <= 0.5 ($met) |"
fi
tiny_met=$(awk -v t="$tiny_med" 'BEGIN {print (t < 50) ? "met" : "not met"}')
echo "| \`tessref render\` 16x16 one triangle (tessref's fixed cost) | $tiny_med ($tiny_min) | < 50 ($tiny_met) |"
echo "| \`tessref --help\` (loading and linking the executable) | $help_med ($help_min) | - |"
(( have_glref )) && echo "| \`tessref-glref-render --help\` (the same for the llvmpipe program) | $gh_med ($gh_min) | - |"
echo
echo "Both PNGs are written by the same libpng writer (io/png_writer.h, zlib level 6): tessref's took $write_ms ms here."
(( have_glref )) && echo "Image check before timing: $check pixels over 1/255 (tessref diff)."
exit 0
