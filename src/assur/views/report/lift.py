"""The figure of the standard lift test (ISO 789-2 / SAE J283; :mod:`assur.machines.hitch_lift`):
the vertical force available at the hitch points and on the test frame against the
height of the hitch points over the lift range, with the minima marked."""

from __future__ import annotations

from ._canvas import new_figure
from .labels import check_lang, t, unit

__all__ = ["lift_test_figure"]


def lift_test_figure(analysis, lang="en"):
    """The lift test's forces [kN] against the hitch point's height [m], or None when
    the analysis has no lift test (:func:`assur.analysis.add_lift_test`).

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
    ('y 56 [m]', '[kN]')
    >>> [text.get_text() for text in ax.texts]  # the minima over the lift range [kN]
    ['min 29.8 kN', 'min 28.7 kN']
    """
    lang = check_lang(lang)
    lt = getattr(analysis, "lift_test", None)
    if lt is None:
        return None
    fig = new_figure()
    ax = fig.add_subplot()
    h, f = lt.test.hitch, lt.test.frame
    series = [(lt.hitch_force, t("c_Gtest", lang, h), "o-", (6, 6))]
    if f is not None:
        series.append((lt.frame_force, t("c_Gtest_frame", lang, f), "s--", (6, -14)))
    for force, label, style, offset in series:
        kn = force / 1e3
        ax.plot(lt.height, kn, style, label=label)
        k = int(kn.argmin())
        ax.annotate(f"min {kn[k]:.3g} {unit('kN', lang)}", (lt.height[k], kn[k]),
                    textcoords="offset points", xytext=offset, fontsize=8)
    ax.set_title(t("tL", lang), fontsize=10)
    ax.set_xlabel(f"{t('y_m', lang)} {h} [{unit('m', lang)}]")
    ax.set_ylabel(f"[{unit('kN', lang)}]")
    ax.grid(True, alpha=0.35)
    ax.legend(fontsize=8)
    return fig
