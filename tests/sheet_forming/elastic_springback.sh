#!/usr/bin/env bash
# Requirement: a stroke that stays elastic springs back to flat. The punch
# goes down 0.5 mm (bending strain below 1e-3, the yield strain is
# 2.75e-3), then punch and die withdraw by 1 mm each, which frees the
# strip, and further (the production file's withdrawal stage). With no plastic strain the released strip is stress free and
# straight: the flange angle after release is 90 degrees to 1e-6, both
# readings (chord and end tangent), while the forming angle is below 90.
# Usage: elastic_springback.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
. "$(dirname "$0")/../run_case.sh"
run_case "$app" "$work" elastic "$(cat <<PRM
include $src/parameters/sheet_forming/sheet_forming_mu01342.prm
subsection Mesh
  set Number of cells through the thickness = 2
  set Number of cells along the length      = 30
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
r = json.load(open(sys.argv[1]))["results"]
checks = [
    ("forming angle below 90", r["forming_angle_deg"] < 90. - 0.1),
    ("chord angle after release 90 to 1e-6",
     abs(r["angle_after_release_deg"] - 90.) <= 1e-6),
    ("end tangent after release 90 to 1e-6",
     abs(r["angle_after_release_end_tangent_deg"] - 90.) <= 1e-6),
    ("no closed node after release",
     r["closed_contact_nodes_after_release"] == 0),
]
failed = False
for name, ok in checks:
    failed = failed or not ok
    print(f"{name:40s} {'ok' if ok else 'FAILED'}")
print(f"forming angle {r['forming_angle_deg']:.6f} deg, after release "
      f"{r['angle_after_release_deg']:.9f} deg")
sys.exit(1 if failed else 0)
PY
