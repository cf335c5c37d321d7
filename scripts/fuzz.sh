#!/usr/bin/env bash
# Builds the libFuzzer fuzzers (fuzz/, docs/fuzzing.md) with Clang in build-fuzz/ and runs each
# target for SECONDS (default 60) on a copy of its seed corpus fuzz/corpus/<target>/ (the
# committed corpus never grows). Prints, per target, the CPU seconds it got, the executions, the
# coverage of libFuzzer's last status line (cov: edges, ft: features) and the crashes found; their
# inputs are kept in the artifacts folder it names. Exits 1 if any target found a crash (or a leak, timeout or OOM).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]   # default: every fuzz/fuzz_*.cpp target
#   scripts/fuzz.sh --minutes N [TARGET...]  # N minutes a target, each continuing from its kept
#                                            # corpus (FUZZ_KEEP_CORPUS=1)
#
# Environment: FUZZ_WORK, the work folder (default out/fuzz: <target>/corpus, <target>/artifacts,
# <target>/log.txt); FUZZ_JOBS, targets run at once (default 1, one core each);
# FUZZ_KEEP_CORPUS=1 continues from the work folder's corpus instead of a fresh copy.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
if [ "${1:-}" = --minutes ]; then
  [[ ${2:-} =~ ^[0-9]+$ ]] || { echo "fuzz.sh: --minutes needs a whole number of minutes" >&2; exit 2; }
  seconds=$(( $2 * 60 ))
  export FUZZ_KEEP_CORPUS=1
  shift 2
else
  seconds=${1:-60}
  [ $# -gt 0 ] && shift
fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi
work=${FUZZ_WORK:-$root/out/fuzz}
jobs=${FUZZ_JOBS:-1}

scripts/install-deps.sh >&2
scripts/install-deps.sh clang libclang-rt-14-dev >&2
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -DTESSREF_BUILD_FUZZ=ON -DTESSREF_BUILD_TESTS=OFF \
    -DTESSREF_BUILD_BENCH=OFF -DTESSREF_BUILD_GLREF=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >&2
fi
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)" --target "${targets[@]}" >&2

run_target() {
  local t=$1 dir=$work/$1
  mkdir -p "$dir/artifacts"
  touch "$dir/artifacts/.start"  # what this run finds is newer than this
  if [ "${FUZZ_KEEP_CORPUS:-0}" != 1 ] || [ ! -d "$dir/corpus" ]; then
    rm -rf "$dir/corpus"
    cp -r "fuzz/corpus/$t" "$dir/corpus"
  fi
  local dict=() max_len=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
  # libFuzzer's inputs stay under 4 KB by default; a scene file must reach the 300 KB of nesting
  # that once overflowed the JSON library's stack.
  [ "$t" = fuzz_scene ] && max_len=(-max_len=1048576)
  # -timeout: one input running longer is a hang (a finding); -rss_limit_mb: so is a blow-up.
  # The CPU time it got (user + system seconds) beside the wall time: on a shared machine the two
  # differ, and the executions follow the CPU time.
  local TIMEFORMAT='%U %S'
  { time "build-fuzz/fuzz/$t" "$dir/corpus" "${dict[@]}" "${max_len[@]}" -max_total_time="$seconds" -rss_limit_mb=4096 \
    -timeout=60 -print_final_stats=1 -artifact_prefix="$dir/artifacts/" >"$dir/log.txt" 2>&1 || true; } 2>"$dir/cpu.txt"
}

# Leaks inside libraries tessref cannot fix (fuzz/lsan.supp says which and why).
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

running=0
for t in "${targets[@]}"; do
  echo "fuzz.sh: $t for ${seconds}s (log: $work/$t/log.txt)" >&2
  run_target "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

status=0
printf '%-14s %8s %8s %12s %7s %8s %8s  %s\n' target seconds cpu_s executions cov ft crashes artifacts
for t in "${targets[@]}"; do
  dir=$work/$t
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log.txt" | tail -1)
  last=$(grep -E '^#[0-9]+' "$dir/log.txt" | grep 'cov:' | tail -1 || true)
  [ -n "$execs" ] || execs=$(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
  crashes=$(find "$dir/artifacts" -maxdepth 1 -type f -newer "$dir/artifacts/.start" \
              \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  [ "$crashes" -eq 0 ] || status=1
  cpu=$(awk '{ printf "%.0f", $1 + $2 }' "$dir/cpu.txt" 2>/dev/null || true)
  printf '%-14s %8s %8s %12s %7s %8s %8s  %s\n' "$t" "$seconds" "${cpu:-?}" "${execs:-?}" "${cov:-?}" "${ft:-?}" \
    "$crashes" "$dir/artifacts"
done
exit $status
