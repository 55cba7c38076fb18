"""The page's plotting module static/plot.js (issue 24) in a real headless Chromium.

``window.AssurPlot.line`` and ``.map`` are called on a bare page holding a 300 px wide box;
the checks read the SVG they draw (tick labels, the curves' path data, the marker, the
tooltip) and drive it with the mouse. The browser is tests/views/conftest.py's.
"""

import math
import re
from pathlib import Path

import pytest

import assur.views.page

pytestmark = pytest.mark.slow

PLOT_JS = (Path(assur.views.page.__file__).parent / "static" / "plot.js").read_text(
    encoding="utf-8")
BOX = "<html><body><div id=box style='width:300px'></div></body></html>"
COMMA = "format: v => String(Number(v.toPrecision(4))).replace('.', ',')"


@pytest.fixture
def page(browser):
    pg = browser.new_page(viewport={"width": 800, "height": 600})
    errors = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.set_content(BOX)
    pg.add_script_tag(content=PLOT_JS)
    yield pg
    pg.close()
    assert not errors, errors


def _make(page, kind, opts):
    """AssurPlot.<kind>(<opts, a JS object literal>) in #box; picks land in window.picked."""
    page.evaluate(f"""() => {{
        window.picked = [];
        const onpick = (...a) => window.picked.push(a);
        window.plot = AssurPlot.{kind}(Object.assign({{onpick}}, {opts}));
        document.getElementById('box').appendChild(window.plot.el);
    }}""")


def _screen(page, x, y):
    """The client position of the viewBox point (x, y)."""
    return page.evaluate("""([x, y]) => {
        const svg = document.querySelector('#box svg');
        const p = new DOMPoint(x, y).matrixTransform(svg.getScreenCTM());
        return [p.x, p.y];
    }""", [x, y])


def _ticks(page, cls, comma=False):
    """[(value, position)] of the tick labels of class cls (position: x or y attribute)."""
    attr = "x" if cls == "xtick" else "y"
    rows = page.evaluate(f"""() => [...document.querySelectorAll('#box .{cls}')]
        .map(t => [t.textContent, Number(t.getAttribute('{attr}'))])""")
    return [(float(t.replace(",", ".") if comma else t), p) for t, p in rows]


def _vertices(d):
    """[(command, x, y)] of a path's M/L data."""
    return [(c, float(x), float(y)) for c, x, y in re.findall(r"([ML])\s*(-?[\d.]+)[ ,](-?[\d.]+)",
                                                               d)]


def _path(page, k=0):
    return page.get_attribute(f"#box path.curve[data-series='{k}']", "d")


def _frame(page):
    return page.evaluate("""() => { const r = document.querySelector('#box .frame');
        return ['x', 'y', 'width', 'height'].map(a => Number(r.getAttribute(a))); }""")


def _is_nice(step):
    mant = step / 10 ** math.floor(math.log10(step) + 1e-9)
    return any(abs(mant - m) < 1e-6 for m in (1, 2, 2.5, 5))


def _check_nice(values, lo, hi, cover):
    assert 4 <= len(values) <= 8, values
    steps = [b - a for a, b in zip(values, values[1:])]
    assert max(steps) - min(steps) < 1e-9 * max(abs(v) for v in values + [1])
    assert _is_nice(steps[0]), values
    if cover:       # the outer ticks enclose the data, less than a step beyond it
        assert values[0] <= lo + 1e-12 and values[-1] >= hi - 1e-12, (values, lo, hi)
        if hi > lo:     # (a constant is padded first)
            assert values[0] > lo - steps[0] and values[-1] < hi + steps[0], (values, lo, hi)
    else:           # the ticks lie inside the range
        assert lo - 1e-12 <= values[0] and values[-1] <= hi + 1e-12, (values, lo, hi)


@pytest.mark.parametrize("lo, hi", [(0.37, 42.1), (-0.003, 0.0071), (1234, 1290), (-5, 0),
                                    (-1, 1), (3, 3), (0, 0)])
def test_tick_labels_are_nice_numbers_covering_the_data_inside_the_box(page, lo, hi):
    ys = [lo + (hi - lo) * k / 10 for k in range(11)]
    _make(page, "line", "{series: [{x: %s, y: %s}], xlabel: 'S1 [mm]', ylabel: 'F [kN]'}"
          % ([2 * k + 0.5 for k in range(11)], ys))
    fx, fy, fw, fh = _frame(page)
    yt, xt = _ticks(page, "ytick"), _ticks(page, "xtick")
    _check_nice([v for v, _ in yt], lo, hi, cover=True)
    _check_nice([v for v, _ in xt], 0.5, 20.5, cover=True)
    for _, y in yt:                       # the label's baseline is 3.5 px below its tick
        assert fy - 0.5 <= y - 3.5 <= fy + fh + 0.5
    for _, x in xt:
        assert fx - 0.5 <= x <= fx + fw + 0.5
    if lo == hi:                          # a constant: padded, the value strictly inside
        assert yt[0][0] < lo < yt[-1][0]
    labels = page.eval_on_selector_all("#box text", "ts => ts.map(t => t.textContent)")
    assert "-0" not in labels


def _y_scale(page):
    """Data units per pixel of the y axis, from two tick labels' values and positions."""
    (v0, p0), (v1, p1) = _ticks(page, "ytick")[:2]
    return (v1 - v0) / (p1 - p0)


@pytest.mark.parametrize("period", [360, None])
def test_a_wrapped_angle_draws_no_line_across_the_wrap(page, period):
    xs = list(range(0, 721, 5))
    ys = [x % 360 for x in xs]
    _make(page, "line", "{series: [{x: %s, y: %s, label: 'β'}], ylabel: 'β [°]', period: %s}"
          % (xs, ys, "null" if period is None else period))
    verts = _vertices(_path(page))
    scale = abs(_y_scale(page))
    jumps = [abs(b[2] - a[2]) * scale for a, b in zip(verts, verts[1:]) if b[0] == "L"]
    if period:
        assert max(jumps) <= period / 2
        assert [c for c, *_ in verts].count("M") == 3      # 0…355, 360…715, 720
        assert len(verts) == len(xs)
    else:                                                    # the same data unwrapped: it would
        assert max(jumps) > 180                              # (the check can fail)


def test_a_missing_value_breaks_the_curve_into_subpaths(page):
    _make(page, "line", "{series: [{x: [0,1,2,3,4,5,6,7,8,9], y: [1,2,3,null,5,6,7,NaN,9,10]},"
          " {x: [0,1,2,3,4,5,6,7,8,9], y: [0,0,0,0,0,0,0,0,0,0], label: 'zero'}]}")
    verts = _vertices(_path(page, 0))
    assert [c for c, *_ in verts] == ["M", "L", "L", "M", "L", "L", "M", "L"]
    assert [c for c, *_ in _vertices(_path(page, 1))].count("M") == 1


def _dot(page, k=0):
    return page.evaluate(f"""() => {{ const d = document.querySelector(
        "#box .marker-dot[data-series='{k}']");
        return [Number(d.getAttribute('cx')), Number(d.getAttribute('cy')),
                d.getAttribute('visibility')]; }}""")


TWO = ("{series: [{x: [0,10,20,30,40,50,60,70,80,90,100], y: [1,4,9,12,17.5,16,11,null,5,3,2],"
       " label: 'run 1'}, {x: [0,10,20,30,40,50,60,70,80,90,100],"
       " y: [2,3,4,5,6,7,8,9,10,11,12], label: 'run 2', dash: true}],"
       " xlabel: 'S1 [mm]', ylabel: 'F [kN]', title: 'Lift', %s}" % COMMA)


def test_the_marker_moves_the_existing_dot_onto_the_data_point(page):
    _make(page, "line", TWO)
    verts = _vertices(_path(page, 1))          # series 1 has no gap: vertex i is point i
    count = page.evaluate("() => document.querySelectorAll('#box *').length")
    page.evaluate("() => { window.dot0 = document.querySelector('#box .marker-dot'); }")
    for i in (0, 4, 9):
        page.evaluate(f"() => plot.marker({i})")
        cx, cy, vis = _dot(page, 1)
        assert vis == "visible"
        assert (cx, cy) == pytest.approx(verts[i][1:], abs=0.01)
        line_x = float(page.get_attribute("#box line.marker", "x1"))
        assert line_x == pytest.approx(cx, abs=0.01)
    page.evaluate("() => plot.marker(7)")      # series 0 has no value at 7: its dot hides
    assert _dot(page, 0)[2] == "hidden" and _dot(page, 1)[2] == "visible"
    # nothing rebuilt: the same elements, moved
    assert page.evaluate("() => document.querySelectorAll('#box *').length") == count
    assert page.evaluate("() => window.dot0 === document.querySelector('#box .marker-dot')")


def test_hover_shows_the_formatted_values_and_a_click_picks_the_nearest_index(page):
    _make(page, "line", TWO)
    assert page.get_attribute("#box .tooltip", "visibility") == "hidden"
    page.evaluate("() => plot.marker(4)")
    cx4, cy4, _ = _dot(page, 0)
    page.mouse.move(*_screen(page, cx4, cy4))
    assert page.get_attribute("#box .tooltip", "visibility") == "visible"
    tip = page.text_content("#box .tooltip")
    assert "17,5" in tip and "S1 [mm]: 40" in tip and "run 1" in tip and "run 2: 6" in tip
    assert float(page.get_attribute("#box .crosshair", "x1")) == pytest.approx(cx4, abs=0.01)

    # a click 70 % of the way from point 6 to point 7 picks 7, at 30 % it picks 6
    page.evaluate("() => plot.marker(6)")
    cx6 = _dot(page, 1)[0]
    page.evaluate("() => plot.marker(7)")
    cx7 = _dot(page, 1)[0]
    fx, fy, fw, fh = _frame(page)
    for frac, want in ((0.7, 7), (0.3, 6)):
        page.mouse.click(*_screen(page, cx6 + frac * (cx7 - cx6), fy + fh / 2))
        assert page.evaluate("() => picked")[-1] == [want]
    page.mouse.move(*_screen(page, cx7, fy + fh / 2))
    assert "—" in page.text_content("#box .tooltip")      # a missing value: a dash
    # at the right edge the tooltip flips to the left of the point, inside the plot
    page.evaluate("() => plot.marker(10)")
    page.mouse.move(*_screen(page, *_dot(page, 1)[:2]))
    assert "S1 [mm]: 100" in page.text_content("#box .tooltip")
    inside = page.evaluate("""() => {
        const t = document.querySelector('#box .tooltip').getBoundingClientRect();
        const s = document.querySelector('#box svg').getBoundingClientRect();
        return t.width > 0 && t.left >= s.left - 0.5 && t.right <= s.right + 0.5
            && t.top >= s.top - 0.5 && t.bottom <= s.bottom + 0.5; }""")
    assert inside
    page.mouse.move(5, 590)                                  # out of the plot
    assert page.get_attribute("#box .tooltip", "visibility") == "hidden"


Z = [[1.0, 2.0, 3.0, 4.0, None],
     [5.0, 6.0, 17.5, 8.0, 9.0],
     [10.0, 11.0, 12.0, 13.0, 14.0],
     [15.0, 16.0, 18.0, 19.0, 20.0]]
MAP = ("{x: [0, 10, 20, 30, 40], y: [0, 5, 10, 15], z: %s, xlabel: 'S1 [mm]', ylabel: 'S2 [mm]',"
       " zlabel: 'G [kN]', %s}" % (str(Z).replace("None", "null"), COMMA))


def _cell(page, i, j):
    return page.evaluate(f"""() => {{ const r = document.querySelector(
        "#box rect.cell[data-i='{i}'][data-j='{j}']");
        return ['x', 'y', 'width', 'height'].map(a => Number(r.getAttribute(a))); }}""")


def _fill(page, i, j):
    fill = page.get_attribute(f"#box rect.cell[data-i='{i}'][data-j='{j}']", "fill")
    return tuple(int(c) for c in re.findall(r"\d+", fill)) if fill.startswith("rgb") else fill


def test_the_map_draws_the_cells_where_the_axes_say_and_picks_the_clicked_one(page):
    _make(page, "map", MAP)
    assert page.locator("#box rect.cell").count() == 20
    xt, yt = _ticks(page, "xtick", comma=True), _ticks(page, "ytick", comma=True)
    _check_nice([v for v, _ in xt], -5, 45, cover=False)
    _check_nice([v for v, _ in yt], -2.5, 17.5, cover=False)
    # the grid point (x[i], y[j]) lies in cell (i, j), by the axes' tick positions
    (xv0, xp0), (xv1, xp1) = xt[:2]
    (yv0, yp0), (yv1, yp1) = yt[:2]
    for i, j in ((0, 0), (2, 1), (4, 3)):
        px = xp0 + (10 * i - xv0) * (xp1 - xp0) / (xv1 - xv0)
        py = yp0 - 3.5 + (5 * j - yv0) * (yp1 - yp0) / (yv1 - yv0)
        x, y, w, h = _cell(page, i, j)
        assert x < px < x + w and y < py < y + h
    # viridis: dark purple at the lowest value, yellow at the highest; the hole is grey
    lo, hi = _fill(page, 0, 0), _fill(page, 4, 3)
    assert lo[0] < 100 and lo[2] > lo[1] and hi[0] > 200 and hi[1] > 200 and hi[2] < 100
    assert "missing" in page.get_attribute("#box rect.cell[data-i='4'][data-j='0']", "class")
    zt = [float(t.replace(",", ".")) for t in page.eval_on_selector_all(
        "#box .ztick", "ts => ts.map(t => t.textContent)")]
    _check_nice(zt, 1, 20, cover=False)

    x, y, w, h = _cell(page, 2, 1)
    page.mouse.move(*_screen(page, x + w / 2, y + h / 2))
    tip = page.text_content("#box .tooltip")
    assert "S1 [mm]: 20" in tip and "S2 [mm]: 5" in tip and "G [kN]: 17,5" in tip
    page.mouse.click(*_screen(page, x + 0.8 * w, y + 0.2 * h))
    x, y, w, h = _cell(page, 4, 0)
    page.mouse.click(*_screen(page, x + w / 2, y + h / 2))
    assert page.evaluate("() => picked") == [[2, 1], [4, 0]]
    assert "G [kN]: —" in page.text_content("#box .tooltip")

    page.evaluate("() => plot.marker(3, 2)")
    outline = [float(page.get_attribute("#box rect.marker", a))
               for a in ("x", "y", "width", "height")]
    assert outline == pytest.approx(_cell(page, 3, 2), abs=0.5)


def _fits_and_reads_well(page):
    box = page.evaluate("() => document.getElementById('box').getBoundingClientRect().width")
    svg = page.evaluate("() => document.querySelector('#box svg').getBoundingClientRect().width")
    assert box == 300 and 0 < svg <= 300
    assert page.evaluate("() => document.getElementById('box').scrollWidth") <= 300
    words = page.evaluate("() => document.getElementById('box').textContent")
    assert "undefined" not in words and "NaN" not in words


def test_plots_fit_their_box_and_never_print_undefined_or_nan(page):
    # bare options: no labels, no format, a series with holes
    _make(page, "line", "{series: [{x: [0, 1, 2, null, 4], y: [3, NaN, null, 2, 1]}]}")
    assert page.locator("#box .legend").count() == 0          # one series without a label
    page.mouse.move(*_screen(page, *_dot_at(page, 0)))
    assert page.get_attribute("#box .tooltip", "visibility") == "visible"
    _fits_and_reads_well(page)
    page.evaluate("() => plot.destroy()")
    assert page.locator("#box .assur-plot").count() == 0

    # many long labels: the legend wraps to several rows inside the width
    series = ", ".join("{x: [0, 1, 2], y: [%d, 2, 3], label: 'a rather long run name %d'}" % (k, k)
                       for k in range(6))
    _make(page, "line", "{series: [%s], width: 300}" % series)
    rows = page.evaluate("""() => [...document.querySelectorAll('#box .legend text')]
        .map(t => t.getAttribute('y'))""")
    assert len(rows) == 6 and len(set(rows)) >= 2
    right = page.evaluate("""() => Math.max(...[...document.querySelectorAll('#box .legend text')]
        .map(t => t.getBBox().x + t.getBBox().width))""")
    assert right <= 300
    _fits_and_reads_well(page)
    page.evaluate("() => plot.destroy()")

    _make(page, "map", "{x: [1, 2, 3], y: [7], z: [[null, 2, 2]]}")
    x, y, w, h = _cell(page, 0, 0)
    page.mouse.move(*_screen(page, x + w / 2, y + h / 2))
    assert page.get_attribute("#box .tooltip", "visibility") == "visible"
    _fits_and_reads_well(page)


def _dot_at(page, i):
    page.evaluate(f"() => plot.marker({i})")
    return _dot(page, 0)[:2]


def test_a_long_legend_label_is_cut_to_the_plot_and_kept_whole_as_its_tooltip(page):
    long = "angle of the outer wheel by Ackermann β* = arcctg(ctg α + A/L) " * 3
    _make(page, "line", "{series: [{x: [0, 1, 2], y: [0, 1, 4], label: 'β'}, "
                        f"{{x: [0, 1, 2], y: [0, 1, 3], label: {long!r}, dash: true}}]}}")
    texts = page.evaluate("""() => [...document.querySelectorAll('#box .legend text')]
        .map(t => [t.firstChild.nodeValue, t.querySelector('title') ? t.querySelector('title').textContent : null,
                   t.getBBox().x + t.getBBox().width])""")
    width = page.evaluate("document.querySelector('#box svg').viewBox.baseVal.width")
    assert texts[0][:2] == ["β", None]                     # a short label as it is
    cut, whole, right = texts[1]
    assert cut.endswith("…") and whole == long and long.startswith(cut[:-1])
    assert right <= width                                   # inside the plot's box
