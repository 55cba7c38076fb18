"""The documentation site's own checks (docs/, ``make docs``) and the release plumbing.

The site itself is built by ``make docs`` in CI (``.ci/run``) with warnings as errors;
its gallery scripts run there and assert the seeds' printed numbers. Here, quickly:

* every bundled model file (``src/assur/models/*.toml``) has a gallery page that loads
  it, and every gallery script checks its numbers (``assert``);
* the generated pages cover what they document: every command of the CLI, every
  registered group type (its sample model file loads and assembles over its range);
* optional guide pages enter the toctree only when they exist;
* the bars of absolute values in docstrings are escaped for docutils, not those of
  tables, literal blocks, doctests or inline literals;
* the version is written once and read everywhere (``assur --version``,
  ``python -m assur --version``, the package metadata).
"""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib

import pytest
from typer.testing import CliRunner

import assur
from assur.views.cli import app
from tests.helpers import DOCS, ROOT, import_path

GALLERY = DOCS / "gallery"
# the documentation's own extensions (docs/_ext, imported by Sphinx from docs/)
import_path("_ext", DOCS / "_ext")
from _ext import bars, gen_cli, gen_groups_drawn, gen_optional  # noqa: E402


def _scripts():
    return sorted(GALLERY.glob("plot_*.py"))


def _bundled_names():
    return sorted(p.stem for p in (ROOT / "src" / "assur" / "models").glob("*.toml"))


@pytest.mark.parametrize("name", _bundled_names())
def test_every_bundled_model_has_a_gallery_page(name):
    """A gallery script loads the file by name (``io.bundled("name")``) or through
    its ``examples`` function."""
    pattern = re.compile(rf"""bundled\(\s*["']{name}["']\s*\)|examples\.{name}\(""")
    pages = [p.name for p in _scripts() if pattern.search(p.read_text(encoding="utf-8"))]
    assert pages, f"no gallery page loads the bundled model {name!r} (docs/gallery/plot_*.py)"


def test_every_seed_machine_is_in_the_gallery():
    """The brief's list: 003 hitch, 000 header, 002 combine, labs 1–6 of 001, 004 crane."""
    names = " ".join(p.stem for p in _scripts())
    for key in ("003_hitch", "000_header", "002_combine", "loader_lab1", "conditioner_lab2",
                "cleaning_lab3", "steering_lab4", "spout_lab5", "adapter_lab6", "crane"):
        assert key in names, key


@pytest.mark.parametrize("script", _scripts(), ids=lambda p: p.stem)
def test_gallery_scripts_check_their_numbers_and_have_bilingual_titles(script):
    text = script.read_text(encoding="utf-8")
    assert re.search(r"^assert ", text, re.M), f"{script.name} asserts no number"
    doc = text.split('"""')[1]
    title = doc.strip().splitlines()[0]
    assert re.search("[А-Яа-я]", title) and re.search("[A-Za-z]", title), title
    underline = doc.strip().splitlines()[1]
    assert set(underline) == {"="} and len(underline) == len(title), script.name


def test_cli_page_has_every_command():
    import typer

    page = gen_cli.render()
    group = typer.main.get_command(app)
    commands = group.list_commands(typer.Context(group, info_name="assur"))
    assert {"check", "analyze", "tables", "fit", "simulate", "demo"} <= set(commands)
    for name in commands:
        assert f"## `assur {name}`" in page, name
    assert "`--version`" in page and "`--draw-at`" in page


def test_every_group_type_has_a_sample_that_assembles():
    from assur import io
    from assur.groups import registry

    assert set(gen_groups_drawn.SAMPLES) == set(registry())
    for name in registry():
        model = io.loads(gen_groups_drawn.model_text(name), name=f"sample_{name}.toml")
        types = {g.type_name for g in model.mechanism.groups}
        assert name in types or name == "frame", name
        kin = model.mechanism.solve(model.range)
        assert kin.closure_residual().max() <= 1e-9, name


def test_optional_pages_only_when_present(tmp_path):
    assert gen_optional.render(tmp_path) == ""
    (tmp_path / "tolerance.md").write_text("# Tolerances\n", encoding="utf-8")
    text = gen_optional.render(tmp_path)
    assert "/tolerance\n" in text and "design" not in text and "page" not in text


@pytest.mark.parametrize("line,expected", [
    ("the distance |A–B| [m]", r"the distance \|A–B\| [m]"),
    ("``|x|`` stays", "``|x|`` stays"),
    ("| a | b |", "| a | b |"),
    ("+----+----+", "+----+----+"),
    ("|origin–out| and |toward–out|", r"\|origin–out\| and \|toward–out\|"),
])
def test_bars_of_absolute_values_are_escaped(line, expected):
    assert bars.escape([line]) == [expected]


def test_bars_leave_literal_blocks_and_doctests_alone():
    lines = ["Drawn::", "", "    A |---| B", "", ">>> abs(-1) | 0", "1", "", "after |x|"]
    out = bars.escape(list(lines))
    assert out[:7] == lines[:7] and out[7] == r"after \|x\|"


# ---- release plumbing -------------------------------------------------------------------
def test_version_from_one_place():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    project = meta["project"]
    assert "version" not in project and "version" in project["dynamic"]
    assert meta["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "assur.__version__"}
    assert re.fullmatch(r"\d+\.\d+\.\d+", assur.__version__)
    assert project["license"] == "MIT" and (ROOT / "LICENSE").is_file()
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert f"## [{assur.__version__}]" in changelog


def test_assur_version_option():
    r = CliRunner().invoke(app, ["--version"])
    assert r.exit_code == 0 and r.output.strip() == f"assur {assur.__version__}"


def test_python_m_assur_version():
    r = subprocess.run([sys.executable, "-m", "assur", "--version"], capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == f"assur {assur.__version__}"
