"""Inline displays in notebooks (:mod:`assur.views.notebook`; issue 13): the
``_repr_html_`` of mechanisms, results, analyses and model files, in both languages,
without importing matplotlib."""

import numpy as np

from assur import examples
from assur import io as aio
from assur.io import bundled


def test_repr_html_of_mechanism_result_and_model():
    m = examples.hitch_003()
    h = m._repr_html_()
    assert "RRR" in h or "dyad" in h
    assert "L56 = 1.035 m" in h
    a = m.analyze(np.linspace(0.42, 0.67, 4))
    h = a._repr_html_()
    assert h.count("<svg") == 1 and 'id="pt-56"' in h and "Table 4.1" in h
    from assur.views.notebook import analysis_html
    ru = analysis_html(a, "ru")   # the word "table" in the report's language too
    assert "Таблица 4.1" in ru and "Table 4.1" not in ru
    k = m.solve(np.linspace(0.42, 0.67, 4))
    assert "<svg" in k._repr_html_()
    h = aio.load(bundled("hitch_003"))._repr_html_()
    assert "<svg" in h and "Table 6.1" in h
    # a model that cannot assemble shows the message instead of the drawing
    h = aio.load(bundled("header_000"))._repr_html_()
    assert "<svg" not in h and "cannot close" in h



def test_display_does_not_import_matplotlib():
    from tests.helpers import python_output
    code = ("import sys, numpy as np; from assur import examples; "
            "examples.hitch_003().analyze(np.linspace(0.42, 0.67, 3))._repr_html_(); "
            "print('matplotlib' in sys.modules)")
    assert python_output(code) == "False"

