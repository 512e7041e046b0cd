"""The examples type-check against the module's stubs under `mypy --strict` (python3-mypy), as an
editor or a CI job of a user would check a script of theirs: the stubs (python/ringvib.pyi, beside
the module) must describe every function and attribute the examples use, with types that hold.
A script that misuses the module fails the same check (the second test), so the first cannot pass
because the stubs are missing or ignored."""
import os
import pathlib
import subprocess
import sys

from conftest import SOURCE

MODULE_DIR = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0])


def mypy(paths, tmp_path):
    env = dict(os.environ, MYPYPATH=str(MODULE_DIR))
    return subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                           "--cache-dir", str(tmp_path / "cache"), *map(str, paths)],
                          capture_output=True, text=True, env=env, cwd=tmp_path, timeout=600)


def test_the_examples_pass_mypy_strict_against_the_stubs(tmp_path):
    assert (MODULE_DIR / "ringvib.pyi").exists(), "the stubs are not beside the module"
    examples = sorted((SOURCE / "examples").glob("*.py"))
    assert len(examples) >= 4
    run = mypy(examples, tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    assert f"no issues found in {len(examples)} source files" in run.stdout


def test_a_script_that_misuses_the_module_fails_the_same_check(tmp_path):
    script = tmp_path / "wrong.py"
    script.write_text("import ringvib\n"
                      "s = ringvib.Scene.load('x.toml')\n"
                      "w: str = ringvib.modes(s, 'fem').omega\n"        # an ndarray, not a str
                      "ringvib.modes(s, 'fem').omegas\n")               # no such attribute
    run = mypy([script], tmp_path)
    assert run.returncode == 1, run.stdout
    assert "Incompatible types in assignment" in run.stdout and '"omegas"' in run.stdout, run.stdout
