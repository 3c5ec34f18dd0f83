#!/usr/bin/env bash
# Requirement: 'Nonlinear solver/Active-set solves in later iterations'
# changes the iteration path only, its solves are counted, and it solves
# the wrapped zone on one linearisation. The first 17 mm of the forming
# stroke (coarse mesh, 34 steps, mu = 0.1342, J2 plasticity, finite
# strain), then held for a step in each of two stages, run with 1 solve in
# later iterations (the semismooth update with one change per equilibrium
# once the set cycles) and with up to 60. From 13 mm on the strip lies on
# the punch with almost no pressure: without the solves some step needs
# more than 15 Newton iterations (28), with them every step needs at most
# 15 (8). The punch force at every step agrees to 1e-7 of the largest
# force (both runs converge to the Newton tolerance on the same accepted
# steps, so the plastic history is the same); summary.json counts no
# later solve with 1 and at least one with 60.
# Usage: later_iteration_solves.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/partial_stroke.sh"
for solves in 1 60; do
  partial_stroke "$app" "$src" "$work" "solves_$solves" 34 17 \
    "  set Active-set solves in later iterations = $solves"
done

python3 - "$work" <<'PY'
import csv, json, os, sys
work = sys.argv[1]
runs = {}
for solves in ("1", "60"):
    d = os.path.join(work, f"solves_{solves}")
    summary = json.load(open(os.path.join(d, "summary.json")))
    with open(os.path.join(d, "punch_force.csv")) as f:
        forces = [float(row["punch_force_N"]) for row in csv.DictReader(f)]
    runs[solves] = (summary["newton"], forces)
(one, f0), (many, f1) = runs["1"], runs["60"]
largest = max(abs(f) for f in f0)
deviation = max(abs(a - b) for a, b in zip(f0, f1)) / largest
most = lambda n: n["max_iterations_per_step_with_cutbacks"]
checks = [
    ("no cutback in either run",
     one["n_cutbacks"] == 0 and many["n_cutbacks"] == 0),
    ("the same 36 steps", len(f0) == len(f1) == 36),
    ("punch forces agree to 1e-7", deviation <= 1e-7),
    ("no later solve with 1", one["later_iterations_extra_solves"] == 0),
    ("later solves counted with 60", many["later_iterations_extra_solves"] > 0),
    ("more than 15 iterations in a step with 1", most(one) > 15),
    ("at most 15 iterations per step with 60", most(many) <= 15),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:45s} {'ok' if ok else 'FAILED'}")
print(f"Newton iterations {one['total_iterations']} (at most {most(one)} per "
      f"step) with 1 solve, {many['total_iterations']} (at most {most(many)}; "
      f"+{many['later_iterations_extra_solves']} later solves) with 60; "
      f"largest force deviation {deviation:.1e}")
sys.exit(1 if failed else 0)
PY
