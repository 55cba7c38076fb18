"""Extra columns a model declares (``assur.core.columns``; DESIGN.md §11): formulas
evaluated by a whitelisted expression walker (never ``eval``), column sign maps,
``[model] gravity`` — general hooks, so that no seed is named in the core."""

import re

import numpy as np
import pytest

from assur import examples, io
from assur.core.columns import Formula, FormulaError, SignMap, parse
from assur.io import ModelFileError
from assur.views.report import seed_tables
from assur.core.statics import GRAVITY
from tests.helpers.mechanisms import LIFT

TABLES = '[tables]\nratios = [["5", "3"]]\ntransmissions = ["56"]\n'
assert TABLES in LIFT


def lift(extra, name="lift.toml"):
    return io.loads(LIFT.replace(TABLES, TABLES + extra), name=name)


# ---- the expression walker --------------------------------------------------------------
@pytest.mark.parametrize("expr", [
    "__import__('os').system('true')",
    "X.__class__",
    "P[0]",
    "(lambda: 1)()",
    "P if P else 1",
    "P < 1",
    "'text'",
    "sqrt(x=P)",
    "open('f')",
    "[P]",
    "P and 1",
    "True",
    "P @ P",
    "P // 2",
])
def test_anything_but_arithmetic_is_refused(expr):
    with pytest.raises(FormulaError):
        parse(expr)


@pytest.mark.parametrize("expr,message", [
    ("(P", "cannot read the expression"),
    ("X(1, 2)", "X() takes one point"),
    ("atan2(P)", "atan2() takes 2 arguments"),
    ("foo(P)", "unknown function foo()"),
    ("X(P + 1)", "expected the name of a point"),
    ("", "non-empty"),
    ("-" * 2000 + "1", "at most 1000 characters"),
])
def test_refusals_say_what_is_wrong(expr, message):
    with pytest.raises(FormulaError, match=re.escape(message)):
        parse(expr)


def test_a_deeply_nested_expression_is_a_formula_error():
    with pytest.raises(FormulaError):
        parse("(" * 400 + "1" + ")" * 400)


def test_names_points_and_links_are_collected():
    f = Formula("q", "sqrt(X(S6)**2 + Y(56)**2) * cos(phi(\"5\")) / L - pi + dphi(3) + S")
    assert f.names == {"L", "S"} and f.points == {"S6", "56"} and f.links == {"5", "3"}


def test_formula_values_match_the_kinematics(hitch_analysis):
    a = hitch_analysis
    kin, mech = a.kinematics, a.mechanism
    f = Formula("t", "L56*cos(phi(5)) + X(05) - X(56) + I(S6)*S + 2**-1 - abs(-dphi(3))")
    got = f.evaluate(kin)
    want = (mech.params["L56"] * np.cos(kin.phi("5")) + mech.params["X05"] - kin.x("56")
            + kin.transmission("S6") * kin.q("S") + 0.5 - np.abs(kin.dphi("3")))
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    assert got.shape == kin.shape


def test_formula_over_a_batch_of_designs():
    s = examples.hitch_003_range()
    P6 = np.array([27500.0, 30000.0])
    a = examples.hitch_003(P6=P6).analyze(s)
    got = a.formula("GS6max")
    assert got.shape == (2, 10)
    x = a.kinematics.x("S6")
    r_amin = 0.2 * (P6[:, None] + 56000.0 + 8000.0)
    np.testing.assert_allclose(got, (56000.0 * 1.62 + 8000.0 * (0.6 + 2.96) - r_amin) / x,
                               rtol=1e-12)


def test_division_by_zero_is_an_error_naming_the_formula(hitch_analysis):
    with pytest.raises(FormulaError, match=r"formula 'z' = 1/\(S - S\)"):
        Formula("z", "1/(S - S)").evaluate(hitch_analysis.kinematics)


def test_unknown_names_are_refused_against_the_mechanism():
    m = examples.hitch_003()
    for expr, what in (("P7 + 1", "unknown name 'P7'"), ("X(S9)", "unknown point 'S9'"),
                       ("phi(9)", "unknown link '9'")):
        with pytest.raises(FormulaError, match=re.escape(what)):
            Formula("bad", expr).check(m)


def test_sign_map_is_checked():
    with pytest.raises(ValueError, match="1 or -1"):
        SignMap(("R05x",), 2, "")
    with pytest.raises(ValueError, match="column names"):
        SignMap((), -1, "")


# ---- model files ---------------------------------------------------------------------------
def test_a_formula_in_a_file_becomes_a_column_in_its_unit():
    """``unit = "kN"``: the SI value divided by 1000; no ``table``: a table "F" of its
    own; the flags become its notes."""
    model = lift('[[tables.formulas]]\nname = "M56"\nunit = "kN*m"\n'
                 'expr = "P * (X(56) - X(05))"\nflags = ["a note"]\n')
    a = model.mechanism.analyze(model.range)
    tabs = {t.id: t for t in seed_tables(a)}
    t = tabs["F"]
    assert t.symbols == ["S", "M56"] and t.column("M56").unit == "kN*m"
    kin = a.kinematics
    np.testing.assert_allclose(t["M56"], 27.5 * (kin.x("56") - kin.x("05")), rtol=1e-12)
    assert [n["en"] for n in t.notes] == ["a note"]
    np.testing.assert_allclose(a.formula("M56"), 1e3 * t["M56"], rtol=1e-12)
    with pytest.raises(KeyError, match="no formula 'M5'"):
        a.formula("M5")


def test_the_hitch_gs6max_column_is_in_table_6_1_flagged(hitch_analysis):
    t = next(t for t in seed_tables(hitch_analysis) if t.id == "6.1")
    assert t.symbols[-1] == "GS6max" and t.column("GS6max").unit == "N"
    assert any("subtracts a force" in n["en"] for n in t.notes)
    np.testing.assert_array_equal(t["GS6max"], hitch_analysis.formula("GS6max"))


@pytest.mark.parametrize("extra,key,at,message", [
    ('[[tables.formulas]]\nname = "F1"\nexpr = "P * Q"\n', "tables.formulas[0].expr",
     "expr =", "unknown name 'Q'"),
    ('[[tables.formulas]]\nname = "F1"\nexpr = "__import__(P)"\n', "tables.formulas[0].expr",
     "expr =", "unknown function __import__()"),
    ('[[tables.formulas]]\nname = "F1"\nexpr = "P"\nunit = "furlongs per fish"\n',
     "tables.formulas[0].unit", "unit =", "unit"),
    ('[[tables.formulas]]\nname = "F1"\nexpr = "P"\ntable = "6,1"\n',
     "tables.formulas[0].table", "table =", 'did you mean "6.1"'),
    ('[[tables.formulas]]\nname = "F1"\nexpr = "P"\n[[tables.formulas]]\nname = "F2"\n'
     'expr = "P"\n[[tables.formulas]]\nname = "F1"\nexpr = "P"\n', "tables.formulas[2].name",
     'name = "F1"\nexpr = "P"\n\0', "already used"),
    ('[[tables.formulas]]\nname = "F1"\n', "tables.formulas[0].expr", "[[tables.formulas]]",
     'missing required key "expr"'),
    ('[[tables.signs]]\ncolumns = ["R05x"]\nsign = 2\n', "tables.signs[0].sign", "sign =",
     "1 or -1"),
    ('reactions = { R05 = ["0", "5", -1] }\n', "tables.reactions.R05", "reactions =",
     "expected at most 2 items"),
])
def test_formula_sign_and_reaction_errors_are_located(extra, key, at, message):
    with pytest.raises(ModelFileError) as exc:
        lift(extra)
    e = exc.value
    assert e.key_path == key and message in e.problem, str(e)
    lines = LIFT.replace(TABLES, TABLES + extra).splitlines()
    if at.endswith("\0"):  # the last line starting with the first line of ``at``
        want = max(i for i, l in enumerate(lines, 1) if l == at.split("\n")[0])
    else:
        want = next(i for i, l in enumerate(lines, 1) if l.startswith(at))
    assert e.line == want, str(e)


def test_sign_maps_mark_columns_and_carry_their_note():
    model = lift('reactions = { R05 = ["0", "5"] }\n'
                 '[[tables.signs]]\ncolumns = ["R05x", "F_S"]\nsign = -1\n'
                 'note = "printed as the force of 5 on 0"\n')
    a = model.mechanism.analyze(model.range)
    tabs = {t.id: t for t in seed_tables(a)}
    t51, t41 = tabs["5.1"], tabs["4.1"]
    assert t51.column("R05x").printed_sign == -1 and t51.column("R05y").printed_sign == 1
    assert t41.column("F_S").printed_sign == -1
    for t in (t51, t41):
        assert any(n["en"] == "printed as the force of 5 on 0" for n in t.notes)
    plain = a.statics.to_frame()
    printed = a.statics.to_frame(printed_signs=True)
    np.testing.assert_array_equal(printed["R05x"], -plain["R05x"])
    np.testing.assert_array_equal(printed["R05y"], plain["R05y"])
    np.testing.assert_array_equal(printed["F_S"], -plain["F_S"])


# ---- gravity ------------------------------------------------------------------------------
MASS = '[[loads]]\ntype = "mass"\nlink = "5"\nm = "100 kg"\npoint = "56"\n'


def test_gravity_default_and_the_model_s_own():
    base = LIFT.replace("[[cylinders]]", MASS + "\n[[cylinders]]")
    m981 = io.loads(base, name="a.toml")
    m = io.loads(base.replace('notes = [', 'gravity = "9.80665 m/s^2"\nnotes = ['),
                 name="b.toml")
    assert GRAVITY == 9.81 and m981.mechanism.g == 9.81
    assert m.mechanism.g == 9.80665
    a1 = m981.mechanism.analyze(m981.range)
    a2 = m.mechanism.analyze(m.range)
    f_w = 27500.0 * a1.kinematics.transmission("56")   # the weight P at 56, in N
    f1 = a1.statics.actuator_force("S") - f_w          # the mass' part
    f2 = a2.statics.actuator_force("S") - f_w
    np.testing.assert_allclose(f2 / f1, 9.80665 / 9.81, rtol=1e-9)
    # the keyword still wins
    a3 = m.mechanism.analyze(m.range, g=9.81)
    np.testing.assert_allclose(a3.statics.actuator_force("S"), a1.statics.actuator_force("S"),
                               rtol=1e-12)


@pytest.mark.parametrize("value,message", [('"9.81 m/s"', "expected an acceleration"),
                                           ('"-9.81 m/s^2"', "positive")])
def test_gravity_is_checked(value, message):
    with pytest.raises(ModelFileError) as exc:
        io.loads(LIFT.replace('notes = [', f'gravity = {value}\nnotes = ['), name="g.toml")
    assert exc.value.key_path == "model.gravity" and message in exc.value.problem
    assert exc.value.line == 5
