#!/usr/bin/env bash
# The main job: set up, build in Release, run every production case of the
# suite (and benchmark 1 with friction at 1/100 of the load), run the
# studies, and write results/report.html. Exits non-zero if a judged check
# of the report fails or a case has no result.
# Usage: scripts/run_main.sh [--quick]
#   --quick  coarser meshes and a shorter study, for a first look.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
quick=false
case "${1:-}" in
  --quick) quick=true ;;
  "") ;;
  *) echo "usage: scripts/run_main.sh [--quick]" >&2; exit 2 ;;
esac

setup_start=$SECONDS
bash scripts/setup.sh
bash scripts/build.sh Release "$root/build-release"
echo "== setup and build: $((SECONDS - setup_start)) s"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
results="$root/results"
mkdir -p "$results"
rm -f "$results/report.html"
start=$SECONDS

# Run one case; prefix every console line with the elapsed time. With
# --quick, and for a case derived from a production file (a name and
# override lines), the case runs from results/cases/<name>.prm, which
# includes the production file and overrides it.
run_case() { # app, production .prm, [case name, override lines]
  local app="$1" prm="$2" name="${3:-$(basename "$2" .prm)}" overrides="${4:-}"
  echo "== [$((SECONDS - start)) s] $app: $name"
  if $quick || [ -n "$overrides" ]; then
    local level=6
    [ "$app" = punch3d ] && level=3
    # The 3D models' production meshes are already coarser than that.
    [[ "$name" == *3d* ]] && level=1
    [ "$app" = loaded_pin ] && level=1
    mkdir -p "$results/cases"
    { echo "include $root/$prm"
      if $quick; then
        echo "subsection Mesh"
        if [ "$app" = sheet_forming ]; then
          echo "  set Number of cells through the thickness = 2"
          echo "  set Number of cells along the length      = 30"
        elif [ "$app" = reynolds_roller ]; then
          echo "  set Number of cells through the thickness = 3"
          echo "  set Number of cells along the length      = 60"
        else
          echo "  set Number of contact refinements = $level"
        fi
        echo "end"
      fi
      if [ -n "$overrides" ]; then printf '%s\n' "$overrides"; fi
    } > "$results/cases/$name.prm"
    prm="$results/cases/$name.prm"
  fi
  rm -f "$results/$app/$name/summary.json"
  # The 3D cases run on every core of the machine (their MPI runs give the
  # serial answer, as the .mpirun tests check).
  local launcher=()
  if [[ "$name" == *3d* ]] || [ "$app" = loaded_pin ]; then
    launcher=(mpirun -np "$(nproc)")
  fi
  # A failed run leaves no summary.json; the report then lists the case as
  # not run and the main job exits non-zero after the remaining work.
  "${launcher[@]}" "$root/build-release/$app/$app" "$prm" 2>&1 |
    while IFS= read -r line; do printf '  [%4d s] %s\n' $((SECONDS - start)) "$line"; done ||
    echo "== [$((SECONDS - start)) s] $app: $name FAILED (no result)"
}

for app in cgs_roller punch3d loaded_pin; do
  for prm in parameters/$app/*.prm; do
    run_case "$app" "$prm"
  done
done
for app in sheet_forming reynolds_roller; do
  for prm in parameters/$app/*.prm; do
    run_case "$app" "$prm"
  done
done
# Benchmark 1 with friction at 1/100 of the load, the half-space limit in
# which Spence's solution and the exact-coupling solution hold: the
# production file with the load, the contact strip and the search distance
# scaled, and three more refinements toward the contact (the same a/h as at
# full load, as in scripts/friction_sweep.py --loads small).
if $quick; then small_level=9; else small_level=11; fi
run_case cgs_roller parameters/cgs_roller/spence_mu01.prm spence_mu01_small_load \
"subsection Loading
  set Force per unit thickness = 350
end
subsection Contact
  set Search distance = 0.5
end
subsection Mesh
  set Number of contact refinements = $small_level
  set Contact zone length = 0.8
end
subsection Output
  set Output directory = $results/cgs_roller/spence_mu01_small_load
end
subsection Run control
  set Measure contact cost = false
end
"
echo "== [$((SECONDS - start)) s] production cases done"

study_start=$SECONDS
echo "== accuracy-versus-time study (benchmark 1)"
if $quick; then study_flags=(--quick --degrees 1 2); else study_flags=(); fi
python3 scripts/accuracy_time_study.py "${study_flags[@]}" \
  --build "$root/build-release" --out "$results/studies/cgs_roller_accuracy_time"
echo "== study wall time: $((SECONDS - study_start)) s"

study_start=$SECONDS
echo "== friction sweep (benchmark 1, Coulomb, c/a against Spence)"
if $quick; then sweep_flags=(--quick); else sweep_flags=(); fi
# The sweep reports runs outside the Spence band; that is a result, not an
# error of the main job.
python3 scripts/friction_sweep.py "${sweep_flags[@]}" \
  --build "$root/build-release" --out "$results/studies/cgs_roller_friction_sweep" ||
  echo "== friction sweep: some runs outside the band (see the table)"
echo "== sweep wall time: $((SECONDS - study_start)) s"

study_start=$SECONDS
echo "== mesh study (benchmark 2, axisymmetric)"
if $quick; then mesh_flags=(--quick); else mesh_flags=(); fi
python3 scripts/punch_mesh_study.py "${mesh_flags[@]}" \
  --build "$root/build-release" --out "$results/studies/punch3d_mesh"
echo "== mesh study wall time: $((SECONDS - study_start)) s"

study_start=$SECONDS
echo "== mesh study (benchmark 4, loaded pin)"
# The uniform levels, and level 1 graded toward the arc end.
if $quick; then
  pin_flags=(--levels 1 2 --arc-end-refinements 1 2)
else
  pin_flags=(--levels 1 2 3 --arc-end-refinements 2 3)
fi
python3 scripts/pin_mesh_study.py "${pin_flags[@]}" \
  --build "$root/build-release" --out "$results/studies/loaded_pin_mesh"
echo "== mesh study wall time: $((SECONDS - study_start)) s"

study_start=$SECONDS
echo "== mesh study (benchmark 3, Q2, mu = 0.1342)"
# Through the thickness and along the length; the two finest runs give the
# error estimate.
if $quick; then
  forming_meshes=(2x30 2x60)
else
  forming_meshes=(2x60 2x120 4x120)
fi
python3 scripts/forming_study.py --mus 01342 --degrees 2 --meshes "${forming_meshes[@]}" \
  --build "$root/build-release" --out "$results/studies/sheet_forming" ||
  echo "== forming study: some runs failed or did not converge (see the table)"
echo "== mesh study wall time: $((SECONDS - study_start)) s"

study_start=$SECONDS
echo "== model choices (benchmark 5)"
# The production file with one change each: rotation increment, penalty
# incompressibility, Q1 F-bar, the elastic roller (--quick: 60 x 3 cells, a
# quarter turn).
if $quick; then choice_flags=(--quick); else choice_flags=(); fi
python3 scripts/rolling_choices.py "${choice_flags[@]}" \
  --build "$root/build-release" --out "$results/studies/reynolds_roller" ||
  echo "== model choices: some runs failed (see the table)"
echo "== model choices wall time: $((SECONDS - study_start)) s"

# Every judged check of the report compares a result with a reference that
# holds for it, so a failed check (or a case without a result) is a
# regression: the main job then exits non-zero, after the wall times.
if $quick; then report_flags=(--quick); else report_flags=(); fi
report_status=0
python3 scripts/make_report.py --results "$results" "${report_flags[@]}" || report_status=$?
echo "== main job wall time: $((SECONDS - start)) s (plus $((start - setup_start)) s setup and build)"
echo "== open $results/report.html"
if [ "$report_status" -ne 0 ]; then
  echo "== the report has failed checks or cases without a result (exit status $report_status)" >&2
fi
exit "$report_status"
