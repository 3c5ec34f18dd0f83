#!/usr/bin/env bash
# Configure and build the suite, or one target of it.
# Usage: scripts/build.sh <Debug|Release> [build directory] [target]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
type="${1:-Release}"
build="${2:-$root/build-$(echo "$type" | tr '[:upper:]' '[:lower:]')}"
target="${3:-all}"
mkdir -p "$build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="$type" \
  -DCMAKE_COMPILE_WARNING_AS_ERROR=ON > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
cmake --build "$build" --target "$target" -j"$(nproc)"
