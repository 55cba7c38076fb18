"""Checks of written reports shared by the report tests."""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path


def read_report_csv(path, lang="en") -> list[list[str]]:
    """The rows of a report's CSV in ``lang``'s dialect (Russian: ``;``, the decimal
    comma, a byte-order mark), numbers still as text with a decimal point."""
    from assur.views.report.tables._files import CSV_DIALECTS

    sep, point, encoding = CSV_DIALECTS[lang]
    with open(path, encoding=encoding, newline="") as fh:
        rows = list(csv.reader(fh, delimiter=sep))
    return [rows[0]] + [[c.replace(point, ".") for c in r] for r in rows[1:]]


def assert_csvs_clean(directory: Path, name: str, lang: str = "en") -> list[Path]:
    """Every CSV table in ``directory`` (in ``lang``'s dialect) has unique headers and
    only finite numbers, none written ``-0.0``; returns the files (at least one)."""
    files = sorted(Path(directory).glob("*.csv"))
    assert files, f"{name}: no CSV file in {directory}"
    for f in files:
        rows = read_report_csv(f, lang)
        assert len(set(rows[0])) == len(rows[0]), f"{name}: {f.name}: duplicate headers"
        for row in rows[1:]:
            for cell in row:
                assert math.isfinite(float(cell)), f"{name}: {f.name} holds {cell}"
                assert cell != "-0.0", f"{name}: {f.name} holds -0.0"
    return files


def label_problems(fig) -> list[str]:
    """What a reader of ``fig`` would see wrong in its texts (titles, axis and tick
    labels, legends, annotations): raw TeX — a ``\\``, ``_`` or ``$`` outside the math
    segments — or a math segment matplotlib cannot parse (it would print it raw);
    and a figure with no data on any of its axes."""
    from matplotlib.mathtext import MathTextParser
    from matplotlib.text import Text

    parser = MathTextParser("path")
    out = []
    if not any(ax.has_data() for ax in fig.axes):
        out.append("a figure with nothing drawn")
    for text in fig.findobj(Text):
        s = text.get_text()
        parts = re.split(r"(?<!\\)\$", s)
        if len(parts) % 2 == 0:  # an odd number of dollars: printed as they are
            parts = [s]
        for k, part in enumerate(parts):
            if k % 2:
                try:
                    parser.parse(f"${part}$", 72)
                except ValueError:
                    out.append(f"math that does not parse: {s!r}")
            elif re.search(r"[\\_$]", part):
                out.append(f"raw TeX: {s!r}")
    return out


#: bundled models that extend another and add only what the analysis report does not
#: show (``[design]``, ``[tolerances]``, a ``[model]`` title): their report has the base's
#: tables, figures and layout, so the report's own checks (screen, print, units, language)
#: run on the base (tests/models/test_models.py checks that this still holds)
SAME_REPORT = {"hitch_003_design": "hitch_003", "hitch_003_tolerances": "hitch_003",
               "cleaning_lab3_design": "cleaning_lab3",
               "conditioner_lab2_design": "conditioner_lab2"}
#: the top-level keys such a variant may have
REPORT_NEUTRAL_KEYS = {"extends", "model", "design", "tolerances"}
