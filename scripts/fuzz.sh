#!/usr/bin/env bash
# Runs every libFuzzer target (fuzz/) for a fixed time each, one after the other, from the
# seed corpus in fuzz/corpus/TARGET (shipped cases and small meshes); what a run adds to the
# corpus stays in build-sanitize/fuzz-corpus/TARGET, crashes in build-sanitize/fuzz-findings/.
# Installs clang-14 and its runtimes first (install-dependencies.sh --fuzz) and builds in
# build-sanitize/ (scripts/sanitize.sh's build: ASan + UBSan + coverage). docs/testing.md.
#   scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]     default 600 s, every target
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] ||
  targets=(fuzz_case_file fuzz_set_assignments fuzz_body_mesh_obj fuzz_body_mesh_stl fuzz_body_mesh_ply
    fuzz_pattern_svg fuzz_pattern_json fuzz_pattern_dxf)
bash scripts/install-dependencies.sh --fuzz
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIGHTFIT_SANITIZE=ON \
  -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" >/dev/null
cmake --build build-sanitize --parallel "$(nproc)" --target "${targets[@]}"
export ASAN_OPTIONS="detect_leaks=1:detect_odr_violation=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer-suppressions/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
status=0
for target in "${targets[@]}"; do
  seeds=fuzz/corpus/${target#fuzz_}
  corpus=build-sanitize/fuzz-corpus/$target findings=build-sanitize/fuzz-findings/$target
  mkdir -p "$corpus" "$findings"
  echo "== $target: $seconds s from $seeds"
  # -rss_limit_mb: an input that makes a reader allocate without bound is a finding.
  nice build-sanitize/fuzz/"$target" "$corpus" "$seeds" -max_total_time="$seconds" \
    -rss_limit_mb=2048 -timeout=30 -max_len=65536 -artifact_prefix="$findings/" \
    -print_final_stats=1 2>"build-sanitize/fuzz-$target.log" || status=1
  grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE|ERROR|SUMMARY" \
    "build-sanitize/fuzz-$target.log" | tail -n 4 || true
done
ls build-sanitize/fuzz-findings/*/ 2>/dev/null || true
exit "$status"
