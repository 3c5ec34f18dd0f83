#!/usr/bin/env bash
# Requirement: the strip's bottom, held in x while pressing (the
# specification's phase 1), is freed by applying its support's reaction as
# a force and ramping that force to zero over a stage (channel 'Bottom x
# release'). Production file (mu = 0.3) on 60 x 3 cells: pressing 3 mm in 5
# steps, the release in 4 steps, then 4 degrees of the turn in 1 step.
# Checks: after pressing the bottom corners have not moved in x (held);
# the held bottom carries a horizontal force (the roller's x force is more
# than 1e-3 of its y force, so the ramp below is not trivially zero); at
# every release step the roller's x force equals (1 - f) times its value
# after pressing, f the released fraction (the strip's horizontal balance:
# the bottom's remaining force is (1 - f) times the support's reaction),
# to 1e-8 of the vertical force; after the release it vanishes to 1e-8 of
# the vertical force; the strip's force balance holds to 1e-8 at every
# step; the turned step converges.
# Usage: bottom_release.sh REYNOLDS_ROLLER SOURCE_DIR WORK_DIR
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
subsection Load program
  subsection Stage 1
    set Number of steps = 5
  end
  subsection Stage 2
    set Number of steps = 4
  end
  subsection Stage 3
    set Number of steps = 1
    set Roller angle    = 4
  end
end
PRM
)"

python3 - "$work/case/history.csv" <<'PY'
import csv, sys
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
pressed = [r for r in rows if abs(r["time"] - 1.) < 1e-9][0]
release = [r for r in rows if 1. + 1e-9 < r["time"] <= 2. + 1e-9]
fx0 = pressed["roller_force_x_N_per_mm"]
fy0 = pressed["roller_force_y_N_per_mm"]
ramp = max(abs(r["roller_force_x_N_per_mm"] - (2. - r["time"]) * fx0)
           / abs(r["roller_force_y_N_per_mm"]) for r in release)
released = release[-1]
left = abs(released["roller_force_x_N_per_mm"] / released["roller_force_y_N_per_mm"])
balance = max(r["balance_relative_error"] for r in rows)
checks = [
    ("bottom corners held in x while pressing",
     pressed["ux_bottom_left_mm"] == 0. and pressed["ux_bottom_right_mm"] == 0.),
    (f"held bottom carries |Fx/Fy| = {abs(fx0 / fy0):.2e} > 1e-3", abs(fx0 / fy0) > 1e-3),
    (f"release steps: {len(release)}", len(release) == 4),
    (f"Fx = (1 - f) Fx(pressed) to {ramp:.1e} <= 1e-8 of Fy", ramp <= 1e-8),
    (f"released: |Fx/Fy| = {left:.1e} <= 1e-8", left <= 1e-8),
    (f"force balance {balance:.1e} <= 1e-8 at every step", balance <= 1e-8),
    ("turned 4 degrees", rows[-1]["roller_angle_deg"] == 4.),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:60s} {'ok' if ok else 'FAILED'}")
sys.exit(1 if failed else 0)
PY
