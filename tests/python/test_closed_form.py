"""The free ring through the module against the closed form, recomputed here from the formula
(not from ring/closed_form.cpp): the in-plane bending frequencies of a free, inextensible,
thin Euler-Bernoulli ring without rotary inertia,

    omega_k = sqrt(E I / (rho A R^4)) * k (k^2 - 1) / sqrt(k^2 + 1),   k = 2, 3, ...

each a double eigenvalue (cos and sin k theta) (Hoppe 1871; Love, "Treatise on the
Mathematical Theory of Elasticity", 4th ed., sec. 294; Soedel, "Vibrations of Shells and
Plates", 3rd ed., eq. 6.6.14; ring/closed_form.hpp cites the same).

The rigid-segment chain converges to the inextensible ring at second order in 1/n (docs/commands.md,
`converge`: the multibody chain's Richardson column is order 2).
"""
import math

import numpy as np

import ringvib
from conftest import scene_path

R, E, RHO, D = 10.0, 2.1e11, 7.8e3, 0.12  # scenes/free-ring.toml
A = math.pi * D**2 / 4
I = math.pi * D**4 / 64
K = range(2, 8)  # six double frequencies: modes 1..12


def closed_form(k):
    return math.sqrt(E * I / (RHO * A * R**4)) * k * (k * k - 1) / math.sqrt(k * k + 1)


def chain(n):
    s = ringvib.Scene.load(scene_path("free-ring.toml"), set={"multibody.n": n, "multibody.rotary_inertia": False})
    return ringvib.modes(s, "multibody", 2 * len(K))


def errors(m):
    """Relative error of each of the 12 frequencies against its k."""
    exact = np.repeat([closed_form(k) for k in K], 2)
    return np.abs(m.omega - exact) / exact


def test_free_ring_has_three_rigid_modes_and_double_frequencies():
    m = chain(160)
    assert m.rigid_modes == 3
    # A double frequency is two modes within 1e-6 relative (compare/table.hpp, kDegenerate).
    pairs = m.omega.reshape(-1, 2)
    assert np.all(np.abs(pairs[:, 1] - pairs[:, 0]) <= 1e-6 * pairs[:, 0]), pairs


def test_multibody_converges_to_the_closed_form_at_second_order():
    ns = [80, 160, 320, 640]
    worst = [errors(chain(n)).max() for n in ns]
    rate = -np.polyfit(np.log(ns), np.log(worst), 1)[0]
    # Expected 2 (the chain's error is O(1/n^2)); 0.1 allows the pre-asymptotic bend of
    # four refinements, while an order-1 error would miss it by 0.9.
    assert abs(rate - 2.0) < 0.1, f"observed order {rate:.3f}, errors {worst}"
    # The finest chain within 1e-3 of the closed form: k = 7 at n = 640 (91 segments per
    # wave) is measured 1.7e-4 off (observed order 2.02).
    assert worst[-1] < 1e-3, worst
