"""Symbols that write code: trace plain arithmetic into a generated kernel.

A :class:`Sym` stands for a scalar local variable of the generated element loop.
Arithmetic on symbols and numbers, and the numpy ufuncs the group and load code
uses (``np.hypot``, ``np.cos``, ``np.arctan2``…, dispatched through
``__array_ufunc__``), emit one assignment each into an
:class:`~assur.kernel.emit.Emitter` and return the symbol of the result. Numbers
combine with numbers in Python (constants are folded): only what involves a symbol
is written (a symbol plus 0.0 is still one line; the compiler sees it). This lets one implementation of a group's reactions or of a load
serve both the array evaluation and the fused kernel (:mod:`assur.core.outputs`).
"""

from __future__ import annotations

import numbers

import numpy as np

__all__ = ["Sym", "Tracer"]

_BINARY = {np.add: "+", np.subtract: "-", np.multiply: "*", np.true_divide: "/",
           np.power: "**"}
_CALLS = {np.arctan2: "math.atan2", np.sin: "math.sin",
          np.cos: "math.cos", np.tan: "math.tan", np.sqrt: "math.sqrt",
          np.arcsin: "math.asin", np.arccos: "math.acos", np.arctan: "math.atan",
          np.exp: "math.exp", np.log: "math.log", np.absolute: "abs",
          np.copysign: "math.copysign"}


class Tracer:
    """Names and emits the temporaries of traced expressions into ``E``.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.emit import Emitter
    >>> from assur.kernel.sym import Tracer
    >>> E = Emitter(1)
    >>> t = Tracer(E, prefix="f")
    >>> F = -t.sym("P16") * np.cos(t.sym("T4"))       # a force's x component [N]
    >>> F, t.n, [line.strip() for line in E.lines]
    (Sym(f2), 3, ['f0 = -P16', 'f1 = math.cos(T4)', 'f2 = f0 * f1'])
    """

    def __init__(self, E, prefix="z"):
        self.E = E
        self.prefix = prefix
        self.n = 0

    def new(self, expr: str) -> "Sym":
        """Assign ``expr`` to a new local and return its symbol.

        Examples
        --------
        >>> from assur.kernel.emit import Emitter
        >>> from assur.kernel.sym import Tracer
        >>> E = Emitter(1)
        >>> t = Tracer(E)
        >>> t.new("x7 - x2"), t.new("y7 - y2")
        (Sym(z0), Sym(z1))
        >>> [line.strip() for line in E.lines]
        ['z0 = x7 - x2', 'z1 = y7 - y2']
        """
        name = f"{self.prefix}{self.n}"
        self.n += 1
        self.E(f"{name} = {expr}")
        return Sym(name, self)

    def sym(self, name: str) -> "Sym":
        """The symbol of an existing local (or expression without side effects).

        Examples
        --------
        >>> from assur.kernel.emit import Emitter
        >>> from assur.kernel.sym import Tracer
        >>> E = Emitter(1)
        >>> t = Tracer(E)
        >>> x = t.sym("x7")                        # no line emitted for an existing local
        >>> E.lines
        []
        >>> (x - 1.0).name, E.lines[0].strip()
        ('z0', 'z0 = x7 - 1.0')
        """
        return Sym(name, self)


def code(v) -> str:
    """Source text of a symbol or a number."""
    if isinstance(v, Sym):
        return v.name
    if isinstance(v, np.ndarray) and v.ndim == 0:
        v = v[()]
    if isinstance(v, numbers.Real):
        return repr(float(v))
    raise TypeError(f"cannot trace {type(v).__name__} into a kernel")


class Sym:
    """A scalar local of the generated code (see the module docstring).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.emit import Emitter
    >>> from assur.kernel.sym import Tracer
    >>> E = Emitter(1)
    >>> t = Tracer(E)
    >>> dx, dy = t.sym("t6dx"), t.sym("t6dy")
    >>> r = 2.0 * np.hypot(dx, dy) * (0.5 * 4.0)     # 0.5 * 4.0 is folded in Python
    >>> r, [line.strip() for line in E.lines]
    (Sym(z2), ['z0 = math.sqrt(t6dx * t6dx + t6dy * t6dy)', 'z1 = 2.0 * z0', 'z2 = z1 * 2.0'])
    >>> np.arctan2(dy, dx).name, E.lines[-1].strip()
    ('z3', 'z3 = math.atan2(t6dy, t6dx)')
    """

    __slots__ = ("name", "tracer")
    __array_priority__ = 1000

    def __init__(self, name, tracer):
        self.name = name
        self.tracer = tracer

    def _bin(self, op, other, reverse=False):
        a, b = (code(other), code(self)) if reverse else (code(self), code(other))
        return self.tracer.new(f"{a} {op} {b}")

    def __add__(self, o):
        return self._bin("+", o)

    def __radd__(self, o):
        return self._bin("+", o, True)

    def __sub__(self, o):
        return self._bin("-", o)

    def __rsub__(self, o):
        return self._bin("-", o, True)

    def __mul__(self, o):
        return self._bin("*", o)

    def __rmul__(self, o):
        return self._bin("*", o, True)

    def __truediv__(self, o):
        return self._bin("/", o)

    def __rtruediv__(self, o):
        return self._bin("/", o, True)

    def __pow__(self, o):
        return self._bin("**", o)

    def __neg__(self):
        return self.tracer.new(f"-{self.name}")

    def __pos__(self):
        return self

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            return NotImplemented
        tracer = next(x.tracer for x in inputs if isinstance(x, Sym))
        if ufunc in _BINARY:
            return tracer.new(f"{code(inputs[0])} {_BINARY[ufunc]} {code(inputs[1])}")
        if ufunc is np.negative:
            return tracer.new(f"-{code(inputs[0])}")
        if ufunc is np.positive:
            return inputs[0]
        if ufunc is np.hypot:
            # √(a² + b²): a libm hypot call would keep the element loop from being
            # vectorized; the lengths of a model are bounded (assur.core.inputs), no overflow
            a, b = (code(x) for x in inputs)
            return tracer.new(f"math.sqrt({a} * {a} + {b} * {b})")
        if ufunc in _CALLS:
            return tracer.new(f"{_CALLS[ufunc]}({', '.join(code(x) for x in inputs)})")
        return NotImplemented

    def __repr__(self):
        return f"Sym({self.name})"
