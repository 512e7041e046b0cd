#!/usr/bin/env bash
# README command 2: install what is missing, build every target, run the whole test suite
# (labels unit, validation, cli, stress) with a report of its 20 slowest tests, then the unit
# tests and the fuzzers from one clang build under AddressSanitizer + UndefinedBehaviorSanitizer
# (CMake preset `sanitize`, without the deal.II plug-in): the unit tests, then libFuzzer on the
# scene reader and on the sweep's input for 60 s in all (tests/fuzz). Each phase prints its
# wall time, and a closing line the total. CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
phases=()
phase() {  # phase NAME COMMAND...: runs it and records its wall time
  local name=$1 t0=$SECONDS
  shift
  "$@"
  phases+=("$name $((SECONDS - t0)) s")
  echo "phase: $name took $((SECONDS - t0)) s"
}

phase install bash scripts/install-deps.sh
phase build bash scripts/build.sh

run_tests() {
  local status=0
  ctest --test-dir build --output-on-failure -j "$(nproc)" --output-junit ctest-junit.xml || status=$?
  python3 scripts/slowest-tests.py build/ctest-junit.xml 20 || true
  return $status
}
phase tests run_tests

sanitize_build() {
  echo "sanitize: building the unit tests and the fuzzers with clang, ASan + UBSan (build-sanitize/)"
  if ! { cmake --preset sanitize && cmake --build --preset sanitize -j "$(nproc)"; } >build-sanitize.log 2>&1; then
    grep -E "error|Error" build-sanitize.log | head -40 >&2 || true
    echo "sanitize: build failed; the log is in build-sanitize.log" >&2
    return 1
  fi
}
phase sanitize-build sanitize_build
phase sanitize-tests ctest --preset sanitize -j "$(nproc)"

# Coverage-guided fuzzing, 60 s in all: the scene reader and --set for 30 s (seeded from
# tests/fuzz/corpus, the shipped scenes), then the sweep's --vary lists and --resume files for
# 30 s (tests/fuzz/corpus-sweep); new inputs go to scratch copies.
fuzz() {
  local target name corpus
  for target in scene:corpus sweep:corpus-sweep; do
    name=${target%%:*}
    corpus=$(mktemp -d)
    cp tests/fuzz/"${target#*:}"/* "$corpus"/
    if ! (cd "$corpus" && "$OLDPWD/build-sanitize/bin/fuzz_$name" -max_total_time=30 -max_len=4096 "$corpus" >fuzz.log 2>&1); then
      tail -40 "$corpus/fuzz.log" >&2
      echo "fuzz_$name: a finding (the input is in $corpus/crash-* or leak-*): add it as a regression test" >&2
      return 1
    fi
    echo "fuzz_$name: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$corpus/fuzz.log"), no finding"
    rm -rf "$corpus"
  done
}
phase fuzz fuzz

echo "test.sh: passed in $((SECONDS - start)) s ($(IFS=,; echo "${phases[*]}" | sed 's/,/, /g'))"
