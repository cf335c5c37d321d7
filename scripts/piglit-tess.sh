#!/usr/bin/env bash
# Runs piglit's tessellation tests on tessref: every .shader_test under
# tests/spec/arb_tessellation_shader/ (recursively) that has a `[tessellation evaluation shader]`
# section, fetched by scripts/fetch-piglit.sh, through `tessref shader-test`. Prints tessref's
# verdict lines (paths relative to arb_tessellation_shader/) and its closing line
# `N passed, M failed, K skipped`.
#
#   scripts/piglit-tess.sh [--suite DIR] [--table FILE] [--expect-pass N] [TESSREF OPTIONS...]
#
# --suite DIR       another folder under tests/spec/ instead (e.g.
#                   arb_enhanced_layouts/execution/component-layout): its files with a
#                   tessellation control or evaluation shader.
# --section NAME    with --suite: its files with a `[NAME]` section instead (e.g.
#                   --suite glsl-1.50/execution/geometry --section 'geometry shader').
# --verdicts FILE   llvmpipe's verdicts for --table (default tests/data/piglit/llvmpipe_verdicts.txt).
# --table FILE      also writes a Markdown table: file, tessref's verdict and reason, and
#                   llvmpipe's verdict from tests/data/piglit/llvmpipe_verdicts.txt (measured by
#                   scripts/piglit-llvmpipe.sh).
# --expect-pass N   fails unless exactly N files pass.
# --expect-fail F   (repeatable) file F (relative, as printed) fails as it does on llvmpipe, where
#                   piglit expects what the GL spec leaves open, or needs what tessref lacks (the
#                   caller names it): its failure is the expected verdict, and its passing is
#                   reported as a change.
# Other arguments go to `tessref shader-test` as they are (e.g. --threads 2).
# The binary is ${TESSREF_BIN:-build/cli/tessref}. Exit status 0 only when no file failed (and
# the pass count is N, with --expect-pass).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
verdicts_file=$root/tests/data/piglit/llvmpipe_verdicts.txt
log() { echo "piglit-tess: $*" >&2; }
die() {
  log "error: $*"
  exit 2
}
usage() { sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; }

table=""
expect=""
expect_fail=()
suite=""
section=""
pass_through=()
while [ $# -gt 0 ]; do
  case $1 in
    --table | --expect-pass | --suite | --expect-fail | --section | --verdicts)
      [ $# -ge 2 ] || die "$1 needs a value"
      case $1 in
        --table) table=$2 ;;
        --suite) suite=$2 ;;
        --section) section=$2 ;;
        --verdicts) verdicts_file=$2 ;;
        --expect-fail) expect_fail+=("$2") ;;
        *) expect=$2 ;;
      esac
      shift 2
      ;;
    --table=*) table=${1#--table=} && shift ;;
    --expect-pass=*) expect=${1#--expect-pass=} && shift ;;
    -h | --help)
      usage
      exit 0
      ;;
    *) pass_through+=("$1") && shift ;;
  esac
done
if [ -n "$expect" ] && ! [[ $expect =~ ^[0-9]+$ ]]; then
  die "--expect-pass needs a count, not '$expect'"
fi
[[ $verdicts_file == /* ]] || verdicts_file=$PWD/$verdicts_file
if [ -n "$table" ]; then
  [ -d "$(dirname "$table")" ] || die "--table $table: folder $(dirname "$table") does not exist"
  table=$(cd "$(dirname "$table")" && pwd)/$(basename "$table")
fi

bin=${TESSREF_BIN:-build/cli/tessref}
[[ $bin == */* ]] || bin=$(command -v "$bin") || die "tessref binary '${TESSREF_BIN:-}' not found in PATH"
[ -x "$bin" ] || die "tessref binary $bin not found or not executable: build it (cmake --build build --target tessref_cli) or set TESSREF_BIN"
[[ $bin == /* ]] || bin=$PWD/$bin

spec=$("$root/scripts/fetch-piglit.sh" | tail -n1) || die "scripts/fetch-piglit.sh failed"
tess=$spec/${suite:-arb_tessellation_shader}
[ -d "$tess" ] || die "$tess not found (fetch-piglit.sh printed '$spec')"
pattern='\[tessellation evaluation shader\]'
[ -z "$suite" ] || pattern='\[tessellation (control|evaluation) shader\]'
[ -z "$section" ] || pattern="\\[$section\\]"

cd "$tess"
mapfile -t files < <(find . -name '*.shader_test' -type f -print0 |
  xargs -0 grep -lE "$pattern" | sed 's|^\./||' | LC_ALL=C sort)
[ ${#files[@]} -gt 0 ] || die "no .shader_test with a tessellation shader in $tess"

work=$(mktemp -d "${TMPDIR:-/tmp}/piglit-tess.XXXXXX")
trap 'rm -rf "$work"' EXIT
rc=0
"$bin" shader-test "${pass_through[@]}" "${files[@]}" | tee "$work/out" || rc=$?

closing=$(tail -n1 "$work/out")
if ! [[ $closing =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed,\ ([0-9]+)\ skipped$ ]]; then
  die "tessref shader-test stopped without its closing line (exit status $rc)"
fi
passed=${BASH_REMATCH[1]} failed=${BASH_REMATCH[2]} skipped=${BASH_REMATCH[3]}
lines=$(grep -cE '^(pass|fail|skip): ' "$work/out" || true)
if [ $((passed + failed + skipped)) -ne ${#files[@]} ] || [ "$lines" -ne ${#files[@]} ]; then
  die "tessref reported $lines verdicts ($closing) for ${#files[@]} files"
fi
if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then
  die "tessref shader-test exited with status $rc and no failed file"
fi

if [ -n "$table" ]; then
  declare -A llvmpipe=()
  if [ -f "$verdicts_file" ]; then
    while read -r path verdict; do
      [ -n "$path" ] && [ "${path:0:1}" != "#" ] && llvmpipe[$path]=$verdict
    done < "$verdicts_file"
    measured=$(sed -n 's/^# piglit: Debian package piglit //p' "$verdicts_file")
    have=$(cat "$spec/../../version" 2> /dev/null || true)
    [ "$measured" = "$have" ] ||
      log "warning: llvmpipe's verdicts are for piglit $measured, the tests are piglit $have"
  else
    log "warning: $verdicts_file not found: the llvmpipe column is empty"
  fi
  {
    echo "| file | tessref | reason | llvmpipe |"
    echo "|---|---|---|---|"
    grep -E '^(pass|fail|skip): ' "$work/out" | while IFS= read -r line; do
      verdict=${line%%: *}
      rest=${line#*: }
      file=${rest%%: *}
      reason=""
      [ "$rest" = "$file" ] || reason=${rest#*: }
      reason=${reason//|/\\|}
      echo "| \`$file\` | $verdict | $reason | ${llvmpipe[$file]:-not measured} |"
    done
  } > "$work/table"
  cp "$work/table" "$table"
  log "wrote $table"
fi

status=0
mapfile -t failed_files < <(sed -n 's/^fail: \([^:]*\):.*/\1/p' "$work/out")
unexpected=0
for f in "${failed_files[@]}"; do
  if [[ " ${expect_fail[*]} " == *" $f "* ]]; then
    log "$f failed, as expected (--expect-fail: the reason is in the CMake comment or docs/piglit.md)"
  else
    unexpected=$((unexpected + 1))
  fi
done
for f in "${expect_fail[@]}"; do
  [[ " ${failed_files[*]} " == *" $f "* ]] || { log "$f was expected to fail and did not"; status=1; }
done
if [ "$unexpected" -ne 0 ]; then
  log "$unexpected of ${#files[@]} files failed"
  status=1
fi
if [ -n "$expect" ] && [ "$passed" -ne "$expect" ]; then
  log "expected $expect files to pass, $passed passed ($closing)"
  status=1
fi
exit "$status"
