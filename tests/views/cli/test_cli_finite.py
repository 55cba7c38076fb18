"""No command ends with exit 0 after writing a NaN or an infinity (issue 27).

Every command that writes results checks them with the one checker,
:func:`assur.core.inputs.check_table`, before it writes anything: a value that is not
finite is one message (exit 1) naming the table, the column and the row, and no file
is written. The inputs' spans keep the bundled models finite, so most cases spoil a
result on its way to the writer (the check is what is tested); the work cycles of a
pump so slow that the dynamic forces vanish are a real input that printed ``nan``
in the conclusions before.
"""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import io
from assur.core.inputs import check_table
from assur.errors import ModelError
from assur.views.cli import app

runner = CliRunner()

_NOT_FINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w.])", re.I)


def _written(out):
    return sorted(p.name for p in out.rglob("*") if p.is_file()) if out.exists() else []


def _one_line(r) -> str:
    return " ".join(r.output.split())


def _spoil(monkeypatch, module, name, change):
    """``module.name`` made to return its result after ``change(result)`` has put a
    value that is not finite in it (on its way to the writer)."""
    real = getattr(module, name)

    def spoiled(*args, **kwargs):
        result = real(*args, **kwargs)
        change(result)
        return result

    monkeypatch.setattr(module, name, spoiled)


def _refused(args) -> str:
    """The one-line message of a command that must end with exit 1."""
    r = runner.invoke(app, args)
    assert r.exit_code == 1, r.output
    return _one_line(r)


def test_the_checker_names_table_column_row_and_key():
    cols = {"t [s]": np.array([0.0, 0.5, 1.0]), "p1 [MPa]": np.array([0.0, 2.0, 3.0]),
            "phase": np.array(["rest", "moving", "moving"]), "n": np.array([1, 2, 3])}
    check_table("simulation", cols)  # text and integers are finite
    cols["p1 [MPa]"][2] = -np.inf
    with pytest.raises(ModelError) as e:
        check_table("simulation", cols)
    assert ("table 'simulation': column 'p1 [MPa]' is -inf at row 2 (t [s] = 1.0)"
            in str(e.value))
    with pytest.raises(ModelError, match=r"column 'q' is nan at row 1, element \(0,\)"):
        check_table("t", {"q": np.array([[1.0, 2.0], [np.nan, 3.0]])}, key="")
    # a value left undefined on purpose (None, shown "—") is no number; a NaN among
    # objects is one
    check_table("t", {"σ": np.array([None, None], dtype=object)})
    with pytest.raises(ModelError, match="column 'σ' is nan at row 1"):
        check_table("t", {"σ": np.array([1.0, float("nan")], dtype=object)})


def test_cycles_of_a_pump_whose_dynamic_forces_vanish_is_refused(tmp_path):
    """η_v = 1e-9: the cycle takes 7.4e9 s, the dynamic forces are 0 and the ratios
    of conclusion 3 were 0/0 (``nan`` in cycles_conclusions.csv and the HTML, exit 0)."""
    text = io.bundled("crane_lv184a").read_text(encoding="utf-8")
    assert text.count("eta_volumetric = ") == 1
    path = tmp_path / "crane.toml"
    path.write_text(re.sub(r"eta_volumetric = \S+", "eta_volumetric = 1e-9", text),
                    encoding="utf-8")
    out = tmp_path / "out"
    r = runner.invoke(app, ["cycles", str(path), "-o", str(out)])
    msg = _one_line(r)
    if r.exit_code == 1 and "drive[" in msg:  # refused at load: the root of it
        assert "eta_volumetric" in msg
    else:
        assert r.exit_code == 1, r.output
        assert "Fd1_max, Fd2_max with the flow divider are 0 N" in msg, msg
        assert "eta_volumetric" in msg
    assert _written(out) == []


def test_cycles_refuses_a_table_value_that_is_not_finite(tmp_path, monkeypatch):
    import assur.views.report.cycles as cycles

    def change(df):
        df.loc[3, "F2_max"] = np.inf

    _spoil(monkeypatch, cycles, "sweep", change)
    out = tmp_path / "out"
    msg = _refused(["cycles", str(io.bundled("crane_lv184a")), "-o", str(out)])
    assert "table 'cycles (scenarios)': column 'F2_max' is inf at row 3 (scenario = " in msg
    assert _written(out) == []


def test_simulate_refuses_a_time_series_that_is_not_finite(tmp_path, monkeypatch):
    import assur.dynamics as dynamics

    def change(result):
        result.p1[4] = np.nan

    _spoil(monkeypatch, dynamics, "simulate_model", change)
    out = tmp_path / "out"
    msg = _refused(["simulate", str(io.bundled("adapter_lab6")), "--duration", "0.1", "-o",
                    str(out)])
    assert "table 'simulation.csv': column 'p1 [MPa]' is nan at row 4 (t [s] = " in msg, msg
    assert _written(out) == []


def test_dxf_refuses_a_drawing_that_is_not_finite(tmp_path, monkeypatch):
    import assur.views.cli._page as page

    def change(analysis):
        kin = analysis.kinematics
        kin.x(kin.points[1])[-1] = np.inf  # a view of the result's buffer

    _spoil(monkeypatch, page, "_assemble", change)
    out = tmp_path / "hitch.dxf"
    msg = _refused(["dxf", str(io.bundled("hitch_003")), "-o", str(out)])
    assert re.search(r"column 'X34' is inf at row 1 \(S = 0\.67", msg), msg
    assert not out.exists()


def test_fit_refuses_a_parameter_that_is_not_finite(tmp_path, monkeypatch):
    import assur.io
    import assur.synthesis.fitting as fitting

    monkeypatch.setattr(assur.io, "read_targets", lambda table, mech: [])
    monkeypatch.setattr(fitting, "fit_parameters", lambda *a, **k: SimpleNamespace(
        params={"L4": 0.66, "L5": float("nan")}, outliers=[], max_residual=lambda: 0.0))
    r = runner.invoke(app, ["fit", str(io.bundled("hitch_003")), str(tmp_path / "t.csv"),
                            "--fit", "L4=0.5:0.8", "--fit", "L5=0.4:0.6"])
    assert r.exit_code == 1, r.output
    assert "table 'fitted parameters [SI]': column 'L5' is nan" in _one_line(r), r.output
    assert not _NOT_FINITE.search(r.output.split("error:")[0]), r.output


@pytest.mark.slow
def test_optimize_refuses_a_best_design_that_is_not_finite(tmp_path, monkeypatch):
    import assur.views.cli._synthesis as synthesis

    def change(found):
        found[0].x[1] = np.inf  # (result, executor, seconds): the best design

    _spoil(monkeypatch, synthesis, "_search", change)
    out = tmp_path / "out"
    msg = _refused(["optimize", str(io.bundled("hitch_003_design")), "--popsize", "2",
                    "--maxiter", "1", "--positions", "3", "--no-polish", "-o", str(out)])
    assert re.search(r"table 'hitch_003_design_best\.toml \(best design\) \[SI\]': column "
                     r"'\w+' is inf", msg), msg
    assert _written(out) == []


def test_tolerance_refuses_a_table_value_that_is_not_finite(tmp_path, monkeypatch):
    import assur.synthesis.tolerance as tolerance

    def change(result):
        result.nominal[2, 0] = np.inf  # the nominal machine's first output at position 2

    _spoil(monkeypatch, tolerance, "monte_carlo", change)
    out = tmp_path / "out"
    msg = _refused(["tolerance", str(io.bundled("hitch_003_tolerances")), "--samples", "20",
                    "-o", str(out)])
    assert re.search(r"table 'tolerance_worst': column 'nominal' is inf at row 0 \(output = "
                     r"'p\(ГЦ\)", msg), msg
    assert _written(out) == []


@pytest.mark.parametrize("seed, assembling", [(0, 0), (1, 1)])
def test_tolerance_with_no_or_one_machine_that_assembles(tmp_path, seed, assembling):
    """±5 m on the frame pivot X05: of two hitches drawn none (seed 0) or one (seed 1)
    assembles. None: one message saying how many and why (exit 1), nothing written;
    one: every file written without a NaN, σ (MC) "—" on the terminal."""
    from assur.synthesis.tolerance import monte_carlo

    path = tmp_path / "wide.toml"
    path.write_text(f'extends = "{io.bundled("hitch_003").as_posix()}"\n\n[model]\n'
                    f'name = "wide"\n\n[tolerances]\nX05 = {{ pm = "5000 mm", dist = '
                    f'"uniform" }}\n', encoding="utf-8")
    model = io.load(path)
    drawn = monte_carlo(model, None, model.tolerances, samples=2, seed=seed)
    assert int(drawn.assembled.sum()) == assembling  # the case this test is about
    out = tmp_path / "out"
    r = runner.invoke(app, ["tolerance", str(path), "--samples", "2", "--seed", str(seed),
                            "-o", str(out)])
    msg = _one_line(r)
    if assembling == 0:
        assert r.exit_code == 1, r.output
        assert "none of the 2 machines drawn assembles" in msg and "(machine 0: " in msg
        assert _written(out) == []
        return
    assert r.exit_code == 0, r.output
    assert "Traceback" not in r.output and not _NOT_FINITE.search(r.output), r.output
    assert "—" in r.output
    files = _written(out)
    assert {"tolerance.html", "tolerance.xlsx", "tolerance_worst.csv",
            "tolerance_positions.csv"} <= set(files)
    for name in files:
        if name.endswith((".csv", ".html")):
            text = re.sub(r"data:[^'\"]*", "", (out / name).read_text(encoding="utf-8"))
            assert not _NOT_FINITE.search(text), name
