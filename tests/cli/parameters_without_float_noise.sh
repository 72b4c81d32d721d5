#!/usr/bin/env bash
# Printed defaults are the shortest decimals that read back as the same number: 0.24, not
# 0.23999999999999999 (seven or more 0s or 9s in a row after the decimal point, then a last digit,
# is the noise of printing a binary double to 17 digits).
#   parameters_without_float_noise.sh TIGHTFIT
set -u
tightfit=$1
for format in "" --prm --json; do
  output=$("$tightfit" --print-parameters $format 2>&1) || { echo "--print-parameters $format failed"; exit 1; }
  noise=$(grep -E '[0-9]\.[0-9]*(0000000|9999999)[0-9]' <<<"$output")
  [ -z "$noise" ] || { printf 'float noise in --print-parameters %s:\n%s\n' "$format" "$noise"; exit 1; }
done
# The cylinder's display height, 0.24 m, as the case would write it.
"$tightfit" --print-parameters --prm | grep -q -E '^ *set Display height *= 0\.24$' ||
  { echo "Body/Cylinder/Display height is not printed as 0.24"; exit 1; }
exit 0
