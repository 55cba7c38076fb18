"""Hydraulic components (:mod:`assur.dynamics.drive.base`): the contract of the
registry — every component documents its fields with units and has its row in
docs/simulation.md — and the components' refusal of bad values. (The line's losses:
test_line.py; the flow divider: test_divider.py.)"""

from __future__ import annotations

import dataclasses
import re

import pytest

from assur.dynamics.drive import FlowDivider, Line, registry
from assur.dynamics.drive.base import ROLES
from assur.errors import ModelError
from tests.helpers import ROOT


def test_every_component_follows_the_contract():
    """type_name, role, quantities naming fields, a numpydoc Parameters section that
    documents every field with a unit in brackets, and a row in docs/simulation.md."""
    doc = (ROOT / "docs" / "simulation.md").read_text(encoding="utf-8")
    from assur.io._drive import KINDS
    for name, cls in registry().items():
        assert cls.type_name == name and cls.role in ROLES
        fields = {f.name for f in dataclasses.fields(cls)}
        assert set(cls.quantities) <= fields, name
        assert all(q in KINDS for q in cls.quantities.values()), name
        text = cls.__doc__
        assert "Parameters" in text, name
        for f in fields - {"name"}:
            m = re.search(rf"^\s+(\w+, )*{f}(, \w+)* :.*$", text, re.M)
            assert m, f"{name}.{f} undocumented"
            if f in cls.quantities:
                block = text[m.end():].split(" : ", 1)[0]
                assert re.search(r"\[[^\]]+\]", block), f"{name}.{f}: no unit in brackets"
        assert f"`{name}`" in doc, f"{name} missing from docs/simulation.md"


def test_components_refuse_bad_values():
    with pytest.raises(ModelError, match="diameter"):
        Line(length=5.0, diameter=0.0)
    # an unnamed component's message has no stray space before the colon
    with pytest.raises(ModelError, match=r"^line: diameter = 0\.0 must be a finite number > 0$"):
        Line(length=5.0, diameter=0.0)
    with pytest.raises(ModelError, match="regulation_range"):
        registry()["relief_valve"](16e6, 0.0)
    with pytest.raises(ModelError, match="position must be one of"):
        registry()["directional_valve"]("float")
    with pytest.raises(ModelError, match="shares"):
        FlowDivider((0.7, 0.7))
    with pytest.raises(ValueError, match="component type must be one of"):
        from assur.dynamics.drive import component_type
        component_type("gear_pmp")


