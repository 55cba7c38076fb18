"""Figures on an Agg canvas and their files: what every figure of the report is
drawn on (no pyplot, no GUI, no global state)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

__all__ = ["new_figure", "titled_axes", "save", "to_png_bytes"]


def new_figure(width=6.4, height=4.0) -> Figure:
    """An empty figure on an Agg canvas with a constrained layout."""
    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def titled_axes(fig, title, xlabel, ylabel):
    """A new subplot of ``fig`` with its title, axis labels and a light grid."""
    ax = fig.add_subplot()
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.35)
    return ax


_FORMATS = ("png", "svg")


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
    fig.savefig(path, format=fmt, dpi=dpi, metadata=meta)
    return path


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
    if bbox_inches is None and hasattr(fig.canvas, "buffer_rgba"):
        # one draw on the Agg canvas (its layout included) and Pillow's encoder: the
        # same pixels as savefig, which draws the figure twice (a pass to lay it out)
        from PIL import Image

        fig.set_dpi(dpi)
        fig.canvas.draw()
        Image.fromarray(np.asarray(fig.canvas.buffer_rgba())).save(buf, format="PNG")
        return buf.getvalue()
    fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": None},
                bbox_inches=bbox_inches)
    return buf.getvalue()
