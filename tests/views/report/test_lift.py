"""The lift test's figure (:mod:`assur.views.report.lift`): its two curves are the
result's forces at the hitch point and on the test frame [kN] against the hitch
point's height [m], their minima annotated; in Russian the same numbers; without a
lift test, no figure."""

import numpy as np
import pytest

from assur import io
from assur.analysis import add_lift_test
from assur.views.report.lift import lift_test_figure


@pytest.fixture(scope="module")
def analysis():
    model = io.load(io.bundled("hitch_003"))
    plain = model.mechanism.analyze(model.range)
    with_test = add_lift_test(model.mechanism.analyze(model.range), model.lift_test)
    return plain, with_test


def test_the_curves_are_the_results_forces(analysis):
    plain, a = analysis
    assert lift_test_figure(plain) is None
    lt = a.lift_test
    for lang in ("en", "ru"):
        ax = lift_test_figure(a, lang).axes[0]
        hitch, frame = ax.lines[:2]
        for line, force in ((hitch, lt.hitch_force), (frame, lt.frame_force)):
            np.testing.assert_allclose(line.get_xdata(), lt.height, rtol=1e-12)
            np.testing.assert_allclose(line.get_ydata(), np.asarray(force) / 1e3, rtol=1e-12)
        texts = [t.get_text() for t in ax.texts]
        want = [np.min(lt.hitch_force) / 1e3, np.min(lt.frame_force) / 1e3]
        assert [float(t.split()[1].replace(",", ".")) for t in texts] == \
            pytest.approx(want, abs=0.05)
