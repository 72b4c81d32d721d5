#!/usr/bin/env bash
# Configures and builds tightfit (Release) in build/, using every core. With target names
# (`bash scripts/build.sh tightfit`) it builds only those: the executable alone skips the tests
# and benchmarks.
set -euo pipefail
cd "$(dirname "$0")/.."
# The unity build compiles each library in batches of 16 files: a cold build takes about a
# third less CPU time (docs/performance.md, "Building"). To edit the code, configure a build
# of your own without it (docs/testing.md).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTIGHTFIT_UNITY_BUILD=ON
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build --parallel "$(nproc)" "${targets[@]}"
