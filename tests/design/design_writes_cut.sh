#!/usr/bin/env bash
# A design on the cone: it meets its targets (exit 0), writes its tables and its cut, and
# `tightfit pattern` reads the cut's DXF back as one piece.
#   design_writes_cut.sh TIGHTFIT DESIGN.prm CASE.prm OUTPUT_DIR
set -eu
tightfit=$1 design=$2 case=$3 out=$4
rm -rf "$out"
"$tightfit" design "$design" --set "Design/Case=$case" --output "$out" >"$out.log" 2>&1 ||
  { cat "$out.log"; echo "design failed"; exit 1; }
for f in design_iterations.csv design.csv cut.csv cut.svg cut.dxf iteration_1/pressure.csv; do
  [[ -s $out/$f ]] || { echo "missing $out/$f"; exit 1; }
done
grep -q "every band within the tolerance" "$out.log" || { cat "$out.log"; exit 1; }
"$tightfit" pattern "$out/cut.dxf" --output "$out/pattern" >"$out/pattern.log" 2>&1 ||
  { cat "$out/pattern.log"; echo "tightfit pattern could not read the cut"; exit 1; }
grep -q "cone stocking" "$out/pattern.log" || { cat "$out/pattern.log"; exit 1; }
