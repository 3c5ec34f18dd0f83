#!/usr/bin/env bash
# Requirement: 'Nonlinear solver/Extrapolate initial guess' changes the
# iteration path only. The first 4 mm of the forming stroke (coarse mesh,
# 8 steps, mu = 0.1342, J2 plasticity, no cutback) run twice, from the last
# accepted state and from the extrapolation of the last two, then held
# for a step in each of two stages (a new stage starts from the last
# state): the punch
# force at every step agrees to 1e-7 of the largest force (both runs
# converge to the Newton tolerance, and the plastic history is that of the
# same accepted steps), and the extrapolated run needs fewer Newton
# iterations in all.
# Usage: extrapolated_initial_guess.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/partial_stroke.sh"
for extrapolate in false true; do
  partial_stroke "$app" "$src" "$work" "extrapolate_$extrapolate" 8 4 \
    "  set Extrapolate initial guess = $extrapolate"
done

python3 - "$work" <<'PY'
import csv, json, os, sys
work = sys.argv[1]
runs = {}
for extrapolate in ("false", "true"):
    d = os.path.join(work, f"extrapolate_{extrapolate}")
    summary = json.load(open(os.path.join(d, "summary.json")))
    with open(os.path.join(d, "punch_force.csv")) as f:
        forces = [float(row["punch_force_N"]) for row in csv.DictReader(f)]
    runs[extrapolate] = (summary["newton"], forces)
(plain, f0), (extrapolated, f1) = runs["false"], runs["true"]
largest = max(abs(f) for f in f0)
deviation = max(abs(a - b) for a, b in zip(f0, f1)) / largest
checks = [
    ("no cutback in either run",
     plain["n_cutbacks"] == 0 and extrapolated["n_cutbacks"] == 0),
    ("the same 10 steps", len(f0) == len(f1) == 10),
    ("punch forces agree to 1e-7", deviation <= 1e-7),
    ("fewer Newton iterations when extrapolated",
     extrapolated["total_iterations"] < plain["total_iterations"]),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:45s} {'ok' if ok else 'FAILED'}")
print(f"Newton iterations {plain['total_iterations']} from the last state, "
      f"{extrapolated['total_iterations']} extrapolated; largest force "
      f"deviation {deviation:.1e}")
sys.exit(1 if failed else 0)
PY
