"""A design search along a held path (issue 25): the mini-loader's self-levelling lift
(loader_lab1_level.toml, the traverse cylinder S1 held so that φ9 keeps its target while
the boom cylinder S extends) searched over the lever pivot L35, the tie L8 and the held
target φ9 itself. Every design's S1 is solved at every position of S with its own
parameters (:func:`assur.core.held.hold_paths`), the outputs evaluated there; checked
against the loaded model's analysis and against a fresh load of each design's own file
(its path solved by the loader, one design at a time)."""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from assur import io
from assur.core.held import NO_ROOT, hold_path, hold_paths
from assur.errors import ModelError
from assur.io.problems import load_problem
from assur.synthesis.search.problem import ASSEMBLY, FEASIBLE

LEVEL = io.bundled("loader_lab1_level").resolve()
OUTPUTS = ["p(MPT)", "p(MPS)", "Y(S9)", "G(MPS, 09)"]
DESIGN = f"""extends = "{LEVEL.as_posix()}"

[design.variables]
L35 = {{ within = "5 mm" }}
L8 = {{ within = "5 mm" }}
phi9_level = {{ within = "1 deg" }}

[[design.constraints]]
quantity = "Y(S9)"
of = "min"
at_least = "0.5 m"

[[design.constraints]]
type = "capacity"
cylinder = "MPS"
point = "09"
at_least = "10 kN"

[[design.objectives]]
minimize = "p(MPT)"
of = "max"
"""


@pytest.fixture(scope="module")
def design_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("held") / "level_design.toml"
    path.write_text(DESIGN, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def problem(design_file):
    return load_problem(design_file)


def _design_model(tmp_path, x, names):
    """A fresh load of the design ``x`` [SI]: a file extending the level lift with its
    parameters, its held path solved by the loader."""
    units = {"L35": ("m", 1.0), "L8": ("m", 1.0), "phi9_level": ("deg", math.pi / 180)}
    lines = [f'{n} = "{float(v) / units[n][1]!r} {units[n][0]}"' for n, v in zip(names, x)]
    path = tmp_path / f"design_{abs(hash(tuple(x)))}.toml"
    path.write_text(f'extends = "{LEVEL.as_posix()}"\n\n[params]\n' + "\n".join(lines)
                    + "\n", encoding="utf-8")
    return io.load(path)


def _reductions(model):
    """The criteria's outputs reduced over the model's own (load-time) path."""
    f = model.mechanism.evaluate(model.range, outputs=OUTPUTS)
    return {o: (float(np.min(f[o])), float(np.max(f[o]))) for o in OUTPUTS}


def test_the_file_design_is_the_loaded_models_analysis(problem):
    """(a) The original design evaluated by the search equals the analysis of the
    loaded model over its held path, to 1e-12."""
    model = io.load(LEVEL)
    np.testing.assert_array_equal(problem.positions, model.range)
    assert problem.path.holds[0].refs == ("phi9_level", "S1_short", "S1max")
    b = problem.evaluate(problem.x0[None])
    assert b.status.tolist() == [FEASIBLE], b.reasons
    a = model.analyze()
    p_mpt = a.cylinder("MPT").pressure
    assert abs(b.objectives[0, 0] - p_mpt.max()) <= 1e-12 * p_mpt.max()
    y = a.kinematics.y("S9")
    assert abs(b.values[0, 0] - y.min()) <= 1e-12
    G = _reductions(model)["G(MPS, 09)"][0]
    assert abs(b.values[0, 1] - G) <= 1e-12 * G
    assert problem.reference() is not None    # the original's own values evaluate


def test_each_design_of_a_batch_is_its_own_fresh_load(problem, tmp_path):
    """(b) A batch of designs that move the held S1 (and its target): design by design,
    the values of a fresh load of that design's file, to 1e-10."""
    X = np.vstack([problem.x0, problem.sample(5, seed=3)])
    b = problem.evaluate(X)
    assert b.feasible.all(), b.reasons
    s1 = []
    for i, x in enumerate(X):
        model = _design_model(tmp_path, x, problem.names)
        red = _reductions(model)
        assert model.path.residual < 1e-12
        s1.append(model.range[:, 1])
        np.testing.assert_allclose(problem.positions_of(x), model.range, rtol=0, atol=1e-10)
        want = [red["Y(S9)"][0], red["G(MPS, 09)"][0]]
        np.testing.assert_allclose(b.values[i], want, rtol=1e-10)
        np.testing.assert_allclose(b.objectives[i, 0], red["p(MPT)"][1], rtol=1e-10)
    # the designs' held paths differ (the test can fail when they are not their own)
    assert min(np.abs(a - s1[0]).max() for a in s1[1:]) > 1e-4
    assert np.ptp(b.objectives[:, 0]) > 1e3                  # [Pa]


def test_a_design_whose_held_coordinate_cannot_reach_is_infeasible(problem):
    """(c) A lever pivot L35 10 cm farther out leaves the tool beyond S1's stroke at
    the first position: that design is infeasible with its reason; the others of the
    batch evaluate as they do alone, no NaN anywhere."""
    from assur.synthesis.search.problem import Problem
    wide = Problem(problem.original, problem.positions, [
        type(problem.variables[0])("L35", 1.95, 2.2)], problem.constraints,
        problem.objectives, path=problem.path)
    X = np.array([[2.05], [2.15], [2.052], [2.0]])             # L35 [m]
    b = wide.evaluate(X)
    assert b.status.tolist() == [FEASIBLE, ASSEMBLY, FEASIBLE, ASSEMBLY], b.reasons
    assert b.reasons[1] == ("does not assemble along the held path: no S1 within its "
                            "limits reaches the target of phi9 at position 0 (S = 1.00106)")
    assert "at position 8 (S = 1.20021)" in b.reasons[3]
    assert int(b.code[1]) == int(b.code[3]) == NO_ROOT
    assert 11 >= b.failed_positions[1] > b.failed_positions[3] > 0   # from the start / the end
    text = b.explain(1)
    assert "at S = 1.00106 m (position 1 of the path) no S1 in [0.77 m, 0.98 m] reaches " \
           "phi9 = 75 deg" in text, text
    assert wide.verify(X[1]) == text
    for i in (0, 2):
        alone = wide.evaluate(X[i:i + 1])
        np.testing.assert_array_equal(b.objectives[i], alone.objectives[0])
        np.testing.assert_array_equal(b.values[i], alone.values[0])
    for arr in (b.values, b.objectives, b.margins, b.violation, b.amount):
        assert np.isfinite(arr).all()
    assert (b.violation[[1, 3]] > 1 + len(wide.constraints)).all()


def test_a_design_limit_of_the_held_coordinate(problem, tmp_path):
    """A design variable that is the held coordinate's limit (S1max): a design whose
    limits cross fails alone, the others hold their own S1 stroke."""
    from assur.synthesis.search.problem import Problem, Variable
    pb = Problem(problem.original, problem.positions, [Variable("S1max", 0.7, 1.0)],
                 problem.constraints, problem.objectives, path=problem.path)
    b = pb.evaluate(np.array([[0.98], [0.75], [0.9]]))      # S1max [m]
    assert b.status.tolist() == [FEASIBLE, ASSEMBLY, ASSEMBLY], b.reasons
    assert "S1's limits are not [low, high]" in b.reasons[1]
    assert "no S1 within its limits reaches" in b.reasons[2]  # 0.9 m: S1 ≈ 0.94 m at first


def test_hold_paths_is_hold_path_design_by_design():
    """The batched solver against the one-design solver, for designs that change the
    mechanism and the held target (the hold's refs: phi9_level); each design's φ9 at
    its positions is its own target."""
    model = io.load(LEVEL)
    mech, h, s = model.mechanism, model.path.holds[0], model.path.s
    P = {"L35": np.array([2.05, 2.046, 2.054, 2.2]), "L8": np.array([0.5, 0.503, 0.497, 0.5]),
         "phi9_level": np.radians([75.0, 74.5, 75.8, 75.0])}
    p = hold_paths(mech, "S", s, [h], P)
    assert p.ok.tolist() == [True, True, True, False]
    for i in range(3):
        one = hold_path(mech, "S", s, [h], {k: v[i] for k, v in P.items()})
        for a, b in ((one.q, p.q[i]), (one.dq, p.dq[i]), (one.ddq, p.ddq[i])):
            np.testing.assert_allclose(b, a, rtol=0, atol=1e-12)
        phi9 = mech.solve(p.q[i], {k: v[i] for k, v in P.items()}).phi("9")
        assert np.abs(phi9 - P["phi9_level"][i]).max() < 1e-12
        assert one.holds[0].target == P["phi9_level"][i]
    with pytest.raises(ModelError) as e:
        hold_path(mech, "S", s, [h], {k: v[3] for k, v in P.items()})
    assert str(e.value) == str(p.error(3))
    assert (p.q[3] == 0).all() and np.isfinite(p.q).all()


def test_optimize_along_a_held_path_runs(design_file, tmp_path):
    """(d) ``assur optimize`` on a file with [design] over a held path: exit 0, the best
    design written (it loads: its own held path solved)."""
    r = subprocess.run([str(Path(sys.executable).with_name("assur")), "optimize", str(design_file),
                        "--maxiter", "3", "--popsize", "4", "--seed", "1", "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    best = tmp_path / "out" / "level_design_best.toml"
    assert best.is_file()
    assert io.load(best).path is not None
