#!/usr/bin/env bash
# Installs what ringvib needs and is missing, with apt-get (Debian 12).
# Idempotent: packages already installed are skipped; nothing is downloaded then.
# Runs as root without a terminal (CI); as another user it uses sudo if present.
set -euo pipefail

packages=(
  cmake g++ make ninja-build pkg-config git
  libeigen3-dev            # dense and sparse linear algebra (all solvers)
  libarpack2-dev           # ARPACK (through deal.II in fem_reference/)
  libspectra-dev           # shift-invert Lanczos on Eigen sparse matrices (multibody, lumped)
  liblapack-dev            # banded LU (dgbtrf) of the multibody dynamics' O(n) Newton solve
  libdeal.ii-dev           # FE reference only (fem_reference/)
  libtomlplusplus-dev      # scene files
  libcli11-dev             # command line
  nlohmann-json3-dev       # JSON output
  libfmt-dev               # formatting
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev         # bench/
  gnuplot-nox              # figures (pngcairo terminal)
  libxml2-utils            # xmllint: the tests check that JUnit output parses
  time                     # /usr/bin/time -v: peak memory in bench/process.sh
  calculix-ccx             # ccx: the external FE column (calculix/), and its tests
  clang libclang-rt-14-dev # libFuzzer + sanitizers: the scene reader's fuzzer (tests/fuzz)
  pybind11-dev python3-dev # the Python module (python/)
  python3-numpy            # its results as NumPy arrays
  python3-pytest           # its tests (tests/python)
  python3-mypy             # the examples type-checked against the stubs (tests/python/test_types.py)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: missing packages (${missing[*]}) and not root; run as root" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q >/dev/null || { echo "install-deps: apt-get update failed" >&2; exit 1; }
for p in "${missing[@]}"; do
  if ! apt-cache show "$p" >/dev/null 2>&1; then
    echo "install-deps: package '$p' cannot be found by apt-get; cannot continue" >&2
    exit 1
  fi
done
if ! $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >/tmp/ringvib-apt.log 2>&1; then
  tail -20 /tmp/ringvib-apt.log >&2
  echo "install-deps: apt-get install failed for: ${missing[*]} (log: /tmp/ringvib-apt.log)" >&2
  exit 1
fi
echo "install-deps: done"
