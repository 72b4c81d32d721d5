#!/usr/bin/env bash
# A case run from another directory finds the files it names: a relative path is read from the
# working directory first, then from the case file's folder; when neither has the file, the
# message names both paths tried (exit status 2).
#   case_files_found_beside_the_case.sh TIGHTFIT CASE PATTERN_FILE SCRATCH
# CASE names PATTERN_FILE by its bare file name (cases/patterns/tube_45T.prm).
set -u
tightfit=$1 case_file=$2 pattern_file=$3 scratch=$4
rm -rf "$scratch"
mkdir -p "$scratch/case" "$scratch/elsewhere"
cp "$case_file" "$pattern_file" "$scratch/case/"
case_copy=$scratch/case/$(basename "$case_file")
pattern_name=$(basename "$pattern_file")
small=(--set "Garment/Mesh scale=2" --set "Protocol/Final alpha=1.1" --set "Protocol/Alpha increment=0.1"
       --set "Output/Write VTU=false" --output "$scratch/out")
fail() { printf '%s\n%s\n' "$1" "$2"; exit 1; }

# From another directory: the pattern beside the case is found.
cd "$scratch/elsewhere" || exit 1
output=$("$tightfit" run "$case_copy" "${small[@]}" 2>&1) ||
  fail "the run from another directory failed (status $?):" "$output"
[ "$(($(wc -l <"$scratch/out/pressure.csv") - 1))" -eq 4 ] || fail "expected 4 load steps (0 to 3)" "$output"

# A file of that name in the working directory comes first: a broken one stops the run, named.
echo '{"pattern": ' >"$pattern_name"
output=$("$tightfit" run "$case_copy" "${small[@]}" 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "expected status 2 with a broken $pattern_name in the working directory, got $status" "$output"
grep -q "not valid JSON" <<<"$output" || fail "the working directory's file was not the one read" "$output"
rm "$pattern_name"

# Neither: both paths tried are named.
rm "$scratch/case/$pattern_name"
output=$("$tightfit" run "$case_copy" "${small[@]}" 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "expected status 2 for a missing pattern file, got $status" "$output"
pattern="Garment/Pattern file: File = '$pattern_name': cannot open the file; tried $scratch/elsewhere/$pattern_name \(relative to the working directory\) and $scratch/case/$pattern_name \(relative to the case file\)"
grep -q -E -- "$pattern" <<<"$output" || fail "the message does not name both paths tried: /$pattern/" "$output"
exit 0
