"""The figure of the standard lift test (ISO 789-2 / SAE J283; :mod:`assur.machines.hitch_lift`):
the vertical force available at the hitch points and on the test frame against the
height of the hitch points over the lift range, with the minima marked."""

from __future__ import annotations

from ._canvas import new_figure
from .labels import check_lang, t, unit
from .numbers import quantity

__all__ = ["lift_test_figure"]


def lift_test_figure(analysis, lang="en", units=None):
    """The lift test's forces against the hitch point's height, in the display units
    (``units``; default: the model file's), or None when the analysis has no lift
    test (:func:`assur.analysis.add_lift_test`).

    Examples
    --------
    >>> from assur import io
    >>> from assur.analysis import add_lift_test
    >>> from assur.views.report.lift import lift_test_figure
    >>> model = io.load(io.bundled("hitch_003"))  # its [lift_test]: point 56 and frame F610
    >>> m = model.mechanism
    >>> a = m.analyze(model.range)
    >>> lift_test_figure(a) is None  # no lift test added
    True
    >>> ax = lift_test_figure(add_lift_test(a, model.lift_test)).axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('y 56 [m]', 'force F [kN]')
    >>> [text.get_text() for text in ax.texts]  # the minima over the lift range [kN]
    ['min 29.83 kN', 'min 28.67 kN']
    """
    from ...core.display import unit_system

    lang = check_lang(lang)
    lt = getattr(analysis, "lift_test", None)
    if lt is None:
        return None
    du = unit_system(analysis.mechanism, units)
    fig = new_figure()
    ax = fig.add_subplot()
    h, f = lt.test.hitch, lt.test.frame
    series = [(lt.hitch_force, t("c_Gtest", lang, h), "o-", (6, 6))]
    if f is not None:
        series.append((lt.frame_force, t("c_Gtest_frame", lang, f), "s--", (6, -14)))
    height = du.value(lt.height, "length")
    for force, label, style, offset in series:
        shown = du.value(force, "force")
        ax.plot(height, shown, style, label=label)
        k = int(shown.argmin())
        ax.annotate(f"min {quantity(force[k], 'force', du, lang)}", (height[k], shown[k]),
                    textcoords="offset points", xytext=offset, fontsize=8)
    ax.set_title(t("tL", lang), fontsize=10)
    ax.set_xlabel(f"{t('y_m', lang)} {h} [{unit(du['length'].text, lang)}]")
    ax.set_ylabel(f"{t('y_force', lang)} [{unit(du['force'].text, lang)}]")
    ax.grid(True, alpha=0.35)
    ax.legend(fontsize=8)
    return fig
