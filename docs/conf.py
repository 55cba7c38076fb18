"""Sphinx configuration of the assur documentation (``make docs``).

Sphinx + numpydoc + sphinx-gallery + the pydata theme, the stack of the scientific
Python projects our users read (pvlib, scipy, python-control): the guide pages are
the repository's Markdown files read through MyST, the gallery's scripts run on every
build, and the API reference comes from the numpydoc docstrings.

Some pages are generated here before the build, from the code itself, so they cannot
go out of date: the command reference (from typer's app), the drawings of every group
type (from the group registry, drawn by :mod:`assur.views.report.drawing`) and the list of
optional guide pages that exist. The build is offline: no intersphinx inventories are
fetched.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))  # the generators under docs/_ext

import matplotlib

matplotlib.use("Agg")

import assur  # noqa: E402

from _ext import gen_api, gen_cli, gen_groups_drawn, gen_optional  # noqa: E402

project = "assur"
author = "The assur developers"
copyright = "2026, The assur developers"
version = release = assur.__version__
language = "en"

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "_ext.bars",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_ext", "gallery/README.rst", "tutorials/README.rst", "**/README.md",
                    "auto_gallery/*.ipynb", "auto_gallery/*.py", "auto_gallery/*.zip",
                    "auto_gallery/*.json", "auto_gallery/*.md5",
                    "auto_tutorials/*.ipynb", "auto_tutorials/*.py", "auto_tutorials/*.zip",
                    "auto_tutorials/*.json", "auto_tutorials/*.md5"]

# --- generated pages ---------------------------------------------------------
GENERATED = HERE / "_generated"
GENERATED.mkdir(exist_ok=True)
gen_cli.write(GENERATED / "cli.md")
gen_groups_drawn.write(GENERATED / "groups.md", GENERATED / "groups")
gen_optional.write(GENERATED / "optional.md", HERE)
gen_api.write(HERE)

# every bundled model file has a gallery page that loads it (tests/docs/test_docs.py too)
_scripts = [p.read_text(encoding="utf-8") for p in (HERE / "gallery").glob("plot_*.py")]
_missing = [p.stem for p in sorted((HERE.parent / "src" / "assur" / "models").glob("*.toml"))
            if not any(f'bundled("{p.stem}")' in t or f"examples.{p.stem}(" in t
                       for t in _scripts)]
if _missing:
    raise RuntimeError(f"docs/gallery: no page loads the bundled model(s) {_missing}")

# --- MyST ------------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

# --- autodoc / numpydoc ------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"show-inheritance": False}
autodoc_typehints = "none"
autodoc_member_order = "bysource"
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks = set()

# --- sphinx-gallery ------------------------------------------------------------------
os.environ.setdefault("ASSUR_DOCS_BUILD", "1")
sphinx_gallery_conf = {
    "examples_dirs": ["gallery", "tutorials"],
    "gallery_dirs": ["auto_gallery", "auto_tutorials"],
    "filename_pattern": r"/plot_",
    "ignore_pattern": r"_common\.py",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "show_memory": False,
    "plot_gallery": "True",
    "abort_on_example_error": False,  # run them all; the build fails at the end
    "reset_modules": ("matplotlib",),
    "doc_module": ("assur",),
    "backreferences_dir": None,
    "image_scrapers": ("matplotlib", "_ext.scraper.scrape"),
    "min_reported_time": 1e9,
}

# --- HTML ------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"assur {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "navbar_end": ["theme-switcher", "navbar-icon-links"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False
html_last_updated_fmt = None
