#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite
# (labels unit, validation, cli, stress), then the unit tests again under
# AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset `sanitize`, without the
# deal.II plug-in). CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"

echo "sanitizers: building the unit tests with ASan + UBSan (build-sanitize/)"
if ! { cmake --preset sanitize && cmake --build --preset sanitize -j "$(nproc)"; } >build-sanitize.log 2>&1; then
  grep -E "error|Error" build-sanitize.log | head -40 >&2 || true
  echo "sanitizers: build failed; the log is in build-sanitize.log" >&2
  exit 1
fi
ctest --preset sanitize -j "$(nproc)"
