#!/usr/bin/env bash
# The convenience path timed with two builds of tessref in one run (issue 19's speed check): a mesh
# scene drawn with the built-in C++ programs and with their GLSL twins by the OLD revision and by
# this tree, alternating, and the same mesh written as a scene of draws (tessref scene --as-draws:
# buffers, glDrawElements, the twins as files) drawn by this tree. Each figure is the median frame
# time of `tessref render --repeat R` (the frame only: no start-up, no image write), and the median
# of N such processes. Images are checked: the two builds give the same bytes, and the draw form
# gives the twins' bytes.
#
#   scripts/bench-revisions.sh [--runs N] [--repeat R] [--new-build DIR] [OLD_REV]
#
# OLD_REV defaults to 3f7fe03, the last commit before scenes of draws. Builds into
# build-rev/{old,new} (Release, only the tessref command); --new-build takes this tree's tessref
# from an existing Release build instead (e.g. build). Writes build-rev/revisions.md.
# Exit status: 0 done, 1 an image differs, 2 bad usage or a build failure.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=5 repeat=10 old=3f7fe03 new_build=
while (( $# )); do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --new-build) new_build=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "bench-revisions.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) old=$1; shift ;;
  esac
done
git rev-parse --verify -q "$old^{commit}" >/dev/null || { echo "bench-revisions.sh: '$old' is not a commit" >&2; exit 2; }

out=build-rev
mkdir -p "$out"
build() {  # build SOURCE_DIR BUILD_DIR
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DTESSREF_BUILD_TESTS=OFF -DTESSREF_BUILD_BENCH=OFF \
    -DTESSREF_BUILD_GLREF=OFF >"$2.cmake.log" 2>&1 &&
    cmake --build "$2" -j"$(nproc)" --target tessref_cli >"$2.build.log" 2>&1 ||
    { tail -30 "$2.build.log" "$2.cmake.log" >&2 2>/dev/null; echo "bench-revisions.sh: build of $1 failed" >&2; exit 2; }
}
echo "bench-revisions.sh: building $old and this tree (logs in $out/)" >&2
old_commit=$(git rev-parse "$old^{commit}")
if [[ -x $out/old/cli/tessref && $(cat "$out/old.commit" 2>/dev/null) == "$old_commit" ]]; then
  echo "bench-revisions.sh: $out/old is already $old" >&2  # a revision's build does not change
else
  rm -rf "$out/src-old" "$out/old" "$out/old.commit" && mkdir -p "$out/src-old"
  git archive "$old" | tar -x -C "$out/src-old"
  build "$out/src-old" "$out/old"
  echo "$old_commit" >"$out/old.commit"
fi
old_bin=$out/old/cli/tessref new_bin=$out/new/cli/tessref
if [[ -n $new_build ]]; then
  grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$new_build/CMakeCache.txt" 2>/dev/null ||
    { echo "bench-revisions.sh: $new_build is not a Release build of this tree" >&2; exit 2; }
  cmake --build "$new_build" -j"$(nproc)" --target tessref_cli >"$out/new.build.log" 2>&1 ||
    { tail -30 "$out/new.build.log" >&2; echo "bench-revisions.sh: build of $new_build failed" >&2; exit 2; }
  new_bin=$new_build/cli/tessref
else
  build . "$out/new"
fi
"$new_bin" scene --as-draws "$out/as_draws" >/dev/null

# frame_ms BIN ARGS...: the median frame time of one process's --repeat frames.
frame_ms() {
  local bin=$1; shift
  "$bin" render --repeat "$repeat" "$@" 2>&1 | sed -n 's/.*frame \([0-9.]*\) ms.*/\1/p' | tail -1
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

status=0
same() {  # same A.png B.png WHAT
  cmp -s "$1" "$2" || { echo "bench-revisions.sh: $3: the images differ ($1, $2)" >&2; status=1; }
}
declare -A cases=(
  [default]=""
  [level64]="--set tessellation.inner=64 --set tessellation.outer=64"
  [twins]="--set shaders.program=twins"
)
report=$out/revisions.md
{
  echo "| scene | $old (ms) | this tree (ms) | this / $old |"
  echo "| --- | --- | --- | --- |"
} >"$report"
for name in default level64 twins; do
  read -r -a args <<<"${cases[$name]}"
  a=() b=()
  for ((i = 0; i < runs; i++)); do  # alternating, so that both see the same machine state
    a+=("$(frame_ms "$old_bin" "${args[@]}" -o "$out/old_$name.png")")
    b+=("$(frame_ms "$new_bin" "${args[@]}" -o "$out/new_$name.png")")
  done
  same "$out/old_$name.png" "$out/new_$name.png" "$name, $old against this tree"
  ma=$(printf '%s\n' "${a[@]}" | median) mb=$(printf '%s\n' "${b[@]}" | median)
  echo "| $name | $ma | $mb | $(awk -v a="$ma" -v b="$mb" 'BEGIN { printf "%.3f", b / a }') |" >>"$report"
done
# The same mesh as a scene of draws against the twins on the mesh path, both with this tree.
a=() b=()
for ((i = 0; i < runs; i++)); do
  a+=("$(frame_ms "$new_bin" --set shaders.program=twins -o "$out/mesh_twins.png")")
  b+=("$(frame_ms "$new_bin" "$out/as_draws/scene.json" -o "$out/draws_twins.png")")
done
same "$out/mesh_twins.png" "$out/draws_twins.png" "the draw form against the twins on the mesh path"
ma=$(printf '%s\n' "${a[@]}" | median) mb=$(printf '%s\n' "${b[@]}" | median)
{
  echo
  echo "| this tree | mesh path, twins (ms) | scene of draws, twins (ms) | draws / mesh |"
  echo "| --- | --- | --- | --- |"
  echo "| default | $ma | $mb | $(awk -v a="$ma" -v b="$mb" 'BEGIN { printf "%.3f", b / a }') |"
  echo
  echo "Median frame of \`tessref render --repeat $repeat\`, median of $runs processes each, $(nproc) threads, $(date -u +%Y-%m-%d)."
} >>"$report"
cat "$report"
exit "$status"
