"""Load types come from one registry (issue 22, DESIGN.md decision 9): each type declares
its fields once (:func:`assur.core.loads.param`) and is registered with
:func:`assur.core.loads.register`; the ``[[loads]]`` schema, the file loader's checks,
the ``Mechanism`` builder methods and the docs table derive from the registry. A new
load type is one class (plus its tests): a toy type registered here is accepted by
files, gets a builder and appears in the docs table."""

from __future__ import annotations

import dataclasses
import inspect
import pathlib
import re
import subprocess
import sys
from typing import ClassVar

import numpy as np
import pytest

from assur import Mechanism, io
from assur.core import loads
from assur.core.loads import Load, PointForce, param, register, registry
from assur.core.quantities import parameter_quantities
from assur.io import ModelFileError, _schema

ROOT = pathlib.Path(__file__).resolve().parents[2]

#: a cylinder–lever four-bar (seed 003's first group), the toy load at the lever's pin
LIFT = """
[model]
name = "lift"
coordinates = ["S"]

[params]
L3 = "0.2 m"
F1 = "1 kN"

[range]
S = { from = "0.42 m", to = "0.67 m", count = 3 }

[frame]
"01" = ["0.415 m", "0.563 m"]
"03" = ["0.25 m", "1.112 m"]

[[groups]]
type = "cylinder_lever"
name = "lever"
base = "01"
pivot = "03"
out = "23"
lever = "L3"
s = "S"
branch = -1
links = ["2", "3"]

[[loads]]
type = "toy_pull"
point = "23"
F = "F1"
"""


@pytest.fixture
def toy():
    """A load type registered by this test module alone (removed afterwards): a pull
    of ``F`` [N] along +x at a point."""

    @dataclasses.dataclass(frozen=True)
    class Pull(Load):
        """A pull along +x.

        Examples
        --------
        >>> 1 + 1
        2
        """

        point: str = param("point", doc="where it pulls")
        F: object = param("value", "force", "nonneg", doc="its magnitude [N]")
        link: str | None = param("link", default=None, doc="the link it pulls")

        type_name: ClassVar[str] = "toy_pull"
        summary: ClassVar[str] = "a pull F along +x at a point"

        def apply(self, c):
            c.force(self.link or c.owner(self.point), self.point, c.value(self.F), 0.0)

    register(Pull)
    try:
        yield Pull
    finally:
        loads.unregister(Pull)
        assert not hasattr(Mechanism, "toy_pull")
        assert "toy_pull" not in _schema.load_types()   # the derived schema follows


def test_a_registered_load_type_is_read_from_files(toy):
    m = io.loads(LIFT, name="lift.toml").mechanism
    (ld,) = m.loads
    assert type(ld) is toy and (ld.point, ld.F, ld.link) == ("23", "F1", None)
    assert parameter_quantities(m)["F1"] == "force"       # its declared quantity
    # the statics see it: the same as a force (F, 0) at the point
    same = m.with_loads([PointForce("23", fx=1000.0)])
    q = np.array([0.42, 0.55, 0.67])                      # S [m]
    np.testing.assert_allclose(m.analyze(q).statics.actuator_force("S"),
                               same.analyze(q).statics.actuator_force("S"), rtol=1e-12)


@pytest.mark.parametrize("old, new, where, message", [
    ('F = "F1"', 'F = "F1"\nlnk = "3"', "loads[0].lnk",
     'unknown key "lnk"; did you mean "link"? (allowed: type, point, F, link)'),
    ('F = "F1"', "", "loads[0].F", 'missing required key "F"'),
    ('F = "F1"', 'F = "1 m"', "loads[0].F", "expected a force"),
    ('F = "F1"', 'F = "-1 kN"', "loads[0].F", "expected a non-negative force"),
    ('point = "23"', 'point = "24"', "loads[0].point", 'unknown point "24"'),
    ('F = "F1"', 'F = "F1"\nlink = "9"', "loads[0].link", 'unknown link "9"'),
    ('"toy_pull"', '"toy_pul"', "loads[0].type", 'unknown load type "toy_pul"; did you mean '
                                                 '"toy_pull"'),
])
def test_a_registered_load_type_has_the_file_checks(toy, old, new, where, message):
    with pytest.raises(ModelFileError) as exc:
        io.loads(LIFT.replace(old, new), name="lift.toml")
    assert exc.value.key_path == where and message in str(exc.value), str(exc.value)


def test_a_registered_load_type_gets_a_builder(toy):
    m = (Mechanism("lift", coordinates=("S",), params={"L3": 0.2})
         .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
         .cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3", s="S",
                         branch=-1, links=("2", "3")))
    built = m.toy_pull("23", 1000.0)
    assert built.loads == (toy("23", 1000.0),) == m.add_load("toy_pull", "23", F=1000.0).loads
    assert str(inspect.signature(Mechanism.toy_pull)) == (
        "(self, point: 'str', F: 'object', link: 'str | None' = None) -> 'Mechanism'")
    doc = inspect.getdoc(Mechanism.toy_pull)
    assert doc.startswith("Add a pull F along +x at a point") and ">>>" in doc
    assert "``F`` [force]: its magnitude [N]" in doc


def test_a_registered_load_type_is_in_the_docs_table(toy):
    row = next(r for r in io.load_types_table().splitlines() if r.startswith("| `toy_pull` |"))
    assert row == ("| `toy_pull` | `point` (point): where it pulls; `F` (force ≥ 0): its "
                   "magnitude [N]; `link` (link, *optional*): the link it pulls | a pull F "
                   "along +x at a point |")


def test_a_load_type_must_not_hide_a_mechanism_method():
    @dataclasses.dataclass(frozen=True)
    class Solve(Load):
        point: str = param("point")
        type_name: ClassVar[str] = "solve"

        def apply(self, c):
            pass

    with pytest.raises(ValueError, match="Mechanism.solve exists already"):
        register(Solve)
    assert "solve" not in registry() and Mechanism.solve.__name__ == "solve"


@pytest.mark.parametrize("declare, message", [
    (lambda: param("spot"), "unknown role 'spot'"),
    (lambda: param("value"), "a value needs a quantity"),
    (lambda: param("value", "speed"), "a value needs a quantity"),
    (lambda: param("point", "length"), "a value needs a quantity"),
    (lambda: param("value", "force", "even"), "a flag is one of"),
])
def test_declarations_are_checked_on_registration(declare, message):
    Bad = dataclasses.make_dataclass("Bad", [("x", object, declare())], bases=(Load,),
                                     frozen=True, namespace={"type_name": "bad",
                                                             "apply": lambda self, c: None})
    with pytest.raises(ValueError, match=message):
        register(Bad)
    assert "bad" not in registry()


# ---- every registered type -----------------------------------------------------------------
@pytest.mark.parametrize("name", list(registry()))
def test_each_type_declares_its_fields_once(name):
    cls = registry()[name]
    fields = dataclasses.fields(cls)
    assert [f.name for f in cls.fields] == [f.name for f in fields]
    assert cls.summary and all(f.doc for f in cls.fields)
    assert cls.quantities == {f.name: f.quantity for f in cls.fields if f.role == "value"}
    assert set(cls.point_fields) == {f.name for f in cls.fields if f.role == "point"}
    # the file schema: the same keys, required where the constructor requires them
    spec = _schema.load_types()[name]
    assert list(spec.model_fields) == ["type"] + [f.name for f in cls.fields]
    assert [n for n, f in spec.model_fields.items() if f.is_required()][1:] == [
        f.name for f in fields if f.default is dataclasses.MISSING]
    # the builder: named after the type, with the constructor's signature
    builder = getattr(Mechanism, name)
    assert builder.load_type is cls
    assert list(inspect.signature(builder).parameters)[1:] == [f.name for f in fields]
    assert ">>>" in inspect.getdoc(builder)


def test_builders_keep_their_signatures():
    """The public builder methods of the built-in types, as before the registry."""
    sig = {n: str(inspect.signature(getattr(Mechanism, n)))
           for n in ("weight", "force", "moment", "spring", "mass", "resisting_moment")}
    assert sig["weight"].startswith("(self, point: 'str', P: 'Ref', link: 'str | None' = None, "
                                    "name: 'str | None' = None)")
    assert "(self, point: 'str', fx: 'Ref' = 0.0, fy: 'Ref' = 0.0," in sig["force"]
    assert sig["moment"].startswith("(self, link: 'str', M: 'Ref', name: 'str | None' = None)")
    assert sig["spring"].startswith("(self, name: 'str', a: 'str', b: 'str', rate: 'Ref', "
                                    "free_length: 'Ref', preload: 'Ref' = 0.0, links: "
                                    "'tuple[str, str] | None' = None, count: 'Ref' = 1)")
    assert sig["mass"].startswith("(self, link: 'str', m: 'Ref', point: 'str', J: 'Ref' = 0.0)")
    assert sig["resisting_moment"].startswith(
        "(self, link: 'str', M: 'Ref', travel: 'int' = 1, coordinate: 'str | None' = None, "
        "name: 'str | None' = None)")


def test_spring_links_given_as_a_list_are_a_pair():
    from assur import examples
    m = examples.hitch_003().with_loads().spring("k", "07", "S6", 1e4, 1.0, links=["0", "6"])
    assert m.loads[0].links == ("0", "6")


def test_the_docs_table_is_the_generated_one():
    doc = (ROOT / "docs" / "model-format.md").read_text(encoding="utf-8")
    begin, end = doc.index(_schema.LOAD_TABLE_BEGIN), doc.index(_schema.LOAD_TABLE_END)
    assert doc[begin + len(_schema.LOAD_TABLE_BEGIN) + 1:end] == io.load_types_table(), \
        "run python docs/gen_groups.py"
    for name in registry():
        assert f"| `{name}` |" in doc and f"`.{name}`" in doc, name
    r = subprocess.run([sys.executable, str(ROOT / "docs" / "gen_groups.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_io_and_mechanism_do_not_list_load_types():
    """Nothing outside assur.core.loads names a load type: the schema, the loader and the
    mechanism read the registry."""
    src = ROOT / "src" / "assur"
    for path in [src / "core" / "mechanism.py", src / "core" / "_building.py",
                 src / "core" / "_checks.py", *sorted((src / "io").glob("_*.py"))]:
        text = path.read_text(encoding="utf-8")
        for name in ("WeightSpec", "SpringSpec", '"resisting_moment"', "ResistingMoment(",
                     "Spring(", "Mass("):
            assert not re.search(r"\b" + re.escape(name), text), (path.name, name)
