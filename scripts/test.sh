#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite
# (labels unit, validation, cli, stress). CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
