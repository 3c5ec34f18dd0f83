#!/usr/bin/env bash
# Requirement: in the small-load limit, benchmark 1 with finite-strain
# kinematics and contact in the current configuration agrees with the
# small-strain run: peak pressure p0, contact half-width a and stick ratio
# c/a within 0.2 %.
#
# The load is 1/1600 of the benchmark's (a/R = 0.003), with the mesh of
# spence_small_load scaled by a/R (contact strip and search distance 1/4 of
# its values, two contact refinements more), so that a/h is the same. There the tilt of the deformed interface at
# the stick-zone edge, about 0.75 c/R = 9e-4 rad, is below 1 % of mu = 0.1:
# the traction splits into pressure and friction as in the small-strain
# model. (At 1/100 of the load the tilt is 7 times larger and c/a differs
# by one node; see cgs_roller/README.md.) c is resolved to the node
# spacing (2 % of a), so the stick zone must end at the same node.
# Usage: finite_strain_small_load.sh CGS_ROLLER SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"

run() { # name, kinematics
  cat > "$work/$1.prm" <<PRM
include $src/parameters/cgs_roller/spence_mu01.prm
subsection Loading
  set Force per unit thickness = 21.875  # N/mm, 1/1600 of the benchmark load
end
subsection Contact
  set Search distance = 0.125            # mm
end
subsection Mesh
  set Number of contact refinements = 12
  set Contact zone length           = 0.2  # mm
end
subsection Load program
  subsection Stage 1
    set Number of steps = 10
  end
end
subsection Solid
  set Kinematics = $2
end
subsection Output
  set Output directory       = $work/$1
  set Write graphical output = false
  set Write plots            = false
  set Verbosity              = quiet
end
subsection Run control
  set Measure contact cost = false
end
PRM
  if ! "$app" "$work/$1.prm" > "$work/$1.log" 2>&1; then
    cat "$work/$1.log"
    echo "finite_strain_small_load: the $2 case did not run"
    exit 1
  fi
}

run small "small strain"
run finite "finite strain"

python3 - "$work/small/summary.json" "$work/finite/summary.json" <<'PY'
import json, sys
small = json.load(open(sys.argv[1]))["results"]
finite = json.load(open(sys.argv[2]))["results"]
tolerance = 2e-3
failed = False
for key, name in [("peak_pressure_MPa", "p0 [MPa]"),
                  ("contact_half_width_mm", "a [mm]"),
                  ("stick_ratio_c_over_a", "c/a")]:
    s, f = small[key], finite[key]
    difference = (f - s) / s
    ok = abs(difference) <= tolerance
    failed = failed or not ok
    print(f"{name:10s} small strain {s:.6g}  finite strain {f:.6g}  "
          f"difference {100 * difference:+.3f} %  "
          f"{'ok' if ok else 'FAILED'} (tolerance 0.2 %)")
sys.exit(1 if failed else 0)
PY
