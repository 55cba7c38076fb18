"""What a group compiles against (:mod:`assur.core.compile_context`): slots in the order
points are first used, a parameter's row its index among the names, literals and
derived rows after them, the coordinates' indices; compiling the hitch's groups by
hand gives the program's own rows."""

from assur import examples
from assur.core.compile_context import CompileContext


def test_slots_rows_and_literals():
    c = CompileContext(("S", "T"), ("L3", "L4"))
    assert [c.slot(p) for p in ("01", "03", "01", "23")] == [0, 1, 0, 2]
    assert c.pref("L4") == 1 and c.pref(0.61) == ("lit", 0.61)
    assert (c.lref("S"), c.lref("T"), c.lref("L3")) == (-1, -2, 0)
    assert c.coord("T") == 1
    lit, der = c.pref(0.61), c.derived_row()
    assert c.resolve(lit) == 2 and c.resolve(der) == 3


def test_compiling_by_hand_gives_the_programs_slots():
    """The groups compiled one after the other against a fresh context: every point in
    the slot the program gave it, one row per group."""
    m = examples.hitch_003()
    prog = m.program()
    c = CompileContext(m.coordinates, tuple(m.params))
    rows = []
    for i, g in enumerate(m.groups):
        c.current = i
        for p in g.inputs():
            c.slot(p)
        rows.append(g.compile(c))
    assert len(rows) == len(prog.rows)
    assert {p: c.slot(p) for p in m.points} == dict(prog.slot)
