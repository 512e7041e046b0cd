#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite
# (labels unit, validation, cli, stress), then the unit tests again under
# AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset `sanitize`, without the
# deal.II plug-in), then fuzzes the scene reader and the sweep's input for 60 s in all
# (libFuzzer, tests/fuzz). CI runs exactly this (.ci/run).
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

# Coverage-guided fuzzing (libFuzzer, clang, ASan + UBSan), 60 s in all: the scene reader
# and --set for 30 s (seeded from tests/fuzz/corpus, the shipped scenes), then the sweep's
# --vary lists and --resume files for 30 s (tests/fuzz/corpus-sweep); new inputs go to
# scratch copies.
echo "fuzz: the scene reader and the sweep's input, 30 s each (tests/fuzz)"
if ! { cmake -S tests/fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release &&
       cmake --build build-fuzz -j "$(nproc)"; } >build-fuzz.log 2>&1; then
  tail -20 build-fuzz.log >&2
  echo "fuzz: build failed; the log is in build-fuzz.log" >&2
  exit 1
fi
for target in scene:corpus sweep:corpus-sweep; do
  name=${target%%:*}
  corpus=$(mktemp -d)
  cp tests/fuzz/"${target#*:}"/* "$corpus"/
  if ! (cd "$corpus" && "$OLDPWD/build-fuzz/fuzz_$name" -max_total_time=30 -max_len=4096 "$corpus" >fuzz.log 2>&1); then
    tail -40 "$corpus/fuzz.log" >&2
    echo "fuzz_$name: a finding (the input is in $corpus/crash-* or leak-*): add it as a regression test" >&2
    exit 1
  fi
  echo "fuzz_$name: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$corpus/fuzz.log"), no finding"
  rm -rf "$corpus"
done
