#!/usr/bin/env bash
# Builds tightfit with AddressSanitizer and UndefinedBehaviorSanitizer (CMake option
# TIGHTFIT_SANITIZE) in build-sanitize/ and runs the whole test suite there
# (docs/testing.md). Uses clang++-14 when it is installed (scripts/install-dependencies.sh
# --fuzz; the same build then holds the fuzz targets), g++ otherwise.
#   scripts/sanitize.sh [CTEST ARGUMENTS...]     e.g. scripts/sanitize.sh -R contact
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
compiler=()
command -v clang++-14 >/dev/null && compiler=(-DCMAKE_CXX_COMPILER=clang++-14)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIGHTFIT_SANITIZE=ON \
  "${compiler[@]}" "${launcher[@]}"
cmake --build build-sanitize --parallel "$(nproc)"
# Leaks are reported at exit by LeakSanitizer; the suppressions name what MPI, PETSc and
# their plugins keep until the process ends (docs/testing.md). Open MPI unloads its plugins
# at MPI_Finalize and they have no frame pointers: kept loaded and unwound slowly, their
# allocations show the library names the suppressions match, not "<unknown module>".
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_odr_violation=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer-suppressions/lsan.supp:print_suppressions=0:fast_unwind_on_malloc=0"
export OMPI_MCA_mca_base_component_disable_dlclose=1
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
start=$(date +%s)
status=0
ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" "$@" || status=$?
echo "sanitized suite: $(($(date +%s) - start)) s, ctest status $status"
exit "$status"
