#!/usr/bin/env bash
# README command 1: install what is missing, build, and regenerate the paper's Table 1
# from scenes/paper1990.toml (report, data and figures in out/paper1990/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh ringvib
./build/bin/ringvib run scenes/paper1990.toml --paper --out out/paper1990
