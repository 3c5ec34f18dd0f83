#!/usr/bin/env bash
# Requirement: without friction a rigid roller turning about its fixed axis
# exerts only normal pressures, whose lines of action pass through the
# axis; the pressed strip (held in x on its bottom, since nothing else
# holds it) must not change while the roller turns. Coarse Q2-P1 mesh
# (60 x 3 cells), exactly incompressible rubber, pressed 3 mm in 5 steps,
# then turned 90 degrees clockwise in 4 steps. Checks: the run completes;
# the x displacements of the four corners after the turn equal those after
# pressing to 1e-8 mm (the Newton tolerance; measured: identical); the vertical
# force on the roller stays the same to 1e-8 relative; the driving torque
# stays below 1e-4 F R (the roller's force points at its axis up to the
# dual-weighted mean of the partner points, a discretisation error:
# measured 7.8e-6 F R on this mesh, 9e-7 F R on 4 mm cells; with
# friction, pressing at mu = 0.3 gave 4e-3 F R); the strip's force
# balance (roller force against the bottom's reaction) holds to 1e-8 at
# every step (the multipliers of exact incompressibility once left it at
# 1e-5).
# Usage: frictionless_rolling.sh REYNOLDS_ROLLER SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/../run_case.sh"
run_case "$app" "$work" case "$(cat <<PRM
include $src/parameters/reynolds_roller/reynolds_roller_mu03.prm
subsection Mesh
  set Number of cells along the length      = 60
  set Number of cells through the thickness = 3
end
subsection Supports
  set Bottom free in x from stage = 0
end
subsection Contact
  set Friction law         = frictionless
  set Friction coefficient = 0
end
subsection Load program
  subsection Stage 1
    set Number of steps = 5
  end
  subsection Stage 2
    set Number of steps = 1
  end
  subsection Stage 3
    set Number of steps = 4
    set Roller angle    = 90
  end
end
PRM
)"

python3 - "$work/case/history.csv" <<'PY'
import csv, sys
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
pressed = [r for r in rows if r["roller_angle_deg"] == 0.][-1]
turned = rows[-1]
corners = ["ux_A_mm", "ux_bottom_left_mm", "ux_top_right_mm", "ux_bottom_right_mm"]
shift = max(abs(turned[c] - pressed[c]) for c in corners)
force = pressed["roller_force_y_N_per_mm"]
force_change = max(abs(r["roller_force_y_N_per_mm"] - force) / force
                   for r in rows if r["roller_angle_deg"] > 0.)
torque = max(abs(r["driving_torque_N"]) for r in rows if r["roller_angle_deg"] > 0.)
balance = max(r["balance_relative_error"] for r in rows)
checks = [
    ("turned 90 degrees", turned["roller_angle_deg"] == 90.),
    (f"corners unchanged by the turn ({shift:.1e} mm <= 1e-8)", shift <= 1e-8),
    (f"vertical force unchanged ({force_change:.1e} <= 1e-8)", force_change <= 1e-8),
    (f"driving torque {torque / (force * 30.):.1e} F R <= 1e-4", torque <= 1e-4 * force * 30.),
    (f"force balance {balance:.1e} <= 1e-8 at every step", balance <= 1e-8),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:60s} {'ok' if ok else 'FAILED'}")
print(f"u_x(A) after pressing {pressed['ux_A_mm']:.6f} mm, vertical force {force:.4f} N/mm")
sys.exit(1 if failed else 0)
PY
