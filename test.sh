#!/usr/bin/env bash
# Runs the whole test suite: installs what is missing, builds, runs every test with CTest.
# With --sanitize, builds and runs the tests under AddressSanitizer + UndefinedBehaviorSanitizer
# (in build-asan/). Both builds compile each module as one unit (SEGSLAM_UNITY_BUILD, the default of
# scripts/build.sh): that is what makes a clean build fast enough for CI. build/ is configured
# exactly as setup.sh configures it, so that test.sh after setup.sh compiles nothing again. Tests
# that need ../shared (real data, models) skip with a message without it.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install_deps.sh
scripts/build_web.sh
if [ "${1:-}" = "--sanitize" ]; then
  # GCC 12's flow-based warnings (maybe-uninitialized inside std::regex and std::function, among
  # others) give false positives on ASan-instrumented code, so this build does not turn warnings
  # into errors; the plain build above keeps -Werror for the same sources. -O1 with line tables
  # only: the sanitizers still report file and line, and the build takes far less time.
  scripts/build.sh build-asan -DSEGSLAM_SANITIZE=ON -DSEGSLAM_BUILD_BENCH=OFF -DSEGSLAM_WERROR=OFF \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
else
  scripts/build.sh build
  ctest --test-dir build --output-on-failure -j"$(nproc)"
fi
