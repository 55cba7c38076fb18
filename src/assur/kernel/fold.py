"""Constant folding of a generated element's straight-line code.

The group types emit their jets generically: a frame point's analogs are the
literal ``0.0``, a parameter length's derivative is ``0.0``, the input
coordinate's is ``1.0``, and the code multiplies and adds them like any other
value. The compiler cannot drop ``x * 0.0`` or ``x + 0.0`` (IEEE semantics: x may
be an infinity, or −0.0), so without folding every such term costs a multiply and
an add at every position (in the seed-003 hitch, about a third of the element's
arithmetic).

:func:`fold` propagates the names bound to numeric literals and simplifies with
the identities that hold for every finite operand: ``x·0 = 0``, ``x·1 = x``,
``x ± 0 = x``, ``0 − x = −x``, ``x/1 = x``, ``−(−x) = x``, literal arithmetic, and
conditional expressions with a literal test. The results differ from the
unfolded code at most in the sign of a zero: an element whose values are not
finite is a failed one (its group's status is set by a select on finite
conditions) and its outputs are written as 0.
"""

from __future__ import annotations

import ast
import math
import operator

__all__ = ["fold"]

_ARITH = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
          ast.Div: operator.truediv}
_CMP = {ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt,
        ast.GtE: operator.ge, ast.Eq: operator.eq, ast.NotEq: operator.ne}


def _num(node):
    """The float value of a numeric literal node (``-c`` included), else None."""
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return float(node.value)
    if (isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub)
            and isinstance(node.operand, ast.Constant)
            and type(node.operand.value) in (int, float)):
        return -float(node.operand.value)
    return None


def _lit(v: float):
    """A node for the finite float ``v`` (a negative one as ``-c``, which unparses
    with the right precedence)."""
    if math.copysign(1.0, v) < 0:
        return ast.UnaryOp(ast.USub(), ast.Constant(-v))
    return ast.Constant(v)


def _neg(node):
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return node.operand
    v = _num(node)
    if v is not None:
        return _lit(-v)
    return ast.UnaryOp(ast.USub(), node)


class _Folder(ast.NodeTransformer):
    def __init__(self):
        self.consts: dict[str, float] = {}

    def visit_Name(self, node):
        if isinstance(node.ctx, ast.Load) and node.id in self.consts:
            return _lit(self.consts[node.id])
        return node

    def visit_UnaryOp(self, node):
        self.generic_visit(node)
        if isinstance(node.op, ast.USub):
            inner = node.operand
            if isinstance(inner, ast.UnaryOp) and isinstance(inner.op, ast.USub):
                return inner.operand
        return node

    def visit_BinOp(self, node):
        self.generic_visit(node)
        op = type(node.op)
        a, b = _num(node.left), _num(node.right)
        if op not in _ARITH:
            return node
        if a is not None and b is not None:
            try:
                v = _ARITH[op](a, b)
            except ZeroDivisionError:
                return node
            return _lit(v) if math.isfinite(v) else node
        if op is ast.Mult:
            if a == 0.0 or b == 0.0:
                return _lit(0.0)
            if a == 1.0:
                return node.right
            if b == 1.0:
                return node.left
            if a == -1.0:
                return _neg(node.right)
            if b == -1.0:
                return _neg(node.left)
        elif op is ast.Add:
            if a == 0.0:
                return node.right
            if b == 0.0:
                return node.left
        elif op is ast.Sub:
            if b == 0.0:
                return node.left
            if a == 0.0:
                return _neg(node.right)
        elif op is ast.Div:
            if b == 1.0:
                return node.left
        return node

    def visit_Compare(self, node):
        self.generic_visit(node)
        if len(node.ops) == 1 and type(node.ops[0]) in _CMP:
            a, b = _num(node.left), _num(node.comparators[0])
            if a is not None and b is not None:
                return ast.Constant(_CMP[type(node.ops[0])](a, b))
        return node

    def visit_IfExp(self, node):
        self.generic_visit(node)
        if isinstance(node.test, ast.Constant) and isinstance(node.test.value, bool):
            return node.body if node.test.value else node.orelse
        return node

    def visit_Call(self, node):
        self.generic_visit(node)
        if (isinstance(node.func, ast.Name) and node.func.id == "abs" and len(node.args) == 1
                and _num(node.args[0]) is not None):
            return _lit(abs(_num(node.args[0])))
        return node


def fold(lines: list[str]) -> list[str]:
    """The element lines ``lines`` (indented assignments and comments, in order)
    with literal values propagated and the finite-operand identities applied.

    Every assignment is kept (a name bound to a literal may be an output; the
    compiler drops the unused ones); each line keeps its indentation.

    Examples
    --------
    >>> from assur.kernel.fold import fold
    >>> lines = ["    x0_0 = 0.0",                       # a frame point's analog [m/m]
    ...          "    t4r1 = t4ra * 1.0 + t4m11 * x0_0 + t4m12 * y0_0",
    ...          "    t4r2 = 0.0 * 0.0 - (a * a + b * b) + t4m21 * x0_0",
    ...          "    x4 = x0 + t4a * t4ux - (-1.0) * t4h * t4uy",
    ...          "    st = 69 if ((st < 0) & (t4L == 0.0)) else st"]
    >>> for line in fold(lines):
    ...     print(line)
        x0_0 = 0.0
        t4r1 = t4ra + t4m12 * y0_0
        t4r2 = -(a * a + b * b)
        x4 = x0 + t4a * t4ux - -t4h * t4uy
        st = 69 if (st < 0) & (t4L == 0.0) else st
    >>> fold(["    x = 1.0 if 0.5 > 0.0 else 2.0", "    y = x * z"])   # literal test
    ['    x = 1.0', '    y = z']
    """
    folder = _Folder()
    out = []
    for line in lines:
        s = line.strip()
        if not s or s.startswith("#"):
            out.append(line)
            continue
        indent = line[:len(line) - len(s)]
        tree = ast.parse(s)
        stmt = tree.body[0]
        if not (len(tree.body) == 1 and isinstance(stmt, ast.Assign)
                and len(stmt.targets) == 1 and isinstance(stmt.targets[0], ast.Name)):
            # not a plain assignment: substitute and simplify, bind nothing
            out.append(indent + ast.unparse(ast.fix_missing_locations(folder.visit(tree))))
            continue
        stmt.value = folder.visit(stmt.value)
        name = stmt.targets[0].id
        v = _num(stmt.value)
        if v is not None:
            folder.consts[name] = v
        else:
            folder.consts.pop(name, None)
        out.append(indent + ast.unparse(ast.fix_missing_locations(tree)))
    return out
