#!/usr/bin/env bash
# Two builds of ringvib side by side, for "no slower" claims: each command runs with the
# old and the new binary in turn (alternating, so that both see the same machine load),
# N times each (default 5); prints both medians of the process wall time and their ratio.
# Usage: bench/side_by_side.sh OLD_BIN NEW_BIN [N]
#   e.g. git worktree add /tmp/old REV && (cd /tmp/old && cmake --preset release &&
#        cmake --build build -j2 --target ringvib ringvib_fem)
#        bench/side_by_side.sh /tmp/old/build/bin/ringvib build/bin/ringvib
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2 runs=${3:-5}
wall() {  # seconds of one run of "$@"
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || true
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
compare() {
  local a=() b=()
  for _ in $(seq "$runs"); do
    a+=("$(wall "$old" "$@")")
    b+=("$(wall "$new" "$@")")
  done
  local ma mb
  ma=$(printf '%s\n' "${a[@]}" | median)
  mb=$(printf '%s\n' "${b[@]}" | median)
  awk -v c="$*" -v a="$ma" -v b="$mb" 'BEGIN {printf "| %s | %.3f | %.3f | %.2f |\n", c, a, b, b / a}'
}
forced=scenes/paper1990-forced.toml
echo "| command (median of $runs, process wall) | old s | new s | new/old |"
echo "|---|---|---|---|"
compare run scenes/paper1990.toml --paper
compare static scenes/paper1990-static-compare.toml
compare respond scenes/paper1990-forced-compare.toml
compare modes scenes/paper1990-multibody.toml --solver multibody --set multibody.n=100000
compare modes scenes/paper1990-multibody.toml --solver multibody --set multibody.n=1000000
compare static scenes/paper1990-static.toml --solver multibody --set multibody.n=10000
for integrator in newmark generalized-alpha energy-momentum; do
  compare respond "$forced" --solver multibody --set multibody.n=10000 --set response.t_end=10 \
    --set "response.integrator=\"$integrator\""
done
compare respond "$forced" --solver lumped --set lumped.n=10000 --set response.t_end=10
compare respond "$forced" --solver lumped --set lumped.n=2000 --set lumped.variant=\"frame-consistent\" --set response.t_end=10
compare respond "$forced" --solver fem --set fem.elements=200 --set response.t_end=10
compare static scenes/ring-collapse.toml
