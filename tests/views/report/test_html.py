"""The HTML report (:mod:`assur.views.report.html`) of the seed-003 hitch: every table
of the analysis is on the page, each cell its value rounded to the digits it shows;
the Russian page shows the same numbers under other titles; ``write_html`` writes
the page ``render_html`` makes."""

import re
from html.parser import HTMLParser

import numpy as np
import pytest

from assur.views.report.html import render_html, write_html
from assur.views.report.tables import seed_tables


class Tables(HTMLParser):
    """``{table id: [[cell, …], …]}`` of the report's tables (header row first)."""

    def __init__(self):
        super().__init__()
        self.tables, self.current, self.row, self.cell = {}, None, None, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "h3" and (a.get("id") or "").startswith("table-"):
            self.current = a["id"][len("table-"):]
            self.tables[self.current] = []
        elif tag == "tr" and self.current:
            self.row = []
            self.tables[self.current].append(self.row)
        elif tag in ("td", "th") and self.row is not None:
            self.cell = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None:
            self.row.append(self.cell.strip())
            self.cell = None
        elif tag == "table":
            self.current, self.row = None, None

    def handle_data(self, data):
        if self.cell is not None and not self.cell.endswith("["):
            self.cell += data


def page_tables(page):
    p = Tables()
    p.feed(page)
    return p.tables


@pytest.fixture(scope="module")
def pages(hitch_analysis):
    kw = dict(figures={}, animation=False, drawing=False)
    return (render_html(hitch_analysis, **kw), render_html(hitch_analysis, "ru", **kw))


def test_every_table_cell_is_its_value(hitch_analysis, pages):
    en, _ = pages
    got = page_tables(en)
    tabs = seed_tables(hitch_analysis, units="file")  # the report's display units
    assert [t.id.lower().replace(".", "-") for t in tabs] == list(got)
    for t in tabs:
        rows = got[t.id.lower().replace(".", "-")]
        header, body = rows[0], rows[1:]
        # the closure residuals are one check line under the table, not a column
        columns = [c for c in t.columns if c.symbol != "closure"]
        assert [h.split("[")[0].rstrip("*") for h in header] == [c.symbol for c in columns]
        for j, col in enumerate(columns):
            values = np.atleast_1d(col.values)
            assert len(body) == len(values)
            for row, v in zip(body, values):
                text = row[j]
                digits = len(text.split(".")[1]) if "." in text else 0
                assert abs(float(text) - v) <= 0.5 * 10 ** -digits * (1 + 1e-9), \
                    (t.id, col.symbol, text, v)


def test_russian_numbers_and_the_written_page(hitch_analysis, pages, tmp_path):
    en, ru = pages
    assert "Таблица 2.1" in ru and "Table 2.1" not in ru
    ten, tru = page_tables(en), page_tables(ru)
    # the same numbers, with the decimal comma in Russian
    assert [[x.replace(".", ",") for x in r[1:]] for t in ten.values() for r in t[1:]] == \
        [r[1:] for t in tru.values() for r in t[1:]]
    path = write_html(hitch_analysis, tmp_path / "r.html", figures={}, animation=False,
                      drawing=False)
    assert path.read_text(encoding="utf-8") == en
    assert not re.search(r'(src|href)="https?://', en)  # self-contained


@pytest.mark.parametrize("name", ["hitch_003", "loader_lab1", "combine_002", "steering_lab4"])
def test_first_page_holds_the_verdicts_each_its_tables_value(name):
    """The first section after the title is the verdicts; each links to the table or
    section that shows it, and its number is that table's cell at that row (the same
    value, in the same display units)."""
    import html as _html

    from assur import io
    from assur.core.display import unit_system
    from assur.views.report.verdicts import verdicts

    a = io.load(io.bundled(name)).analyze()
    for lang, system in (("en", "file"), ("ru", "imperial")):
        du = unit_system(a.mechanism, system)
        tabs = seed_tables(a, lang, units=du)
        page = render_html(a, lang, figures={}, animation=False, drawing=False, tables=tabs,
                           units=du)
        sections = re.findall(r'<section id="([a-z]+)"', page)
        assert sections[0] == "verdicts", sections
        items = re.findall(r'<li class="verdict (\w+)">.*?<a href="#([\w-]+)">(.*?)</a></li>',
                           page)
        ids = set(re.findall(r'id="([\w-]+)"', page))
        vs = verdicts(a, tabs, du, lang)
        assert len(items) == len(vs) >= 2
        assert {(s, h, _html.unescape(t)) for s, h, t in items} == \
            {(v.status, v.anchor, v.text) for v in vs}
        for status, href, _ in items:
            assert href in ids, href
        by_id = {t.id: t for t in tabs}
        for v in vs:
            if v.table is None:
                continue
            col = by_id[v.table].column(v.column)
            assert v.value == col.values[v.row]  # the table's own number
