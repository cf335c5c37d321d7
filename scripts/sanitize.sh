#!/usr/bin/env bash
# Runs the test suite under sanitizers (docs/sanitizers.md). Installs what is missing through
# scripts/install-deps.sh (GCC's libasan, libubsan and libtsan come with build-essential).
#
#   scripts/sanitize.sh asan  [CTEST ARGS...]  AddressSanitizer + UndefinedBehaviorSanitizer (and
#                                              LeakSanitizer) over the whole ctest suite, glref
#                                              (Mesa llvmpipe) and piglit included, but not
#                                              install_consumer (see below); build-asan/ (no
#                                              benchmarks: they are not tests)
#   scripts/sanitize.sh tsan  [CTEST ARGS...]  ThreadSanitizer over the threaded tests: the areas
#                                              that run tessref::Parallel on several threads
#                                              (common, raster, pipeline with the CLI, tess);
#                                              build-tsan/
#   scripts/sanitize.sh short [CTEST ARGS...]  CI's pass (.ci/run): ASan + UBSan, test binaries
#                                              only (no glref, bench or piglit), a subset of the
#                                              parser, mesh, TPG, executor and pipeline tests;
#                                              build-asan-short/
#
# Undefined behaviour, an ASan, LSan or TSan report each fail the test that hit them, and the
# script. The last line printed is ctest's summary line ("100% tests passed, 0 tests failed out
# of N"); the exit status is ctest's (1 if only a sanitizer report failed). Extra arguments go to
# ctest, e.g. `scripts/sanitize.sh asan -R Tpg` or `-L pipeline`.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mode=${1:-}
[ $# -gt 0 ] && shift
jobs=$(nproc 2>/dev/null || echo 2)
supp=$root/scripts/sanitizer
start=$(date +%s)
log() { echo "sanitize.sh $mode [$(($(date +%s) - start))s] $*" >&2; }

# The ASan + UBSan flags. vptr is left out: it checks dynamic types through RTTI, which the
# uninstrumented libraries (assimp, OpenImageIO, glslang) and the image I/O module (hidden
# visibility) do not share with tessref's code, so it reports false "wrong dynamic type" errors
# across them. float-cast-overflow is not in GCC's `undefined` (it is in Clang's): a float -> int
# conversion out of range is undefined behaviour, and a rasterizer makes many.
asan_flags="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize=vptr"
asan_flags+=" -fno-sanitize-recover=all -fno-omit-frame-pointer"

case $mode in
  asan | short)
    flags=$asan_flags
    if [ "$mode" = asan ]; then
      build=build-asan glref=ON
    else
      # Its own folder: CI builds it from scratch, and without glref (which tessref_cli links
      # when it is built) the build is shorter.
      build=build-asan-short glref=OFF
    fi
    ;;
  tsan)
    # glref is left out: Mesa's threads are not instrumented, and no glref test is threaded.
    flags="-fsanitize=thread -fno-omit-frame-pointer"
    build=build-tsan glref=OFF
    ;;
  -h | --help)
    sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"
    exit 0
    ;;
  *)
    echo "usage: scripts/sanitize.sh asan|tsan|short [CTEST ARGS...] (try --help)" >&2
    exit 2
    ;;
esac

# Reports go to files (log_path), not to stderr: a test that runs the tessref binary and expects
# it to fail could otherwise take a report for the failure it expected. Any report fails the
# script, whatever ctest says, and is printed at the end. exitcode=86 (no tessref command exits
# with it) and halt_on_error make the first report end the process, so it fails the test too.
reports=$root/$build/sanitizer-reports
common="log_path=$reports/report:exitcode=86:halt_on_error=1"
# ASan: detect_stack_use_after_return, check_initialization_order and strict_init_order are checks
#   that are off by default.
#   verify_asan_link_order=0: a CLI test runs tessref under faketime (LD_PRELOAD), which puts
#   libfaketime before libasan in the library list, and ASan otherwise refuses to start.
#   intercept_tls_get_addr=0: GCC 12's runtime guesses the size of glibc's dynamic TLS blocks
#   with a heuristic for glibc 2.19 (google/sanitizers#1322); with glibc 2.36 it sometimes reads
#   a bogus range, and LeakSanitizer's tracer then crashes at exit ("Tracer caught signal 11",
#   exit status 1) in processes that touched a thread_local of a dlopened library (OpenImageIO's
#   error messages, in the image I/O module). Without the interceptor LSan does not scan
#   dynamic TLS; nothing of tessref's lives there.
# ASan and LSan: scripts/sanitizer/asan.supp and lsan.supp (third-party libraries only).
# UBSan: print_stacktrace names the path to the undefined operation.
export ASAN_OPTIONS="$common:suppressions=$supp/asan.supp:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:verify_asan_link_order=0:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="$common:print_stacktrace=1"
# TSan: scripts/sanitizer/tsan.supp (oneTBB's internals, and Embree's and the image libraries'
# own threads; see there and common/parallel.cpp).
export TSAN_OPTIONS="$common:second_deadlock_stack=1:suppressions=$supp/tsan.supp:print_suppressions=0"

scripts/install-deps.sh >&2

# -O1: the sanitizers' recommended level (fast enough, exact stack traces); -g1: line tables, all
# that reports need (a quarter faster to build than -g, and half the size); no -DNDEBUG, so that
# the assertions in glm's and nlohmann::json's headers check indices and keys too.
log "configuring $build ($flags)"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_CXX_FLAGS="$flags" -DTESSREF_BUILD_TESTS=ON -DTESSREF_BUILD_BENCH=OFF \
  -DTESSREF_BUILD_GLREF=$glref -DTESSREF_BUILD_FUZZ=OFF > /dev/null

# Reports from the build count too (gtest_discover_tests runs the test binaries).
rm -rf "$reports"
mkdir -p "$reports"
ctest_args=(--output-on-failure --no-label-summary -j "$jobs")
case $mode in
  asan)
    log "building everything"
    cmake --build "$build" -j "$jobs"
    # install_consumer is left out: it checks that a find_package(tessref) consumer loads the
    # image I/O module through its RUNPATH, and under ASan it cannot (ASan's dlopen interceptor
    # becomes dlopen's caller, and glibc then searches libasan's RUNPATH, not the program's).
    ctest_args+=(-E '^install_consumer$')
    ;;
  tsan)
    targets=(tessref_cli test_common test_raster test_pipeline test_tess)
    log "building ${targets[*]}"
    cmake --build "$build" -j "$jobs" --target "${targets[@]}"
    ctest_args+=(-L '^(common|raster|pipeline|tess)$')
    ;;
  short)
    targets=(tessref_cli test_common test_tpg test_shader test_pipeline test_tess)
    log "building ${targets[*]}"
    cmake --build "$build" -j "$jobs" --target "${targets[@]}"
    # Left out, for time (20-55 s each under ASan, repeating code that the tests kept run): most
    # of the TPG's exhaustive sweeps over levels (kept: TpgSurfaceRules for triangles_fractional_odd
    # and quads_fractional_even, TpgRules' outer edges for triangles_equal, quads_fractional_odd
    # and isolines_fractional_even, so every domain and spacing; TpgReference covers them all
    # besides), and two repeats of whole renders (GlslTwins across threads and batch sizes, Cli
    # across a clock change). The raster area is left out as well: the pipeline tests run the
    # rasterizer.
    sweeps='SurfaceDomains/TpgSurfaceRules\.WindingInteriorAndTransitionInvariance/(triangles_equal|triangles_fractional_even|quads_equal|quads_fractional_odd)'
    sweeps+='|AllSpacings/TpgRules\.OuterEdgesFollowTheSpec/(triangles_fractional_even|triangles_fractional_odd|quads_equal|quads_fractional_even|isolines_equal|isolines_fractional_odd)'
    repeats='GlslTwins\.ImagesAndDumpsDoNotDependOnThreadsOrBatchSize|Cli\.OutputBytesDoNotDependOnTheClock'
    ctest_args+=(-L '^(common|tpg|shader|pipeline|tess)$' -E "^($sweeps|$repeats)\$")
    ;;
esac

log "running ctest ${ctest_args[*]} $*"
logfile=$build/sanitize-$mode.log
rc=0
(cd "$build" && ctest "${ctest_args[@]}" "$@") 2>&1 | tee "$logfile" || rc=$?
shopt -s nullglob
found=("$reports"/report.*)
if [ ${#found[@]} -gt 0 ]; then
  log "${#found[@]} sanitizer report(s) in $reports:"
  for f in "${found[@]}"; do
    echo "--- $f" >&2
    cat "$f" >&2
  done
  [ "$rc" -ne 0 ] || rc=1
fi
log "done: ctest exit status $rc, ${#found[@]} sanitizer report(s); log in $logfile"
summary=$(grep -E '^[0-9]+% tests passed' "$logfile" | tail -n1 || true)
echo "${summary:-no ctest summary (see $logfile)}"
exit "$rc"
