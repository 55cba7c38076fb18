"""Dynamics figures (:mod:`assur.views.report.dynamics`): every figure in both languages
from the bundled cleaning example, angles in degrees, one design at a time."""

import numpy as np
import pytest

from assur import io
from assur.dynamics.balancing import CounterMass, balance
from assur.dynamics.crank import crank_dynamics
from assur.views.report.dynamics import DYNAMICS_FIGURES, figures
from assur.views.report.figures import save


@pytest.fixture(scope="module")
def results():
    model = io.load(io.bundled("cleaning_lab3"))
    kin = model.mechanism.solve(model.range)
    dyn = crank_dynamics(kin, qdot=-30.0)
    fw = dyn.flywheel(delta=0.05)
    b = balance(kin, [CounterMass("3", (0.0, 30.0), (-0.3, 0.3), (-0.1, 0.1))], maxiter=30)
    return dyn, fw, b


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_figure_in_both_languages(results, lang, tmp_path):
    dyn, fw, b = results
    figs = figures(dyn, lang, flywheel=fw, balancing=b)
    assert tuple(figs) == DYNAMICS_FIGURES
    texts = " ".join(t.get_text() for f in figs.values() for ax in f.axes
                     for t in [ax.title, ax.xaxis.label, ax.yaxis.label])
    if lang == "ru":
        assert "угол кривошипа" in texts and "мм" in texts
    else:
        assert "crank angle" in texts and "[deg]" in texts
    for name, fig in figs.items():
        assert save(fig, tmp_path / f"{name}.png").stat().st_size > 1000
    # the crank-angle axes run over [0°, 360°), sorted
    x = figs["reduced_moment"].axes[0].lines[0].get_xdata()
    assert x.min() >= 0 and x.max() < 360 and np.all(np.diff(x) >= 0)
    # the centre-of-mass path is drawn about its mean, in millimetres
    line = figs["centre_of_mass"].axes[0].lines[0]
    assert np.ptp(line.get_xdata()) == pytest.approx(2e3 * float(dyn.centre.amplitude_x))


def test_figures_without_flywheel_or_balancing(results):
    dyn, _, _ = results
    figs = figures(dyn)
    assert "energy_mass" not in figs and len(figs["centre_of_mass"].axes[0].lines) == 2
    with pytest.raises(ValueError, match="lang must be one of"):
        figures(dyn, "de")
