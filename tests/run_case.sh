# Shared by the application test scripts: run_case APP WORK NAME PRM_BODY
# writes WORK/NAME.prm (PRM_BODY, then output settings into WORK/NAME),
# runs APP on it and on failure prints the end of its log and exits 1.
run_case() {
  local app="$1" work="$2" name="$3" body="$4"
  cat > "$work/$name.prm" <<PRM
$body
subsection Output
  set Output directory       = $work/$name
  set Write graphical output = false
  set Write plots            = false
  set Verbosity              = normal
end
PRM
  if ! "$app" "$work/$name.prm" > "$work/$name.log" 2>&1; then
    tail -20 "$work/$name.log"
    echo "$(basename "$0"): the $name run did not complete"
    exit 1
  fi
}
