#!/usr/bin/env bash
# Same input, same bytes: two serial runs of one case write identical pressure.csv (the
# wall-clock column masked), pressure_theta.csv and garment and body VTU files.
#   same_input_same_bytes.sh TIGHTFIT CASE OUTPUT_DIR BACKEND
set -eu
tightfit=$1 case_file=$2 out=$3 backend=$4
rm -rf "$out"
mkdir -p "$out"
for run in a b; do
  "$tightfit" run "$case_file" --output "$out/$run" --set "Solver/Backend=$backend" \
    --set "Garment/Mesh scale=2" --set "Protocol/Final alpha=1.2" \
    --set "Protocol/Alpha increment=0.1" >"$out/$run.log" 2>&1 ||
    { echo "run $run failed:"; cat "$out/$run.log"; exit 1; }
done
# The wall-clock column, by name, is the one thing allowed to differ.
mask='BEGIN { FS = OFS = "," } NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time_s") c = i }
  { if (c) $c = "-"; print }'
cmp <(awk "$mask" "$out/a/pressure.csv") <(awk "$mask" "$out/b/pressure.csv") ||
  { echo "pressure.csv differs between two runs of the same input"; exit 1; }
compared=1
for file in "$out"/a/*.vtu "$out"/a/*.pvd "$out"/a/pressure_theta.csv; do
  name=$(basename "$file")
  cmp "$file" "$out/b/$name" || { echo "$name differs between two runs of the same input"; exit 1; }
  compared=$((compared + 1))
done
[ "$compared" -ge 8 ] || { echo "only $compared files compared"; exit 1; }
exit 0
