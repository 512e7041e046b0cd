"""Every value the module returns equals the `ringvib` command's output for the same scene
and overrides. It is the same code, so the comparison is exact wherever the command prints
full precision (its JSON: nlohmann::json writes the shortest text that reads back to the
same double); the response CSV prints 12 significant digits (compare/response.cpp), and
there the module's values are formatted the same way and compared as text.

Overrides are given twice: as Python values to the module and as TOML text written by hand
to the command, so that the module's TOML writer is checked too. `seconds` is wall time,
different in every run: only its presence is checked.
"""
import json
import math
import pickle
import tempfile
import pathlib

import numpy as np
import pytest

import ringvib
from conftest import command, ringvib_json, scene_path, sets

# (scene, solver, count or None, {key: Python value}, {key: TOML text for --set})
MODES_CASES = [
    ("paper1990.toml", "multibody", None, {"multibody.n": 80}, {"multibody.n": "80"}),
    ("paper1990.toml", "multibody", 8, {"multibody.n": 400, "multibody.dependent": "paper"},
     {"multibody.n": "400", "multibody.dependent": "paper"}),  # the O(n) path (sparse above n = 256)
    ("paper1990.toml", "lumped", 12, {"lumped.variant": "frame", "lumped.n": 60},
     {"lumped.variant": '"frame"', "lumped.n": "60"}),
    ("paper1990.toml", "fem", 10, {"fem.elements": 20, "fem.degree": 4}, {"fem.elements": "20", "fem.degree": "4"}),
    ("free-ring.toml", "multibody", None, {"ring.section": {"shape": "circle", "diameter": 0.1}, "ring.E": 2.0e11},
     {"ring.section": '{ shape = "circle", diameter = 0.1 }', "ring.E": "2e11"}),
    ("imperfect-ring.toml", "fem", None, {"fem.elements": 60}, {"fem.elements": "60"}),  # its split pairs
]


def modes_matches_json(m, j):
    assert m.solver == j["solver"]
    assert m.model == j["model"]
    assert m.rigid_modes == j["rigid_modes"]
    assert m.omega.tolist() == j["omega"]  # exact: the same doubles
    assert m.unknowns == j["unknowns"]
    assert m.max_residual == j["max_residual"]
    assert m.residual_norm == j["residual_norm"]
    assert m.error_estimate == j.get("error_estimate", 0.0)
    assert math.isfinite(m.seconds) and m.seconds >= 0 and "seconds" in j
    pairs = [{**p, "modes": list(p["modes"]), "omega": list(p["omega"])} for p in m.pairs]
    assert pairs == j.get("pairs", [])  # the split pairs, exact


@pytest.mark.parametrize("scene,solver,count,values,texts", MODES_CASES,
                         ids=[f"{c[1]}-{i}" for i, c in enumerate(MODES_CASES)])
def test_modes_equal_the_commands_json(scene, solver, count, values, texts):
    s = ringvib.Scene.load(scene_path(scene), set=values)
    m = ringvib.modes(s, solver, count)
    args = ["modes", scene_path(scene), "--solver", solver, "--json", *sets(texts)]
    if count is not None:
        args += ["--count", count]
    modes_matches_json(m, ringvib_json(*args))
    assert m.shapes.shape == (len(m.omega), ringvib.STATIONS, 2)


SCENE_TWO_CHAINS = """
title = "two chains"
[ring]
radius = 10.0
E = 2.1e11
rho = 7.8e3
section = { shape = "circle", diameter = 0.12 }
[supports]
pin = 180.0
[multibody]
n = 40
[lumped]
n = 40
[modes]
count = 9
solvers = ["multibody", "lumped"]
[table]
base = "multibody"
against = ["lumped"]
"""


def test_shapes_equal_the_report_json(tmp_path):
    """`ringvib run --out DIR` writes each model's shapes (modes_<solver>.json) in full precision."""
    scene = tmp_path / "two.toml"
    scene.write_text(SCENE_TWO_CHAINS)
    out = tmp_path / "out"
    run = command("run", scene, "--out", out, "--set", "multibody.n=48")
    assert run.returncode == 0, run.stderr
    s = ringvib.Scene.load(str(scene), set={"multibody.n": 48})
    for solver in ("multibody", "lumped"):
        j = json.loads((out / f"modes_{solver}.json").read_text())
        m = ringvib.modes(s, solver)
        modes_matches_json(m, j)
        assert m.stations_deg.tolist() == j["stations_deg"]
        assert len(j["shapes"]) == len(m.omega)
        for k, shape in enumerate(j["shapes"]):
            assert m.shapes[k, :, 0].tolist() == shape["radial"]
            assert m.shapes[k, :, 1].tolist() == shape["tangential"]


def test_from_toml_equals_load(tmp_path):
    scene = tmp_path / "two.toml"
    scene.write_text(SCENE_TWO_CHAINS)
    a = ringvib.modes(ringvib.Scene.from_toml(SCENE_TWO_CHAINS), "lumped")
    b = ringvib.modes(ringvib.Scene.load(str(scene)), "lumped")
    assert a.omega.tolist() == b.omega.tolist()


@pytest.mark.parametrize("paper", [False, True])
def test_table_equals_the_commands_json(paper):
    values = {"fem.elements": 20, "table.reference": False, "modes.count": 12}
    texts = {"fem.elements": "20", "table.reference": "false", "modes.count": "12"}
    s = ringvib.Scene.load(scene_path("paper1990.toml"), set=values)
    rows = ringvib.table(s, paper=paper)
    j = ringvib_json("table", scene_path("paper1990.toml"), "--format", "json", *(["--paper"] if paper else []),
                     *sets(texts))
    assert rows == j["rows"]
    assert len(rows) == 12 and "fem_diff_pct" in rows[0] and (("paper_multibody" in rows[0]) == paper)


def test_with_gives_the_same_scene_as_load_with_set():
    base = ringvib.Scene.load(scene_path("paper1990.toml"))
    a = base.with_({"multibody.n": 60}, multibody__rotary_inertia=False)
    b = ringvib.Scene.load(scene_path("paper1990.toml"), set={"multibody.n": 60, "multibody.rotary_inertia": False})
    assert a.toml == b.toml
    assert a.overrides == ["multibody.n=60", "multibody.rotary_inertia=false"]
    assert ringvib.modes(a, "multibody").omega.tolist() == ringvib.modes(b, "multibody").omega.tolist()
    assert base.overrides == []  # scenes are immutable


STATIC_CASES = [
    ("multibody", {"multibody.n": 60}, {"multibody.n": "60"}),
    ("lumped", {"lumped.n": 40, "static.force": [-1.5e4, 0.0]}, {"lumped.n": "40", "static.force": "[-1.5e4, 0.0]"}),
]


@pytest.mark.parametrize("solver,values,texts", STATIC_CASES, ids=[c[0] for c in STATIC_CASES])
def test_static_equals_the_commands_json(solver, values, texts):
    s = ringvib.Scene.load(scene_path("paper1990-static.toml"), set=values)
    r = ringvib.static(s, solver)
    j = ringvib_json("static", scene_path("paper1990-static.toml"), "--solver", solver, "--json", *sets(texts))
    assert r.solver == j["solver"]
    assert r.unknowns == j["unknowns"]
    assert r.steps == j["steps"]
    assert r.newton_iterations == j["newton_iterations"]
    assert r.displacements.dtype.names == ("angle", "ux", "uy")
    assert [dict(zip(("angle", "ux", "uy"), map(float, d))) for d in r.displacements] == j["displacements"]
    assert r.nodes.ndim == 2 and r.nodes.shape[1] == 2 and np.isfinite(r.nodes).all()


def test_static_path_equals_the_commands_json():
    # A load history (there and back) records the path: every equilibrium the command's JSON
    # lists, with the same load factors, displacements and plastic work.
    values = {"static.history": [1.0, 0.0], "static.steps": 4, "multibody.n": 40}
    texts = {"static.history": "[1.0, 0.0]", "static.steps": "4", "multibody.n": "40"}
    s = ringvib.Scene.load(scene_path("pinched-ring-plastic.toml"), set=values)
    r = ringvib.static(s, "multibody")
    j = ringvib_json("static", scene_path("pinched-ring-plastic.toml"), "--solver", "multibody", "--json",
                     *sets(texts))
    assert r.end == j["end"] and r.end_load == j["end_load"]
    assert r.dissipated == j["dissipated"]
    assert len(r.path) == j["path_points"] == len(j["path"])
    assert r.path.dtype.names[:2] == ("load_factor", "ovalisation")
    assert r.path.dtype.names[-2:] == ("dissipated", "plastic_curvature")
    for row, p in zip(r.path, j["path"]):
        assert row["load_factor"] == p["load_factor"]
        assert row["dissipated"] == p["dissipated"]
        for d in p["displacements"]:
            name = f'{d["angle"]:g}'
            assert row["ux_" + name] == d["ux"] and row["uy_" + name] == d["uy"]


def test_driven_static_reaction_equals_the_commands_json():
    # static.displacement: the reaction at the end and along the path, as the command's JSON has
    # them (crushed-ring.toml, the lumped chain at n = 40); a loaded path has none.
    values = {"lumped.n": 40}
    s = ringvib.Scene.load(scene_path("crushed-ring.toml"), set=values)
    r = ringvib.static(s, "lumped")
    j = ringvib_json("static", scene_path("crushed-ring.toml"), "--solver", "lumped", "--json", *sets({"lumped.n": "40"}))
    assert r.reaction == tuple(j["reaction"])
    assert r.path.dtype.names[-2:] == ("reaction_x", "reaction_y")
    assert len(r.path) == len(j["path"])
    for row, p in zip(r.path, j["path"]):
        assert (row["reaction_x"], row["reaction_y"]) == tuple(p["reaction"])
    assert ringvib.static(ringvib.Scene.load(scene_path("paper1990-static.toml")), "lumped").reaction is None


def test_static_limit_points_equal_the_commands_json():
    # The deep arch's path passes its limit point: the module's limit_points are the JSON's.
    values = {"multibody.n": 20}
    s = ringvib.Scene.load(scene_path("deep-arch.toml"), set=values)
    r = ringvib.static(s, "multibody")
    j = ringvib_json("static", scene_path("deep-arch.toml"), "--solver", "multibody", "--json", "--set", "multibody.n=20")
    assert len(r.limit_points) == len(j["limit_points"]) == 1
    assert r.limit_points.dtype.names == ("load_factor", "ux_90", "uy_90")
    row, p = r.limit_points[0], j["limit_points"][0]
    assert row["load_factor"] == p["load_factor"]
    assert row["ux_90"] == p["displacements"][0]["ux"] and row["uy_90"] == p["displacements"][0]["uy"]


def test_spinning_modes_equal_the_commands_json():
    # The spinning tyre in the fixed frame: frequencies, each mode's wave and direction, and
    # the wave pairs with Bryan's factor are the JSON's, to the bit.
    values = {"multibody.n": 40}
    s = ringvib.Scene.load(scene_path("spinning-tyre.toml"), set=values)
    m = ringvib.modes(s, "multibody")
    j = ringvib_json("modes", scene_path("spinning-tyre.toml"), "--solver", "multibody", "--json",
                     "--set", "multibody.n=40")
    assert m.frame == j["frame"] == "fixed"
    assert list(m.omega) == j["omega"]
    assert m.wave == j["wave"] and m.direction == j["direction"]
    assert m.wave_pairs == j["wave_pairs"]
    assert {p["wave"] for p in m.wave_pairs} >= {2, 3}


def test_bench_equals_the_commands_csv(tmp_path):
    # The same sweep as the command's: the same solvers, sizes and errors (times differ run to
    # run); the progress callback receives the study's lines as str.
    values = {"static.solvers": ["multibody"]}
    texts = {"static.solvers": '["multibody"]'}
    lines = []
    b = ringvib.bench(ringvib.Scene.load(scene_path("paper1990-static-compare.toml"), set=values),
                      progress=lines.append)
    run = command("bench", scene_path("paper1990-static-compare.toml"), "-q", "--out", str(tmp_path / "out"),
                  *sets(texts))
    assert run.returncode == 0, run.stderr
    header, rows = csv_table((tmp_path / "out" / "bench_static.csv").read_text())
    assert b["modal"] is None and len(b["nonlinear"]) == 1
    static = b["nonlinear"][0]
    assert static["analysis"] == "static"
    points = static["points"]
    assert points["curve"] == [r[header.index("solver")] for r in rows]
    assert points["size"].tolist() == [int(r[header.index("size")]) for r in rows]
    assert points["max_error_pct"].tolist() == pytest.approx([float(r[header.index("error_pct")]) for r in rows],
                                                              rel=1e-10)
    assert static["reference_value"] == pytest.approx(float(rows[0][header.index("reference_m")]), rel=1e-10)
    assert (points["seconds"] > 0).all()
    assert lines and all(isinstance(line, str) and line for line in lines)
    assert lines[0] == "ringvib: computing the converged static reference"


def test_sweep_equals_the_commands_json(tmp_path):
    # The command's sweep.json rows, but for the seconds (which differ run to run); the progress
    # callable sees every case finish once.
    vary = {"multibody.n": [20, 40, 80], "static.force": [[-1e4, 0.0], [-3e4, 0.0]]}
    calls = []
    rows = ringvib.sweep(ringvib.Scene.load(scene_path("paper1990-static.toml")), vary, jobs=2,
                         progress=lambda done, total, failed: calls.append((done, total, failed)))
    run = command("sweep", scene_path("paper1990-static.toml"), "--vary", "multibody.n=[20, 40, 80]",
                  "--vary", "static.force=[[-1e4, 0.0], [-3e4, 0.0]]", "--out", str(tmp_path / "out"))
    assert run.returncode == 0, run.stderr
    expected = json.loads((tmp_path / "out" / "sweep.json").read_text())["rows"]
    strip = lambda r: {k: v for k, v in r.items() if k != "seconds"}
    assert [strip(r) for r in rows] == [strip(r) for r in expected]
    assert sorted(calls) == [(i, 6, 0) for i in range(1, 7)]
    with pytest.raises(ringvib.InputError) as e:
        ringvib.sweep(ringvib.Scene.load(scene_path("paper1990-static.toml")), {"multibody.n": [40, 3]})
    assert "multibody.n" in str(e.value)


def test_static_table_equals_the_commands_json():
    values = {"static.solvers": ["multibody", "lumped"]}
    texts = {"static.solvers": '["multibody", "lumped"]'}
    s = ringvib.Scene.load(scene_path("paper1990-static.toml"), set=values)
    rows = ringvib.static_table(s)
    j = ringvib_json("static", scene_path("paper1990-static.toml"), "--format", "json", *sets(texts))
    assert rows == j["rows"]
    assert {r["quantity"] for r in rows} == {"ux", "uy", "u"}


def csv_table(text):
    lines = text.strip().splitlines()
    header = lines[0].split(",")
    return header, [line.split(",") for line in lines[1:]]


@pytest.mark.parametrize("solver,integrator", [("multibody", "newmark"), ("multibody", "generalized-alpha"),
                                               ("lumped", "midpoint")])
def test_response_equals_the_commands_csv(solver, integrator):
    values = {"response.t_end": 0.4, "response.integrator": integrator, "response.record": [0.0, 90.0, 22.5],
              "multibody.n": 80, "lumped.n": 80}
    texts = {"response.t_end": "0.4", "response.integrator": f'"{integrator}"', "response.record": "[0, 90, 22.5]",
             "multibody.n": "80", "lumped.n": "80"}
    s = ringvib.Scene.load(scene_path("paper1990-forced.toml"), set=values)
    r = ringvib.respond(s, solver)
    run = command("respond", scene_path("paper1990-forced.toml"), "--solver", solver, "--csv", "-", *sets(texts))
    assert run.returncode == 0, run.stderr
    header, rows = csv_table(run.stdout)
    assert list(r.history.dtype.names) == header
    assert len(r.history) == len(rows) == len(r.t) == 41
    # The CSV has 12 significant digits (%.12g): the module's doubles printed the same way
    # must give the same text, digit for digit.
    for name in header:
        column = r.history[name]
        printed = [str(int(v)) if name == "newton_iterations" else format(float(v), ".12g") for v in column]
        assert printed == [row[header.index(name)] for row in rows], name
    assert r.record_angles.tolist() == [0.0, 90.0, 22.5]
    assert np.array_equal(r.ux[2], r.history["ux_22.5"]) and np.array_equal(r.uy[1], r.history["uy_90"])
    assert r.solver == solver


def test_response_table_equals_the_commands_json():
    values = {"response.t_end": 0.3, "response.solvers": ["multibody", "lumped"]}
    texts = {"response.t_end": "0.3", "response.solvers": '["multibody", "lumped"]'}
    s = ringvib.Scene.load(scene_path("paper1990-forced.toml"), set=values)
    rows = ringvib.response_table(s)
    j = ringvib_json("respond", scene_path("paper1990-forced.toml"), "--format", "json", *sets(texts))
    assert rows == j["rows"]


def test_solvers_are_the_commands():
    """The registry's names are those `ringvib modes --help` offers for --solver."""
    names = [e["name"] for e in ringvib.solvers()]
    help_text = command("modes", "--help").stdout
    assert " | ".join(names) in help_text
    by_name = {e["name"]: e for e in ringvib.solvers()}
    assert by_name["multibody"]["size_key"] == "multibody.n"
    assert set(by_name["multibody"]["analyses"]) == {"modes", "static", "response"}


def test_a_scene_pickles():
    s = ringvib.Scene.load(scene_path("paper1990.toml"), set={"multibody.n": 60})
    t = pickle.loads(pickle.dumps(s))
    assert t.toml == s.toml and t.overrides == s.overrides and t.file == s.file


def test_the_library_prints_nothing(capfd):
    """Checked on the file descriptors: a C++ write to stdout or stderr (the FE plug-in and
    deal.II loading included) would show."""
    s = ringvib.Scene.load(scene_path("paper1990.toml"), set={"fem.elements": 20, "ring.section": {"shape": "rectangle", "width": 0.1, "height": 1.5}})
    assert s.warnings  # a thick ring: the command warns on stderr, the module only lists it
    ringvib.table(s)
    ringvib.static(ringvib.Scene.load(scene_path("paper1990-static.toml")))
    ringvib.respond(ringvib.Scene.load(scene_path("paper1990-forced.toml"), set={"response.t_end": 0.1}))
    assert capfd.readouterr() == ("", "")


# Linear buckling: the module's factors are the command's JSON, exactly; its shapes (which the
# command's JSON leaves out) are those of the same eigenpairs, checked against the closed form's
# count: under hydrostatic pressure the ring on a pin and a roller buckles at 3 EI/R^3 twice
# (scenes/ring-buckling.toml; ring/closed_form.hpp), the chain at n = 40 within its O(1/n^2).
BUCKLING_CASES = [("multibody", {"multibody.n": 40}, {"multibody.n": "40"}),
                  ("lumped", {"lumped.n": 40}, {"lumped.n": "40"})]


@pytest.mark.parametrize("solver,values,texts", BUCKLING_CASES, ids=[c[0] for c in BUCKLING_CASES])
def test_buckling_equals_the_commands_json(solver, values, texts):
    s = ringvib.Scene.load(scene_path("ring-buckling.toml"), set=values)
    b = ringvib.buckling(s, solver)
    j = ringvib_json("buckling", scene_path("ring-buckling.toml"), "--solver", solver, "--json", *sets(texts))
    assert b["solver"] == j["solver"] == solver
    assert b["model"] == j["model"]
    assert b["factors"].tolist() == j["factors"]  # exact: the same doubles
    assert b["unknowns"] == j["unknowns"]
    assert b["shapes"].shape == (len(b["factors"]), ringvib.STATIONS, 2)
    assert np.all(np.isfinite(b["shapes"]))
    ei_r3 = 2.1e11 * math.pi * 0.12**4 / 64 / 10.0**3
    # 3 EI/R^3, a double factor; the chain's O(1/n^2) error at n = 40 is well under 1 %.
    assert abs(b["factors"][0] / ei_r3 - 3.0) < 0.03 and abs(b["factors"][1] / ei_r3 - 3.0) < 0.03


def test_buckling_table_equals_the_commands_json():
    values = {"multibody.n": 40, "lumped.n": 40, "buckling.solvers": ["multibody", "lumped"],
              "buckling.reference": False}
    texts = {"multibody.n": "40", "lumped.n": "40", "buckling.solvers": '["multibody", "lumped"]',
             "buckling.reference": "false"}
    rows = ringvib.buckling_table(ringvib.Scene.load(scene_path("ring-buckling.toml"), set=values))
    j = ringvib_json("buckling", scene_path("ring-buckling.toml"), "--format", "json", *sets(texts))
    assert rows == j["rows"]


def test_converge_equals_the_commands_csv():
    """The module's study is the command's convergence.csv (12 significant digits there:
    compare/converge.cpp), series by series; the seconds are wall time (only their count)."""
    values, texts = {"modes.count": 4}, {"modes.count": "4"}
    c = ringvib.converge(ringvib.Scene.load(scene_path("paper1990.toml"), set=values))
    with tempfile.TemporaryDirectory() as d:
        out = pathlib.Path(d) / "conv"
        run = command("converge", scene_path("paper1990.toml"), "-q", "--out", out, *sets(texts))
        assert run.returncode == 0, run.stderr
        lines = (out / "convergence.csv").read_text().splitlines()
    assert lines[0] == "series,parameter,size,max_error_pct,mean_error_pct,seconds,fitted_order"
    rows = [line.rsplit(",", 6) for line in lines[1:]]
    assert c["modes"] == 4
    assert len(rows) == sum(len(s["size"]) for s in c["series"])
    g = lambda x: f"{x:.12g}"
    i = 0
    for s in c["series"]:
        assert len(s["size"]) == len(s["max_error_pct"]) == len(s["mean_error_pct"]) == len(s["seconds"])
        for k in range(len(s["size"])):
            name, parameter, size, max_e, mean_e, _seconds, order = rows[i]
            assert name == f'"{s["name"]}"' and parameter == s["parameter"]
            assert [size, max_e, mean_e, order] == [g(s["size"][k]), g(s["max_error_pct"][k]),
                                                   g(s["mean_error_pct"][k]), g(s["fitted_order"])]
            i += 1
    # The chains' second order and the cubic FE's fourth (docs/measured.md, "Convergence").
    orders = {s["name"]: s["fitted_order"] for s in c["series"]}
    assert abs(orders["multibody"] - 2.0) < 0.1 and abs(orders["fem (p = 3)"] - 4.0) < 0.1


def test_trim_equals_the_commands_json():
    """ringvib.trim is `ringvib trim --json`; its trimmed scene has the pair's split removed."""
    s = ringvib.Scene.load(scene_path("imperfect-ring.toml"), set={"multibody.n": 60})
    t = ringvib.trim(s, 1, [60.0, 90.0], solver="multibody")
    j = ringvib_json("trim", scene_path("imperfect-ring.toml"), "--mode", 1, "--at", "60,90", "--solver", "multibody",
                     "--json", *sets({"multibody.n": "60"}))
    for key in ("mode", "wave", "solver", "masses", "split_before", "split_after", "orientation_before", "steps"):
        assert t[key] == j[key], key
    after = ringvib.modes(t["scene"], "multibody")
    assert all(p["wave"] != 2 or p["relative_split"] < 1e-6 for p in after.pairs)
    with pytest.raises(ringvib.InputError, match="--at"):
        ringvib.trim(s, 1, [75.0, 30.0], solver="multibody")  # 45 degrees apart: alike on k = 2
