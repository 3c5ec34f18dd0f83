#!/usr/bin/env bash
# Run the production case hertz_frictionless_q1 on the mesh of
# run_main.sh --quick with a given block modulus, judge it with
# scripts/make_report.py --quick, and check the verdict.
# Usage: report_verdict.sh CGS_ROLLER SOURCE_DIR WORK_DIR BLOCK_MODULUS pass|fail
set -euo pipefail
app="$1" src="$2" work="$3" modulus="$4" expect="$5"
case_name=hertz_frictionless_q1
rm -rf "$work"
mkdir -p "$work"
cat > "$work/case.prm" <<PRM
include $src/parameters/cgs_roller/$case_name.prm
subsection Block material
  set Young's modulus = $modulus   # MPa; the benchmark's is 70000
end
subsection Mesh
  set Number of contact refinements = 6   # the mesh of run_main.sh --quick
end
subsection Load program
  subsection Stage 1
    set Number of steps = 1   # frictionless: p0 and a do not depend on the load path
  end
end
subsection Output
  set Output directory       = $work/results/cgs_roller/$case_name
  set Write graphical output = false
  set Write plots            = false
  set Verbosity              = quiet
end
subsection Run control
  set Measure contact cost = false
end
PRM
if ! "$app" "$work/case.prm" > "$work/run.log" 2>&1; then
  cat "$work/run.log"
  echo "report_verdict: the case did not run"
  exit 1
fi
status=0
python3 "$src/scripts/make_report.py" --results "$work/results" --quick \
  --only "cgs_roller/$case_name" > "$work/report.log" 2>&1 || status=$?
cat "$work/report.log"
echo "make_report.py exit status: $status"
case "$expect" in
  pass)
    if [ "$status" -ne 0 ] || grep -q '^FAIL' "$work/report.log"; then
      echo "report_verdict: expected every check to pass"
      exit 1
    fi ;;
  fail)
    if [ "$status" -eq 0 ] || ! grep -q "^FAIL cgs_roller/$case_name: " "$work/report.log"; then
      echo "report_verdict: expected a failed check and a non-zero exit"
      exit 1
    fi ;;
  *) echo "report_verdict: expect 'pass' or 'fail', not '$expect'"; exit 2 ;;
esac
echo "report_verdict: as expected ($expect)"
