#!/usr/bin/env bash
# Runs a command and checks its exit status and, optionally, that its output (stdout and
# stderr together) matches a pattern:
#   expect.sh STATUS PATTERN COMMAND [ARG ...]      (PATTERN "" checks the status only)
set -u
expected_status=$1
pattern=$2
shift 2
output=$("$@" 2>&1)
status=$?
if [ "$status" -ne "$expected_status" ]; then
  printf 'expected exit status %s, got %s from: %s\n%s\n' "$expected_status" "$status" "$*" "$output"
  exit 1
fi
if [ -n "$pattern" ] && ! grep -q -E -- "$pattern" <<<"$output"; then
  printf 'output of "%s" does not match /%s/:\n%s\n' "$*" "$pattern" "$output"
  exit 1
fi
exit 0
