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
