#!/usr/bin/env bash
# Process wall time and peak memory of ringvib commands, median of N runs (default 5),
# wall time from the shell's clock (includes /usr/bin/time's own start, about 1 ms),
# peak memory from /usr/bin/time -v. Usage: bench/process.sh [N] -- ARGS...   (one command)
# or without arguments: the benchmark of docs/development.md (a multibody-only scene, the full paper
# table and run, and a tiny FE scene, which is mostly the FE plug-in's start: dlopen of
# libringvib_fem.so and the ~200 libraries deal.II pulls in).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
if [ "${1:-}" != "" ] && [ "${1:-}" != "--" ]; then runs=$1; shift; fi
[ "${1:-}" = "--" ] && shift
bin=./build/bin/ringvib
measure() {
  local walls=() rss=()
  for _ in $(seq "$runs"); do
    local t0 t1 out
    t0=$(date +%s.%N)
    out=$(/usr/bin/time -v "$bin" "$@" 2>&1 >/dev/null | tail -25)
    t1=$(date +%s.%N)
    walls+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')")
    rss+=("$(echo "$out" | awk -F': ' '/Maximum resident set size/ {print $2}')")
  done
  local mw mr
  mw=$(printf '%s\n' "${walls[@]}" | sort -g | awk -v n="$runs" 'NR==int((n+1)/2)')
  mr=$(printf '%s\n' "${rss[@]}" | sort -g | awk -v n="$runs" 'NR==int((n+1)/2)')
  awk -v c="ringvib $*" -v n="$runs" -v w="$mw" -v r="$mr" \
    'BEGIN {printf "%-60s median of %d: wall %7.1f ms, peak RSS %6.1f MB\n", c, n, w * 1000, r / 1024}'
}
if [ $# -gt 0 ]; then
  measure "$@"
else
  measure modes scenes/paper1990-multibody.toml --solver multibody
  measure run scenes/paper1990-multibody.toml
  measure table scenes/paper1990.toml
  measure run scenes/paper1990.toml --paper
  measure modes scenes/paper1990.toml --solver fem --set fem.elements=8 --set modes.count=5
fi
