"""The curves of the report's diagrams against the generalized coordinate: the
abscissa, its order and breaks, and the maps over a grid of two coordinates
(:mod:`assur.views.report.figures`)."""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import MaxNLocator

from ._canvas import figure_legend, new_figure
from .labels import check_lang, t, unit
from .tables import _View, grid_of




#: the most positions whose curves are drawn with a marker at each
MARKED_POSITIONS = 40

#: line styles and markers of a curve that coincides with one drawn before it
_SAME_STYLES = (dict(ls="--", marker="x", markersize=7, lw=1.6),
                dict(ls=":", marker="+", markersize=9, lw=1.6),
                dict(ls="-.", marker="D", markersize=5, markerfacecolor="none", lw=1.4))


def plot_order(x):
    """The positions sorted by the abscissa ``x`` (stable: equal values keep their
    order), shape (n,)."""
    return np.argsort(np.asarray(x), kind="stable")


def wrap_breaks(y, period=360.0):
    """Indices i where a wrapped angle jumps between the sorted positions i and i + 1
    by more than half a ``period`` (a wrap from 360° to 0°, not a motion)."""
    y = np.asarray(y, dtype=float)
    return np.flatnonzero(np.abs(np.diff(y)) > 0.5 * period)


def broken(x, y, breaks):
    """``(x, y)`` as masked arrays with a masked point after each index of ``breaks``:
    matplotlib draws no line across a masked point."""
    if len(breaks) == 0:
        return x, y
    at = np.asarray(breaks) + 1
    xs = np.ma.masked_array(np.insert(np.asarray(x, dtype=float), at, 0.0))
    ys = np.ma.masked_array(np.insert(np.asarray(y, dtype=float), at, 0.0))
    mask = np.zeros(xs.shape, dtype=bool)
    mask[at + np.arange(len(at))] = True
    xs.mask, ys.mask = mask, mask
    return xs, ys


def path_abscissa(columns):
    """Index of the first coordinate that changes strictly monotonically along the
    positions (the abscissa of paired paths), or 0."""
    for k, q in enumerate(columns):
        d = np.diff(np.asarray(q, dtype=float))
        if d.size and (np.all(d > 0) or np.all(d < 0)):
            return k
    return 0


def _grid_layout(fig, nrow, ncol, top, left=0.75, right=0.95, bottom=0.55, wgap=1.2,
                 hgap=0.85):
    """A fixed layout of a grid of map panels (each with its colour bar on the right),
    margins and gaps in inches: the same places as a constrained layout finds for
    these panels, without measuring every tick label of every panel (the bulk of a
    report's time for a machine of two coordinates)."""
    fig.set_layout_engine("none")
    W, H = fig.get_figwidth(), fig.get_figheight()
    aw = (W - left - right - (ncol - 1) * wgap) / ncol
    ah = (H - top - bottom - (nrow - 1) * hgap) / nrow
    # the panels are made after this: the figure's subplot parameters place them
    fig.subplotpars.update(left=left / W, right=1.0 - right / W, bottom=bottom / H,
                           top=1.0 - top / H, wspace=wgap / aw, hspace=hgap / ah)


class _MapAxes:
    """Collects the curves of a figure over two coordinates; :meth:`_Plot.done` draws
    each as a map (heatmap with contours) over the grid. A horizontal reference line
    (a load, F_max, p_max, the 20 % share) becomes a red contour at its level."""

    def __init__(self, title, ylabel, yunit):
        self.title, self.ylabel, self.yunit = title, ylabel, yunit
        self.series, self.levels = [], []

    def axhline(self, y, label=None, **kw):
        self.levels.append((float(y), label))

    def axhspan(self, *a, **kw):
        pass

    def set_ylim(self, *a, **kw):
        pass

    def get_ylim(self):
        return (0.0, 1.0)

    def legend(self, *a, **kw):
        pass


class _Plot:
    """Shared abscissa and labels for one design.

    One coordinate: the curves against it. Two coordinates on a full grid: maps
    (a heatmap with contours per curve, the axes in the coordinates' units). Paired
    paths (the coordinates move together, ``[range] paired = true``): the curves
    against the first coordinate that changes monotonically along the path."""

    def __init__(self, analysis, lang, design, units=None):
        self.lang = check_lang(lang)
        self.v = _View(analysis, design, units=units)
        v = self.v
        #: the unit of each axes' values as given to :meth:`line` (shown in the display units)
        self._units: dict = {}
        self.grid = None
        self.c = v.coords[0]
        if v.k == 2:
            self.grid = grid_of(v.coord_values(v.coords[0]), v.coord_values(v.coords[1]))
        if v.k == 1 or self.grid is None:
            k = 0 if v.k == 1 else path_abscissa([v.coord_values(c) for c in v.coords])
            c = v.coords[k]
            self.x, xu = v.units.convert(v.coord_values(c), v.coord_unit(c))
            self.x = np.asarray(self.x, dtype=float)
            self.xlabel = f"{v.coord_label(c)[lang]} [{unit(xu, lang)}]"
            if v.k > 1:
                others = ", ".join(o for o in v.coords if o != c)
                self.xlabel += "; " + t("paired_axis", lang, others)
            self.c = c
        else:
            self.x = np.arange(v.n)
            self.xlabel = t("position", lang)
        #: the positions in the order drawn (sorted by the abscissa)
        self.order = plot_order(self.x)
        self._drawn: dict = {}

    @property
    def is_map(self) -> bool:
        return self.grid is not None

    def axes(self, title, ylabel, yunit, width=6.4, height=4.0):
        """New axes whose curves are given in ``yunit`` (``"N"``, ``"Pa"``, ``"deg"``…,
        the unit of the values passed to :meth:`line` and :meth:`y`) and shown in the
        display unit of its kind."""
        fig = new_figure(width, height)
        shown = self.v.units.convert(0.0, yunit)[1]
        if self.is_map:
            ax = _MapAxes(title, ylabel, shown)
        else:
            ax = fig.add_subplot()
            ax.set_title(title)
            ax.set_xlabel(self.xlabel)
            ax.set_ylabel(f"{ylabel} [{unit(shown, self.lang)}]")
            ax.grid(True, alpha=0.35)
        self._units[id(ax)] = yunit
        return fig, ax

    def y(self, ax, values):
        """``values`` given in the unit of ``ax`` (:meth:`axes`) in its display unit."""
        shown, _ = self.v.units.convert(values, self._units.get(id(ax), "-"))
        return shown

    def axis_label(self, c):
        v = self.v
        return f"{c} [{unit(v.units.convert(0.0, v.coord_unit(c))[1], self.lang)}]"

    def surface(self, y):
        """Values over the positions as a 2-D array (second coordinate × first)."""
        u1, u2, i1, i2 = self.grid
        z = np.full((len(u2), len(u1)), np.nan)
        z[i2, i1] = np.asarray(y, dtype=float)
        return np.ma.masked_invalid(z)

    def done(self, fig, ax=None):
        """The finished figure: a map figure draws its collected curves here."""
        maps = getattr(fig, "_assur_maps", None) if ax is None else ax
        if not isinstance(maps, _MapAxes):
            return fig
        n = len(maps.series)
        if n == 0:
            return None
        ncol = min(n, 3)
        nrow = -(-n // ncol)
        fig.set_size_inches(4.3 * ncol, 3.5 * nrow + 0.5)
        u1, u2, _, _ = self.grid
        c1, c2 = self.v.coords
        u1 = np.asarray(self.v.units.convert(u1, self.v.coord_unit(c1))[0], dtype=float)
        u2 = np.asarray(self.v.units.convert(u2, self.v.coord_unit(c2))[0], dtype=float)
        yu = unit(maps.yunit, self.lang)
        title = t("f_map", self.lang, maps.title, c1, c2) + f"; {maps.ylabel} [{yu}]"
        labels = list(dict.fromkeys(lab for _, lab in maps.levels if lab))
        if labels:
            title += "; " + ", ".join(labels) + " (- - -)"
        import textwrap
        lines = textwrap.wrap(title, 48 * ncol)
        fig.suptitle("\n".join(lines), fontsize="medium", y=1.0 - 0.1 / fig.get_figheight(),
                     va="top")
        _grid_layout(fig, nrow, ncol, top=0.35 + 0.2 * len(lines))
        first = None
        for k, (label, y) in enumerate(maps.series):
            # the panels share the coordinates' axes: their values and names are
            # printed on the outer panels only (the bottom row, the left column)
            ax = fig.add_subplot(nrow, ncol, k + 1, sharex=first, sharey=first)
            first = first or ax
            z = self.surface(y)
            mesh = ax.pcolormesh(u1, u2, z, shading="nearest", cmap="viridis")
            bar = fig.colorbar(mesh, ax=ax, label=yu)
            bar.locator = MaxNLocator(5)
            lo, hi = float(np.min(z)), float(np.max(z))
            if hi - lo > 1e-12 * max(abs(lo), abs(hi), 1e-300):
                cs = ax.contour(u1, u2, z, levels=6, colors="k", linewidths=0.6)
                ax.clabel(cs, fontsize="x-small", fmt="%.4g")
                for level, _ in maps.levels:
                    if lo < level < hi:
                        ax.contour(u1, u2, z, levels=[level], colors="C3", linewidths=1.6,
                                   linestyles="--")
            ax.set_title(label, fontsize="small")
            row, col = divmod(k, ncol)
            if k + ncol >= n:  # nothing below it: the bottom of its column
                ax.set_xlabel(self.axis_label(c1))
            else:
                ax.tick_params(labelbottom=False)
            if col == 0:
                ax.set_ylabel(self.axis_label(c2))
            else:
                ax.tick_params(labelleft=False)
        if first is not None:
            first.xaxis.set_major_locator(MaxNLocator(5))
            first.yaxis.set_major_locator(MaxNLocator(5))
        return fig

    def line(self, ax, y, label, angle=False, **kw):
        """Draw ``y`` over the positions sorted by the abscissa; an ``angle`` curve [°]
        in the wrapped convention is broken where it wraps; a curve equal to one
        drawn before on these axes gets another style and the label ``this = that``.
        On a map figure the curve is kept and drawn as a map by :meth:`done`."""
        y = np.asarray(self.y(ax, y), dtype=float)
        if isinstance(ax, _MapAxes):
            ax.series.append((label, y))
            return
        drawn = self._drawn.setdefault(id(ax), [])
        same = [lab for yy, lab in drawn if yy.shape == y.shape and np.allclose(
            yy, y, rtol=0.0, atol=1e-9 * max(float(np.max(np.abs(y))) if y.size else 0.0, 1.0))]
        drawn.append((y, label))
        if same:
            kw.update(_SAME_STYLES[(len(same) - 1) % len(_SAME_STYLES)])
            label = f"{label} = {same[0]}"
            kw.setdefault("zorder", 3)
        # a marker at each position where the positions are few (a seed's table of 10),
        # none on a dense curve (a crank turn's 361) but the marks that tell a curve from
        # the one it coincides with, then every n/12-th
        dense = len(self.x) > MARKED_POSITIONS
        if dense and "marker" in kw:
            kw.setdefault("markevery", max(1, len(self.x) // 12))
        kw.setdefault("marker", None if dense else "o")
        kw.setdefault("markersize", 3)
        xs, ys = self.x[self.order], y[self.order]
        breaks = wrap_breaks(ys) if angle and self.v.angles == "wrapped" else []
        xs, ys = broken(xs, ys, breaks)
        ax.plot(xs, ys, label=label, **kw)

    @staticmethod
    def legend(fig, ax, n):
        if isinstance(ax, _MapAxes):
            return
        if n > 5:
            figure_legend(fig, "right", fontsize="small")
        elif n > 0:
            ax.legend(fontsize="small")
