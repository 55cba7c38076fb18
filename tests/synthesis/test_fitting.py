"""assur.synthesis.fitting: parameters fitted to a table, robust to a misprint (issue 10)."""

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.synthesis.fitting import Target, fit_parameters
from tests.helpers.mechanisms import LIFT

DEG = np.pi / 180


@pytest.fixture(scope="module")
def lift():
    return io.loads(LIFT, name="lift.toml").mechanism


def table(mech, q, **params):
    """φ5 [°] and φ3' [rad/m] printed to 3 decimals, as a seed would."""
    kin = mech.with_params(**params).solve(q)
    return np.round(np.degrees(kin.phi("5")), 3), np.round(kin.dphi("3"), 3)


def test_known_dimensions_are_recovered_and_a_misprint_is_flagged(lift):
    q = np.linspace(0.43, 0.66, 8)
    phi5, dphi3 = table(lift, q, L4=0.655, L3=0.205)
    phi5[3] += 10.0                                        # a digit slip in the "seed"
    fit = fit_parameters(lift, {"L4": (0.5, 0.8), "L3": (0.15, 0.25)},
                         [Target("phi5", "phi(5)", q, phi5, scale=DEG, period=360),
                          Target("dphi3", "dphi(3)", q, dphi3)], screen=256, starts=4)
    assert fit.params["L4"] == pytest.approx(0.655, abs=2e-5)
    assert fit.params["L3"] == pytest.approx(0.205, abs=2e-5)
    assert [(t, p) for t, p, *_ in fit.outliers] == [("phi5", q[3])]
    printed, fitted = fit.outliers[0][2:]
    assert fitted == pytest.approx(printed - 10.0, abs=1e-3)
    # the rest within one unit of the last printed digit (2 tolerances of half a unit)
    assert fit.max_residual() <= 2.0


def test_the_plain_least_squares_would_be_dragged_by_the_misprint(lift):
    q = np.linspace(0.43, 0.66, 8)
    phi5, dphi3 = table(lift, q, L4=0.655, L3=0.205)
    phi5[3] += 10.0
    kw = dict(screen=256, starts=4)
    targets = [Target("phi5", "phi(5)", q, phi5, scale=DEG, period=360),
               Target("dphi3", "dphi(3)", q, dphi3)]
    robust = fit_parameters(lift, {"L4": (0.5, 0.8), "L3": (0.15, 0.25)}, targets, **kw)
    plain = fit_parameters(lift, {"L4": (0.5, 0.8), "L3": (0.15, 0.25)}, targets,
                           loss="linear", **kw)
    err = lambda f: abs(f.params["L4"] - 0.655)   # noqa: E731
    assert err(plain) > 100 * err(robust)


def test_a_fit_is_reproducible(lift):
    q = np.linspace(0.43, 0.66, 5)
    phi5, _ = table(lift, q, L4=0.62)
    t = [Target("phi5", "phi(5)", q, phi5, scale=DEG)]
    a = fit_parameters(lift, {"L4": (0.5, 0.8)}, t, screen=64, starts=2)
    b = fit_parameters(lift, {"L4": (0.5, 0.8)}, t, screen=64, starts=2)
    assert a.params == b.params


def test_inputs_are_checked(lift):
    q = [0.5, 0.6]
    with pytest.raises(ModelError, match="one value per position"):
        Target("x", "phi(5)", q, [1.0])
    with pytest.raises(ModelError, match="tolerance and scale"):
        Target("x", "phi(5)", q, [1.0, 2.0], tolerance=0)
    t = Target("x", "phi(5)", q, [1.0, 2.0])
    with pytest.raises(ModelError, match="unknown parameter"):
        fit_parameters(lift, {"L9": (0.1, 0.2)}, [t])
    with pytest.raises(ModelError, match="low < high"):
        fit_parameters(lift, {"L4": (0.8, 0.5)}, [t])
    with pytest.raises(ModelError, match="assembles"):
        fit_parameters(lift, {"L4": (5.0, 6.0)}, [t], screen=16)


# ---- a printed table from a file, and `assur fit` ------------------------------------
T51 = """S [m],phi(5) [deg],dphi(3) [1/m],dphi(5) [1/m],dphi(5)/dphi(3) [-]
0.35,43.665,19.413,40,2.06
0.37,74.59,13.037,21.199,1.626
0.39,96.732,11.258,18.123,1.61
0.41,117.051,10.619,17.613,1.659
0.43,137.623,10.56,18.511,1.753
0.45,160.025,10.975,20.873,1.902
0.47,186.316,11.971,25.516,2.135
0.49,220.154,14.061,24.552,2.457
0.51,268.384,19.591,50.584,2.582
"""   # seed 001 table 5.1 (φ5, φ3', φ5', U53), as printed


def test_a_printed_table_keeps_each_values_precision(tmp_path):
    from assur import examples
    p = tmp_path / "t51.csv"
    p.write_text(T51.replace("40,", "40.0,", 1), encoding="utf-8")
    t = {x.name: x for x in io.read_targets(p, examples.spout_lab5())}
    assert set(t) == {"phi(5)", "dphi(3)", "dphi(5)", "dphi(5)/dphi(3)"}
    assert t["phi(5)"].period == 360.0 and t["phi(5)"].scale == pytest.approx(DEG)
    assert t["dphi(5)"].tolerance[0] == pytest.approx(0.05)     # "40.0"
    assert t["dphi(5)"].tolerance[1] == pytest.approx(0.0005)   # "21.199"
    assert t["dphi(5)/dphi(3)"].tolerance[2] == pytest.approx(0.005)  # "1.61"


@pytest.mark.parametrize("text,message", [
    ("S,phi(5) [deg]\n0.35,1\n", "expected a header"),
    ("X [m],phi(5) [deg]\n0.35,1\n", "first column must be the coordinate"),
    ("S [m],phi(9) [deg]\n0.35,1\n", "unknown link '9'"),
    ("S [m],phi(5) [furlongs per wok]\n0.35,1\n", "cannot read the unit"),
    ("S [m],phi(5) [deg]\n0.35,abc\n", "row 2, column 2: expected a number"),
])
def test_a_bad_table_is_located(tmp_path, text, message):
    from assur import examples
    p = tmp_path / "bad.csv"
    p.write_text(text, encoding="utf-8")
    with pytest.raises(ModelError, match=message):
        io.read_targets(p, examples.spout_lab5())


def test_assur_fit_on_the_command_line(tmp_path):
    from typer.testing import CliRunner

    from assur.views.cli import app
    p = tmp_path / "t51.csv"
    p.write_text(T51, encoding="utf-8")
    r = CliRunner().invoke(app, ["fit", str(io.bundled("spout_lab5")), str(p),
                                 "--fit", "L13=0.3:0.6", "--fit", "L3=0.05:0.2",
                                 "--screen", "64", "--starts", "2", "--outlier", "4"])
    assert r.exit_code == 0, r.output
    assert "432.89" in r.output and "94.999" in r.output   # L13, L3 [mm], the file's unit
    assert "24.552" in r.output and "34.55" in r.output    # the slip, and what fits
    bad = CliRunner().invoke(app, ["fit", str(io.bundled("spout_lab5")), str(p),
                                   "--fit", "L13=a:b"])
    assert bad.exit_code == 1 and "NAME=LOW:HIGH" in bad.output


def test_the_fit_jacobian_is_exact():
    """The refinement's Jacobian comes from the dual numbers (not differences): it
    equals central differences of the residuals, and is None for ddphi (second
    analogs are not carried; the fit differences then)."""
    from assur import examples
    from assur.synthesis.fitting import _jacobian, _residuals
    m = examples.hitch_003()
    S = np.array([0.42, 0.47, 0.52, 0.60])
    targets = [Target("phi6", "phi(6)", S, [88.458, 90.028, 92.817, 99.0], scale=np.pi / 180),
               Target("U", "dphi(6)/dphi(3)", S, [1.0, 1.0, 1.0, 1.0], tolerance=0.01),
               Target("y", "Y(56) + 0.1*X(S6)", S, [0.2, 0.3, 0.5, 0.8])]
    names = ["L7", "L6", "X07"]
    x = np.array([m.params[n] for n in names], dtype=float)
    J = _jacobian(m, names, x, targets, S)
    h = 1e-6
    fd = np.stack([(_residuals(m, names, (x + h * e)[None], targets, S)[0][0]
                    - _residuals(m, names, (x - h * e)[None], targets, S)[0][0]) / (2 * h)
                   for e in np.eye(len(names))], axis=1)
    np.testing.assert_allclose(J, fd, rtol=1e-5, atol=1e-6 * np.abs(fd).max())
    assert _jacobian(m, names, x, [Target("a", "ddphi(3)", S, [0.0] * 4)], S) is None
