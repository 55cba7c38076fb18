"""Figures on an Agg canvas and their files: what every figure of the report is
drawn on (no pyplot, no GUI, no global state)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.layout_engine import LayoutEngine

__all__ = ["FitLayout", "new_figure", "figure_legend", "titled_axes", "plain_texts", "save", "to_png_bytes"]


class FitLayout(LayoutEngine):
    """The layout of a figure with one plot area — an axes and its twins — and the
    legends placed by :func:`figure_legend` at its right or foot: the decorations
    (tick labels, axis labels, title, legends) measured once and the plot area made
    as large as they leave room for. Any other figure (several plot areas, a
    suptitle, colour bars) is given matplotlib's constrained layout.

    The constrained layout measures every decoration of every axes twice, each time
    making every tick: a third of a single-plot figure's drawing, for margins this
    engine finds in one measurement (padded by ``pad`` inches, as the constrained
    layout's ``w_pad``/``h_pad``).

    Examples
    --------
    >>> from assur.views.report._canvas import figure_legend, new_figure, to_png_bytes
    >>> fig = new_figure(6.4, 4.0)
    >>> ax = fig.add_subplot()
    >>> for k in range(8):
    ...     _ = ax.plot([0, 1], [k, k + 1], label=f"curve {k}")
    >>> _ = ax.set_ylabel("a rather long axis label [kN]")
    >>> leg = figure_legend(fig, "right", fontsize="small")
    >>> png = to_png_bytes(fig, dpi=50)
    >>> drawn, area, beside = ax.get_tightbbox(), ax.get_window_extent(), leg.get_window_extent()
    >>> bool(0 < drawn.x0 < 0.1 * fig.bbox.width)   # the axis label in, near the edge
    True
    >>> bool(area.x1 < beside.x0 < beside.x1 < fig.bbox.width)  # the legend beside the plot
    True
    """

    _adjust_compatible = True
    _colorbar_gridspec = True

    def __init__(self, pad=4 / 72, **kwargs):
        super().__init__(**kwargs)
        self.pad = float(pad)
        #: the figure legends and their sides, ``(legend, "right" | "bottom")``
        self.legends: list = []

    def execute(self, fig):
        from matplotlib.layout_engine import ConstrainedLayoutEngine
        from matplotlib.transforms import Bbox

        axes = fig.axes
        areas = {tuple(np.round(ax.get_position(original=True).bounds, 9)) for ax in axes}
        if len(areas) != 1 or fig.get_suptitle() or fig.texts:
            return ConstrainedLayoutEngine().execute(fig)
        renderer = _renderer(fig)
        W, H = fig.bbox.width, fig.bbox.height
        pad = self.pad * fig.dpi
        boxes = [b for b in (ax.get_tightbbox(renderer) for ax in axes) if b is not None]
        decorated = Bbox.union(boxes)
        area = axes[0].get_window_extent(renderer)
        right = bottom = 0.0
        for legend, side in self.legends:
            box = legend.get_window_extent(renderer)
            if side == "right":
                right = max(right, box.width + pad)
            else:
                bottom = max(bottom, box.height + pad)
        x0 = pad + area.x0 - decorated.x0
        x1 = W - pad - right - (decorated.x1 - area.x1)
        y0 = pad + bottom + area.y0 - decorated.y0
        y1 = H - pad - (decorated.y1 - area.y1)
        # labels too long for the figure: the plot keeps a fifth of it
        x1, y1 = max(x1, x0 + 0.2 * W), max(y1, y0 + 0.2 * H)
        for ax in axes:
            ax.set_position([x0 / W, y0 / H, (x1 - x0) / W, (y1 - y0) / H])


def _renderer(fig):
    """The figure's Agg renderer (or a new one of its size while another canvas prints it)."""
    if hasattr(fig.canvas, "get_renderer"):
        return fig.canvas.get_renderer()
    from matplotlib.backends.backend_agg import RendererAgg
    return RendererAgg(int(fig.bbox.width), int(fig.bbox.height), fig.dpi)


def new_figure(width=6.4, height=4.0) -> Figure:
    """An empty figure on an Agg canvas laid out by :class:`FitLayout` (a figure of
    several plot areas by matplotlib's constrained layout)."""
    fig = Figure(figsize=(width, height), layout=FitLayout())
    FigureCanvasAgg(fig)
    return fig


def figure_legend(fig, side="right", **kwargs):
    """A legend of the figure's curves at its ``side`` (``"right"``: at the top of the
    right margin; ``"bottom"``: centred at the foot, ``ncols`` as given), outside the
    plot area: the figure's layout leaves it room."""
    engine = fig.get_layout_engine()
    if isinstance(engine, FitLayout):
        legend = fig.legend(loc="upper right" if side == "right" else "lower center", **kwargs)
        engine.legends.append((legend, side))
        return legend
    return fig.legend(loc="outside right upper" if side == "right" else "outside lower center",
                      **kwargs)


def titled_axes(fig, title, xlabel, ylabel):
    """A new subplot of ``fig`` with its title, axis labels and a light grid."""
    ax = fig.add_subplot()
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.35)
    return ax


_FORMATS = ("png", "svg")


def _texts(artist):
    """The texts under ``artist``; of an axis only its label and offset (its tick
    labels are numbers, and listing them makes every tick: a third of a figure's time)."""
    from matplotlib.axis import Axis
    from matplotlib.text import Text
    if isinstance(artist, Text):
        yield artist
    if isinstance(artist, Axis):
        yield artist.label
        yield artist.offsetText
        return
    for child in artist.get_children():
        yield from _texts(child)


def plain_texts(fig):
    """Every text of ``fig`` printed as written: no ``$…$`` read as TeX (a model's name
    is shown literally; the labels are plain Unicode,
    :func:`assur.views.report.labels.symbol`)."""
    for text in _texts(fig):
        text.set_parse_math(False)
    return fig


def save(fig, path, dpi=110) -> Path:
    """Write a figure as PNG or SVG, chosen by the file suffix.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import examples
    >>> from assur.views.report.figures import save, stability
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> fig = stability(a)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = save(fig, Path(d) / "fig_stability.svg")
    ...     head = p.read_text(encoding="utf-8")[:200]
    >>> p.name, "<svg" in head
    ('fig_stability.svg', True)
    >>> save(fig, "fig_stability.pdf")
    Traceback (most recent call last):
    ...
    ValueError: the file suffix must be one of: ['.png', '.svg']; got 'fig_stability.pdf'
    """
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in _FORMATS:
        raise ValueError(f"the file suffix must be one of: {['.' + f for f in _FORMATS]}; "
                         f"got {path.name!r}")
    meta = {"Software": None} if fmt == "png" else {"Creator": None}
    plain_texts(fig)
    if fmt == "svg":
        # texts as text (<text>, in the figure's font family): found by a search,
        # copied and edited in a drawing program, and a third faster to write than
        # each glyph as a path
        from matplotlib import rc_context
        with rc_context({"svg.fonttype": "none"}):
            if _laid_out(fig):
                # printed directly: savefig would draw the figure once more first (a
                # pass to lay it out, with nothing to lay out here) — 40 % of an
                # SVG's time
                from matplotlib.backends.backend_svg import FigureCanvasSVG
                canvas = fig.canvas
                try:
                    FigureCanvasSVG(fig).print_svg(path, metadata=meta)
                finally:
                    fig.set_canvas(canvas)
            else:
                fig.savefig(path, format=fmt, dpi=dpi, metadata=meta)
        return path
    fig.savefig(path, format=fmt, dpi=dpi, metadata=meta)
    return path


def _laid_out(fig) -> bool:
    """True if ``fig`` has no layout left to do (no engine, or its places kept:
    ``set_layout_engine("none")`` after a draw)."""
    from matplotlib.layout_engine import PlaceHolderLayoutEngine
    engine = fig.get_layout_engine()
    return engine is None or isinstance(engine, PlaceHolderLayoutEngine)


def to_png_bytes(fig, dpi=110, bbox_inches=None) -> bytes:
    """The figure as PNG bytes (for embedding); ``bbox_inches="tight"`` crops it to
    its drawn parts.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.figures import stability, to_png_bytes
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> fig = stability(a)  # 6.4 × 4.0 in
    >>> png = to_png_bytes(fig, dpi=50)
    >>> png[1:4], int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    (b'PNG', 320, 200)
    """
    buf = io.BytesIO()
    plain_texts(fig)
    if bbox_inches is None and hasattr(fig.canvas, "buffer_rgba"):
        # one draw on the Agg canvas (its layout included) and Pillow's encoder: the
        # same pixels as savefig, which draws the figure twice (a pass to lay it out)
        from PIL import Image

        fig.set_dpi(dpi)
        fig.canvas.draw()
        # opaque (a white figure): RGB, and zlib level 3 — a third faster than the
        # default 6 for files a tenth larger
        rgb = np.asarray(fig.canvas.buffer_rgba())[..., :3]
        Image.fromarray(np.ascontiguousarray(rgb)).save(buf, format="PNG", compress_level=3)
        return buf.getvalue()
    fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": None},
                bbox_inches=bbox_inches)
    return buf.getvalue()
