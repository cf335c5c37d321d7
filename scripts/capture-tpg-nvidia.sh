#!/usr/bin/env bash
# Captures the NVIDIA driver's tessellation primitive generator over tessref's standard sweep and
# reports how it compares with tessref (identical streams, largest coordinate difference).
#
#   Here (Debian 12, after scripts/build.sh):  scripts/capture-tpg-nvidia.sh pack
#     copies tessref-tpg-reference and the libraries it needs beyond a bare system into
#     .device-bundle/ (ignored by git), plus the GL loader packages (libegl1, libglvnd0, libopengl0).
#   On the GPU machine, from the repository root (carry .device-bundle):
#     scripts/capture-tpg-nvidia.sh run
#     writes tests/data/tpg/nvidia/ (commit it) and prints the comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
bundle=.device-bundle
case "${1:-}" in
  pack)
    rm -rf "$bundle" && mkdir -p "$bundle/lib" "$bundle/debs"
    cp build/glref/tessref-tpg-reference "$bundle/"
    # Every resolved library except the C runtime and the GL/EGL loaders (the driver brings those).
    ldd build/glref/tessref-tpg-reference | awk '/=> \//{print $3}' |
      grep -vE '/(libc|libm|libstdc\+\+|libgcc_s|ld-linux|libEGL|libGL|libGLX|libGLdispatch|libOpenGL)[.-]' |
      xargs -r -I{} cp -L {} "$bundle/lib/"
    (cd "$bundle/debs" && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 >/dev/null 2>&1)
    exclude=$(git rev-parse --git-path info/exclude)
    mkdir -p "$(dirname "$exclude")"
    grep -qx "/$bundle/" "$exclude" 2>/dev/null || echo "/$bundle/" >> "$exclude"
    du -sh "$bundle"
    ;;
  run)
    for f in "$bundle"/debs/*.deb; do dpkg -x "$f" /; done
    ldconfig
    export __EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json}
    export LD_LIBRARY_PATH="$PWD/$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    out=${OUT:-.}/tpg-nvidia
    "$bundle/tessref-tpg-reference" --platform device --out "$out" | tee "$out.report.txt" || true
    mkdir -p tests/data/tpg/nvidia && cp "$out"/* tests/data/tpg/nvidia/ 2>/dev/null || true
    ;;
  *)
    echo "usage: $0 pack|run" >&2
    exit 2
    ;;
esac
