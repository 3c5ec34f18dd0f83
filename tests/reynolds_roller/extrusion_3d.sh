#!/usr/bin/env bash
# Requirement: the 3D extrusion of benchmark 5 (strip and roller extruded
# along z, u_z = 0 on the strip's z faces) is the plane-strain problem
# solved in 3D: its Q2-P1 bricks, quadrilateral mortar faces against the
# cylinder, Coulomb friction and the rotating tool must reproduce the
# plane-strain run step by step. Coarse mesh (30 x 2 cells, one across the
# width), the bottom pressed up 1 mm in 2 steps (held in x), its support
# released in 1 step, then the roller turned 4 degrees in 2 steps with
# mu = 0.3. Checks: the same accepted steps, and every column of
# history.csv (corner displacements, creep ratios, roller force and
# driving torque per mm of depth) equal to 1e-8 of the column's largest
# magnitude (the Newton tolerance is 1e-10 of the load), |J - 1| to 1e-8
# (of J).
# Usage: extrusion_3d.sh REYNOLDS_ROLLER SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/../run_case.sh"
for model in "plane strain" "3d extrusion"; do
  run_case "$app" "$work" "${model// /_}" "$(cat <<PRM
include $src/parameters/reynolds_roller/reynolds_roller_mu03.prm
subsection Geometry
  set Dimension = $model
  set Width     = 10   # mm
end
subsection Mesh
  set Number of cells along the length      = 30
  set Number of cells through the thickness = 2
  set Number of cells across the width      = 1
end
subsection Load program
  subsection Stage 1
    set Number of steps = 2
    set Indentation     = 1
  end
  subsection Stage 2
    set Number of steps = 1
    set Indentation     = 1
  end
  subsection Stage 3
    set Number of steps = 2
    set Roller angle    = 4
  end
end
PRM
)"
done

python3 - "$work/plane_strain" "$work/3d_extrusion" <<'PY'
import csv, json, sys
plane, solid = (list(csv.DictReader(open(d + "/history.csv"))) for d in sys.argv[1:])
dimension = json.load(open(sys.argv[2] + "/summary.json"))["case"]["dimension"]
checks = [("the 3D run is the 3D model", dimension == "3d extrusion"),
          (f"same accepted steps ({len(plane)} and {len(solid)})",
           len(plane) == len(solid) and
           all(a["time"] == b["time"] for a, b in zip(plane, solid)))]
for column in plane[0]:
    if column == "balance_relative_error":
        continue   # round-off of each model, below 1e-10
    scale = 1. if column == "dilatation_error" else \
        max(abs(float(r[column])) for r in plane)
    error = max(abs(float(a[column]) - float(b[column]))
                for a, b in zip(plane, solid))
    checks.append((f"{column}: 3D - plane strain {error:.1e} <= 1e-8 of {scale:.4g}",
                   error <= 1e-8 * scale))
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:75s} {'ok' if ok else 'FAILED'}")
sys.exit(1 if failed else 0)
PY
