#!/usr/bin/env bash
# CalculiX's convergence and ccx time on the pinned paper ring (docs/measured.md,
# "calculix"): every element type at 40 ... 640 elements and the circle as given, 23
# modes each, against the 640-element B32R column and against ringvib's converged FE
# reference. Needs ccx and python3. Usage: bash bench/calculix.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/ringvib-calculix-bench}
mkdir -p "$out"
scene=scenes/paper1990-calculix.toml
build/bin/ringvib table $scene --format json -q --set calculix.elements=40 >"$out/table.json"
for el in B32R B31 B32; do
  for n in 40 80 160 320 640; do
    build/bin/ringvib modes $scene --solver calculix --json --set calculix.elements=$n --set calculix.element=$el \
      >"$out/m_${el}_$n.json"
  done
done
for n in 160 320 640; do
  build/bin/ringvib modes $scene --solver calculix --json --set calculix.elements=$n --set calculix.section=as-given \
    >"$out/m_CIRC_$n.json"
done
python3 - "$out" <<'PY'
import json, sys
d = sys.argv[1]
ref = [r["reference"] for r in json.load(open(f"{d}/table.json"))["rows"]]
conv = json.load(open(f"{d}/m_B32R_640.json"))["omega"]
print("| element | N | max vs B32R 640 | error mode 1 | error mode 4 | error mode 23 | ccx wall s | ccx CPU s | equations |")
print("|---|---|---|---|---|---|---|---|---|")
for el in ["B32R", "B31", "B32", "CIRC"]:
    for n in [40, 80, 160, 320, 640]:
        try:
            j = json.load(open(f"{d}/m_{el}_{n}.json"))
        except OSError:
            continue
        w = j["omega"]
        vc = max(abs(a - b) / b for a, b in zip(w, conv))
        e = [(a - b) / b for a, b in zip(w, ref)]
        name = "B32R, CIRC as given" if el == "CIRC" else el
        print(f"| {name} | {n} | {vc:.1e} | {e[0]:+.2e} | {e[3]:+.2e} | {e[22]:+.2e} | "
              f"{j['model']['ccx_seconds']:.2f} | {j['model']['ccx_cpu_seconds']:.2f} | {j['unknowns']} |")
PY
