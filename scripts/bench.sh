#!/usr/bin/env bash
# tessref against Mesa llvmpipe, in one run, and the machine's limits (issue 7; docs/benchmarks.md,
# bench/README.md):
#   1. frame time at 1024x1024 (frame_bench): default scene (PN 12), icosphere PN 64, Wuson PN 12/64,
#      and the default scene as GLSL with a textured fragment shader;
#   2. the primitive generator alone (tpg_bench) and PN patch evaluation alone (pn_bench), also with
#      the GLSL twins on tessref's SPIR-V executor (batch 64 and 1);
#   3. the rasterizer alone on a seeded triangle soup (raster_bench);
#   4. memory bandwidth and fp32 FMA peak (machine_limits), and every figure as a share of them;
#   5. whole processes: `tessref render` of the default scene to a PNG against the same on llvmpipe,
#      and tessref's fixed cost (scripts/bench-startup.sh, appended to the table).
# Each benchmark program alternates tessref and llvmpipe (random interleaving of repetitions) and
# reports medians. Builds what it needs into build-bench (Release, benchmarks on).
#
#   scripts/bench.sh [--quick] [--no-build]
#
# Writes the Markdown table to build-bench/bench.md and stdout; the benchmarks' logs and JSON go to
# build-bench/bench-results/. --quick runs fewer repetitions (about half the time; figures noisier).
# Exit status: 0 done, 1 a benchmark program failed, 2 bad usage or build failure.
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
build_step=1
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    --no-build) build_step=0 ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

build=build-bench
results=$build/bench-results
targets=(frame_bench pn_bench tpg_bench raster_bench machine_limits bench_report)
start=$(date +%s)
log() { echo "bench.sh [$(( $(date +%s) - start ))s] $*" >&2; }

if (( build_step )); then
  scripts/install-deps.sh >&2
  log "configuring and building ${targets[*]} in $build"
  mkdir -p "$build"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTESSREF_BUILD_BENCH=ON >"$build/bench-cmake.log" 2>&1 ||
    { cat "$build/bench-cmake.log" >&2; echo "bench.sh: cmake configure failed" >&2; exit 2; }
  extra=()  # the GL runner's `info`, for the llvmpipe version (absent when glref is not built)
  cmake --build "$build" --target help 2>/dev/null | grep -q 'tessref-glref$' && extra=(tessref-glref tessref-glref-render)
  cmake --build "$build" -j2 --target "${targets[@]}" tessref_cli "${extra[@]}" >"$build/bench-build.log" 2>&1 ||
    { tail -40 "$build/bench-build.log" >&2; echo "bench.sh: build failed (log: $build/bench-build.log)" >&2; exit 2; }
fi
for t in "${targets[@]}"; do
  [[ -x $build/bench/$t ]] || { echo "bench.sh: $build/bench/$t missing (run without --no-build)" >&2; exit 2; }
done
wuson=/usr/share/assimp/models/OFF/Wuson.off
[[ -r $wuson ]] || echo "bench.sh: $wuson missing (package assimp-testmodels): the Wuson frames are skipped" >&2

# llvmpipe's per-draw buffers must not go through mmap each draw (glref/README.md,
# /work/shared/notes/llvmpipe.md): the same thresholds that glref::keep_draw_buffers_off_mmap sets.
export GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=268435456:glibc.malloc.top_pad=67108864

# Repetitions: light frames, the Wuson level-64 frame (~2-3 s a side), PN, TPG, raster.
if (( quick )); then
  r_frame=3 r_heavy=1 r_pn=3 r_tpg=3 r_raster=3 r_startup=3 limits_flag=--quick
else
  r_frame=9 r_heavy=3 r_pn=7 r_tpg=7 r_raster=7 r_startup=11 limits_flag=
fi

rm -rf "$results"
mkdir -p "$results"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
failed=()

# run NAME PROGRAM REPETITIONS [ARGS...]: one benchmark program, interleaved repetitions, JSON out.
run() {
  local name=$1 program=$2 reps=$3
  shift 3
  log "$name: $program, $reps repetitions"
  if ! "$build/bench/$program" --benchmark_repetitions="$reps" \
        --benchmark_enable_random_interleaving=true --benchmark_min_time=0.2 \
        --benchmark_color=false --benchmark_out="$results/$name.json" \
        --benchmark_out_format=json "$@" >"$results/$name.log" 2>&1; then
    echo "bench.sh: $program failed (log: $results/$name.log)" >&2
    tail -20 "$results/$name.log" >&2
    failed+=("$name")
  fi
  # The program's own closing table: what follows its last benchmark line.
  awk '/^BM_/ {last = NR} {line[NR] = $0} END {for (i = last + 1; i <= NR; i++) if (line[i] != "") print line[i]}' \
    "$results/$name.log" >&2
}

log "machine_limits"
"$build/bench/machine_limits" $limits_flag --json "$results/limits.json" | tee "$results/limits.log" >&2
run frames frame_bench "$r_frame" \
  --benchmark_filter='^BM_(TessrefFrame/(pn12|ico64|wuson12|textured)|LlvmpipeFrame/(pn12|ico64|wuson12|textured)/fair)'
run frames_wuson64 frame_bench "$r_heavy" \
  --benchmark_filter='^BM_(TessrefFrame/wuson64|LlvmpipeFrame/wuson64/fair)'
run tpg tpg_bench "$r_tpg"
run pn pn_bench "$r_pn" \
  --benchmark_filter='^BM_(TessrefPn/(12/256|64/16)|ExecutorPn/(12/256|64/16)/(256|1)|LlvmpipePnDiscard/(12|64)|LlvmpipeFlatDiscard/(12|64))/'
run raster raster_bench "$r_raster"
log "start-up: whole processes, $r_startup rounds"
if ! scripts/bench-startup.sh "$build" "$r_startup" >"$results/startup.md" 2>"$results/startup.log"; then
  echo "bench.sh: bench-startup.sh failed (log: $results/startup.log)" >&2
  cat "$results/startup.log" >&2
  failed+=(startup)
fi

load_after=$(cut -d' ' -f1-3 /proc/loadavg)
model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
cores=$(lscpu | awk -F: '/^Core\(s\) per socket/ {c=$2} /^Socket\(s\)/ {s=$2} END {print c * s}')
renderer=$("$build/glref/tessref-glref" info 2>/dev/null | sed -n 's/^renderer: //p' || true)
mode=$([[ $quick == 1 ]] && echo "--quick" || echo "full")
notes="$(nproc) hardware threads; llvmpipe: ${renderer:-unavailable}, LP_NUM_THREADS=${LP_NUM_THREADS:-default}; \
GLIBC_TUNABLES mmap_threshold 32 MiB, trim_threshold 256 MiB, top_pad 64 MiB; \
$mode run: medians of $r_frame interleaved repetitions ($r_heavy for the Wuson level-64 frame, \
$r_pn PN, $r_tpg TPG, $r_raster raster); load average before $load_before, after $load_after; \
$(( $(date +%s) - start )) s in all."

inputs=()
for name in frames frames_wuson64 tpg pn raster; do
  [[ -s $results/$name.json ]] && inputs+=("$results/$name.json")
done
"$build/bench/bench_report" --limits "$results/limits.json" --machine "$model, $cores cores" \
  --date "$(date -u '+%Y-%m-%d %H:%M UTC')" --notes "$notes" -o "$build/bench.md" "${inputs[@]}"
if [[ -s $results/startup.md ]]; then
  { echo; echo "### Start-up (scripts/bench-startup.sh)"; echo; cat "$results/startup.md"; } >>"$build/bench.md"
  cat "$results/startup.md"
fi
log "table written to $build/bench.md"
if (( ${#failed[@]} )); then
  echo "bench.sh: failed: ${failed[*]}" >&2
  exit 1
fi
