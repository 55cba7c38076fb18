"""A sphinx-gallery image scraper for the figures assur's reports make.

:mod:`assur.views.report` draws on plain :class:`matplotlib.figure.Figure` objects with an
Agg canvas (no pyplot: reports run in servers and threads), which sphinx-gallery's
matplotlib scraper does not see. This scraper looks at the example's variables after
each code block and saves every such figure it has not saved yet — a figure bound
to a name, or held in a list, tuple or dict — in the order they were made. Figures
managed by pyplot are left to the matplotlib scraper.
"""

from __future__ import annotations

from matplotlib.figure import Figure
from sphinx_gallery.scrapers import figure_rst

#: attribute marking a figure already saved
_MARK = "_assur_gallery_saved"


def _figures(value, depth=0):
    if isinstance(value, Figure):
        yield value
    elif depth < 2 and isinstance(value, (list, tuple)):
        for v in value:
            yield from _figures(v, depth + 1)
    elif depth < 2 and isinstance(value, dict):
        for v in value.values():
            yield from _figures(v, depth + 1)


def scrape(block, block_vars, gallery_conf):
    """Save the new report figures of the block; reST that shows them."""
    found = {}
    for name, value in list(block_vars.get("example_globals", {}).items()):
        if name.startswith("_"):
            continue
        for fig in _figures(value):
            manager = getattr(fig.canvas, "manager", None)
            if manager is None and not getattr(fig, _MARK, False):
                found[id(fig)] = fig
    paths = []
    for fig in found.values():  # in the order of the example's names
        setattr(fig, _MARK, True)
        path = next(block_vars["image_path_iterator"])
        fig.savefig(path, dpi=90)
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])
