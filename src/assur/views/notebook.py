"""How a mechanism, a result and a model show themselves in a notebook (``_repr_html_``).

Jupyter calls ``_repr_html_`` on the last value of a cell, as it does for pandas
and matplotlib objects. :class:`assur.Mechanism`, :class:`assur.core.kinematics.Kinematics`,
:class:`assur.analysis.Analysis` and :class:`assur.io.Model` define it by calling
the functions here, which build plain HTML: the model summary (groups, links,
parameters), the drawing as inline SVG (:mod:`assur.views.svg`, no matplotlib) and,
for an analysis, the seed-like tables (:func:`assur.views.report.tables.seed_tables`).
Nothing here computes anything a result does not already hold, except that a
:class:`~assur.io.Model` is analyzed over its file's range to be shown; a model
that cannot assemble shows its error message instead of the drawing.

Examples
--------
>>> import numpy as np
>>> from assur import examples
>>> html = examples.hitch_003().analyze(np.linspace(0.42, 0.67, 4))._repr_html_()
>>> "<svg" in html and "Table 4.1" in html
True
"""

from __future__ import annotations

from html import escape

import numpy as np

__all__ = ["mechanism_html", "kinematics_html", "analysis_html", "model_html"]

#: rows of a table shown inline before it is cut (the rest is in the files)
MAX_ROWS = 40


def _cell(v) -> str:
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    v = float(v)
    if not np.isfinite(v):
        return "" if np.isnan(v) else ("∞" if v > 0 else "−∞")
    if 1e3 <= abs(v) < 1e10:
        return f"{v:.0f}"
    return f"{v:.5g}"


def _summary(mech) -> str:
    rows = "".join(f"<tr><td>{escape(g.name)}</td><td>{escape(type(g).type_name)}</td>"
                   f"<td>{escape(', '.join(map(str, g.inputs())))}</td>"
                   f"<td>{escape(', '.join(map(str, g.outputs())))}</td></tr>"
                   for g in mech.groups)
    links = ", ".join(f"{escape(str(l.name))} ({escape(l.tail)}–{escape(l.head)})"
                      for l in mech.links)
    params = []
    for k, v in mech.params.items():
        u = mech.units.get(k)
        a = np.asarray(v, dtype=float)
        if a.size != 1:
            params.append(f"{escape(k)} = array{a.shape}")
            continue
        x = float(a.ravel()[0]) / (u.scale if u is not None else 1.0)
        unit = f" {escape(u.text)}" if u is not None and u.text != "-" else ""
        params.append(f"{escape(k)} = {x:.6g}{unit}")
    return (f"<p><b>{escape(str(mech.title))}</b> — <code>{escape(mech.name)}</code>, "
            f"coordinates {escape(', '.join(mech.coordinates))}</p>"
            f"<table><tr><th>group</th><th>type</th><th>from points</th><th>new points</th>"
            f"</tr>{rows}</table><p><b>links</b>: {links}</p>"
            f"<p><b>parameters</b>: {'; '.join(params)}</p>")


def mechanism_html(mech) -> str:
    """The model summary of a :class:`~assur.Mechanism` (it has no positions yet).

    Examples
    --------
    >>> import re
    >>> from assur import examples
    >>> from assur.views.notebook import mechanism_html
    >>> html = mechanism_html(examples.hitch_003())
    >>> re.findall(r"<tr><td>([^<]*)</td><td>dyad</td>", html)   # the RRR dyads
    ['II (4,5)', 'III (6,7)']
    >>> "<svg" in html                       # no positions: no drawing
    False
    """
    return f"<div class='assur'>{_summary(mech)}</div>"


def _drawing(kin) -> str:
    from .geometry import geometry
    from .svg import svg
    if len(kin.shape) != 1:
        return "<p>(a batch of designs: draw one with <code>geometry(kin, design=…)</code>)</p>"
    return svg(geometry(kin))


def kinematics_html(kin) -> str:
    """Summary, the drawing at the first position (the last as an outline) and the
    positions' table (:meth:`Kinematics.to_frame`, cut at :data:`MAX_ROWS` rows).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.notebook import kinematics_html
    >>> kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 4))   # S [m]
    >>> html = kinematics_html(kin)
    >>> html.count("<svg"), "<th>phi2</th>" in html   # the drawing, the table's columns
    (1, True)
    """
    parts = [_summary(kin.mechanism), _drawing(kin)]
    if len(kin.shape) == 1:
        frame = kin.to_frame()
        parts.append(frame.head(MAX_ROWS).to_html(float_format=_cell, border=0))
    return f"<div class='assur'>{''.join(parts)}</div>"


def _tables_html(tables, lang="en") -> str:
    from .report.labels import t as label
    word = label("table", lang)
    out = []
    for t in tables:
        n = len(t)
        head = "".join(f"<th>{escape(c.symbol)} [{escape(c.unit)}]</th>" for c in t.columns)
        body = "".join("<tr>" + "".join(f"<td>{_cell(np.atleast_1d(c.values)[i])}</td>"
                                        for c in t.columns) + "</tr>"
                       for i in range(min(n, MAX_ROWS)))
        more = f"<p>… {n - MAX_ROWS} more rows</p>" if n > MAX_ROWS else ""
        out.append(f"<h4>{word} {escape(t.label)}. {escape(t.title(lang))}</h4>"
                   f"<table><tr>{head}</tr>{body}</table>{more}")
    return "".join(out)


def analysis_html(analysis, lang: str = "en") -> str:
    """Summary, drawing and the seed-like tables of an :class:`~assur.analysis.Analysis`.

    Examples
    --------
    >>> import re
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.notebook import analysis_html
    >>> analysis = examples.hitch_003().analyze(np.linspace(0.42, 0.67, 4))   # S [m]
    >>> heads = re.findall(r"<h4>([^<]*)</h4>", analysis_html(analysis))
    >>> heads[0], len(heads)                 # the seed's tables and the IC check
    ('Table 2.1. Geometric analysis: link angles', 7)
    >>> "Результаты геометрического анализа" in analysis_html(analysis, lang="ru")
    True
    """
    return f"<div class='assur'>{_analysis_parts(analysis, lang)}</div>"


def _analysis_parts(analysis, lang) -> str:
    from .report.tables import seed_tables
    kin = analysis.kinematics
    parts = [_summary(analysis.mechanism), _drawing(kin)]
    if len(kin.shape) == 1:
        parts.append(_tables_html(seed_tables(analysis, lang=lang), lang))
    return "".join(parts)


def model_html(model, lang: str = "en") -> str:
    """A loaded model file: its solved conditions and its analysis over the file's
    range, or the error that stops it.

    Examples
    --------
    >>> import re
    >>> from assur import io
    >>> from assur.views.notebook import model_html
    >>> html = model_html(io.load(io.bundled("hitch_003")))
    >>> re.findall(r"<li>([^<]*)</li>", html)    # the seed's Find blocks [m]
    ['L4 = 0.661283167 (SI)', 'Sp = 0.46935694 (SI)', 'L7 = 0.752169525 (SI)']
    >>> html = model_html(io.load(io.bundled("header_000")))   # seed 000: cannot assemble
    >>> print(re.search(r"<pre[^>]*>(.*)</pre>", html).group(1))  # doctest: +ELLIPSIS
    rigid point &#x27;arm 46&#x27; (link 3) fails at position 0 (S = 0.65): ... by 4.66 mm; ...
    """
    from ..errors import AssemblyError, ModelError, SingularPositionError
    solved = "".join(f"<li>{escape(s.condition.unknown)} = {float(s.value):.9g} (SI)</li>"
                     for s in model.solved)
    head = (f"<p>model file <code>{escape(str(model.source or '<string>'))}</code>, "
            f"{len(model.range)} positions</p>" + (f"<ul>{solved}</ul>" if solved else ""))
    try:
        analysis = model.analyze()
    except (AssemblyError, ModelError, SingularPositionError) as e:
        return (f"<div class='assur'>{head}{_summary(model.mechanism)}"
                f"<pre style='color:#8a1c0c'>{escape(str(e))}</pre></div>")
    return f"<div class='assur'>{head}{_analysis_parts(analysis, lang)}</div>"
