"""The links a model file without ``[links]`` gets from its groups
(``assur.io._links.derived_links``, docs/model-format.md "[links] and [distances]"):
one per named body with two points or more, from its first point to its second;
a file with ``[links]`` gets exactly its own."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.io._links import derived_links
from assur.views.report import seed_tables

#: the seed-004 crane's bodies (Mechanism.bodies order) and their first two points
CRANE_LINKS = [("3", "A", "B"), ("1", "O", "B"), ("4", "Bc", "E"), ("a2", "P0", "E"),
               ("c2", "E", "G"), ("2", "O1", "G")]


@pytest.fixture(scope="module")
def lv185():
    model = io.load(io.bundled("crane_lv185"))
    analysis = model.analyze()
    tables = {t.id: t for t in seed_tables(analysis)}
    return model.mechanism, analysis.kinematics, tables


def _angle(kin, tail, head):
    return np.arctan2(kin.y(head) - kin.y(tail), kin.x(head) - kin.x(tail))


def test_crane_lv185_gets_the_links_of_its_named_bodies(lv185):
    mech, kin, _ = lv185
    assert [(l.name, l.tail, l.head) for l in mech.links] == CRANE_LINKS
    assert kin.links == tuple(n for n, _, _ in CRANE_LINKS)
    assert mech.tables["derived_links"] == kin.links
    # the rule: a named body's first two points, the frame and one-point bodies left out
    for name, tail, head in CRANE_LINKS:
        assert mech.bodies[name]["points"][:2] == [tail, head]
    assert "0" not in kin.links


def test_crane_lv185_table_2_1_angles_are_the_directions_of_the_named_points(lv185):
    """φ<link> of table 2.1 [°] is atan2 of the link's two points (Kinematics x, y) at
    every position (modulo 360° whatever the table's angle convention)."""
    _, kin, tables = lv185
    t = tables["2.1"]
    assert [c.symbol for c in t.columns] == ["S1", "S2"] + [f"phi{n}" for n, _, _ in CRANE_LINKS]
    for name, tail, head in CRANE_LINKS:
        col = t.column(f"phi{name}")
        want = np.degrees(_angle(kin, tail, head))
        diff = np.mod(col.values - want + 180.0, 360.0) - 180.0
        assert len(col.values) == 64
        np.testing.assert_allclose(diff, 0.0, atol=1e-9)
        assert col.label == {"en": f"angle of link {name} ({tail} → {head})",
                             "ru": f"угол звена {name} ({tail} → {head})"}
    assert any("[links]" in n["en"] and "[links]" in n["ru"] for n in t.notes)
    assert any("[links]" in n["en"] for n in tables["3.1"].notes)


def test_crane_lv185_table_3_1_analogs_are_the_finite_differences_of_the_angles(lv185):
    """dφ<link>_<S> of table 3.1 [rad/m] against central differences of the angles of the
    links' two points along S1 and S2 (h = 1e-6 m: truncation ~h², rounding ~1e-10)."""
    mech, _, tables = lv185
    t = tables["3.1"]
    q = np.stack([t.column("S1").values, t.column("S2").values], axis=-1)
    h = 1e-6
    checked = 0
    for j, c in enumerate(("S1", "S2")):
        step = np.zeros(2)
        step[j] = h
        plus, minus = mech.solve(q + step), mech.solve(q - step)
        for name, tail, head in CRANE_LINKS:
            symbol = f"dphi{name}_{c}"
            turn = np.angle(np.exp(1j * (_angle(plus, tail, head) - _angle(minus, tail, head))))
            fd = turn / (2 * h)
            if symbol not in [col.symbol for col in t.columns]:
                # left out along a coordinate that does not turn the link (a note says so)
                assert c == "S2" and name in ("3", "1")
                np.testing.assert_allclose(fd, 0.0, atol=1e-8)
                continue
            np.testing.assert_allclose(t.column(symbol).values, fd, rtol=1e-6, atol=1e-8)
            checked += 1
    assert checked == 10


def test_a_file_with_links_gets_exactly_its_own():
    """hitch_003 writes [links]: its links, table 2.1 columns and labels stay."""
    model = io.load(io.bundled("hitch_003"))
    mech = model.mechanism
    assert [l.name for l in mech.links] == ["2", "3", "34", "4", "5", "6", "7"]
    assert "derived_links" not in mech.tables
    t = next(t for t in seed_tables(model.analyze()) if t.id == "2.1")
    assert [c.symbol for c in t.columns] == ["S", "phi2", "phi3", "phi34", "phi4", "phi5",
                                             "phi6", "phi7"]
    assert t.column("phi3").label["en"] == "angle of link 3"
    assert not any("[links]" in n["en"] for n in t.notes)


TINY = """
[model]
name = "tiny"
coordinates = ["S"]

[params]
L3 = "200 mm"

[range]
S = { from = "0.42 m", to = "0.67 m", count = 3 }

[frame]
"01" = [0.415, 0.563]
"03" = [0.25, 1.112]
"05" = [0.9, 1.0]

[[groups]]
type = "cylinder_lever"
name = "I"
base = "01"
pivot = "03"
out = "23"
lever = "L3"
s = "S"
branch = -1
links = ["2", "3"]

[[groups]]
type = "rigid_point"
name = "arm"
origin = "03"
toward = "23"
out = "34"
length = "0.3 m"
angle = "30 deg"
links = ["3"]

[[groups]]
type = "dyad"
name = "II"
a = "34"
b = "05"
out = "45"
ra = "0.5 m"
rb = "0.45 m"
branch = 1
"""


def test_a_tiny_file_without_links_gets_its_derived_links():
    """Named bodies give links (the cylinder 2 too); the unnamed links of dyad II
    ("II:a", "II:b") and the frame do not."""
    mech = io.loads(TINY, name="tiny.toml").mechanism
    assert set(mech.bodies) == {"0", "2", "3", "II:a", "II:b"}
    assert mech.bodies["3"]["points"] == ["03", "23", "34"]
    assert [(l.name, l.tail, l.head) for l in mech.links] == [("2", "01", "23"),
                                                              ("3", "03", "23")]
    assert mech.tables["derived_links"] == ("2", "3")
    bare = io.loads(TINY + "\n[links]\n", name="tiny.toml").mechanism  # none of its own
    assert derived_links(bare) == mech.links
    r = mech.solve([0.42, 0.67])
    for name, tail, head in (("2", "01", "23"), ("3", "03", "23")):
        np.testing.assert_allclose(r.phi(name), np.arctan2(r.y(head) - r.y(tail),
                                                            r.x(head) - r.x(tail)))


def test_links_in_the_file_turn_the_derivation_off():
    """A [links] table, even an empty one, is the file's whole choice."""
    one = io.loads(TINY + '\n[links]\n"3" = ["03", "34"]\n', name="tiny.toml").mechanism
    assert [(l.name, l.tail, l.head) for l in one.links] == [("3", "03", "34")]
    assert "derived_links" not in one.tables
    none = io.loads(TINY + "\n[links]\n", name="tiny.toml").mechanism
    assert none.links == () and "derived_links" not in none.tables


def test_a_distance_keeps_its_angle_name():
    """A [distances] angle named like a body stays the distance's direction; the other
    bodies are derived."""
    text = TINY + '\n[distances]\nd = { a = "01", b = "34", angle = "3" }\n'
    mech = io.loads(text, name="tiny.toml").mechanism
    assert [(l.name, l.tail, l.head) for l in mech.links] == [("3", "01", "34"),
                                                              ("2", "01", "23")]
    assert mech.tables["derived_links"] == ("2",)
