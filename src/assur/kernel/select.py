"""Branch-free conditional expressions for generated kernels.

The generated element loop is straight-line code in which ``a if c else b``
appears a few times per group (failure selects, guarded reciprocals). Numba turns
every conditional expression into two basic blocks and a φ variable, and its SSA
reconstruction and liveness passes cost (φ variables × blocks): the compile time
of a fused kernel grew quadratically with the number of groups (a 40-group chain:
33 s, of which 1 s in LLVM). :func:`branchless` rewrites every conditional
expression of the generated code as ``_sel(c, a, b)``, an intrinsic that lowers to
one LLVM ``select``: the element loop is one basic block, numba's passes are linear
and LLVM gets the select it would have formed by if-conversion anyway.

Both operands are evaluated. The generated code's operands have no side effects
and cannot raise (kernels use ``error_model="numpy"``: 1/0 is inf, sqrt(−1) is
NaN, and the select discards them), so the results are bitwise those of the
conditional expression.
"""

from __future__ import annotations

import ast

__all__ = ["branchless", "sel"]


def _make_sel():
    from numba import types
    from numba.extending import intrinsic

    @intrinsic
    def sel(typingctx, cond, a, b):
        """``a if cond else b`` without a branch (both are evaluated)."""
        if isinstance(a, types.Boolean) and isinstance(b, types.Boolean):
            res = types.boolean
        else:
            res = typingctx.unify_types(a, b)
            if res is None or not isinstance(res, types.Number):
                return None
        sig = res(cond, a, b)

        def codegen(context, builder, signature, args):
            c, x, y = args
            c = context.cast(builder, c, signature.args[0], types.boolean)
            x = context.cast(builder, x, signature.args[1], res)
            y = context.cast(builder, y, signature.args[2], res)
            return builder.select(c, x, y)

        return sig, codegen

    return sel


_made: list = []


def __getattr__(name):
    # ``sel`` is made on first use (by a generated kernel): importing assur does not
    # import numba
    if name == "sel":
        if not _made:
            _made.append(_make_sel())
        return _made[0]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class _IfExpToSel(ast.NodeTransformer):
    def visit_IfExp(self, node):
        self.generic_visit(node)
        return ast.copy_location(
            ast.Call(func=ast.Name("_sel", ast.Load()),
                     args=[node.test, node.body, node.orelse], keywords=[]), node)


def branchless(line: str) -> str:
    """``line`` (one indented statement or comment) with each ``a if c else b``
    written ``_sel(c, a, b)``; lines without one are returned unchanged.

    Examples
    --------
    >>> from assur.kernel.select import branchless
    >>> branchless("    st = 97 if ((st < 0) & (t6r > P28 + P9)) else st")
    '    st = _sel((st < 0) & (t6r > P28 + P9), 97, st)'
    >>> branchless("    t6ir = 1.0 / t6r if t6r > 0.0 else 0.0")
    '    t6ir = _sel(t6r > 0.0, 1.0 / t6r, 0.0)'
    >>> branchless("    x6 = x2 + t6dx")              # no conditional expression: unchanged
    '    x6 = x2 + t6dx'
    """
    if " if " not in line or line.lstrip().startswith("#"):
        return line
    indent = line[:len(line) - len(line.lstrip())]
    tree = _IfExpToSel().visit(ast.parse(line.strip()))
    return indent + ast.unparse(ast.fix_missing_locations(tree))
