# Shared by the test scripts that compare iteration paths on the start of
# benchmark 3. partial_stroke APP SOURCE_DIR WORK NAME STEPS STROKE SOLVER
# runs the production file with mu = 0.1342 on the coarse mesh (2 x 30
# cells) over the first STROKE mm of the forming stroke in STEPS steps,
# then holds the punch for a step in each of two stages (a new stage
# starts from the last state), without release; SOLVER holds entries of
# subsection "Nonlinear solver". Optional: CELLS along the length (30) and
# EXTRA, further subsections. The results go to WORK/NAME (run_case).
. "$(dirname "${BASH_SOURCE[0]}")/../run_case.sh"
partial_stroke() {
  local app="$1" src="$2" work="$3" name="$4" steps="$5" stroke="$6"
  local solver="$7" cells="${8:-30}" extra="${9:-}"
  run_case "$app" "$work" "$name" "$(cat <<PRM
include $src/parameters/sheet_forming/sheet_forming_mu01342.prm
subsection Mesh
  set Number of cells through the thickness = 2
  set Number of cells along the length      = $cells
end
$extra
subsection Load program
  subsection Stage 1
    set Number of steps    = $steps
    set Punch displacement = $stroke
  end
  subsection Stage 2
    set Name               = hold
    set Number of steps    = 1
    set Punch displacement = $stroke
    set Die displacement   = 0
  end
  subsection Stage 3
    set Name               = hold
    set Number of steps    = 1
    set Punch displacement = $stroke
    set Die displacement   = 0
  end
end
subsection Release
  set Release stage = 0
end
subsection Nonlinear solver
$solver
end
PRM
)"
}
