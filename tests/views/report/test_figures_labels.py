"""Every diagram of a report is drawn and readable (issue 23): no figure with nothing on
it, no raw TeX in any text a reader sees — among the models, a steering drive whose
links are named with letters (``w3``, ``a5``: once printed ``\\varphiw3``), a machine
with no load to lift (no capacity diagram) and one whose only moving link is a
cylinder (no link angles)."""

import pytest

from assur import io
from assur.core.display import SYSTEMS, unit_system
from assur.views.report.labels import symbol
from assur.views.report.figures import figures
from tests.helpers.documents import allowed_units, axis_units
from tests.helpers.reports import label_problems

NAMES = ["hitch_003", "steering_lab4", "spout_lab5", "adapter_lab6", "combine_002",
         "crane_lv185"]


@pytest.mark.parametrize("name, lang", [(n, ("en", "ru")[k % 2]) for k, n in enumerate(NAMES)])
def test_every_figure_drawn_and_no_raw_tex(name, lang):
    """... and every axis in the report's display units: each model in another unit
    system and language, all four systems and both languages covered."""
    a = io.load(io.bundled(name)).analyze()
    system = SYSTEMS[NAMES.index(name) % len(SYSTEMS)]
    du = unit_system(a.mechanism, system)
    figs = figures(a, lang, units=du)
    assert figs
    allowed = allowed_units(du, lang)
    for fig_name, fig in figs.items():
        assert not label_problems(fig), (name, fig_name, label_problems(fig))
        units = axis_units(fig)
        assert units, (name, fig_name)  # every figure's axes name their unit
        assert set(units) <= allowed, (name, system, lang, fig_name, set(units) - allowed)


def test_the_diagrams_of_each_machine_are_its_own():
    """Only the diagrams with data: the steering drive lifts nothing; the adapter's
    file has no [links], and its cylinder 2 and lever 3 are its links (derived from
    its groups, assur.io._links), with a reaction at every joint."""
    steering = figures(io.load(io.bundled("steering_lab4")).analyze())
    adapter = figures(io.load(io.bundled("adapter_lab6")).analyze())
    assert "capacity" not in steering and {"angles", "analogs"} <= set(steering)
    assert set(adapter) == {"angles", "analogs", "reactions", "hodograph"}


def test_a_symbol_of_a_name_with_letters_is_not_raw_tex():
    assert symbol("φ", "w3") == "φ w3"
    assert symbol("φ", "3") == "φ₃"
    assert symbol("φ", "a$b", prime=True) == "φ′ a$b"  # printed as written (no TeX)
