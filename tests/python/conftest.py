"""Shared helpers of the ringvib module's tests (run by CTest: tests/python/CMakeLists.txt).

The oracle of most tests is the `ringvib` command of the same build run as a user runs it:
RINGVIB_COMMAND names it, RINGVIB_SOURCE_DIR the source tree (the shipped scenes).
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("RINGVIB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
COMMAND = os.environ.get("RINGVIB_COMMAND", str(SOURCE / "build" / "bin" / "ringvib"))


def scene_path(name):
    """A shipped scene, by file name."""
    return str(SOURCE / "scenes" / name)


def command(*args):
    """Runs the command; returns the CompletedProcess (stdout, stderr as text)."""
    return subprocess.run([COMMAND, *map(str, args)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=600)


def ringvib_json(*args):
    """Runs the command, expects exit 0, and parses what it prints as JSON."""
    run = command(*args)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def sets(overrides):
    """The command's --set arguments for {key: toml_text}: the TOML written by hand in each
    test, so that the module's own conversion of Python values is under test too."""
    out = []
    for key, text in overrides.items():
        out += ["--set", f"{key}={text}"]
    return out


def pytest_sessionfinish(session, exitstatus):
    """A run that collected nothing, or skipped a test, fails: nothing passes unseen."""
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    skipped = len(reporter.stats.get("skipped", [])) if reporter else 0
    if session.testscollected == 0 or skipped:
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
