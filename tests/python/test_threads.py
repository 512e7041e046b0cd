"""A sweep on a ThreadPoolExecutor gives exactly the serial sweep's results: the module
releases the GIL inside solves, the solvers are reentrant (scratch values are local), and FE
solves take turns inside the process (compare/fem_module.cpp), as in `ringvib sweep -j N`.
The oracle is the serial run of the same cases; equal means bit for bit, since every case
runs the same arithmetic whichever thread runs it.
"""
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import ringvib
from conftest import scene_path

# Eight cases: the chain at five sizes (both paths: sparse above n = 256), the lumped
# frame, and two FE meshes (taking turns on the plug-in's lock).
CASES = [("multibody", {"multibody.n": n}) for n in (40, 80, 160, 320, 640)] + [
    ("lumped", {"lumped.n": 80, "lumped.variant": "frame"}),
    ("fem", {"fem.elements": 16, "fem.degree": 3}),
    ("fem", {"fem.elements": 24, "fem.degree": 4}),
]


def solve(case):
    solver, overrides = case
    s = ringvib.Scene.load(scene_path("paper1990.toml"), set=overrides)
    return ringvib.modes(s, solver, 12)


def test_threaded_sweep_equals_serial_sweep():
    serial = [solve(c) for c in CASES]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(solve, CASES))
    assert len(threaded) == len(CASES) == 8
    for case, a, b in zip(CASES, serial, threaded):
        assert a.solver == b.solver == case[0]
        assert np.array_equal(a.omega, b.omega), case
        assert np.array_equal(a.shapes, b.shapes), case
        assert a.max_residual == b.max_residual and a.unknowns == b.unknowns, case


def test_threads_sharing_one_scene():
    s = ringvib.Scene.load(scene_path("paper1990.toml"))
    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda _: ringvib.modes(s, "multibody", 10).omega, range(8)))
    for r in results[1:]:
        assert np.array_equal(r, results[0])


# Found by a robustness probe: two threads asking for FE modes when the plug-in cannot be loaded hung forever
# (one raised InputError at once). The oracle is the contract: every call raises InputError
# naming the FE solver, none waits on another. Run in a child process whose
# RINGVIB_FEM_MODULE names a file that does not exist, so that a deadlock fails the test by
# its timeout instead of hanging the suite, and so that this process's own plug-in (the
# other tests') stays loadable.
MISSING_PLUGIN_SCRIPT = r"""
import sys
from concurrent.futures import ThreadPoolExecutor
import ringvib

scene = ringvib.Scene.load(sys.argv[1], set={"fem.elements": 16})

def fem(_):
    try:
        ringvib.modes(scene, "fem", 4)
        return "solved"
    except ringvib.InputError as e:
        return "InputError: " + str(e)

with ThreadPoolExecutor(max_workers=2) as pool:
    for outcome in pool.map(fem, range(4)):
        print(outcome, flush=True)
"""


def test_threads_refused_by_a_missing_plugin_do_not_deadlock(tmp_path):
    import os
    import subprocess
    import sys

    env = dict(os.environ, RINGVIB_FEM_MODULE=str(tmp_path / "no-such-dir" / "libringvib_fem.so"))
    run = subprocess.run([sys.executable, "-c", MISSING_PLUGIN_SCRIPT, scene_path("paper1990.toml")], env=env,
                         capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
    assert run.returncode == 0, run.stderr
    outcomes = run.stdout.splitlines()
    assert len(outcomes) == 4, run.stdout + run.stderr
    for o in outcomes:
        assert o.startswith("InputError: ") and "not available" in o and "no-such-dir" in o, o
