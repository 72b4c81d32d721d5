#!/usr/bin/env bash
# The dressed tops' pressure pictures in docs/figures (docs/dressing.md): runs each top case and
# copies its pressure_front.png and pressure_back.png as docs/figures/CASE_front.png and
# CASE_back.png. Each run also leaves its regions.csv and solver.log in output/CASE/ for the
# tables beside the pictures.
#
# Usage: scripts/top-figures.sh [TIGHTFIT [CASE...]]
#   TIGHTFIT  the program (default build/app/tightfit)
#   CASE      case names in cases/ (default: top_female top_male top_female_bodice), or
#             compression_top_BODY: cases/compression_top.prm on the body BODY, one of female
#             (the case's own), male (MakeHuman's) and garmentcode_male
#             (docs/cookbook-dressed-top.md)
# About 90 s of CPU for the female aaron top, 40 s for the male one and 20 s for the bodice
# (docs/dressing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
tightfit=${1:-build/app/tightfit}
shift || true
cases=("$@")
[[ ${#cases[@]} -gt 0 ]] || cases=(top_female top_male top_female_bodice)
if [[ ! -x $tightfit ]]; then
  echo "top-figures: $tightfit is not an executable (build first: scripts/build.sh)" >&2
  exit 2
fi
for name in "${cases[@]}"; do
  prm=cases/$name.prm
  body=()
  case $name in
    compression_top_female) prm=cases/compression_top.prm ;;
    compression_top_male)
      prm=cases/compression_top.prm
      body=(--set "Body/Mesh/File=../data/bodies/makehuman_default_male_body_m.obj") ;;
    compression_top_garmentcode_male)
      prm=cases/compression_top.prm
      body=(--set "Body/Mesh/File=../data/bodies/garmentcode_mean_male.obj") ;;
  esac
  if [[ ! -f $prm ]]; then
    echo "top-figures: no case file $prm" >&2
    exit 2
  fi
  out=output/$name
  echo "== $prm -> $out"
  "$tightfit" run "$prm" "${body[@]}" --set "Output/Directory=$out"
  for view in front back; do
    cp "$out/pressure_$view.png" "docs/figures/${name}_$view.png"
  done
  cat "$out/regions.csv"
done
