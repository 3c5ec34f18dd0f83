#!/usr/bin/env bash
# Set up, check formatting, build in Debug and run the whole test suite.
# Usage: scripts/run_tests.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash scripts/setup.sh

echo "== format check"
git ls-files '*.h' '*.cc' | xargs clang-format --dry-run --Werror

echo "== build (Debug)"
bash scripts/build.sh Debug "$root/build-debug"

# The parallel tests use mpirun, which refuses to run as root by default.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
echo "== tests"
ctest --test-dir "$root/build-debug" -j"$(nproc)" --output-on-failure
