"""The registry of rating kinds."""

from dataclasses import dataclass
from typing import ClassVar

import pytest

from assur.machines.ratings import Rating, param, register, rating_type, registry


def test_every_kind_cites_its_standard_and_documents_its_parameters():
    for name, cls in registry().items():
        assert cls.type_name == name and cls.standard.startswith("ISO")
        assert cls.__doc__ and all(p.doc for p in cls.fields)


def test_a_kind_must_implement_evaluate_and_declare_its_fields():
    @dataclass(frozen=True)
    class Lazy(Rating):
        point: str = param("point")
        type_name: ClassVar[str] = "lazy_rating"
    with pytest.raises(TypeError, match="implement evaluate"):
        register(Lazy)

    @dataclass(frozen=True)
    class Bare(Rating):
        point: str = "A"
        type_name: ClassVar[str] = "bare_rating"

        def evaluate(self, mech, kin):
            return None
    with pytest.raises(TypeError, match="not declared"):
        register(Bare)
    assert "bare_rating" not in registry() and "lazy_rating" not in registry()
    with pytest.raises(KeyError, match="no rating type 'bare_rating'"):
        rating_type("bare_rating")
