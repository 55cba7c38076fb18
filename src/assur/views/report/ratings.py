"""The report's figures of the ratings (``[[rating]]``, :mod:`assur.machines.ratings`;
their tables: :mod:`assur.views.report.tables`): one per rating, titled from the
model's rating, in the user's units. The numbers are the rating's own
(:class:`assur.machines.ratings.RatingResult`); nothing is computed here."""

from __future__ import annotations

import numpy as np

from ...texts import localize
from ._canvas import new_figure
from .labels import check_lang, unit

__all__ = ["rating_figures"]


def rating_figures(analysis, lang="en", units=None) -> dict:
    """``{name: Figure}``, one per rating of ``analysis`` (named by its kind,
    :func:`assur.machines.ratings.names_of`): its curves (``y``) over its
    abscissa (``x``), one curve per value of its ``group`` (a load chart: one per boom
    position), in the display units (``units``; default: the model file's).

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.ratings import rating_figures
    >>> figs = rating_figures(io.load(io.bundled("crane_lv184a")).analyze())
    >>> list(figs)
    ['crane_chart']
    >>> ax = figs["crane_chart"].axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('reach of D [m]', 'lifting capacity at D [N]')
    """
    from ...core.display import unit_system
    lang = check_lang(lang)
    du = unit_system(analysis.mechanism, units)
    from ...machines.ratings import names_of
    figs = {}
    ratings = list(getattr(analysis, "ratings", None) or ())
    for r, name in zip(ratings, names_of(ratings)):
        fig = new_figure()
        ax = fig.add_subplot()
        xs = r.get(r.x)
        xv, xu = du.convert(np.asarray(xs.values, float), xs.unit)
        xv = np.asarray(xv, float)
        groups = [None]
        if r.group is not None:
            gv = np.asarray(r[r.group])
            groups = list(dict.fromkeys(gv.tolist()))
            if len(groups) == len(gv):  # a path: the group moves at every row, one curve
                groups = [None]
        styles = ("-", "--", ":", "-.")
        for j, sym in enumerate(r.y):
            ys = r.get(sym)
            yv, yu = du.convert(np.asarray(ys.values, float), ys.unit)
            yv = np.asarray(yv, float)
            for gi, g in enumerate(groups):
                sel = np.ones(len(xv), bool) if g is None else np.asarray(r[r.group]) == g
                label = localize(ys.label, lang)
                if g is not None:  # one curve per value of the group, in the rows' order
                    gs = r.get(r.group)
                    gv, gu = du.convert(float(g), gs.unit)
                    label = f"{label}, {r.group} = {float(gv):.4g} {unit(gu, lang)}"
                # rows whose abscissa repeats (a grid of three coordinates over one of
                # them) are points, not a line through the grid's order
                repeats = len(np.unique(xv[sel])) < int(sel.sum())
                ax.plot(xv[sel], yv[sel], linestyle="none" if repeats else styles[j % len(styles)],
                        marker="o" if repeats else ".", markersize=3 if repeats else 6,
                        color=f"C{gi % 10}" if g is not None else f"C{j}", label=label)
        ax.set_title(r.rating.heading(lang), fontsize=10)
        ax.set_xlabel(f"{localize(xs.label, lang)} [{unit(xu, lang)}]")
        first = r.get(r.y[0])
        ax.set_ylabel(f"{localize(first.label, lang)} "
                      f"[{unit(du.convert(1.0, first.unit)[1], lang)}]")
        ax.grid(True, alpha=0.35)
        if r.y:
            ax.legend(fontsize=8)
        figs[name] = fig
    return figs
