#!/usr/bin/env bash
# Fetches piglit's shader tests from Debian's piglit package into a cache folder outside the
# repository (they are Mesa's files, under their license) and prints the path of its tests/spec
# folder on the last line of stdout; everything else goes to stderr. For example:
#
#   export TESSREF_PIGLIT_SPEC=$(scripts/fetch-piglit.sh | tail -n1)
#
# The cache, ${TESSREF_PIGLIT_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/tessref/piglit}, holds
# tests/spec with every .shader_test of the package and all of arb_tessellation_shader/ (about
# 12 MB: the package's whole tests/spec is 77 MB, mostly other tests' data), and a file
# `version` with the package version. Idempotent: a cache of the version apt offers is kept.
# Runs apt-get update (as root or with sudo) only if the download fails.
set -euo pipefail

dir=${TESSREF_PIGLIT_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/tessref/piglit}
spec=$dir/tests/spec
log() { echo "fetch-piglit: $*" >&2; }
die() {
  log "error: $*"
  exit 1
}

for tool in apt-get apt-cache dpkg-deb tar; do
  command -v "$tool" > /dev/null || die "$tool not found: this needs Debian's apt and dpkg"
done

# Keep the cache unless apt knows a different version (no package lists: keep it too).
candidate=$(apt-cache policy piglit 2> /dev/null | awk '/Candidate:/ { print $2 }')
if [ -f "$dir/version" ] && [ -d "$spec/arb_tessellation_shader" ]; then
  have=$(cat "$dir/version")
  if [ -z "$candidate" ] || [ "$candidate" = "(none)" ] || [ "$candidate" = "$have" ]; then
    log "piglit $have already in $dir"
    echo "$spec"
    exit 0
  fi
  log "$dir has piglit $have, apt offers $candidate"
elif [ -e "$dir" ] && [ -n "$(ls -A "$dir")" ]; then
  # Never delete a folder this script did not make (TESSREF_PIGLIT_DIR set by mistake).
  die "$dir exists and is not a piglit cache (no $dir/version): move it away or set TESSREF_PIGLIT_DIR"
fi

mkdir -p "$(dirname "$dir")"
work=$(mktemp -d "$(dirname "$dir")/.piglit-fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT

download() { (cd "$work" && apt-get download piglit) >&2; }
if ! download; then
  log "apt-get download piglit failed: updating the package lists"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo > /dev/null || die "apt-get update needs root, and sudo is not installed"
    sudo=sudo
  fi
  $sudo apt-get update >&2 || die "apt-get update failed"
  download || die "cannot download Debian's piglit package (it is in Debian 12's main archive)"
fi
debs=("$work"/piglit_*.deb)
[ -f "${debs[0]}" ] || die "apt-get download left no piglit_*.deb"
version=$(dpkg-deb -f "${debs[0]}" Version)

# Unpack only what is kept: the whole package is 2 GB unpacked (generated_tests).
log "unpacking piglit $version"
mkdir "$work/x"
dpkg-deb --fsys-tarfile "${debs[0]}" |
  tar -x -C "$work/x" --wildcards './usr/lib/*/piglit/tests/spec/*.shader_test' \
    './usr/lib/*/piglit/tests/spec/arb_tessellation_shader/*' ||
  die "cannot unpack ${debs[0]}"
found=("$work"/x/usr/lib/*/piglit/tests/spec/arb_tessellation_shader)
[ -d "${found[0]}" ] || die "the package has no tests/spec/arb_tessellation_shader"
mkdir -p "$work/new/tests"
mv "$(dirname "${found[0]}")" "$work/new/tests/spec"
echo "$version" > "$work/new/version"

rm -rf "$dir"
mv "$work/new" "$dir"
log "piglit $version: $(find "$spec" -name '*.shader_test' | wc -l) .shader_test files, $(du -sh "$spec" | cut -f1), in $dir"
echo "$spec"
