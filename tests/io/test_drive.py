"""The ``[[drive]]`` entries of a model file (:mod:`assur.io._drive`, issue 27): a value
of the wrong type, or outside the physical span of its kind (a slip of a unit or an
exponent), is refused at its key and line — never an AttributeError, an overflow or
a simulation that runs on NaN — and a component's own check is located at the key it
names."""

from __future__ import annotations

import re

import pytest

from assur import io
from assur.core.inputs import SPANS
from assur.dynamics.drive import registry, span
from assur.io import ModelFileError

CRANE = io.bundled("crane_lv184a").read_text(encoding="utf-8")


def _with(entry_type, key, value):
    """The crane's file with ``key = value`` in its first ``entry_type`` entry, and
    the line of that key (1-based)."""
    start = CRANE.index(f'type = "{entry_type}"')
    m = re.compile(rf"^{key} = .*$", re.M).search(CRANE, start)
    assert m, (entry_type, key)
    text = CRANE[:m.start()] + f"{key} = {value}" + CRANE[m.end():]
    return text, CRANE[:m.start()].count("\n") + 1


BAD = [
    ("gear_pump", "displacement", "true", "expected a volume"),
    ("gear_pump", "displacement", "[1, 2]", "expected a volume"),
    ("gear_pump", "displacement", "{ a = 1 }", "expected a volume"),
    ("gear_pump", "displacement", '"1e308 cm^3"', "a volume of at most 10 m³"),
    ("gear_pump", "displacement", '"1e-300 cm^3"', "outside the physical span of a volume"),
    ("gear_pump", "speed", '"1e308 rpm"', "an angular velocity of at most 10000 rad/s"),
    ("gear_pump", "speed", '"1e-300 rpm"', "outside the physical span of an angular velocity"),
    ("gear_pump", "eta_volumetric", "5", "outside the physical span of a plain number, 0.01 … 1"),
    ("gear_pump", "eta_volumetric", "1e-9", "0.01 … 1"),
    ("relief_valve", "setting", '"1e7 MPa"', "a pressure of at most 1e+12 Pa"),
    ("directional_valve", "nominal_flow", '"1e-300 l/min"', "outside the physical span of a flow"),
    ("line", "diameter", '"1e-300 mm"', "outside the physical span of a length"),
    ("line", "fittings", "1e12", "outside the physical span of a plain number"),
    ("line", "length", '"-4 m"', "outside the physical span of a length"),
]


@pytest.mark.parametrize("entry_type, key, value, words", BAD)
def test_a_bad_drive_value_is_refused_at_its_key(entry_type, key, value, words):
    text, line = _with(entry_type, key, value)
    with pytest.raises(ModelFileError) as e:
        io.loads(text, name="crane.toml")
    assert e.value.line == line
    assert re.fullmatch(rf"drive\[\d+\]\.{key}", e.value.key_path), e.value.key_path
    assert words in str(e.value)


def test_every_value_field_has_a_physical_span():
    """Every value field of every registered component type has a span whose ends
    are ordered and finite (its kind's, assur.core.inputs.SPANS, or its own; a plain
    number without its own span is checked by the component: η0 in (0, 1]), and the
    bundled drives lie inside."""
    for name, cls in registry().items():
        for field, kind in cls.quantities.items():
            if kind == "number" and field not in getattr(cls, "spans", {}):
                continue
            lo, hi = span(cls, field)
            assert 0 <= lo < hi < float("inf"), (name, field)
    kinds = {q for cls in registry().values() for q in cls.quantities.values()}
    assert set(SPANS) >= kinds - {"number"}
    for name in ("crane_lv184a", "crane_lv185", "crane_lv215", "adapter_lab6"):
        if io.bundled(name).exists():
            io.load(io.bundled(name))   # no value outside its span
