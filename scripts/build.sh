#!/usr/bin/env bash
# Configures and builds the `release` CMake preset (Release, FE plug-in, tests) into
# build/. The compiler's output goes to build/build.log and is shown only if the build
# fails.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
echo "build: compiling into build/ (the first build takes several minutes: deal.II is slow to compile)"
if ! { cmake --preset release && cmake --build --preset release -j "$(nproc)"; } >build/build.log 2>&1; then
  grep -E "error|Error" build/build.log | head -40 >&2 || true
  echo "build: failed; the whole log is in build/build.log" >&2
  exit 1
fi
echo "build: done"
