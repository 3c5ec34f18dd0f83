#!/usr/bin/env bash
# Requirement: the strip's bending stiffness is right before anything
# yields. A punch displacement of 0.5 mm bends the strip elastically
# (largest bending stress 72 MPa, yield 194 MPa) as a beam on the die's two
# shoulders; on Q2 cells (2 x 240, so that a node lies within 0.03 mm of
# the contact point on the shoulder fillet) the punch force must equal the
# three-point bending force of a Timoshenko beam whose supports roll onto
# the fillets (scripts/forming_study.py, three_point_bending_force()) to
# 0.5 %. The theory neglects the friction at the supports and the local
# indentations, which are well below that; the closed node's distance
# from the true contact point moves the force by 3 x 0.03/57.8 = 0.15 %.
# Usage: elastic_bending.sh SHEET_FORMING SOURCE_DIR WORK_DIR
set -euo pipefail
app="$1" src="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
python3 "$src/scripts/forming_study.py" --app "$app" --out "$work" \
  --bending-stroke 0.5 --degrees 2 --meshes 2x240 --max-bending-error 0.005
