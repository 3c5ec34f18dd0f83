#!/usr/bin/env bash
# Requirement: an exception on one MPI rank ends every rank (no hang in a
# collective call), with its message printed once on standard error and a
# non-zero exit.
# Usage: throw_on_rank_1.sh <executable>
set -u
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "run" > "$work/case.prm"
start=$SECONDS
timeout 120 mpirun -np 2 "$1" "$work/case.prm" > "$work/stdout" 2> "$work/stderr"
rc=$?
elapsed=$((SECONDS - start))
count=$(grep -c "throw_on_rank_1: error (MPI rank 1): thrown on rank 1 only" "$work/stderr")
if [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && [ "$count" -eq 1 ]; then
  echo "ended with exit code $rc after ${elapsed} s, message printed once"
  exit 0
fi
echo "FAILED: exit code $rc (124: timed out, a rank hung), message printed $count times"
cat "$work/stderr"
exit 1
