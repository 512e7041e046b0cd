#!/usr/bin/env python3
"""A CI accuracy gate written in Python: each solver's largest frequency error against the
converged FE reference, over the modes a project cares about, held to a bound; the verdict as
JUnit XML (one test case per solver) and as the exit code (0 pass, 1 a gate failed).

`ringvib run SCENE` does this for the scene's `[gates]` (every mode of the table). A script like
this one gates what `[gates]` does not say: a range of modes, a bound per solver given by the CI
job, or several scenes in one report.

    PYTHONPATH=build/python python3 examples/ci_gate.py [--scene scenes/paper1990.toml]
        [--modes 1-9] [--bound multibody=2.5 --bound fem=0.05 ...] [--junit gates.xml]

Bounds are in percent of the reference frequency. A solver without a bound is reported, not
gated.
"""
import argparse
import pathlib
import xml.etree.ElementTree as ET
from typing import Dict, List, Tuple

import ringvib

HERE = pathlib.Path(__file__).resolve().parent


def bounds(items: List[str]) -> Dict[str, float]:
    """['multibody=1.0', ...] -> {'multibody': 1.0, ...}."""
    out: Dict[str, float] = {}
    for item in items:
        solver, _, value = item.partition("=")
        if not value:
            raise SystemExit(f"--bound {item}: expected SOLVER=PERCENT")
        out[solver] = float(value)
    return out


def worst_errors(scene: ringvib.Scene, first: int, last: int) -> Dict[str, Tuple[float, int]]:
    """Each solver's largest |error| (%) against the reference over modes first..last, and its mode."""
    worst: Dict[str, Tuple[float, int]] = {}
    for row in ringvib.table(scene):
        mode = int(row["mode"])
        if not first <= mode <= last:
            continue
        for key, value in row.items():
            if key.endswith("_error_pct"):
                solver = key[: -len("_error_pct")]
                if solver not in worst or abs(float(value)) > worst[solver][0]:
                    worst[solver] = (abs(float(value)), mode)
    return worst


def main() -> int:
    p = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    p.add_argument("--scene", default=str(HERE.parent / "scenes" / "paper1990.toml"))
    p.add_argument("--modes", default="1-9", help="the modes gated, FIRST-LAST")
    p.add_argument("--bound", action="append", default=[], help="SOLVER=PERCENT, repeated")
    p.add_argument("--junit", default="gates.xml")
    a = p.parse_args()

    first_text, _, last_text = a.modes.partition("-")
    first, last = int(first_text), int(last_text or first_text)
    # Without --bound: what the paper's scene holds at n = 40 and 40 frame elements over modes 1-9.
    limits = bounds(a.bound) if a.bound else {"multibody": 2.5, "lumped": 2.5, "fem": 0.05}
    worst = worst_errors(ringvib.Scene.load(a.scene), first, last)
    if not worst:
        print(f"{a.scene}: the table has no reference column (set fem.reference = true)")
        return 2

    suite = ET.Element("testsuite", name=f"accuracy of {pathlib.Path(a.scene).name}, modes {first}-{last}")
    failed = 0
    for solver, (error, mode) in worst.items():
        case = ET.SubElement(suite, "testcase", classname="ringvib.gates", name=solver)
        bound = limits.get(solver)
        verdict = "reported" if bound is None else "pass" if error <= bound else "FAIL"
        print(f"  {solver:10s} largest |error| {error:.4f} % (mode {mode})"
              + ("" if bound is None else f", bound {bound} %") + f": {verdict}")
        if verdict == "FAIL":
            failed += 1
            ET.SubElement(case, "failure", message=f"{error:.4f} % at mode {mode} exceeds {bound} %")
    suite.set("tests", str(len(worst)))
    suite.set("failures", str(failed))
    ET.ElementTree(suite).write(a.junit, encoding="unicode", xml_declaration=True)
    print(f"{failed} gate(s) failed; JUnit XML in {a.junit}")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
