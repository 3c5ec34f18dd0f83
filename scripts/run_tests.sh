#!/usr/bin/env bash
# Set up, check formatting, build and run the test suite: every test on a
# Release build, then the shared library's tests (tests/common) again on a
# Debug build, where deal.II's assertions (index ranges, vector sizes,
# ghost access) are on.
# Usage: scripts/run_tests.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash scripts/setup.sh

echo "== format check"
git ls-files '*.h' '*.cc' | xargs clang-format --dry-run --Werror

# The parallel tests use mpirun, which refuses to run as root by default.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

status=0
echo "== build (Release)"
bash scripts/build.sh Release "$root/build-release"
echo "== tests (Release)"
ctest --test-dir "$root/build-release" -j"$(nproc)" --output-on-failure ||
  status=1

echo "== build (Debug, shared library)"
bash scripts/build.sh Debug "$root/build-debug" contact_common
echo "== tests of the shared library (Debug)"
ctest --test-dir "$root/build-debug" -R '^common/' -j"$(nproc)" \
  --output-on-failure || status=1
exit $status
