"""The ``[[groups]]`` of model files derive from the group registry (DESIGN.md §9):
the table models, the builder's checks, the docs table. The RPR and PRP dyads,
which have no hand-written schema, load from files and equal the same mechanisms
built in Python; a group type registered in one new module is usable in a file
with nothing else changed."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest

from assur import Mechanism, io
from assur.groups import Dyad, base, registry
from assur.io import ModelFileError, _schema
from tests.helpers import ROOT

IO = ROOT / "src" / "assur" / "io"

SLOTTED = """
[model]
name = "slotted"
coordinates = ["q"]

[params]
r = "0.1 m"
e = "0.01 m"
l = "0.5 m"

[range]
q = { from = 0, to = 360, count = 13 }

[frame]
O = [0, 0]
B0 = [0, -0.3]

[[groups]]
type = "crank"
name = "crank"
pivot = "O"
out = "A"
radius = "r"
q = "q"
links = ["2"]

[[groups]]
type = "rpr_dyad"
name = "III"
a = "B0"
b = "A"
out = "D"
length = "l"
offset = "e"
branch = 1
links = ["rod", "sleeve"]

[links]
rod = ["B0", "D"]
"""

WEDGE = """
[model]
name = "wedge"
coordinates = ["s"]

[params]
alpha = "150 deg"

[range]
s = { from = "0 m", to = "200 mm", count = 5 }

[frame]
O = [0, 0]
F = [0.3, 0.1]

[[groups]]
type = "slider_input"
name = "wedge"
origin = "O"
out = "A"
s = "s"
links = ["1"]

[[groups]]
type = "prp_dyad"
name = "follower"
a = "F"
b = "A"
out = "C"
direction_a = 90
direction_b = "alpha"
links = ["2", "3"]
"""


def _same_motion(a, b, q, points, links):
    ra, rb = a.solve(q), b.solve(q)
    assert ra.ok.all() and rb.ok.all()
    for p in points:
        np.testing.assert_array_equal(ra.x(p), rb.x(p))
        np.testing.assert_array_equal(ra.y(p), rb.y(p))
        np.testing.assert_array_equal(ra.transmission(p), rb.transmission(p))
    for link in links:
        np.testing.assert_array_equal(ra.phi(link), rb.phi(link))
    return ra


# ---- the new group types in files ---------------------------------------------------------------
def test_rpr_slotted_lever_file_equals_python():
    """Crank O–A and a slotted lever: the rod pinned at the frame point B0 slides
    through a sleeve pivoted at the crank pin A (кулиса)."""
    model = io.loads(SLOTTED, name="slotted.toml")
    py = (Mechanism("slotted", coordinates=("q",), params={"r": 0.1, "e": 0.01, "l": 0.5})
          .frame("O", 0.0, 0.0).frame("B0", 0.0, -0.3)
          .crank("crank", pivot="O", out="A", radius="r", q="q", links=("2",))
          .rpr_dyad("III", a="B0", b="A", out="D", length="l", offset="e", branch=1,
                    links=("rod", "sleeve"))
          .link("rod", "B0", "D"))
    m = model.mechanism
    assert m.groups == py.groups and m.params == py.params and m.links == py.links
    np.testing.assert_allclose(model.range, np.radians(np.arange(0, 361, 30)), atol=1e-15)
    r = _same_motion(m, py, model.range, ["A", "D"], ["rod"])
    # independent geometry: |B0–D| = l, and the sleeve pivot A is at e from the rod's line
    B0, A = np.array([0.0, -0.3]), np.stack([r.x("A"), r.y("A")], -1)
    D = np.stack([r.x("D"), r.y("D")], -1)
    u = (D - B0) / 0.5
    np.testing.assert_allclose(np.hypot(*(D - B0).T), 0.5, rtol=1e-12)
    w = A - B0
    np.testing.assert_allclose(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0], 0.01, atol=1e-12)
    assert np.all((w * u).sum(-1) > 0)  # branch +1: the sleeve ahead of the pin


def test_prp_wedge_file_equals_python():
    """A wedge pushed along x (slider input) lifts a follower in a vertical guide
    through the frame point F: PRP dyad with two fixed lines, through F at 90° and
    through the slider point A at 150°. Y_C = (s − 0.3)·tan 30°."""
    model = io.loads(WEDGE, name="wedge.toml")
    py = (Mechanism("wedge", coordinates=("s",), params={"alpha": math.radians(150)})
          .frame("O", 0.0, 0.0).frame("F", 0.3, 0.1)
          .slider_input("wedge", origin="O", out="A", s="s", links=("1",))
          .prp_dyad("follower", a="F", b="A", out="C", direction_a=math.pi / 2,
                    direction_b="alpha", links=("2", "3")))
    m = model.mechanism
    assert m.groups == py.groups
    assert m.params["alpha"] == pytest.approx(py.params["alpha"], rel=1e-15)
    r = _same_motion(m, py.with_params(alpha=m.params["alpha"]), model.range, ["A", "C"], [])
    s = np.linspace(0, 0.2, 5)
    np.testing.assert_allclose(r.x("C"), 0.3, atol=1e-14)
    np.testing.assert_allclose(r.y("C"), (s - 0.3) * math.tan(math.radians(30)), atol=1e-14)
    np.testing.assert_allclose(r.transmission("C"), math.tan(math.radians(30)), rtol=1e-12)


def test_prp_line_link_points_are_checked_as_inputs():
    """A line field's two points are inputs of the group: an unknown one is reported
    at its array item, with its line."""
    text = WEDGE.replace("direction_a = 90", 'direction_a = 90\nline_link_a = ["O", "Q"]')
    with pytest.raises(ModelFileError) as exc:
        io.loads(text, name="wedge.toml")
    e = exc.value
    assert e.key_path == "groups[1].line_link_a[1]"
    assert text.splitlines()[e.line - 1].startswith("line_link_a")
    assert 'unknown point "Q": expected a point of the frame or of an earlier group' in str(e)
    # given right, line a is turned 90° from O→F: through F, perpendicular to O→F
    ok = io.loads(text.replace('["O", "Q"]', '["O", "F"]'), name="wedge.toml").mechanism
    assert ok.group("follower").line_link_a == ("O", "F")
    r = ok.solve([0.0, 0.1])
    assert r.ok.all()
    np.testing.assert_allclose((r.x("C") - 0.3) * 0.3 + (r.y("C") - 0.1) * 0.1, 0, atol=1e-14)


@pytest.mark.parametrize("old,new,path,text", [
    ('offset = "e"', 'offset = "10 deg"', "groups[1].offset",
     'expected a length (e.g. "0.48 m"), found "10 deg"'),
    ('branch = 1\nlinks = ["rod"', 'branch = 0\nlinks = ["rod"', "groups[1].branch",
     "expected 1 or -1"),
    ('length = "l"', 'length = "q"', "groups[1].length", 'found "q", which is a generalized '
                                                         "coordinate"),
    ('links = ["rod", "sleeve"]', 'links = ["rod"]', "groups[1].links",
     'expected 2 link names (rod, sleeve), found ["rod"]'),
    ('out = "D"', 'out = "A"', "groups[1].out", 'point "A" is already defined by groups[0]'),
    ('a = "B0"', 'a = "B1"', "groups[1].a", 'unknown point "B1"'),
    ('offset = "e"', 'ofset = "e"', "groups[1].ofset", 'did you mean "offset"?'),
])
def test_rpr_errors_are_located(old, new, path, text):
    assert old in SLOTTED
    bad = SLOTTED.replace(old, new, 1)
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="slotted.toml")
    e = exc.value
    assert e.key_path == path and text in str(e), str(e)
    key = path.rsplit(".", 1)[1]
    assert bad.splitlines()[e.line - 1].startswith(key), (e.line, str(e))


# ---- the schema derives from the registry ----------------------------------------------------
def test_group_tables_are_derived_from_the_fields():
    types = {n: c for n, c in registry().items() if n != "frame"}
    specs = _schema.group_types()
    assert set(specs) == set(types) and "frame" not in specs
    assert list(specs)[:2] == ["cylinder_lever", "dyad"]
    for name, cls in types.items():
        fields = specs[name].model_fields
        assert list(fields) == ["type", "name", "links"] + [f.name for f in cls.fields], name
        for f in cls.fields:
            assert fields[f.name].is_required() == f.required, (name, f.name)
            if not f.required:
                assert fields[f.name].default == f.default, (name, f.name)
        for out in cls.out_fields:  # the points a group adds are point fields
            assert any(f.name == out and f.role == "point" for f in cls.fields), name


def test_io_does_not_switch_on_group_types():
    """No group type's name is written in the io package (the frame is a section)."""
    src = "\n".join(p.read_text(encoding="utf-8") for p in IO.glob("*.py"))
    for name in registry():
        if name != "frame":
            assert f'"{name}"' not in src and f"'{name}'" not in src, name
    assert "_GROUP_" not in src and "g.type ==" not in src


@pytest.mark.parametrize("given,message", [
    ('angle = "phiBD"\nbase = "L3"', "expected either angle, or base, opposite and branch "
                                     "(the triangle), not both: remove base"),
    ('base = "L3"\nopposite = "0.4 m"', "expected angle, or base, opposite and branch (the "
                                        "triangle); missing branch"),
    ('branch = 1', "expected angle, or base, opposite and branch (the triangle); missing "
                   "base, opposite"),
])
def test_rigid_point_forms_come_from_the_group_type(given, message):
    doc = (ROOT / "docs" / "model-format.md").read_text(encoding="utf-8")
    lift = re.search(r"```toml\n(.*?)```", doc, re.S).group(1)
    lift = re.sub(r"(?ms)^\[\[solve\]\].*", "", lift)
    old = 'length = "L34"\nangle = "phiBD"'
    assert old in lift
    with pytest.raises(ModelFileError) as exc:
        io.loads(lift.replace(old, 'length = "L34"\n' + given), name="lift.toml")
    assert exc.value.key_path == "groups[1]" and message in str(exc.value), str(exc.value)
    from assur.groups import RigidPoint
    assert message.startswith(RigidPoint.check_fields(
        {"origin", "toward", "out", "length"} | {ln.split(" =")[0] for ln in given.split("\n")}))


# ---- docs ----------------------------------------------------------------------------------------
def test_docs_group_table_is_the_generated_one():
    doc = (ROOT / "docs" / "model-format.md").read_text(encoding="utf-8")
    begin, end = doc.index(_schema.TABLE_BEGIN), doc.index(_schema.TABLE_END)
    block = doc[begin + len(_schema.TABLE_BEGIN) + 1:end]
    assert block == io.schema_table(), "run python docs/gen_groups.py"
    for name in registry():
        if name != "frame":
            assert f"| `{name}` |" in block and f"`.{name}`" in doc, name
    r = subprocess.run([sys.executable, str(ROOT / "docs" / "gen_groups.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_schema_table_rows():
    rows = io.schema_table().splitlines()
    rpr = next(r for r in rows if r.startswith("| `rpr_dyad` |"))
    assert "`length` (length > 0): \\|A–out\\| along the rod [m]" in rpr
    assert "`offset` (length, *optional*, 0)" in rpr and rpr.endswith("| [rod, sleeve] |")
    rigid = next(r for r in rows if r.startswith("| `rigid_point` |"))
    assert "`angle` (angle, *optional*)" in rigid and rigid.endswith("| [carrier], *optional* |")
    crank = next(r for r in rows if r.startswith("| `crank` |"))
    assert "`q` (angle coordinate)" in crank and "`out` (point it adds)" in crank
    assert all(r.count(" | ") == 3 for r in rows[2:])  # every pipe in a cell is escaped


# ---- a new group type is one module -------------------------------------------------------------
@pytest.fixture
def toy_type():
    """A group type registered by a test module alone (removed afterwards)."""

    @dataclass(frozen=True)
    class ToyDyad(Dyad):
        """An RRR dyad under another name."""
        type_name: ClassVar[str] = "toy_dyad"
        kind: ClassVar[str] = "toy dyad"
        link_roles: ClassVar = ("first", "second")

    base.register(ToyDyad)
    try:
        yield ToyDyad
    finally:
        base.unregister(ToyDyad)
        assert "toy_dyad" not in _schema.group_types()  # the derived schema follows


def test_a_registered_type_is_usable_in_files_and_docs(toy_type):
    text = SLOTTED.replace('type = "rpr_dyad"', 'type = "toy_dyad"').replace(
        'length = "l"\noffset = "e"\n', 'ra = "l"\nrb = "0.4 m"\n')
    m = io.loads(text, name="toy.toml").mechanism
    g = m.group("III")
    assert type(g) is toy_type and (g.ra, g.rb, g.links) == ("l", 0.4, ("rod", "sleeve"))
    assert "| `toy_dyad` | toy dyad |" in io.schema_table()
    with pytest.raises(ModelFileError, match=r"groups\[1\].links: expected 2 link names "
                                             r"\(first, second\)"):
        io.loads(text.replace('links = ["rod", "sleeve"]', 'links = ["rod"]'))
    with pytest.raises(ModelFileError, match='unknown group type "toy_dyda"; did you mean '
                                             '"toy_dyad"'):
        io.loads(text.replace('"toy_dyad"', '"toy_dyda"'))

