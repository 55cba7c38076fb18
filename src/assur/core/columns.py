"""Extra table columns a model declares: named formulas and column sign maps.

Seeds tabulate quantities that are not assur's results — a value computed by a
formula the seed prints (sometimes a wrong one), or a column printed with the
opposite sign to its name. A model reproduces them through two general hooks
(DESIGN.md §11), never through code keyed on a seed:

* :class:`Formula` — a named column computed by a small arithmetic expression
  over the model's parameters, its generalized coordinates and the kinematic
  quantities of its points and links, with the unit it is shown in, the report
  table it joins and optional flags (what is wrong with it) shown as warnings;
* :class:`SignMap` — columns of the report tables that a source prints multiplied
  by a sign, with the note that explains why.

Both are plain data in ``Mechanism.tables`` (``"formulas"``, ``"signs"``); a
model file declares them in ``[[tables.formulas]]`` and ``[[tables.signs]]``
(``docs/model-format.md``).

Expressions
-----------
An expression is parsed by :mod:`ast` and evaluated by walking the tree; only
these nodes are accepted (anything else — attributes, subscripts, comparisons,
lambdas, strings outside a point argument, keyword arguments — is refused when
the formula is made), so nothing in a file is ever executed:

* numbers; ``+ - * / **``; unary ``-`` and ``+``; parentheses;
* names: the model's parameters [SI], its generalized coordinates [m or rad],
  ``pi``;
* ``X(p)``, ``Y(p)`` — coordinates of point ``p`` [m]; ``I(p)`` — its transmission
  number dY/dq [-] (one coordinate); ``phi(l)`` — angle of link ``l`` [rad];
  ``dphi(l)``, ``ddphi(l)`` — its first and second analogs; ``dist(d)`` — a named
  distance [m], ``ddist(d)`` — its analog dd/dq. The point or link is written bare
  (``X(S6)``, ``X(05)``, ``phi(5)``) or as a string (``X("05")``);
* ``sqrt``, ``sin``, ``cos``, ``tan``, ``asin``, ``acos``, ``atan``, ``atan2``,
  ``hypot``, ``abs``, ``exp``, ``log`` of expressions.

The value is computed in SI over the positions (and designs) of a result; the
formula's ``unit`` only says how it is shown (``scale`` = SI value of one unit),
so a formula that is dimensionally wrong — as a seed may print it — is
reproduced as written, and flagged.
"""

from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass, field

import numpy as np

from ..errors import ModelError

__all__ = ["Formula", "SignMap", "FormulaError", "formulas_of", "signs_of", "column_signs"]

#: the ids of the report's tables, in order (a formula's ``table`` names one of them;
#: the report, :mod:`assur.views.report.tables`, builds them)
TABLE_IDS = ("2.1", "2.2", "3.1", "4.1", "G", "5.1", "5.2", "D", "6.1", "IC", "L")

#: functions of one point (name → kinematics accessor)
POINT_FUNCTIONS = ("X", "Y", "I")
#: functions of one link
LINK_FUNCTIONS = ("phi", "dphi", "ddphi")
#: functions of one named distance ([distances]): its length and its analog d/dq
DISTANCE_FUNCTIONS = ("dist", "ddist")
#: arithmetic functions and their arity
MATH_FUNCTIONS = {"sqrt": (np.sqrt, 1), "sin": (np.sin, 1), "cos": (np.cos, 1),
                  "tan": (np.tan, 1), "asin": (np.arcsin, 1), "acos": (np.arccos, 1),
                  "atan": (np.arctan, 1), "atan2": (np.arctan2, 2), "hypot": (np.hypot, 2),
                  "abs": (np.abs, 1), "exp": (np.exp, 1), "log": (np.log, 1)}
CONSTANTS = {"pi": math.pi}
#: longest expression accepted [characters]
MAX_LENGTH = 1000

_BARE_REF = re.compile(r"\b(X|Y|I|phi|dphi|ddphi|dist|ddist)\(\s*([0-9A-Za-z_]+)\s*\)")
_BINOPS = {ast.Add: np.add, ast.Sub: np.subtract, ast.Mult: np.multiply,
           ast.Div: np.divide, ast.Pow: np.power}
_UNARY = {ast.USub: np.negative, ast.UAdd: np.positive}


class FormulaError(ModelError):
    """An expression that is not a formula of the accepted form, or that names
    something the model does not have.

    Examples
    --------
    >>> from assur.core.columns import Formula, FormulaError
    >>> try:
    ...     Formula("bad", "X(56).real")
    ... except FormulaError as e:
    ...     print(e)
    only numbers, names, + - * / **, parentheses and the listed functions are allowed; found Attribute "X('56').real"
    >>> issubclass(FormulaError, ValueError)
    True
    """


def _ref(node, what):
    """The point or link a function argument names (str)."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value:
        return node.value
    if isinstance(node, ast.Constant) and type(node.value) is int and node.value >= 0:
        return str(node.value)
    raise FormulaError(f"expected the name of a {what} (e.g. S6, 56 or \"56\"), found "
                       f"{ast.unparse(node)!r}")


def _check(node, names, points, links, distances=None):
    """Refuse every node outside the accepted grammar; collect the names used."""
    if distances is None:
        distances = set()
    if isinstance(node, ast.Expression):
        return _check(node.body, names, points, links, distances)
    if isinstance(node, ast.Constant):
        if type(node.value) not in (int, float):
            raise FormulaError(f"expected a number, found {ast.unparse(node)}")
        return
    if isinstance(node, ast.Name):
        names.add(node.id)
        return
    if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
        _check(node.left, names, points, links, distances)
        _check(node.right, names, points, links, distances)
        return
    if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
        _check(node.operand, names, points, links, distances)
        return
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        f = node.func.id
        if f in DISTANCE_FUNCTIONS:
            if len(node.args) != 1:
                raise FormulaError(f"{f}() takes one distance, found {len(node.args)} "
                                   f"arguments")
            distances.add(_ref(node.args[0], "distance"))
            return
        if f in POINT_FUNCTIONS or f in LINK_FUNCTIONS:
            if len(node.args) != 1:
                raise FormulaError(f"{f}() takes one {'point' if f in POINT_FUNCTIONS else 'link'}"
                                   f", found {len(node.args)} arguments")
            if f in POINT_FUNCTIONS:
                points.add(_ref(node.args[0], "point"))
            else:
                links.add(_ref(node.args[0], "link"))
            return
        if f in MATH_FUNCTIONS:
            n = MATH_FUNCTIONS[f][1]
            if len(node.args) != n:
                raise FormulaError(f"{f}() takes {n} argument{'s' if n > 1 else ''}, found "
                                   f"{len(node.args)}")
            for a in node.args:
                _check(a, names, points, links, distances)
            return
        known = ", ".join(list(POINT_FUNCTIONS) + list(LINK_FUNCTIONS)
                          + list(DISTANCE_FUNCTIONS) + list(MATH_FUNCTIONS))
        raise FormulaError(f"unknown function {f}(); the functions are: {known}")
    what = type(node).__name__
    raise FormulaError(f"only numbers, names, + - * / **, parentheses and the listed functions "
                       f"are allowed; found {what} {ast.unparse(node)!r}")


def parse(expr: str):
    """Parse and check ``expr``: ``(tree, names, points, links, distances)``.

    Raises
    ------
    FormulaError
        For a syntax error or anything outside the accepted grammar (module notes).
    """
    if not isinstance(expr, str) or not expr.strip():
        raise FormulaError("expected a non-empty expression")
    if len(expr) > MAX_LENGTH:
        raise FormulaError(f"expected an expression of at most {MAX_LENGTH} characters, found "
                           f"{len(expr)}")
    # a point or link written bare (X(05), phi(5), X(S6)) is its name: quote it, so that
    # names with leading zeros read as names
    text = _BARE_REF.sub(lambda m: f'{m.group(1)}("{m.group(2)}")', expr.strip())
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as e:
        raise FormulaError(f"cannot read the expression {expr.strip()!r}: {e.msg}") from None
    except (RecursionError, MemoryError, ValueError):
        raise FormulaError("cannot read the expression: it is nested too deeply") from None
    names, points, links, distances = set(), set(), set(), set()
    try:
        _check(tree, names, points, links, distances)
    except RecursionError:
        raise FormulaError("cannot read the expression: it is nested too deeply") from None
    return (tree, frozenset(names - set(CONSTANTS)), frozenset(points), frozenset(links),
            frozenset(distances))


@dataclass(frozen=True)
class Formula:
    """A named column computed by an expression (module notes).

    Parameters
    ----------
    name : str
        The column's symbol, e.g. ``"GS6max"``.
    expr : str
        The expression, e.g. ``"(P_mcxa*b + P_gr*(a + L) - 0.2*(P6 + P_mcxa + P_gr))/X(S6)"``.
    unit : str, optional
        The unit the column is shown in (``"N"``, ``"kN"``, ``"deg"``, ``"-"``).
        Default ``"-"``.
    scale : float, optional
        SI value of one ``unit``: the column shows ``value/scale``. Default 1.
    table : str or None, optional
        Id of the report table the column joins (``"6.1"``); None: a table of
        the model's formulas.
    label : str or None, optional
        Description shown with the column; default ``"<name> = <expr>"``.
    flags : tuple of str, optional
        What is wrong with the formula (a seed's slip), shown as warnings beside it.

    Raises
    ------
    FormulaError
        If ``expr`` is not an accepted expression or ``scale`` is not positive.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.columns import Formula
    >>> f = Formula("I56", "I(56)", table="3.1")     # the transmission dY56/dS [-]
    >>> r = examples.hitch_003().solve([0.42, 0.67])  # S [m]
    >>> [round(float(v), 3) for v in f.evaluate(r)]  # I56, seed 003's last table [-]
    [4.459, 2.621]
    >>> f.label is None, f.unit                       # described as "I56 = I(56)"
    (True, '-')
    """

    name: str
    expr: str
    unit: str = "-"
    scale: float = 1.0
    table: str | None = None
    label: str | None = None
    flags: tuple = ()
    _parsed: tuple = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name.strip():
            raise FormulaError(f"a formula needs a name, got {self.name!r}")
        scale = float(self.scale)
        if not (math.isfinite(scale) and scale > 0):
            raise FormulaError(f"formula {self.name}: scale must be a positive number, got "
                               f"{self.scale!r}")
        object.__setattr__(self, "scale", scale)
        object.__setattr__(self, "flags", tuple(self.flags))
        object.__setattr__(self, "_parsed", parse(self.expr))

    @property
    def names(self) -> frozenset:
        """Parameter and coordinate names the expression uses.

        Examples
        --------
        >>> from assur.core.columns import Formula
        >>> f = Formula("GS6max", "(P_mcxa*b + P_gr*(a + L) - 0.2*(P6 + P_mcxa + P_gr)) / X(S6)")
        >>> sorted(f.names)
        ['L', 'P6', 'P_gr', 'P_mcxa', 'a', 'b']
        """
        return self._parsed[1]

    @property
    def points(self) -> frozenset:
        """Points named by ``X``, ``Y``, ``I``.

        Examples
        --------
        >>> from assur.core.columns import Formula
        >>> sorted(Formula("h", "hypot(X(56) - X(05), Y(56) - Y(05)) + I(S6)").points)
        ['05', '56', 'S6']
        """
        return self._parsed[2]

    @property
    def links(self) -> frozenset:
        """Links named by ``phi``, ``dphi``, ``ddphi``.

        Examples
        --------
        >>> from assur.core.columns import Formula
        >>> sorted(Formula("mu", "phi(6) - phi(7) + 0*dphi(5) + ddphi('34')").links)
        ['34', '5', '6', '7']
        """
        return self._parsed[3]

    @property
    def distances(self) -> frozenset:
        """Named distances of ``dist``, ``ddist``.

        Examples
        --------
        >>> from assur.core.columns import Formula
        >>> sorted(Formula("v", "dist(l9) * ddist(l7)").distances)
        ['l7', 'l9']
        """
        return self._parsed[4]

    def check(self, mechanism):
        """Refuse names, points and links that ``mechanism`` does not have.

        Raises
        ------
        FormulaError
            Naming the first unknown name, point or link and what is known.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.columns import Formula
        >>> m = examples.hitch_003()
        >>> Formula("dY", "Y(56) - Y(05)").check(m)      # every point exists: no error
        >>> Formula("dY", "Y(56) - Y(99)").check(m)
        Traceback (most recent call last):
        ...
        assur.core.columns.FormulaError: unknown point '99' in 'Y(56) - Y(99)': expected one of 01, 03, 05, 07, 23, 34, 45, 56, 67, S6, F610
        """
        known = set(mechanism.params) | set(mechanism.coordinates)
        for n in sorted(self.names):
            if n not in known:
                raise FormulaError(f"unknown name {n!r} in {self.expr!r}: expected a parameter "
                                   f"or a coordinate ({', '.join(sorted(known))}) or pi")
        for p in sorted(self.points):
            if p not in mechanism.points:
                raise FormulaError(f"unknown point {p!r} in {self.expr!r}: expected one of "
                                   f"{', '.join(mechanism.points)}")
        links = [l.name for l in mechanism.links]
        for l in sorted(self.links):
            if l not in links:
                raise FormulaError(f"unknown link {l!r} in {self.expr!r}: expected one of the "
                                   f"named links ({', '.join(links)})")
        dists = [d.name for d in mechanism.distances]
        for d in sorted(self.distances):
            if d not in dists:
                raise FormulaError(f"unknown distance {d!r} in {self.expr!r}: expected one of "
                                   f"the named distances ({', '.join(dists) or 'none'})")

    def compute(self, terms):
        """The expression's value from ``terms`` (one walker for every kind of value).

        Parameters
        ----------
        terms : mapping
            ``terms["name"](n)`` — a parameter or a coordinate [SI]; ``terms[f](ref)``
            for ``f`` in ``X Y I phi dphi ddphi dist ddist`` — the kinematic quantity
            of a point, link or distance. Arrays for :meth:`evaluate`; the symbols of
            the fused kernel or the dual numbers of the sensitivities for
            :mod:`assur.core.outputs` (numpy's functions dispatch on them).

        Returns
        -------
        value
            Of the type ``terms`` gives [SI].

        Examples
        --------
        Over plain numbers (a stand-in for the kinematics):

        >>> from assur.core.columns import Formula
        >>> f = Formula("Fx", "P*cos(phi(3)) + X(56)")
        >>> terms = {"name": {"P": 2.0}.get, "phi": lambda l: 0.0, "X": lambda p: 0.5}
        >>> float(f.compute(terms))
        2.5
        """
        def walk(node):
            if isinstance(node, ast.Expression):
                return walk(node.body)
            if isinstance(node, ast.Constant):
                return np.float64(node.value)
            if isinstance(node, ast.Name):
                if node.id in CONSTANTS:
                    return np.float64(CONSTANTS[node.id])
                return terms["name"](node.id)
            if isinstance(node, ast.BinOp):
                return _BINOPS[type(node.op)](walk(node.left), walk(node.right))
            if isinstance(node, ast.UnaryOp):
                return _UNARY[type(node.op)](walk(node.operand))
            f = node.func.id
            if f in POINT_FUNCTIONS:
                return terms[f](_ref(node.args[0], "point"))
            if f in LINK_FUNCTIONS:
                return terms[f](_ref(node.args[0], "link"))
            if f in DISTANCE_FUNCTIONS:
                return terms[f](_ref(node.args[0], "distance"))
            return MATH_FUNCTIONS[f][0](*(walk(a) for a in node.args))

        return walk(self._parsed[0])

    def evaluate(self, kin) -> np.ndarray:
        """The formula over the positions (and designs) of ``kin`` [SI].

        Parameters
        ----------
        kin : Kinematics
            A result of :meth:`assur.Mechanism.solve`.

        Returns
        -------
        numpy.ndarray
            Shape ``kin.shape``.

        Raises
        ------
        FormulaError
            Where the formula divides by zero, leaves its domain or overflows: the
            message names the formula and the first such position (never a NaN or an
            infinity in a result).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.columns import formulas_of
        >>> m = examples.hitch_003()
        >>> gs6max = formulas_of(m)[0]                    # as the seed computes it (flagged)
        >>> [round(float(v)) for v in gs6max.evaluate(m.solve([0.42, 0.67]))]   # table 6.1 [N]
        [50645, 57569]
        """
        mech = kin.mechanism
        self.check(mech)

        def param(name):
            v = np.asarray(mech.params[name], dtype=float)
            if v.ndim == 1 and v.shape[0] > 1:  # an array over designs
                return v.reshape((-1,) + (1,) * (len(kin.shape) - 1))
            return v.reshape(()) if v.ndim == 1 else v

        terms = {"X": kin.x, "Y": kin.y, "I": kin.transmission, "phi": kin.phi,
                 "dphi": kin.dphi, "ddphi": kin.ddphi, "dist": kin.length,
                 "ddist": kin.dlength,
                 "name": lambda n: kin.q(n) if n in mech.coordinates else param(n)}

        # floating-point exceptions become errors (never silenced into NaN/inf)
        try:
            with np.errstate(all="raise"):
                out = np.array(np.broadcast_to(np.asarray(self.compute(terms),
                                                          dtype=float), kin.shape))
        except (FloatingPointError, ZeroDivisionError, OverflowError, ValueError) as e:
            raise FormulaError(f"formula {self.name!r} = {self.expr}: cannot be evaluated "
                               f"over the positions ({e})") from None
        if not np.isfinite(out).all():
            i = int(np.flatnonzero(~np.isfinite(out.ravel()))[0])
            raise FormulaError(f"formula {self.name!r} = {self.expr}: not finite at element "
                               f"{i} ({out.ravel()[i]!r})")
        return out


@dataclass(frozen=True)
class SignMap:
    """Columns a source prints multiplied by ``sign``, and why.

    Parameters
    ----------
    columns : tuple of str
        Column symbols of the report tables, e.g. ``("R05x", "R05y")``.
    sign : int
        +1 or −1: the printed column is ``sign`` × assur's value.
    note : str
        The explanation shown with the table and in the report's warnings.

    Examples
    --------
    >>> from assur.core.columns import SignMap
    >>> s = SignMap(["R05x", "R05y"], -1, "printed with the opposite sign")
    >>> s.columns, s.sign
    (('R05x', 'R05y'), -1)
    >>> SignMap(["R05x"], 2)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: the sign of a sign map is 1 or -1, got 2
    """

    columns: tuple
    sign: int = -1
    note: str = ""

    def __post_init__(self):
        cols = tuple(self.columns)
        if not cols or not all(isinstance(c, str) and c for c in cols):
            raise ModelError(f"a sign map needs column names, got {self.columns!r}")
        if isinstance(self.sign, bool) or self.sign not in (1, -1):
            raise ModelError(f"the sign of a sign map is 1 or -1, got {self.sign!r}")
        object.__setattr__(self, "columns", cols)
        object.__setattr__(self, "sign", int(self.sign))


def formulas_of(mechanism) -> tuple:
    """The mechanism's :class:`Formula` objects (``tables["formulas"]``).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.columns import formulas_of
    >>> [(f.name, f.table, f.unit, len(f.flags)) for f in formulas_of(examples.hitch_003())]
    [('GS6max', '6.1', 'N', 3)]
    """
    return tuple(mechanism.tables.get("formulas", ()))


def signs_of(mechanism) -> tuple:
    """The mechanism's :class:`SignMap` objects (``tables["signs"]``).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.columns import signs_of
    >>> s = signs_of(examples.hitch_003())[0]        # seed 003 §5.2–5.3
    >>> s.columns, s.sign
    (('R05x', 'R05y', 'R34x', 'R34y', 'R45x', 'R45y'), -1)
    """
    return tuple(mechanism.tables.get("signs", ()))


def column_signs(mechanism) -> dict:
    """``{column symbol: sign}`` of every column a sign map names.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.columns import column_signs
    >>> signs = column_signs(examples.hitch_003())
    >>> signs["R05x"], signs["R45y"], "R56x" in signs
    (-1, -1, False)
    """
    return {c: s.sign for s in signs_of(mechanism) for c in s.columns}
