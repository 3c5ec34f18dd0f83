#!/usr/bin/env bash
# Set up, build in Release and run every production case of the suite;
# results go to results/<app>/<case>/.
# Usage: scripts/run_main.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash scripts/setup.sh
bash scripts/build.sh Release "$root/build-release"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
start=$(date +%s)
for prm in parameters/cgs_roller/*.prm; do
  echo "== cgs_roller $prm"
  "$root/build-release/cgs_roller/cgs_roller" "$prm"
done
echo "== main job finished in $(( $(date +%s) - start )) s; results in $root/results"
