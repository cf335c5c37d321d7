#!/usr/bin/env bash
# Measures Mesa llvmpipe's verdicts on piglit's tessellation tests, the reference for
# scripts/piglit-tess.sh's table: piglit's own shader_runner (from Debian's piglit package) runs
# every .shader_test under tests/spec/arb_tessellation_shader/ that has a
# `[tessellation evaluation shader]` section on llvmpipe (surfaceless EGL, -auto -fbo), each with
# a 60 s timeout. Writes one line per file (path relative to arb_tessellation_shader/, verdict)
# after a header comment (date, GL renderer, Mesa and piglit versions) to
# tests/data/piglit/llvmpipe_verdicts.txt, or to the file given with -o. Prints one verdict line
# per file and a closing count on stdout.
#
#   scripts/piglit-llvmpipe.sh [-o FILE] [--suite DIR --section NAME]
#
# --suite DIR --section NAME: the files under tests/spec/DIR that have a `[NAME]` section instead
# (e.g. --suite glsl-1.50/execution/geometry --section 'geometry shader'), paths relative to DIR.
#
# Verdicts: pass, fail, skip, warn (shader_runner's own), timeout (over 60 s), crash (no
# PIGLIT result line). Installs libwaffle-1-0, libegl-mesa0 and libgl1-mesa-dri if missing (as
# root or with sudo). Needs Debian's apt and dpkg; the test files come from scripts/fetch-piglit.sh
# and the binaries from the same package version, unpacked into a temporary folder (only
# bin/shader_runner, bin/glinfo and lib/).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/tests/data/piglit/llvmpipe_verdicts.txt
per_file_timeout=60
log() { echo "piglit-llvmpipe: $*" >&2; }
die() {
  log "error: $*"
  exit 1
}
usage() { sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; }

suite=arb_tessellation_shader
section="tessellation evaluation shader"
while [ $# -gt 0 ]; do
  case $1 in
    -o | --suite | --section)
      [ $# -ge 2 ] || die "$1 needs a value"
      case $1 in -o) out=$2 ;; --suite) suite=$2 ;; *) section=$2 ;; esac
      shift 2
      ;;
    -h | --help)
      usage
      exit 0
      ;;
    *) die "unknown argument '$1' (usage: $0 [-o FILE] [--suite DIR --section NAME])" ;;
  esac
done
out_dir=$(dirname "$out")
[ -d "$out_dir" ] || mkdir -p "$out_dir" || die "cannot create $out_dir"

for tool in apt-get dpkg-deb dpkg-query tar timeout find grep sort; do
  command -v "$tool" > /dev/null || die "$tool not found: this needs Debian's apt and dpkg"
done

sudo=""
as_root() {
  if [ "$(id -u)" -ne 0 ] && [ -z "$sudo" ]; then
    command -v sudo > /dev/null || die "installing packages needs root, and sudo is not installed"
    sudo=sudo
  fi
  $sudo "$@"
}

# The runtime: piglit's binaries link waffle; llvmpipe comes with Mesa's EGL and DRI packages.
"$root/scripts/install-deps.sh" libwaffle-1-0 libegl-mesa0 libgl1-mesa-dri >&2 ||
  die "cannot install libwaffle-1-0, libegl-mesa0 and libgl1-mesa-dri"

# The test files, as piglit-tess.sh runs them.
spec=$("$root/scripts/fetch-piglit.sh" | tail -n1) || die "scripts/fetch-piglit.sh failed"
tess=$spec/$suite
[ -d "$tess" ] || die "$tess not found (fetch-piglit.sh printed '$spec')"
tests_version=$(cat "$spec/../../version") || die "no version file beside $spec"

# The binaries, from the same package version.
work=$(mktemp -d "${TMPDIR:-/tmp}/piglit-llvmpipe.XXXXXX")
trap 'rm -rf "$work"' EXIT
download() { (cd "$work" && apt-get download piglit) >&2; }
if ! download || ! compgen -G "$work/piglit_*.deb" > /dev/null; then
  log "apt-get download piglit failed: updating the package lists"
  as_root apt-get update -qq >&2 || die "apt-get update failed"
  download || die "cannot download Debian's piglit package"
fi
debs=("$work"/piglit_*.deb)
[ -f "${debs[0]}" ] || die "apt-get download left no piglit_*.deb"
version=$(dpkg-deb -f "${debs[0]}" Version)
[ "$version" = "$tests_version" ] ||
  die "apt offers piglit $version but the test cache holds $tests_version: rerun scripts/fetch-piglit.sh"
log "unpacking piglit $version's shader_runner"
mkdir "$work/x"
dpkg-deb --fsys-tarfile "${debs[0]}" |
  tar -x -C "$work/x" --wildcards './usr/lib/*/piglit/bin/shader_runner' \
    './usr/lib/*/piglit/bin/glinfo' './usr/lib/*/piglit/lib/*' ||
  die "cannot unpack ${debs[0]}"
rm -f "${debs[0]}"
pdirs=("$work"/x/usr/lib/*/piglit)
piglit=${pdirs[0]}
[ -x "$piglit/bin/shader_runner" ] || die "the package has no bin/shader_runner"

export LD_LIBRARY_PATH=$piglit/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export PIGLIT_PLATFORM=surfaceless_egl
# llvmpipe even where a GPU driver is installed.
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe

info=$(cd "$work" && timeout "$per_file_timeout" "$piglit/bin/glinfo" -auto 2>&1) ||
  die "piglit's glinfo failed on surfaceless EGL: $(printf '%s\n' "$info" | tail -n3)"
renderer=$(printf '%s\n' "$info" | sed -n 's/^GL_RENDERER = //p')
gl_version=$(printf '%s\n' "$info" | sed -n 's/^GL_VERSION = //p')
case $renderer in
  llvmpipe*) ;;
  *) die "the GL renderer is '$renderer', not llvmpipe" ;;
esac
mesa_pkg=$(dpkg-query -W -f='${Version}' libgl1-mesa-dri)
log "$renderer, GL $gl_version, libgl1-mesa-dri $mesa_pkg"

mapfile -t files < <(cd "$tess" && find . -name '*.shader_test' -type f -print0 |
  xargs -0 grep -lF "[$section]" | sed 's|^\./||' | LC_ALL=C sort)
[ ${#files[@]} -gt 0 ] || die "no .shader_test with a [$section] in $tess"

start=$SECONDS
results=$work/results
: > "$results"
declare -A count=()
for f in "${files[@]}"; do
  rc=0
  (cd "$work" && timeout "$per_file_timeout" "$piglit/bin/shader_runner" "$tess/$f" -auto -fbo) \
    > "$work/log" 2>&1 || rc=$?
  verdict=$(sed -n 's/^PIGLIT: {"result": "\([a-z]*\)" }.*/\1/p' "$work/log" | tail -n1)
  if [ "$rc" -eq 124 ]; then
    verdict=timeout
  elif [ -z "$verdict" ]; then
    verdict=crash
  fi
  count[$verdict]=$((${count[$verdict]:-0} + 1))
  echo "$verdict: $f"
  echo "$f $verdict" >> "$results"
done
summary=""
for v in pass fail skip warn timeout crash; do
  [ -n "${count[$v]:-}" ] && summary+="${summary:+, }${count[$v]} $v"
done

tmp=$(mktemp "$out_dir/.llvmpipe_verdicts.XXXXXX")
{
  echo "# Mesa llvmpipe's verdicts on piglit's $suite .shader_test files that have a"
  echo "# [$section] section: piglit's shader_runner FILE -auto -fbo on"
  echo "# surfaceless EGL, $per_file_timeout s timeout per file. Written by scripts/piglit-llvmpipe.sh; do not edit."
  echo "# Date: $(date -u +%Y-%m-%d)"
  echo "# piglit: Debian package piglit $version"
  echo "# Mesa: libgl1-mesa-dri $mesa_pkg; GL_RENDERER = $renderer; GL_VERSION = $gl_version"
  echo "# Result: ${#files[@]} files: $summary"
  echo "# Format: path relative to tests/spec/$suite/, verdict"
  cat "$results"
} > "$tmp"
chmod 644 "$tmp"
mv "$tmp" "$out"
echo "${#files[@]} files: $summary ($((SECONDS - start)) s)"
log "wrote $out"
