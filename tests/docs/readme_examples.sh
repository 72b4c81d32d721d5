#!/usr/bin/env bash
# Runs the example commands of README.md as written, each in a scratch folder laid out like the
# repository (cases/, data/, scripts/ and build/ linked in), and fails naming the first command
# that does not exit with status 0.
#   readme_examples.sh SOURCE_DIR BUILD_DIR SCRATCH_DIR quick|long [PAGE]
# PAGE is README.md unless given (the quick start and the cookbook pages run the same way).
# Commands are the lines of the README's ```sh blocks (a trailing "\" joins lines; a trailing
# "# ..." comment is dropped). A command whose comment gives a time in minutes ("# ~3 min")
# takes minutes: it runs only with "long" (the test docs_readme_examples_long, which
# -DTIGHTFIT_LONG_EXAMPLES=ON registers), the others only with "quick". The block with
# scripts/paper-study.sh and scripts/test.sh is skipped: it installs and builds, which is how
# this test came to run. In the environment, LIST_ONLY=1 lists the commands without running them
# and FROM=N starts at the N-th command of the kind (to finish a run that was stopped).
set -u
source_dir=$1
build_dir=$2
scratch=$3
mode=$4
readme=${5:-$source_dir/README.md}
page=$(basename "$readme")

rm -rf "$scratch"
mkdir -p "$scratch"
for folder in cases data scripts; do ln -s "$source_dir/$folder" "$scratch/$folder"; done
ln -s "$build_dir" "$scratch/build"

# One command per line: "quick<TAB>command" or "long<TAB>command".
commands=$(awk '
  /^```sh/ { inside = 1; joined = ""; next }
  /^```/ { inside = 0; next }
  !inside { next }
  {
    line = $0
    comment = ""
    # A comment starts at a "#" after a blank, outside double quotes.
    quoted = 0
    for (i = 1; i <= length(line); i++) {
      ch = substr(line, i, 1)
      if (ch == "\"") quoted = !quoted
      else if (ch == "#" && !quoted && (i == 1 || substr(line, i - 1, 1) ~ /[ \t]/)) {
        comment = substr(line, i); line = substr(line, 1, i - 1); break
      }
    }
    if (comment ~ /[0-9] *min/) long = 1
    sub(/[ \t]+$/, "", line)
    if (line ~ /\\$/) { joined = joined substr(line, 1, length(line) - 1) " "; next }
    joined = joined line
    gsub(/  +/, " ", joined)
    if (joined != "" && joined !~ /^ *#/) print (long ? "long" : "quick") "\t" joined
    joined = ""; long = 0
  }' "$readme")

ran=0
skipped=0
while IFS=$'\t' read -r kind command; do
  case $command in
    *scripts/paper-study.sh* | *scripts/test.sh*) continue ;;
  esac
  if [ "$kind" != "$mode" ]; then
    skipped=$((skipped + 1))
    continue
  fi
  index=$((${index:-0} + 1))
  if [ "$index" -lt "${FROM:-1}" ]; then continue; fi
  echo "== $command"
  if [ -n "${LIST_ONLY:-}" ]; then ran=$((ran + 1)); continue; fi
  start=$(date +%s)
  # stdin from /dev/null: a command that reads it (mpirun does) must not eat the list.
  if ! (cd "$scratch" && bash -c "$command") </dev/null >"$scratch/last.log" 2>&1; then
    echo "FAILED ($page's command, run in $scratch):"
    echo "  $command"
    tail -n 30 "$scratch/last.log"
    exit 1
  fi
  echo "   ok, $(($(date +%s) - start)) s"
  ran=$((ran + 1))
done <<<"$commands"

if [ "$ran" -eq 0 ]; then
  echo "no $mode command found in $readme"
  exit 1
fi
echo "$ran $page commands ran as written ($skipped of the other kind left to the $([ "$mode" = quick ] && echo long || echo quick) test)"
