#!/usr/bin/env bash
# Configures the `release` CMake preset (Release, Ninja, FE plug-in) into build/ and builds
# the targets named as arguments, or everything (the tests too) without any:
#   bash scripts/build.sh ringvib     the program and its FE plug-in (README command 1)
#   bash scripts/build.sh             every target of the preset (README command 2)
# The compiler's output goes to build/build.log and is shown only if the build fails.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
# A build/ configured by an older checkout with another generator cannot be reused.
if [ -f build/CMakeCache.txt ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' build/CMakeCache.txt; then
  rm -rf build/CMakeCache.txt build/CMakeFiles
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
echo "build: compiling ${*:-every target} into build/ (deal.II is slow to compile: minutes on a first build)"
if ! { cmake --preset release && cmake --build --preset release -j "$(nproc)" "${targets[@]}"; } >build/build.log 2>&1; then
  grep -E "error|Error" build/build.log | head -40 >&2 || true
  echo "build: failed; the whole log is in build/build.log" >&2
  exit 1
fi
echo "build: done"
