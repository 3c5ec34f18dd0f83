#!/usr/bin/env bash
# Requirement: the 3D model of the strip (a quarter model with its edge
# free, Q1 F-bar bricks, the tools extruded along z) springs back to flat
# after an elastic stroke, as the plane-strain model does
# (elastic_springback.sh): the punch goes down 0.5 mm, then punch and die
# withdraw. With no plastic strain the released strip is stress free and
# straight: the flange angle after release is 90 degrees to 1e-6 on the
# middle plane z = 0 and at the free edge, while both forming angles are
# below 90; the punch force equals the die reaction (and the held node's)
# to 1e-6 at every step.
# Usage: elastic_springback_3d.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/../run_case.sh"
run_case "$app" "$work" elastic "$(cat <<PRM
include $src/parameters/sheet_forming/sheet_forming_mu01342.prm
subsection Geometry
  set Dimension = 3d strip
end
subsection Mesh
  set Number of cells through the thickness = 2
  set Number of cells along the length      = 30
  set Number of cells across the half-width = 1
end
subsection Load program
  subsection Stage 1
    set Number of steps    = 2
    set Punch displacement = 0.5
  end
  subsection Stage 2
    set Number of steps    = 4
    set Punch displacement = -0.5
    set Die displacement   = 1
  end
end
PRM
)"

python3 - "$work/elastic/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r = s["results"]
checks = [
    ("the 3D model", s["case"]["dimension"] == "3d strip"),
    ("forming angle below 90, middle", r["forming_angle_deg"] < 90. - 0.1),
    ("forming angle below 90, edge", r["forming_angle_edge_deg"] < 90. - 0.1),
    ("angle after release 90 to 1e-6, middle",
     abs(r["angle_after_release_deg"] - 90.) <= 1e-6),
    ("angle after release 90 to 1e-6, edge",
     abs(r["angle_after_release_edge_deg"] - 90.) <= 1e-6),
    ("end tangent after release 90 to 1e-6",
     abs(r["angle_after_release_end_tangent_deg"] - 90.) <= 1e-6),
    ("no closed node after release",
     r["closed_contact_nodes_after_release"] == 0),
    (f"force balance {r['max_force_balance_relative_error']:.1e} <= 1e-6",
     r["max_force_balance_relative_error"] <= 1e-6),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:45s} {'ok' if ok else 'FAILED'}")
print(f"forming angle {r['forming_angle_deg']:.6f} deg (edge "
      f"{r['forming_angle_edge_deg']:.6f}), after release "
      f"{r['angle_after_release_deg']:.9f} deg")
sys.exit(1 if failed else 0)
PY
