"""Input and numerical errors: the module raises ringvib.InputError (a ValueError) where the
command exits 2 and ringvib.NumericalError where it exits 3, with the command's message
(its stderr after the "ringvib: error: " / "ringvib: numerical failure: " prefix), the file
and key named; and the library itself prints nothing (checked on the file descriptors, so
C++ writes to stderr would show).
"""
import pytest

import ringvib
from conftest import command, scene_path, sets

PAPER = scene_path("paper1990.toml")
STATIC = scene_path("paper1990-static.toml")
FORCED = scene_path("paper1990-forced.toml")


def command_message(run, code, prefix):
    assert run.returncode == code, run.stderr
    lines = [line for line in run.stderr.splitlines() if line.startswith(prefix)]
    assert len(lines) == 1, run.stderr
    return lines[0][len(prefix):]


# (scene, {key: Python value}, {key: TOML text}, the key the message must name)
INPUT_CASES = [
    (PAPER, {"multibody.nn": 80}, {"multibody.nn": "80"}, "multibody.nn"),  # unknown: suggests multibody.n
    (PAPER, {"multibody.n": 3}, {"multibody.n": "3"}, "multibody.n"),  # below the range
    (PAPER, {"ring.section": {"shape": "circle", "diameter": "big"}},
     {"ring.section": '{ shape = "circle", diameter = "big" }'}, "ring.section.diameter"),  # wrong type
    (PAPER, {"modes.solvers": ["sap5"]}, {"modes.solvers": '["sap5"]'}, "modes.solvers"),
    (STATIC, {"static.at": 1.0}, {"static.at": "1.0"}, "static.at"),  # not a hinge of the chain
]


@pytest.mark.parametrize("scene,values,texts,key", INPUT_CASES, ids=[c[3] for c in INPUT_CASES])
def test_input_errors_carry_the_commands_message(capfd, scene, values, texts, key):
    with pytest.raises(ringvib.InputError) as e:
        s = ringvib.Scene.load(scene, set=values)
        # A point that is not a node is refused by the solver's checks, before it runs.
        ringvib.static(s) if scene == STATIC else ringvib.modes(s, "multibody")
    assert isinstance(e.value, ValueError)
    message = str(e.value)
    assert scene in message and key in message, message
    assert e.value.file == scene
    solver = ["--solver", "multibody"] if scene == PAPER else []
    run = command("static" if scene == STATIC else "modes", scene, *solver, *sets(texts))
    assert message == command_message(run, 2, "ringvib: error: ")
    assert capfd.readouterr() == ("", "")


def test_unknown_key_suggests_the_nearest():
    with pytest.raises(ringvib.InputError) as e:
        ringvib.Scene.load(PAPER).with_(multibody__nn=80)
    assert e.value.key.startswith("multibody.nn") and "did you mean 'n'" in str(e.value), str(e.value)


def test_missing_file_and_malformed_toml(capfd):
    with pytest.raises(ringvib.InputError) as e:
        ringvib.Scene.load("/nonexistent/scene.toml")
    assert str(e.value) == command_message(command("table", "/nonexistent/scene.toml"), 2, "ringvib: error: ")
    with pytest.raises(ringvib.InputError) as e:
        ringvib.Scene.from_toml("[ring\nradius = 1.0\n", name="mine.toml")
    assert "mine.toml" in str(e.value) and "line 1" in str(e.value)
    assert capfd.readouterr() == ("", "")


def test_a_value_python_cannot_write_as_toml_names_the_key():
    with pytest.raises(ringvib.InputError) as e:
        ringvib.Scene.load(PAPER, set={"multibody.n": object()})
    assert e.value.key == "multibody.n"


def test_more_modes_than_the_model_has():
    s = ringvib.Scene.load(PAPER)
    with pytest.raises(ringvib.InputError) as e:
        ringvib.modes(s, "multibody", 100)  # n = 40: 37 elastic modes
    assert "37 elastic modes" in str(e.value)
    with pytest.raises(ringvib.InputError):
        ringvib.modes(s, "sap5")


def test_cost_guard_refuses_like_the_command(capfd):
    s = ringvib.Scene.load(PAPER, set={"multibody.n": 100000, "multibody.method": "dense"})
    with pytest.raises(ringvib.InputError) as e:
        ringvib.modes(s, "multibody")
    run = command("modes", PAPER, "--solver", "multibody", "--set", "multibody.n=100000",
                  "--set", 'multibody.method="dense"')
    assert str(e.value) == command_message(run, 2, "ringvib: error: ")
    assert "multibody.n" in str(e.value)
    assert capfd.readouterr() == ("", "")


# A static load far past the ring's limit: the chain's path reaches self-contact.
CRUSH = ({"static.force": [-5e6, 0.0]}, {"static.force": "[-5e6, 0.0]"})


def test_static_failure_raises_numerical_error_with_the_load_reached(capfd):
    s = ringvib.Scene.load(STATIC, set=CRUSH[0])
    with pytest.raises(ringvib.NumericalError) as e:
        ringvib.static(s)
    assert not isinstance(e.value, ValueError)
    run = command("static", STATIC, "--json", *sets(CRUSH[1]))
    assert str(e.value) == command_message(run, 3, "ringvib: numerical failure: ")
    assert e.value.load_factor is not None and 0.0 < e.value.load_factor < 1.0, str(e.value)
    assert f"load factor {e.value.load_factor:g}"[:16] in str(e.value)
    assert e.value.t_reached is None and e.value.partial is None
    assert capfd.readouterr() == ("", "")


# A step load far past what the ring carries: the chain folds onto itself during the step.
SLAM = ({"response.force": [-5e6, 0.0], "response.t_end": 1.0},
        {"response.force": "[-5e6, 0.0]", "response.t_end": "1.0"})


def test_response_failure_raises_numerical_error_with_the_time_reached(capfd):
    s = ringvib.Scene.load(FORCED, set=SLAM[0])
    with pytest.raises(ringvib.NumericalError) as e:
        ringvib.respond(s)
    run = command("respond", FORCED, *sets(SLAM[1]))
    assert str(e.value) == command_message(run, 3, "ringvib: numerical failure: ")
    t = e.value.t_reached
    assert t is not None and 0.0 <= t < 1.0
    partial = e.value.partial
    assert isinstance(partial, ringvib.Response)
    assert partial.solver == "multibody"
    assert partial.t[-1] == t and len(partial.history) == len(partial.t)
    assert capfd.readouterr() == ("", "")


# ---- Ctrl-C ----
# SIGINT to a process inside a solve raises KeyboardInterrupt there, after cleaning up:
# a solve checks for a pending signal at least every 0.1 s of work (docs/python.md).
# Before, a respond ignored it for the whole run (58 s measured) and a hung ccx ran until
# calculix.timeout. Each case runs in a child process that prints "solving" just before the
# call; the parent sends SIGINT a moment later and gives the child a few seconds to print
# what the call raised. The runs asked for would take minutes (or forever: a ccx that never
# finishes), so an ignored signal fails by the timeout.
INTERRUPT_SCRIPT = r"""
import sys, ringvib
scene = ringvib.Scene.load(sys.argv[1], set=eval(sys.argv[3]))
print("solving", flush=True)
try:
    if sys.argv[2] == "calculix":
        ringvib.modes(scene, "calculix", 4)
    else:
        ringvib.respond(scene, sys.argv[2])
    print("finished", flush=True)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
"""


def interrupted(scene, solver, overrides, env=None):
    import os
    import signal
    import subprocess
    import sys
    import time

    p = subprocess.Popen([sys.executable, "-c", INTERRUPT_SCRIPT, scene, solver, repr(overrides)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True,
                         env=env or dict(os.environ))
    try:
        assert p.stdout.readline().strip() == "solving"
        time.sleep(1.0)  # well inside the solve
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=5)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    return out.split(), err


def test_ctrl_c_interrupts_a_long_response():
    # 10^6 steps of the 160-link chain: about a minute.
    out, err = interrupted(FORCED, "multibody", {"multibody.n": 160, "response.dt": 1e-3, "response.t_end": 1000.0,
                                                 "response.record": [0.0]})
    assert out == ["KeyboardInterrupt"], err


def test_ctrl_c_kills_a_hung_ccx_and_leaves_nothing(tmp_path):
    import os
    import time

    # A ccx that never finishes (it records its pid first), on the PATH ahead of any other.
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    pid_file = tmp_path / "ccx.pid"
    ccx = bin_dir / "ccx"
    ccx.write_text(f"#!/bin/sh\necho $$ > {pid_file}\nexec sleep 600\n")
    ccx.chmod(0o755)
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ.get('PATH', '')}", TMPDIR=str(tmp))
    out, err = interrupted(scene_path("paper1990-calculix.toml"), "calculix", {}, env)
    assert out == ["KeyboardInterrupt"], err
    pid = int(pid_file.read_text())
    deadline = time.monotonic() + 2.0
    while time.monotonic() < deadline:  # killed with SIGKILL and reaped: gone at once
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            break
        time.sleep(0.05)
    else:
        os.kill(pid, 9)
        raise AssertionError(f"ccx (pid {pid}) still runs after the KeyboardInterrupt")
    assert list(tmp.iterdir()) == []  # its job folder removed
