#!/usr/bin/env bash
# Builds the tessref command (and only what it needs) and installs it into PREFIX (default
# ~/.local): PREFIX/bin/tessref, its image module in PREFIX/lib/tessref, and the library, headers
# and CMake package for find_package(tessref). Installs missing Debian packages first.
#   scripts/install.sh [PREFIX]
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=${1:-$HOME/.local}
scripts/install-deps.sh
scripts/build.sh --target tessref_cli
cmake --install build --prefix "$prefix" >/dev/null
echo "installed: $prefix/bin/tessref"
case ":$PATH:" in
  *":$prefix/bin:"*) ;;
  *) echo "$prefix/bin is not on PATH; add it: export PATH=\"$prefix/bin:\$PATH\"" ;;
esac
