#!/usr/bin/env bash
# tightfit measure on a body file: exit 0, the size and the girths on screen, and the JSON, CSV
# and picture written.
#   measure_writes_outputs.sh TIGHTFIT BODY.obj DIR
set -u
tightfit=$1 body=$2 dir=$3
rm -rf "$dir"
output=$("$tightfit" measure "$body" --up +y --output "$dir" 2>&1)
status=$?
if [ "$status" -ne 0 ]; then
  printf 'measure exited with %s:\n%s\n' "$status" "$output"
  exit 1
fi
for pattern in "1.590 m tall" "^ *bust " "^ *waist " "^ *B left " "armpit left" "under-bust band"; do
  if ! grep -q -E -- "$pattern" <<<"$output"; then
    printf 'output does not match /%s/:\n%s\n' "$pattern" "$output"
    exit 1
  fi
done
for file in measurements.json measurements.csv body.png; do
  if [ ! -s "$dir/$file" ]; then
    echo "measure did not write $dir/$file"
    exit 1
  fi
done
grep -q '"bust": {"girth_m": 0\.8' "$dir/measurements.json" || { echo "no bust girth in the JSON"; exit 1; }
exit 0
