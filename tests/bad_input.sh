#!/usr/bin/env bash
# Requirement: bad input (misspelt key, negative modulus, boundary id that
# does not exist, missing parameter file, impossible geometry) gives a
# one-line error naming the problem and a non-zero exit, and leaves no result
# file that looks valid; the command line prints usage and documentation.
# Usage: bad_input.sh <executable> <production .prm> <cases file>
# Each line of the cases file is "name|expected text|prm lines" with \n
# between the prm lines; lines starting with # are comments.
set -u
app="$1"
production="$2"
cases="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0

check_error() { # name, expected text, prm body
  local name="$1" expected="$2"
  { echo "include $production"; printf '%b\n' "$3"
    echo "subsection Output"; echo "  set Output directory = results_bad"
    echo "  set Write graphical output = false"; echo "  set Write plots = false"
    echo "end"; } > "$name.prm"
  rm -rf results_bad
  "$app" "$name.prm" > stdout.txt 2> stderr.txt
  local rc=$? lines
  lines=$(wc -l < stderr.txt)
  # Failing runs write no summary, profile or plot.
  if [ "$rc" -ne 0 ] && [ "$lines" -eq 1 ] && grep -q "$expected" stderr.txt &&
     [ -z "$(ls results_bad 2>/dev/null | grep -E 'summary|profile|png')" ]; then
    echo "PASS $name: $(cat stderr.txt)"
  else
    echo "FAIL $name: rc=$rc, $lines stderr lines:"; cat stderr.txt
    failures=$((failures + 1))
  fi
}

n_checks=0
while IFS='|' read -r name expected body; do
  case "$name" in \#*|"") continue ;; esac
  check_error "$name" "$expected" "$body"
  n_checks=$((n_checks + 1))
done < "$cases"

# Missing parameter file.
"$app" does_not_exist.prm > stdout.txt 2> stderr.txt
rc=$?
if [ "$rc" -ne 0 ] && [ "$(wc -l < stderr.txt)" -eq 1 ] &&
   grep -q "does_not_exist.prm" stderr.txt; then
  echo "PASS missing_file: $(cat stderr.txt)"
else
  echo "FAIL missing_file: rc=$rc"; cat stderr.txt; failures=$((failures + 1))
fi

# Usage without arguments (non-zero), documentation with units.
"$app" > stdout.txt 2>&1
if [ $? -ne 0 ] && grep -q "Usage" stdout.txt; then echo "PASS usage"
else echo "FAIL usage"; failures=$((failures + 1)); fi
"$app" --print-parameters > stdout.txt 2>&1
if [ $? -eq 0 ] && grep -q "Young's modulus" stdout.txt && grep -q "Units: MPa" stdout.txt
then echo "PASS print_parameters"
else echo "FAIL print_parameters"; failures=$((failures + 1)); fi

echo "$((n_checks + 3 - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
