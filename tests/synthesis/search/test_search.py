"""Synthesis (issue 12): design problems, batches with reasons, differential evolution
on the seed 003 hitch, the [design] section and --var, the CLI."""

import numpy as np
import pytest

from assur import io
from assur.io import load_problem
from assur.synthesis.search.problem import ASSEMBLY, CONSTRAINT, FEASIBLE
from assur.synthesis.search.search import optimize, pareto
from assur.errors import ModelError

HITCH = io.bundled("hitch_003_design")


@pytest.fixture(scope="module")
def problem():
    return load_problem(HITCH)


def test_original_design_is_the_seeds(problem):
    """Seed 003, table 4.1: ΔGS65 is smallest at S = 0.670, 8.9 %; the original design
    is feasible and its minimum reserve over 50 positions is that value."""
    b = problem.evaluate(problem.x0[None])
    assert b.feasible[0] and b.reasons == [""]
    assert round(float(b.objectives[0, 0]), 1) == 8.9
    # the lift range constraints are the original's own values: Y56(Smin) = 0.2 m (§2.2)
    assert b.values[0, 0] == pytest.approx(0.2, abs=1e-9)


def test_batch_equals_one_by_one(problem):
    """A batch gives each design what it gives alone (criteria and status)."""
    X = problem.sample(40, seed=5)
    b = problem.evaluate(X)
    for i in (0, 7, 23, 39):
        bi = problem.evaluate(X[i:i + 1])
        assert bi.status[0] == b.status[i]
        np.testing.assert_allclose(bi.objectives[0], b.objectives[i], rtol=1e-12)
        np.testing.assert_allclose(bi.values[0], b.values[i], rtol=1e-12)
        assert bi.reasons[0] == b.reasons[i]


def test_infeasible_designs_carry_their_reasons(problem):
    """Designs that cannot assemble, and designs that break a constraint, are marked
    in the batch with the group, the failure and the position — not an exception."""
    X = np.repeat(problem.x0[None], 4, axis=0)
    j = problem.names.index("X03")
    X[1, j] += 0.5          # lever pivot 0.5 m away: cylinder–lever group I (2,3) cannot close
    k = problem.names.index("Y05")
    X[2, k] += 0.03         # lower-link pivot up 30 mm: the lift range is no longer kept
    b = problem.evaluate(X)
    assert list(b.status) == [FEASIBLE, ASSEMBLY, CONSTRAINT, FEASIBLE]
    r = b.reasons
    assert r[0] == r[3] == ""
    assert "does not assemble" in r[1] and "'I (2,3)'" in r[1] and "position 0" in r[1]
    assert "S = 0.42" in r[1]
    assert r[2] == "constraint max Y(56) ≥ 1.04316 m does not hold at position 49 (S = 0.67)"
    assert b.reason(2).startswith(r[2] + ": 1.01") and b.reason(2).endswith(" m")
    # the engine's own words for the assembly failure, with its values
    assert "cylinder–lever group 'I (2,3)'" in b.explain(1)
    assert b.failed_positions[1] > 0 and b.failed_positions[0] == 0


def test_many_infeasible_designs_in_one_batch(problem):
    """Reasons for thousands of failing designs come from one extra kernel pass."""
    X = problem.sample(3000, seed=11)
    X[:, problem.names.index("X03")] += 0.8  # the lever pivot far beyond the cylinder
    b = problem.evaluate(X)
    assert (b.status == ASSEMBLY).all()
    assert len(set(b.reasons)) >= 1 and all("does not assemble" in r for r in b.reasons)


def test_engine_refusal_is_isolated():
    """A design the engine refuses as a whole — the implement's centre of mass fixed at
    a pose S = Sp where the cylinder cannot reach — is split off the batch with the
    engine's message; the rest of the batch is evaluated (and the problem needs no
    constraint)."""
    from assur.synthesis.search import Problem, Variable, criterion
    from assur.synthesis.search.problem import ENGINE
    mech = io.load(io.bundled("hitch_003")).mechanism
    obj = criterion("bound", {"quantity": "Y(S6)", "of": "max"}, mech, sense="maximize")
    S = np.linspace(0.42, 0.67, 8)
    pb = Problem(mech, S, [Variable("Sp", 0.1, 0.6)], [], [obj])
    X = np.array([[0.469], [0.1], [0.5], [0.2], [0.55]])
    b = pb.evaluate(X)
    assert list(b.status) == [FEASIBLE, ENGINE, FEASIBLE, ENGINE, FEASIBLE]
    assert b.reasons[1].startswith("refused by the engine: rigid point fixed at a pose "
                                   "'centre of mass S6' is defined at the pose S = 0.1")
    for i in (0, 2, 4):
        y = pb.with_design(X[i]).solve(S).y("S6")
        assert b.objectives[i, 0] == pytest.approx(y.max(), rel=1e-12)


def test_differential_evolution_beats_the_seed(problem):
    """Issue 12: maximise the minimum capacity reserve over the stroke of the 003 hitch
    with its lift range kept and the pivots within ±30 mm: the optimum is feasible
    and better than the seed's 8.9 % (table 4.1)."""
    res = optimize(problem, popsize=10, maxiter=60, seed=1)
    print(f"\nminimum capacity reserve: seed 8.9 %, optimum {res.value:.2f} % "
          f"({res.evaluations} designs in {res.calls} batches)")
    assert res.feasible and res.verified == ""
    assert res.value > 8.9 + 5.0
    assert np.all(res.x >= problem.bounds[:, 0]) and np.all(res.x <= problem.bounds[:, 1])
    # one batch per generation (and the start), not one call per design
    assert res.calls <= res.generations + 2
    # the lift range holds and the design assembles everywhere, continuity checked
    mech = problem.with_design(res.x)
    kin = mech.solve(problem.positions)
    y = kin.y("56")
    assert y.min() <= 0.2 + 1e-9 and y.max() >= problem.reference()["max Y(56)"][0] - 1e-9


def test_nsga2_pareto_front():
    """Two objectives (reserve up, peak pressure down): a front of feasible designs,
    none dominating another."""
    text = HITCH.read_text(encoding="utf-8").replace('extends = "hitch_003.toml"',
                                                     f'extends = "{io.bundled("hitch_003")}"')
    text += '\n[[design.objectives]]\nminimize = "p(ГЦ)"\nof = "max"\n'
    import tempfile
    from pathlib import Path
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "two.toml"
        p.write_text(text, encoding="utf-8")
        pb = load_problem(p)
        res = pareto(pb, pop_size=24, generations=8, seed=2)
        from assur.views.report.design import pareto_figure
        png = pareto_figure(pb, res, Path(d) / "front.png")
        assert png.stat().st_size > 1000
    assert len(res.X) >= 1 and res.batch.feasible.all()
    F = res.batch.scores()
    for i in range(len(F)):
        dom = np.all(F <= F[i], axis=1) & np.any(F < F[i], axis=1)
        assert not dom.any()


def test_var_option_and_errors():
    mech = io.load(io.bundled("hitch_003")).mechanism
    from assur.io._design import parse_var
    v = parse_var("X01=±30 mm", mech)
    assert (v.low, v.high) == pytest.approx((0.385, 0.445))
    v = parse_var("L4=600 mm:0.72 m", mech)
    assert (v.low, v.high) == pytest.approx((0.6, 0.72))
    with pytest.raises(ModelError, match="not a parameter"):
        parse_var("L44=1:2", mech)
    with pytest.raises(ModelError, match="expected a length"):
        parse_var("L4=0.6 MPa:0.7 m", mech)
    with pytest.raises(ModelError, match="low < high"):
        parse_var("L4=0.7 m:0.6 m", mech)


def _with_design(tmp_path, section):
    base = io.bundled("hitch_003")
    p = tmp_path / "d.toml"
    p.write_text(f'extends = "{base}"\n\n{section}', encoding="utf-8")
    return p


@pytest.mark.parametrize("section, match", [
    ('[design.variables]\nX99 = { within = "30 mm" }\n', r"d\.toml:4: design\.variables\.X99"),
    ('[design.variables]\nX01 = { within = "30 kN" }\n', r"design\.variables\.X01: within"),
    ('[design]\nspeed = 1\n', r"unknown key"),
    ('[design.variables]\nX01 = { within = "30 mm" }\n[[design.constraints]]\n'
     'quantity = "Q(56)"\nat_most = "1 m"\n', r"d\.toml:6: design\.constraints\[0\]\.quantity: unknown output"),
    ('[design.variables]\nX01 = { within = "30 mm" }\n[[design.constraints]]\n'
     'quantity = "Y(56)"\nat_most = "1 MPa"\n', r"d\.toml:7: design\.constraints\[0\]\.at_most: expected a length .*, found '1 MPa'"),
    ('[design.variables]\nX01 = { within = "30 mm" }\n[[design.objectives]]\n'
     'quantity = "Y(56)"\n', r"maximize = … or minimize"),
])
def test_design_section_errors_name_key_and_line(tmp_path, section, match):
    with pytest.raises(io.ModelFileError, match=match):
        io.load(_with_design(tmp_path, section))


def test_transmission_angle_and_box(tmp_path):
    """The transmission angle of the dyad II (4,5) from the distance of its far ends
    equals the angle between the links computed position by position."""
    p = _with_design(tmp_path, '''[design.variables]
X05 = { within = "30 mm" }
[[design.constraints]]
type = "transmission_angle"
links = ["4", "5"]
at_least = "20 deg"
[[design.constraints]]
type = "box"
point = "45"
x = ["-1 m", "1 m"]
y = ["-1 m", "2 m"]
''')
    pb = load_problem(p)
    X = pb.sample(16, seed=3)
    b = pb.evaluate(X)
    for i in np.flatnonzero(b.status != ASSEMBLY)[:4]:
        kin = pb.with_design(X[i]).solve(pb.positions)
        d = np.angle(np.exp(1j * (kin.phi("4") - kin.phi("5"))))
        mu = np.arccos(np.abs(np.cos(d)))
        assert b.values[i, 0] == pytest.approx(mu.min(), abs=1e-9)
        box = min(kin.x("45").min() + 1, 1 - kin.x("45").max(), kin.y("45").min() + 1,
                  2 - kin.y("45").max())
        assert b.values[i, 1] == pytest.approx(box, abs=1e-12)


def test_cli_optimize_writes_a_loadable_best_design(tmp_path):
    from typer.testing import CliRunner
    from assur.views.cli import app
    r = CliRunner().invoke(app, ["optimize", str(HITCH), "--popsize", "6", "--maxiter", "15",
                                 "--seed", "3", "--workers", "0", "-o", str(tmp_path)])
    assert r.exit_code == 0, r.output
    best = io.load(tmp_path / "hitch_003_design_best.toml")
    pb = load_problem(HITCH)
    x = np.array([best.mechanism.params[n] for n in pb.names])
    b = pb.evaluate(x[None])
    assert b.feasible[0] and b.objectives[0, 0] > 8.95
    html = (tmp_path / "design.html").read_text(encoding="utf-8")
    assert "Variables" in html and "X01" in html and "data:image/png;base64" in html
    from assur.views.report.design import comparison_html
    from assur.synthesis.search.search import optimize
    res = optimize(pb, popsize=4, maxiter=3, seed=0)
    ru = comparison_html(pb, res, lang="ru")
    assert "Переменные проектирования" in ru and "максимизировать" in ru


def test_cli_sweep_in_process_to_parquet(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner
    from assur.views.cli import app
    out = tmp_path / "s.parquet"
    r = CliRunner().invoke(app, ["sweep", str(HITCH), "--samples", "500", "--workers", "0",
                                 "-o", str(out)])
    assert r.exit_code == 0, r.output
    df = pd.read_parquet(out)
    assert len(df) == 500 and {"X01", "feasible", "reason"} <= set(df.columns)
    assert (df["reason"] == "").equals(df["feasible"])


def test_reductions_equal_the_array_pass(problem):
    """The criteria of a batch (reduced in the kernel) equal the full analysis of each
    design position by position: the minimum reserve ΔGS65, the largest pressure and
    the lowest and highest Y56."""
    X = problem.sample(300, seed=8)
    b = problem.evaluate(X)
    idx = np.flatnonzero(b.failed_positions == 0)[:40]
    assert len(idx) >= 10
    P6 = float(problem.mechanism.params["P6"])
    for i in idx:
        a = problem.with_design(X[i]).analyze(problem.positions)
        cyl = a.cylinder("ГЦ")
        assert b.objectives[i, 0] == pytest.approx(cyl.reserve("S6", P6).min(), rel=1e-10)
        if b.status[i] in (FEASIBLE, CONSTRAINT):
            y = a.kinematics.y("56")
            np.testing.assert_allclose(b.values[i, :3], [y.min(), y.max(), cyl.pressure.max()],
                                       rtol=1e-10)


def test_cli_refuses_a_bad_var_with_one_message(tmp_path):
    from typer.testing import CliRunner
    from assur.views.cli import app
    r = CliRunner().invoke(app, ["sweep", str(HITCH), "--var", "L44=1:2", "--workers", "0",
                                 "-o", str(tmp_path / "x.parquet")])
    assert r.exit_code == 1
    assert "--var 'L44=1:2': 'L44' is not a parameter" in r.output
    assert "Traceback" not in r.output


def test_capacity_constraint_and_a_point_that_does_not_rise():
    """A capacity at the lever's point 23 (Python API): where 23 goes down with S
    (I(23) ≤ 0) the design is infeasible with that reason; elsewhere the minimum
    capacity equals the array pass's."""
    from assur.synthesis.search import Limit, Problem, Variable, criterion
    from assur.synthesis.search.problem import LIFT
    mech = io.load(io.bundled("hitch_003")).mechanism
    cap = criterion("capacity", {"cylinder": "ГЦ", "point": "23"}, mech,
                    limit=Limit(60e3, "at_least"))
    span = criterion("bound", {"quantity": "Y(23)", "of": "span"}, mech, sense="minimize")
    S = np.linspace(0.42, 0.67, 50)
    pb = Problem(mech, S, [Variable("X03", 0.0, 0.6), Variable("Y03", 0.6, 1.3)], [cap],
                 [span])
    X = np.array([[0.15967816, 0.97725409], [0.25, 1.112]])
    b = pb.evaluate(X)
    assert b.status[0] == LIFT
    kin = pb.with_design(X[0]).solve(S)
    I = kin.transmission("23")
    assert I.min() <= 0 and b.where[0] == int(np.argmin(I))
    assert b.reasons[0] == ("point 23 does not rise with the coordinate: its transmission "
                            f"number I(23) ≤ 0 at position {b.where[0]} (S = {S[b.where[0]]:.6g})")
    a = pb.with_design(X[1]).analyze(S)
    G = a.cylinder("ГЦ").capacity("23")
    assert b.values[1, 0] == pytest.approx(G.min(), rel=1e-10)
    assert b.status[1] == (FEASIBLE if G.min() >= 60e3 else CONSTRAINT)
    y = a.kinematics.y("23")
    assert b.objectives[1, 0] == pytest.approx(y.max() - y.min(), rel=1e-10)


def test_written_design_file_loads_with_the_values(tmp_path):
    """The best design's file extends the original, writes each value in the file's
    own unit (an angle in degrees, a length in m or mm, a plain number) and loads
    back to the same values."""
    from assur.io._design import write_design_file
    from assur.core.quantities import display_units
    base = io.bundled("hitch_003")
    mech = io.load(base).mechanism
    values = {"phiBD": 0.40123456789, "X01": 0.4123456789, "eta": 0.8512345, "Dgc": 0.0812345}
    p = write_design_file(tmp_path / "best.toml",
                          base, values, display_units(mech), header=("a header",))
    text = p.read_text(encoding="utf-8")
    assert text.startswith("# a header\nextends = ") and ' deg"' in text and ' mm"' in text
    got = io.load(p).mechanism.params
    for k, v in values.items():
        assert got[k] == pytest.approx(v, rel=1e-14)


def test_bore_and_relief_as_variables():
    """--var on the cylinder's bore and relief setting (units as in files): the
    capacity scales with D² and p_max (k·p_max·A·η/I, seed 003 §4), the pressure with
    1/D², and the pressure limit follows the relief setting of each design."""
    pb = load_problem(HITCH, variables=("Dgc=70 mm:90 mm", "Pgc_max=15 MPa:20 MPa"))
    assert pb.names[-2:] == ("Dgc", "Pgc_max")
    X = np.repeat(pb.x0[None], 4, axis=0)
    X[1, -2] = 0.09
    X[2, -1] = 20e6
    X[3, -1] = 15e6          # below the working pressure of 16.06 MPa: infeasible
    b = pb.evaluate(X)
    G = 1 + b.objectives[:, 0] / 100  # GS6/P6
    assert G[1] / G[0] == pytest.approx((0.09 / 0.08) ** 2, rel=1e-12)
    assert G[2] / G[0] == pytest.approx(20 / 17.5, rel=1e-12)
    assert b.values[1, 2] == pytest.approx(b.values[0, 2] * (0.08 / 0.09) ** 2, rel=1e-12)
    assert list(b.status[:3]) == [FEASIBLE] * 3 and b.status[3] == CONSTRAINT
    assert b.reasons[3].startswith("constraint max p(ГЦ) ≤ Pgc_max does not hold")
    assert b.reason(3).startswith("constraint max p(ГЦ) ≤ 15 MPa does not hold")


def test_chunks_and_order_do_not_change_results(problem):
    """The same designs in chunks of 37 and in another order give the same results
    (the reasons, made once per batch, included)."""
    X = problem.sample(500, seed=21)
    X[::5, problem.names.index("X03")] += 0.8
    b = problem.evaluate(X)
    small = load_problem(HITCH, chunk=37)
    perm = np.random.default_rng(0).permutation(len(X))
    c = small.evaluate(X[perm])
    np.testing.assert_array_equal(c.status, b.status[perm])
    np.testing.assert_array_equal(c.objectives, b.objectives[perm])
    np.testing.assert_array_equal(c.margins, b.margins[perm])
    assert c.reasons == [b.reasons[i] for i in perm]


def test_bounds_that_exclude_the_file_value_seed_the_nearest_design(tmp_path):
    """Issue 27: a variable's [low, high] not containing the file's value made scipy
    refuse the seed ("x0 lay outside the specified bounds", a traceback); the
    population is seeded with the box's design nearest to the file's."""
    text = io.bundled("hitch_003_design").read_text(encoding="utf-8").replace(
        'X07 = { within = "30 mm" }', 'X07 = ["0.50 m", "0.52 m"]').replace(
        'extends = "hitch_003.toml"', f'extends = "{io.bundled("hitch_003").as_posix()}"')
    path = tmp_path / "d.toml"
    path.write_text(text, encoding="utf-8")
    pb = load_problem(path)
    lo, hi = pb.bounds[pb.names.index("X07")]
    assert not lo <= pb.x0[pb.names.index("X07")] <= hi
    res = optimize(pb, popsize=4, maxiter=2, seed=0, polish=False)
    assert lo <= res.x[pb.names.index("X07")] <= hi
