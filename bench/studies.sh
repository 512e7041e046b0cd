#!/usr/bin/env bash
# The full-size runs of the tests that CI runs small (tests/support/study.hpp): the same test
# code with RINGVIB_STUDY=1, which selects each test's study size. Minutes each on two cores;
# not part of CI. Usage: bench/studies.sh [BUILD_DIR]   (default build/)
# ctest prints each study's time; its numbers are in the test's RecordProperty output (run the
# executable by hand with --gtest_output=json:FILE to keep them).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
studies=(
  FemStress.HundredThousandUnknownsTwentyThreeModes           # 102 400 unknowns (suite: 25 600)
  FemStress.NearThePrecisionLimitTheFreeRingsRigidModesAndFrequenciesHold  # 24 modes (suite: 12)
  MultibodyEnergyMomentumStress.HundredThousandStepsKeepTheBalance  # 10^5 steps (suite: 10^4)
  MultibodyDynamicsStress.NewmarkFullSceneReachesSecondOrder  # the whole 5 s (suite: 1 s)
)
pattern=$(printf '%s|' "${studies[@]}" | sed 's/|$//; s/\./\\./g')
RINGVIB_STUDY=1 ctest --test-dir "$build" -R "^($pattern)\$" --output-on-failure --timeout 3600
