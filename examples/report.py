#!/usr/bin/env python3
"""A report of a scene's frequencies: every solver's column with its true error against the
converged FE reference, as a Markdown page and a CSV file, through the ringvib Python module.

This is what `ringvib run SCENE` writes as report.md, done from Python so that a report can take
the shape its reader needs: here the modes a design cares about (`--modes 1-9`), each solver's
error in percent, and the largest error of each solver in one summary line.

    PYTHONPATH=build/python python3 examples/report.py [--scene scenes/paper1990.toml]
        [--modes 1-23] [--out report.md] [--csv report.csv]

The table's rows are those of `ringvib table SCENE --format json` (modes paired by MAC with the first
column; `<solver>_error_pct` against the reference, which the scene asks for with
fem.reference = true).
"""
import argparse
import csv
import pathlib
from typing import Any, Dict, List, Tuple

import ringvib

HERE = pathlib.Path(__file__).resolve().parent


def mode_range(text: str) -> Tuple[int, int]:
    """'1-9' -> (1, 9); '4' -> (4, 4)."""
    first, _, last = text.partition("-")
    return int(first), int(last or first)


def columns(rows: List[Dict[str, Any]]) -> List[str]:
    """The solvers that have an error against the reference, in the table's order."""
    seen: List[str] = []
    for row in rows:
        for key in row:
            if key.endswith("_error_pct") and key[: -len("_error_pct")] not in seen:
                seen.append(key[: -len("_error_pct")])
    return seen


def markdown(title: str, rows: List[Dict[str, Any]], solvers: List[str]) -> str:
    head = "| mode | reference (rad/s) | " + " | ".join(f"{s} (rad/s) | {s} error %" for s in solvers) + " |"
    rule = "|---" * (2 + 2 * len(solvers)) + "|"
    lines = [f"# {title}", "", head, rule]
    for row in rows:
        cells = [str(row["mode"]), f"{row['reference']:.6g}" if "reference" in row else ""]
        for s in solvers:
            cells.append(f"{row[s]:.6g}" if s in row else "")
            cells.append(f"{row[s + '_error_pct']:+.3f}" if s + "_error_pct" in row else "")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main() -> int:
    p = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    p.add_argument("--scene", default=str(HERE.parent / "scenes" / "paper1990.toml"))
    p.add_argument("--modes", default="1-23", help="the modes reported, FIRST-LAST")
    p.add_argument("--out", default="report.md")
    p.add_argument("--csv", default="report.csv")
    a = p.parse_args()

    scene = ringvib.Scene.load(a.scene)
    first, last = mode_range(a.modes)
    rows = [r for r in ringvib.table(scene) if first <= int(r["mode"]) <= last]
    solvers = columns(rows)
    if not solvers:
        print(f"{a.scene}: the table has no reference column (set fem.reference = true)")
        return 2

    title = f"{pathlib.Path(a.scene).stem}: modes {first} to {last} against the converged FE reference"
    pathlib.Path(a.out).write_text(markdown(title, rows, solvers))
    with open(a.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mode", "reference"] + [f"{s}{suffix}" for s in solvers for suffix in ("", "_error_pct")])
        for row in rows:
            w.writerow([row["mode"], row.get("reference", "")] +
                       [row.get(f"{s}{suffix}", "") for s in solvers for suffix in ("", "_error_pct")])

    print(f"wrote {a.out} and {a.csv}: {len(rows)} modes, solvers {', '.join(solvers)}")
    for s in solvers:
        errors = [abs(float(r[s + "_error_pct"])) for r in rows if s + "_error_pct" in r]
        print(f"  {s:10s} largest |error| {max(errors):.4f} % over {len(errors)} modes")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
