#!/usr/bin/env bash
# Configures and builds tightfit (Release) in build/, using every core. With target names
# (`bash scripts/build.sh tightfit`) it builds only those: the executable alone skips the tests
# and benchmarks.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build --parallel "$(nproc)" "${targets[@]}"
