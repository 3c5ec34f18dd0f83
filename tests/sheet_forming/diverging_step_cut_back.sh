#!/usr/bin/env bash
# Requirement: a load step whose Newton iteration diverges is cut back
# before it takes the stabilized path (pseudo-transient continuation),
# which serves a step with no equilibrium near its start or a retried step
# that fails again. The first 2 mm of the forming stroke in 4 steps
# (mu = 0.1342, J2 plasticity, finite strain) with the displacement
# element on 2 x 60 cells: its first step diverges from the flat strip
# (the iterate throws the flange into the die) and the half step
# converges. Run with the production file's 'Stabilization factor' (1e-4)
# and with none (0): the first run cuts the step back once, makes no
# stabilized solve and needs at most 15 Newton iterations per step,
# cutbacks counted (the stabilized path took 19 solves and 69 iterations
# in that step), and its punch force at every step is the one of the run
# without stabilization to 1e-9 of the largest force.
# Usage: diverging_step_cut_back.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/partial_stroke.sh"
for factor in 1e-4 0; do
  partial_stroke "$app" "$src" "$work" "factor_$factor" 4 2 \
    "  set Stabilization factor = $factor" 60 \
    "$(printf 'subsection Solid\n  set Element technology = displacement\nend')"
done

python3 - "$work" <<'PY'
import csv, json, os, sys
work = sys.argv[1]
runs = {}
for factor in ("1e-4", "0"):
    d = os.path.join(work, f"factor_{factor}")
    summary = json.load(open(os.path.join(d, "summary.json")))
    with open(os.path.join(d, "punch_force.csv")) as f:
        forces = [float(row["punch_force_N"]) for row in csv.DictReader(f)]
    runs[factor] = (summary["newton"], forces)
(stabilized, f0), (plain, f1) = runs["1e-4"], runs["0"]
largest = max(abs(f) for f in f0)
deviation = (max(abs(a - b) for a, b in zip(f0, f1)) / largest
             if len(f0) == len(f1) else float("inf"))
most = stabilized["max_iterations_per_step_with_cutbacks"]
checks = [
    ("the diverging step is cut back", stabilized["n_cutbacks"] >= 1),
    ("no stabilized solve", stabilized["stabilized_solves"] == 0),
    ("at most 15 iterations per step, cutbacks counted", most <= 15),
    ("the steps of the run without stabilization", len(f0) == len(f1)),
    ("punch forces agree to 1e-9", deviation <= 1e-9),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:50s} {'ok' if ok else 'FAILED'}")
print(f"cutbacks {stabilized['n_cutbacks']}, stabilized solves "
      f"{stabilized['stabilized_solves']}, at most {most} Newton iterations "
      f"per step with cutbacks; largest force deviation {deviation:.1e}")
sys.exit(1 if failed else 0)
PY
