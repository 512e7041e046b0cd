"""The examples (examples/, one per user group) run as documented and measure what their oracle
says: the method study's chain converges at second order against the FE reference; the gyroscope
maker's trim cancels the split in every solver; the report and the CI gate reproduce the command's
own table (`ringvib table --format json`).
"""
import csv
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from conftest import COMMAND, SOURCE


def test_convergence_example(tmp_path):
    figure = tmp_path / "convergence.png"
    run = subprocess.run([sys.executable, str(SOURCE / "examples" / "convergence.py"), "--n", "80", "160", "320",
                          "--figure", str(figure)], capture_output=True, text=True, env=dict(os.environ),
                         cwd=tmp_path, timeout=600)
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    rows = [line.split() for line in run.stdout.splitlines() if re.match(r"^\s*\d+\s", line)]
    assert [int(r[0]) for r in rows] == list(range(1, 24))
    order = float(re.search(r"fitted order \(last three n\) of the max error: ([-\d.]+)", run.stdout).group(1))
    # Expected 2; 0.1 allows the pre-asymptotic bend at n = 80 (an order-1 error misses by 0.9).
    assert abs(order - 2.0) < 0.1, run.stdout
    try:
        import matplotlib  # noqa: F401
        assert figure.exists(), run.stdout
    except ImportError:
        assert "no figure" in run.stdout and not figure.exists()


def test_gyroscope_trim_example(tmp_path):
    """examples/gyroscope_trim.py: every solver finds the 1 % defect's k = 2 split at the mass's
    angle (Fox's first order: 0.6 %), and the FE's trim leaves every solver a split at least
    1000 times smaller (measured 5500 to 6900; the chains' O(1/n^2) of the masses' effect)."""
    run = subprocess.run([sys.executable, str(SOURCE / "examples" / "gyroscope_trim.py")], capture_output=True,
                         text=True, env=dict(os.environ), cwd=tmp_path, timeout=600)
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    before = re.findall(r"^\s+(\w+)\s+k = 2: ([\d.e+-]+) at\s+([\d.]+) deg", run.stdout, re.M)
    assert [b[0] for b in before] == ["multibody", "lumped", "fem"], run.stdout
    for _, split, angle in before:
        assert abs(float(split) - 0.006) < 0.0005 and float(angle) == 30.0
    after = re.findall(r"^\s+(\w+)\s+k = 2: relative split ([\d.e+-]+) \(was ([\d.e+-]+)", run.stdout, re.M)
    assert len(after) == 3, run.stdout
    for _, split, was in after:
        assert float(split) < 1e-3 * float(was)


def command_table(scene):
    """The rows of `ringvib table SCENE --format json`: the command's own numbers, the oracle of the
    report and gate examples (which go through the module)."""
    run = subprocess.run([COMMAND, "table", str(scene), "--format", "json"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)["rows"]


def test_report_example_writes_the_commands_errors(tmp_path):
    """examples/report.py: the CSV's frequencies and errors of modes 1..9 are the command's table's,
    to the 12 digits the CSV keeps, and the summary's largest error is the largest of those rows."""
    scene = SOURCE / "scenes" / "paper1990.toml"
    run = subprocess.run([sys.executable, str(SOURCE / "examples" / "report.py"), "--modes", "1-9"],
                         capture_output=True, text=True, env=dict(os.environ), cwd=tmp_path, timeout=600)
    assert run.returncode == 0, run.stderr
    rows = {int(r["mode"]): r for r in command_table(scene) if int(r["mode"]) <= 9}
    with open(tmp_path / "report.csv") as f:
        written = list(csv.DictReader(f))
    assert [int(r["mode"]) for r in written] == list(range(1, 10))
    solvers = [k[: -len("_error_pct")] for k in written[0] if k.endswith("_error_pct")]
    assert sorted(solvers) == ["fem", "lumped", "multibody"]
    for r in written:
        ref = rows[int(r["mode"])]
        assert float(r["reference"]) == pytest.approx(ref["reference"], rel=1e-12)
        for s in solvers:
            assert float(r[s + "_error_pct"]) == pytest.approx(ref[s + "_error_pct"], rel=1e-9, abs=1e-12)
    for s in solvers:
        worst = max(abs(rows[m][s + "_error_pct"]) for m in rows)
        shown = float(re.search(rf"^\s+{s}\s+largest \|error\| ([\d.]+) %", run.stdout, re.M).group(1))
        assert shown == pytest.approx(worst, abs=5e-5), run.stdout
    assert (tmp_path / "report.md").read_text().startswith("# paper1990: modes 1 to 9")


def test_ci_gate_example_fails_a_bound_below_the_error_and_passes_one_above(tmp_path):
    """examples/ci_gate.py: the multibody chain's largest error over modes 1..9 (from the command's
    table) is gated once with a bound 10 % below it (exit 1, one JUnit failure naming it) and once
    10 % above it (exit 0, no failure)."""
    rows = [r for r in command_table(SOURCE / "scenes" / "paper1990.toml") if int(r["mode"]) <= 9]
    worst = max(abs(r["multibody_error_pct"]) for r in rows)
    for factor, code in ((0.9, 1), (1.1, 0)):
        xml = tmp_path / f"gates{code}.xml"
        run = subprocess.run([sys.executable, str(SOURCE / "examples" / "ci_gate.py"), "--modes", "1-9",
                              "--bound", f"multibody={factor * worst}", "--junit", str(xml)],
                             capture_output=True, text=True, env=dict(os.environ), cwd=tmp_path, timeout=600)
        assert run.returncode == code, run.stdout + run.stderr
        suite = ET.parse(xml).getroot()
        failures = suite.findall("./testcase/failure")
        assert len(failures) == (1 if code else 0)
        assert int(suite.get("failures")) == len(failures)
        if code:
            assert suite.find("./testcase[failure]").get("name") == "multibody"
