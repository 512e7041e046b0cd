#!/usr/bin/env bash
# The 23 modes of the 10^5- and 10^6-segment chain (issue 30), two builds side by side:
# each size runs with the old and the new binary in turn (alternating, so that both see
# the same machine load), N times each (default 3); prints the medians of the process
# wall time and of the CPU time (user + sys), and t(10^6) / t(10^5) of each. On the
# shared 2-core machine the wall time follows the load (uptime is printed); the CPU time
# much less so. Usage: bench/chain_modes.sh OLD_BIN NEW_BIN [N]
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2 runs=${3:-3}
scene=scenes/paper1990-multibody.toml
one() {  # "wall cpu" of one run: bin n
  /usr/bin/time -f "%e %U %S" "$1" modes "$scene" --solver multibody --set "multibody.n=$2" \
    --set modes.count=23 2>&1 >/dev/null | tail -1 | awk '{print $1, $2 + $3}'
}
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
declare -A wall cpu
echo "load before: $(uptime | sed 's/.*load/load/')"
for n in 100000 1000000; do
  ow=() oc=() nw=() nc=()
  for _ in $(seq "$runs"); do
    read -r w c < <(one "$old" "$n"); ow+=("$w"); oc+=("$c")
    read -r w c < <(one "$new" "$n"); nw+=("$w"); nc+=("$c")
  done
  wall[old$n]=$(printf '%s\n' "${ow[@]}" | median); cpu[old$n]=$(printf '%s\n' "${oc[@]}" | median)
  wall[new$n]=$(printf '%s\n' "${nw[@]}" | median); cpu[new$n]=$(printf '%s\n' "${nc[@]}" | median)
done
echo "load after: $(uptime | sed 's/.*load/load/')"
echo "| n (median of $runs) | old wall s | new wall s | old CPU s | new CPU s |"
echo "|---|---|---|---|---|"
for n in 100000 1000000; do
  echo "| $n | ${wall[old$n]} | ${wall[new$n]} | ${cpu[old$n]} | ${cpu[new$n]} |"
done
awk -v a="${wall[old1000000]}" -v b="${wall[old100000]}" -v c="${wall[new1000000]}" -v d="${wall[new100000]}" \
  -v e="${cpu[old1000000]}" -v f="${cpu[old100000]}" -v g="${cpu[new1000000]}" -v h="${cpu[new100000]}" \
  'BEGIN {printf "| t(10^6)/t(10^5) | %.1f | %.1f | %.1f | %.1f |\n", a / b, c / d, e / f, g / h}'
