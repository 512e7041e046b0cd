"""No reference or memory leaks over 1000 calls: the resident set stays bounded and the
scene's reference count comes back. The bound is what a leak would exceed several times
over: a Modes of 5 modes holds 5 x 360 x 2 doubles of shapes (28.8 kB), so one leaked
result per call is ~29 MB over 1000 calls; an exception leaked per call, ~1 kB each.
"""
import gc
import sys

import ringvib
from conftest import scene_path

CALLS = 1000
BOUND = 8 * 2**20  # bytes of growth allowed: allocator slack, well under a leak's 29 MB


def rss():
    """Resident set size, bytes (Linux: /proc/self/statm, in pages)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_modes_calls_do_not_leak():
    s = ringvib.Scene.load(scene_path("paper1990.toml"))
    for _ in range(100):  # warm up: the registry, NumPy, allocator pools
        ringvib.modes(s, "multibody", 5)
    gc.collect()
    refs, before = sys.getrefcount(s), rss()
    for _ in range(CALLS):
        m = ringvib.modes(s, "multibody", 5)
        assert m.shapes.shape == (5, 360, 2)
    del m
    gc.collect()
    assert sys.getrefcount(s) == refs
    assert rss() - before < BOUND, f"RSS grew by {(rss() - before) / 2**20:.1f} MiB over {CALLS} calls"


def test_scenes_and_errors_do_not_leak():
    s = ringvib.Scene.load(scene_path("paper1990.toml"))
    for _ in range(100):
        s.with_(multibody__n=44)
    gc.collect()
    refs, before = sys.getrefcount(s), rss()
    for i in range(CALLS):
        t = s.with_({"multibody.n": 40 + 4 * (i % 10)})
        assert t.overrides
        try:
            s.with_({"multibody.nn": 40})
        except ringvib.InputError as e:
            assert e.key.startswith("multibody.nn")
        else:
            raise AssertionError("an unknown key was accepted")
    del t
    gc.collect()
    assert sys.getrefcount(s) == refs
    assert rss() - before < BOUND, f"RSS grew by {(rss() - before) / 2**20:.1f} MiB over {CALLS} calls"
