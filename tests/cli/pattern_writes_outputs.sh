#!/usr/bin/env bash
# `tightfit pattern` on FreeSewing's aaron, cut on the fold and sewn at sides and shoulders:
# it lists the panels (the front unfolded: hem and neck whole, three edges mirrored) and seams,
# writes the meshed panels and the drawing.
#   pattern_writes_outputs.sh TIGHTFIT PATTERN_SVG OUTPUT_DIR
set -eu
tightfit=$1 svg=$2 out=$3
rm -rf "$out"
"$tightfit" pattern "$svg" --edge-length 0.02 --folds "front:1, back:1" --output "$out" \
  --seams "front:3 -- back:3 mirrored reversed; front:5 -- back:5 mirrored reversed" >"$out.log" 2>&1 ||
  { cat "$out.log"; exit 1; }
grep -q "^panel front: 8 edges" "$out.log" || { echo "front not unfolded to 8 edges"; cat "$out.log"; exit 1; }
grep -q "^seam 2: front:5 -- back:5 mirrored (reversed)" "$out.log" || { echo "no seam 2"; cat "$out.log"; exit 1; }
grep -q "^sewn: " "$out.log" || { echo "no sewn mesh"; exit 1; }
for f in pattern.vtu outlines.png; do
  [ -s "$out/$f" ] || { echo "missing $f"; cat "$out.log"; exit 1; }
done
