"""Every bundled model (one file per machine, src/assur/models/): `assur analyze`
writes its tables, and no CSV of it holds NaN or inf; a model kept as its seed prints
it (it cannot assemble) fails with one located message, never a traceback. Each
model's HTML report (its figures and drawing) is rendered, shown and printed in
Chromium by tests/views/report/test_html_browser.py, its documents in every unit
system by tests/models/test_models_documents.py."""

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import io
from assur.views.cli import app
from tests.helpers import ROOT
from tests.helpers.reports import REPORT_NEUTRAL_KEYS, SAME_REPORT, assert_csvs_clean

MODELS = sorted(p.stem for p in Path(io.bundled("hitch_003")).parent.glob("*.toml"))
#: the bundled files kept as their seed prints them: they load, and cannot assemble
AS_PRINTED = {"header_000", "combine_002_printed"}


def test_the_list_of_unassembling_models_is_current():
    assert AS_PRINTED <= set(MODELS)


#: where every bundled model's HTML report is written and checked (here: the tables,
#: through the command line)
HTML_ELSEWHERE = {
    name: "tests/views/report/test_html_browser.py::"
          "test_the_report_reads_on_the_screen_and_prints_on_a4" for name in MODELS}
HTML_ELSEWHERE["loader_lab1"] = \
    "tests/views/report/test_tables.py::test_analyze_writes_the_loader_report"


def test_the_html_reports_written_elsewhere_are_tested_there():
    for name, test in HTML_ELSEWHERE.items():
        assert name in MODELS
        path, func = test.split("::")
        assert f"def {func}(" in (ROOT / path).read_text(encoding="utf-8"), test


@pytest.mark.slow
@pytest.mark.parametrize("name", MODELS)
def test_analyze_writes_every_bundled_report(name, tmp_path):
    formats = "csv" if name in HTML_ELSEWHERE else "csv,html"
    r = CliRunner().invoke(app, ["analyze", str(io.bundled(name)), "-o", str(tmp_path),
                                 "--format", formats])
    if name in AS_PRINTED:
        assert r.exit_code == 1 and "Traceback" not in r.output, r.output
        assert f"{name}.toml" in r.output
        return
    assert r.exit_code == 0, r.output
    assert (tmp_path / "report.html").exists() == ("html" in formats)
    assert_csvs_clean(tmp_path, name)


@pytest.mark.parametrize("variant", sorted(SAME_REPORT))
def test_a_variant_reported_as_its_base_differs_only_where_the_report_does_not_look(variant):
    """The report checks skip these variants (tests.helpers.reports.SAME_REPORT): each
    only adds design or tolerance sections (and its own title) to its base, so its
    mechanism, parameters and range are the base's."""
    import tomllib

    base = SAME_REPORT[variant]
    raw = tomllib.loads(io.bundled(variant).read_text(encoding="utf-8"))
    assert set(raw) <= REPORT_NEUTRAL_KEYS, set(raw) - REPORT_NEUTRAL_KEYS
    assert raw["extends"] == f"{base}.toml"
    assert set(raw.get("model", {})) <= {"name", "title", "notes"}
    v, b = io.load(io.bundled(variant)), io.load(io.bundled(base))
    vm, bm = v.mechanism, b.mechanism
    assert [(g.type_name, str(g.name)) for g in vm.groups] == \
        [(g.type_name, str(g.name)) for g in bm.groups]
    assert {k: np.asarray(x).tolist() for k, x in vm.params.items()} == \
        {k: np.asarray(x).tolist() for k, x in bm.params.items()}
    assert np.array_equal(v.range, b.range)
