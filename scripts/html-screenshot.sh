#!/usr/bin/env bash
# A screenshot of an HTML page (a `tessref verify --html` report) by headless Chromium, and
# optionally its DOM after loading: what a person would see, checked without a person
# (tests/verify/html_test.cpp). Installs chromium (scripts/install-deps.sh) if it is missing.
#
#   scripts/html-screenshot.sh PAGE.html OUT.png [DOM.html] [WIDTHxHEIGHT]   (default 1400x1800)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
[ $# -ge 2 ] || { echo "usage: $0 PAGE.html OUT.png [DOM.html] [WIDTHxHEIGHT]" >&2; exit 2; }
page="$(realpath "$1")"
out="$(realpath -m "$2")"
dom="${3:-}"
size="${4:-1400x1800}"
[ -f "$page" ] || { echo "html-screenshot: $1: no such page" >&2; exit 2; }
command -v chromium >/dev/null || "$here/install-deps.sh" chromium
# A fresh profile each run (no state shared between runs or users); --no-sandbox: root in containers.
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile"
       --no-first-run --disable-extensions --disable-background-networking)
rm -f "$out"
chromium "${flags[@]}" --screenshot="$out" --window-size="${size/x/,}" "file://$page" >/dev/null 2>"$profile.log" || true
if [ ! -s "$out" ]; then
  echo "html-screenshot: chromium wrote no screenshot; it said:" >&2; cat "$profile.log" >&2; rm -f "$profile.log"; exit 1
fi
if [ -n "$dom" ]; then
  chromium "${flags[@]}" --dump-dom "file://$page" >"$dom" 2>"$profile.log" ||
    { echo "html-screenshot: chromium --dump-dom failed:" >&2; cat "$profile.log" >&2; rm -f "$profile.log"; exit 1; }
fi
rm -f "$profile.log"
echo "html-screenshot: $out${dom:+ and $dom}"
