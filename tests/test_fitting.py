"""assur.fitting: parameters fitted to a table, robust to a misprint (issue 10)."""

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.fitting import Target, fit_parameters
from test_columns import LIFT

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
