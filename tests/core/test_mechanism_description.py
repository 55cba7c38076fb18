"""The Mechanism is an immutable description whose solving entry points delegate
(issue 22): its methods live in small modules (assur.core._building, _checks,
_solving) and the class lists them; values kept with it go through one typed memo
contract (assur.core.memo) whose keys name a registered owner."""

from __future__ import annotations

import ast
import pathlib

import pytest

from assur import Mechanism, examples
from assur.core import memo as memo_mod
from assur.core.memo import OWNERS, Memo, check_key

ROOT = pathlib.Path(__file__).resolve().parents[2]
SRC = ROOT / "src" / "assur"

#: the public methods and properties of Mechanism before the split (issue 22)
PUBLIC = """add extended add_group frame link distance weight force moment spring mass
resisting_moment cylinder with_cylinders with_machine with_loads with_params with_gravity g
with_units with_motion motion with_tables points frame_points group defining_index
coordinate_kind topology owner bodies value_of evaluate_positions solve analyze evaluate memo
program prepared prepare coordinate_array cylinder_lever dyad crank slider_input slider_dyad
rigid_point pose_point rpr_dyad prp_dyad""".split()


def test_every_public_method_is_the_classs_own():
    own = vars(Mechanism)
    missing = [n for n in PUBLIC if n not in own]
    assert not missing
    assert Mechanism.solve.__qualname__ == "Mechanism.solve"
    assert Mechanism.add_load.__module__ == "assur.core._building"


def test_removed_names_are_gone():
    from assur.core import inputs
    from assur.dynamics import balancing
    assert not hasattr(Mechanism, "distance_angle")
    assert not hasattr(inputs, "is_checked") and "is_checked" not in inputs.__all__
    assert not hasattr(balancing, "path_of") and "path_of" not in balancing.__all__


# ---- module sizes (issue 22: ≤ ~600 lines per module, ≤ ~80 lines of code per function) --
SPLIT = [SRC / "core" / f for f in ("mechanism.py", "_building.py", "_checks.py",
                                    "_solving.py", "memo.py")]
SPLIT += sorted((SRC / "io").glob("_*.py"))


def _code_lines(node, lines):
    body = node.body
    doc = (0, -1)
    if body and isinstance(body[0], ast.Expr) and isinstance(getattr(body[0], "value", None),
                                                              ast.Constant):
        doc = (body[0].lineno, body[0].end_lineno)
    return sum(1 for i in range(node.lineno, node.end_lineno + 1)
               if not doc[0] <= i <= doc[1] and lines[i - 1].strip()
               and not lines[i - 1].strip().startswith("#"))


@pytest.mark.parametrize("path", SPLIT, ids=lambda p: p.name)
def test_modules_and_functions_stay_small(path):
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    assert len(lines) <= 600, f"{path.name}: {len(lines)} lines"
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            n = _code_lines(node, lines)
            assert n <= 80, f"{path.name}: {node.name} has {n} lines of code"


# ---- the memo contract ---------------------------------------------------------------------
def test_memo_keys_name_a_registered_owner():
    m = examples.hitch_003()
    with pytest.raises(TypeError, match="a memo key is a tuple"):
        m.memo("fused", lambda: 1)
    with pytest.raises(KeyError, match="memo owner 'fused' is not registered"):
        m.memo(("fused", "plan"), lambda: 1)
    assert m.memo(("statics", "test entry"), lambda: [1]) is m.memo(("statics", "test entry"),
                                                                     lambda: [2])


def test_every_memo_call_in_the_package_names_a_registered_owner():
    """Each ``.memo((owner, …), …)`` call written in the package uses a registered owner,
    and each owner is used by its module."""
    used = {}
    for path in SRC.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "memo" and node.args
                    and isinstance(node.args[0], ast.Tuple) and node.args[0].elts
                    and isinstance(node.args[0].elts[0], ast.Constant)):
                owner = node.args[0].elts[0].value
                module = ".".join(path.relative_to(SRC.parent).with_suffix("").parts)
                used.setdefault(owner, set()).add(module)
    assert set(used) <= set(OWNERS), sorted(set(used) - set(OWNERS))
    for owner, modules in used.items():
        home = OWNERS[owner].module   # the owner's module, or its package's modules
        assert all(m == home or m.startswith(home + ".") for m in modules), (owner, modules)


def test_a_copy_with_other_values_keeps_the_structural_entries():
    m = examples.hitch_003()
    prog = m.program()
    ptab = m.prepared(prog)[0]
    m2 = m.with_params(L4=0.65)                                   # [m]
    assert m2.program() is prog                                   # "program": structural
    assert m2.prepared(prog)[0] is not ptab                      # "prepared": not
    assert float(m2.prepared(prog)[0][prog.param_row("L4"), 0]) == 0.65


def test_memo_refuses_an_owner_of_another_module():
    with pytest.raises(ValueError, match="registered by assur.core.statics already"):
        memo_mod.register_owner("statics", "somewhere.else", "clash")
    assert check_key(("statics",)).module == "assur.core.statics"
    assert len(Memo().structural()) == 0
