#!/usr/bin/env python3
"""The multibody chain's error against n for modes 1..23 of the paper's pinned ring, with the
fitted order of convergence, through the ringvib Python module.

The reference is the converged FE solution of the inextensible ring (the continuum a chain
of rigid links converges to; docs/commands.md, `converge`): fem.reference = true refines until the
frequencies change by less than fem.tolerance (1e-9). Modes are paired with the reference's
by the modal assurance criterion (MAC) on the 360 common stations, as the table pairs them.

    PYTHONPATH=build/python python3 examples/convergence.py [--n 40 80 160 320 640] [--figure FILE]

Writes the log-log figure (error % against n, one curve per mode) if matplotlib is
importable, and says so otherwise.
"""
import argparse
import pathlib
import time
from typing import List, Tuple

import numpy as np
import numpy.typing as npt

import ringvib

HERE = pathlib.Path(__file__).resolve().parent


def mac_pairing(a: ringvib.Modes, b: ringvib.Modes) -> Tuple[npt.NDArray[np.intp], npt.NDArray[np.float64]]:
    """For each mode of `a`, the mode of `b` with the largest MAC (shapes: modes x 360 x 2)."""
    x = a.shapes.reshape(len(a.omega), -1)
    y = b.shapes.reshape(len(b.omega), -1)
    mac = (x @ y.T) ** 2 / np.outer((x * x).sum(1), (y * y).sum(1))
    return mac.argmax(axis=1), mac.max(axis=1)


def main() -> None:
    p = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    p.add_argument("--scene", default=str(HERE.parent / "scenes" / "paper1990.toml"))
    p.add_argument("--n", type=int, nargs="+", default=[40, 80, 160, 320, 640], help="segments")
    p.add_argument("--modes", type=int, default=23)
    p.add_argument("--figure", default="convergence.png", help="the figure, if matplotlib is there")
    a = p.parse_args()

    scene = ringvib.Scene.load(a.scene)
    t0 = time.perf_counter()
    reference = ringvib.modes(scene.with_({"fem.reference": True, "fem.extensible": False}), "fem", a.modes)
    print(f"reference: FE, inextensible, {reference.model}, {reference.unknowns} unknowns, "
          f"{time.perf_counter() - t0:.1f} s")

    rows: List[npt.NDArray[np.float64]] = []  # [n][mode], %
    for n in a.n:
        chain = ringvib.modes(scene.with_(multibody__n=n), "multibody", a.modes)
        pair, mac = mac_pairing(chain, reference)
        # Below a MAC of 0.5 the table calls shapes unlike (compare/table.hpp, kWeakMac).
        if len(set(pair)) != len(pair) or mac.min() < 0.5:
            raise SystemExit(f"n = {n}: the chain's modes do not pair one to one with the reference's "
                             f"(lowest MAC {mac.min():.3f})")
        ref = reference.omega[pair]
        rows.append(np.abs(chain.omega - ref) / ref * 100.0)
        print(f"n = {n:5d}: {chain.unknowns} unknowns, {chain.seconds:.3f} s, lowest MAC {mac.min():.3f}")
    errors = np.array(rows)

    ns = np.array(a.n, dtype=float)
    order = -np.array([np.polyfit(np.log(ns[-3:]), np.log(errors[-3:, k]), 1)[0] for k in range(a.modes)])
    print("\nerror % of the multibody chain against the reference (|omega - ref| / ref * 100)")
    print("mode  " + "".join(f"{'n = ' + str(n):>11}" for n in a.n) + "    order")
    for k in range(a.modes):
        print(f"{k + 1:4d}  " + "".join(f"{e:11.3e}" for e in errors[:, k]) + f"  {order[k]:7.3f}")
    worst = errors.max(axis=1)
    overall = -np.polyfit(np.log(ns[-3:]), np.log(worst[-3:]), 1)[0]
    print("max   " + "".join(f"{e:11.3e}" for e in worst) + f"  {overall:7.3f}")
    print(f"\nfitted order (last three n) of the max error: {overall:.3f}; "
          f"per mode {order.min():.3f} to {order.max():.3f}")

    try:
        import matplotlib  # type: ignore[import]  # optional, and without type stubs
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt  # type: ignore[import]
    except ImportError:
        print("matplotlib is not installed: no figure")
        return
    fig, ax = plt.subplots(figsize=(7, 5))
    colours = plt.cm.viridis(np.linspace(0, 1, a.modes))  # mode 1 dark, mode 23 yellow
    for k in range(a.modes):
        ax.loglog(ns, errors[:, k], marker="o", lw=1, ms=3, color=colours[k])
    ax.loglog(ns, worst[0] * (ns[0] / ns) ** 2, "k--", label="order 2")
    bar = fig.colorbar(plt.cm.ScalarMappable(cmap="viridis", norm=plt.Normalize(1, a.modes)), ax=ax)
    bar.set_label("mode")
    ax.set_xlabel("segments n")
    ax.set_ylabel("error against the FE reference (%)")
    ax.set_title(f"Multibody chain, modes 1..{a.modes}: fitted order {overall:.2f}")
    ax.legend()
    fig.savefig(a.figure, dpi=120)
    print(f"wrote {a.figure}")


if __name__ == "__main__":
    main()
