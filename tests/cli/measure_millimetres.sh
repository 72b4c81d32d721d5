#!/usr/bin/env bash
# A body file in millimetres read as metres: measure refuses it (status 2) naming the units.
#   measure_millimetres.sh TIGHTFIT BODY_IN_METRES.obj DIR
set -u
tightfit=$1 body=$2 dir=$3
mkdir -p "$dir"
awk '$1 == "v" { printf "v %.6f %.6f %.6f\n", 1000 * $2, 1000 * $3, 1000 * $4; next } { print }' \
  "$body" > "$dir/body_mm.obj"
exec bash "$(dirname "$0")/expect.sh" 2 "1590 m tall|over 4 m.*0.001 for millimetres" \
  "$tightfit" measure "$dir/body_mm.obj" --up +y --output "$dir/out"
