"""A feature of an optional extra that is not installed says which to install
(:mod:`assur._extras`): ``assur serve`` without uvicorn is one line naming
``assur[page]`` (exit 1, no traceback); the Pareto search without pymoo names
``assur[pareto]``; and every extra's modules are those pyproject.toml installs."""

import sys
import tomllib

import pytest
from typer.testing import CliRunner

from assur import io
from assur._extras import EXTRAS, require
from assur.errors import MissingExtraError
from assur.views.cli import app

from tests.helpers import ROOT


def test_serve_without_the_page_extra_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "uvicorn", None)  # as if not installed
    r = CliRunner().invoke(app, ["serve", str(io.bundled("hitch_003")), "--no-browser"])
    assert r.exit_code == 1
    text = " ".join(r.output.split())
    assert "assur serve needs uvicorn (not installed): pip install 'assur[page]'" in text
    assert "Traceback" not in r.output and "internal error" not in text


def test_the_pareto_search_without_pymoo_names_its_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pymoo", None)
    with pytest.raises(MissingExtraError, match=r"pip install 'assur\[pareto\]'") as e:
        require("pareto", "the Pareto front (NSGA-II)")
    assert e.value.missing == ("pymoo",) and isinstance(e.value, ImportError)


def test_the_extras_are_those_pyproject_installs():
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"][
        "optional-dependencies"]
    for extra, modules in EXTRAS.items():
        names = {d.split(">")[0].split("[")[0].replace("-", "_") for d in extras[extra]}
        assert set(modules) == names, (extra, names)
    assert extras["all"] == [f"assur[{','.join(sorted(EXTRAS))}]"]
