"""Forward-mode dual numbers over numpy arrays, nestable (hyper-dual jets).

A :class:`Dual` is ``val + der·ε`` with ε a vector of P nilpotent directions
(ε_i·ε_j = 0): ``val`` has the array's shape, ``der`` one more trailing axis of
length P holding ∂val/∂p_i. Arithmetic and the numpy ufuncs the group, load and
reaction code of :mod:`assur.groups` and :mod:`assur.core.loads` uses (``np.sqrt``,
``np.hypot``, ``np.arctan2``, ``np.cos``…, dispatched through
``__array_ufunc__``) apply the chain rule exactly, so running that plain-numpy code
on duals gives its value and its exact derivatives (to rounding) at once.

``val`` and ``der`` may themselves be duals (in other directions): a dual in the
parameters whose parts are duals in the generalized coordinates carries the value,
∂/∂q (the kinematic analogs), ∂/∂p and the mixed ∂²/∂q∂p — the derivative of an
analog, hence of a cylinder force, a pressure or a capacity, with respect to a
parameter. Every rule is written with ufuncs on the parts, so the nesting needs no
extra code.

Examples
--------
>>> import numpy as np
>>> x = Dual(np.array([1.0, 2.0]), np.array([[1.0], [1.0]]))
>>> y = np.hypot(x, 3.0) * np.sin(x)
>>> bool(np.allclose(y.der[:, 0], (x.val / np.hypot(x.val, 3.0)) * np.sin(x.val)
...                   + np.hypot(x.val, 3.0) * np.cos(x.val)))
True
"""

from __future__ import annotations

import numpy as np

__all__ = ["Dual", "base", "expand", "where", "variables"]


def base(x):
    """The plain value under any nesting of duals (an ndarray or a number).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.dual import Dual, base
    >>> inner = Dual(np.array([0.42]), np.ones((1, 1)))     # a dual in q
    >>> outer = Dual(inner, np.zeros((1, 2)))                # a dual in two parameters
    >>> [float(v) for v in base(outer)], base(2.5)          # S [m], a plain number
    ([0.42], 2.5)
    """
    while isinstance(x, Dual):
        x = x.val
    return x


def expand(x):
    """``x[..., None]`` for a number, an array or a dual (to multiply a derivative).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.dual import Dual, expand
    >>> expand(np.array([1.0, 2.0])).shape, expand(3.0).shape
    ((2, 1), (1,))
    >>> expand(Dual(np.array([1.0, 2.0]), np.ones((2, 3)))).shape   # val (2, 1), der (2, 1, 3)
    (2, 1)
    """
    if isinstance(x, Dual):
        return x[..., None]
    return np.asanyarray(x)[..., None]


def where(cond, a, b):
    """``np.where`` for duals: the value and every derivative taken from ``a`` where
    ``cond`` holds, from ``b`` elsewhere.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.dual import variables, where
    >>> x, = variables([np.array([-2.0, 3.0])])
    >>> y = where(x.val > 0, x * x, -x)       # x² where positive, −x elsewhere
    >>> [float(v) for v in y.val], [float(v) for v in y.der[:, 0]]   # value, ∂y/∂x
    ([2.0, 9.0], [-1.0, 6.0])
    """
    cond = np.asarray(cond, dtype=bool)
    if not isinstance(a, Dual) and not isinstance(b, Dual):
        out = np.where(cond, a, b)
        for x in (a, b):  # keep an array subclass (a complex-step array in the tests)
            if isinstance(x, np.ndarray) and type(x) is not np.ndarray:
                return out.view(type(x))
        return out
    da = a.der if isinstance(a, Dual) else 0.0
    db = b.der if isinstance(b, Dual) else 0.0
    va = a.val if isinstance(a, Dual) else a
    vb = b.val if isinstance(b, Dual) else b
    return Dual(where(cond, va, vb), where(cond[..., None], da, db))


def _parts(x):
    return (x.val, x.der) if isinstance(x, Dual) else (x, None)


def _add(a, b, sign=1.0):
    va, da = _parts(a)
    vb, db = _parts(b)
    val = va + vb if sign > 0 else va - vb
    if db is None:
        return Dual(val, da)
    if da is None:
        return Dual(val, db if sign > 0 else -db)
    return Dual(val, da + db if sign > 0 else da - db)


def _mul(a, b):
    va, da = _parts(a)
    vb, db = _parts(b)
    if db is None:
        return Dual(va * vb, da * expand(vb))
    if da is None:
        return Dual(va * vb, expand(va) * db)
    return Dual(va * vb, da * expand(vb) + expand(va) * db)


def _div(a, b):
    va, da = _parts(a)
    vb, db = _parts(b)
    val = va / vb
    if db is None:
        return Dual(val, da / expand(vb))
    if da is None:
        return Dual(val, -expand(val / vb) * db)
    return Dual(val, (da - expand(val) * db) / expand(vb))


def _unary(x, f, fprime):
    """f(x) with derivative f'(x)·dx."""
    return Dual(f(x.val), expand(fprime(x.val)) * x.der)


def _pow(a, b):
    if isinstance(b, Dual):
        return np.exp(b * np.log(a))
    c = float(b)
    if c == 2.0:
        return _mul(a, a)
    return _unary(a, lambda v: v ** c, lambda v: c * v ** (c - 1.0))


def _atan2(y, x):
    vy, dy = _parts(y)
    vx, dx = _parts(x)
    val = np.arctan2(vy, vx)
    r2 = vx * vx + vy * vy
    der = 0.0
    if dy is not None:
        der = expand(vx / r2) * dy
    if dx is not None:
        der = der - expand(vy / r2) * dx
    return Dual(val, der)


_UNARY = {
    np.sqrt: (np.sqrt, lambda v: 0.5 / np.sqrt(v)),
    np.sin: (np.sin, np.cos),
    np.cos: (np.cos, lambda v: -np.sin(v)),
    np.tan: (np.tan, lambda v: 1.0 / (np.cos(v) * np.cos(v))),
    np.arcsin: (np.arcsin, lambda v: 1.0 / np.sqrt(1.0 - v * v)),
    np.arccos: (np.arccos, lambda v: -1.0 / np.sqrt(1.0 - v * v)),
    np.arctan: (np.arctan, lambda v: 1.0 / (1.0 + v * v)),
    np.exp: (np.exp, np.exp),
    np.log: (np.log, lambda v: 1.0 / v),
}
_COMPARE = (np.less, np.less_equal, np.greater, np.greater_equal, np.equal, np.not_equal,
            np.isfinite, np.isnan, np.isinf, np.signbit)


class Dual:
    """A value and its exact derivatives in P directions (see the module docstring).

    Parameters
    ----------
    val : ndarray, number or Dual
        The value, any shape (a dual for nested jets).
    der : ndarray, number or Dual
        ∂val/∂p_i along a trailing axis of length P (broadcastable to
        ``shape + (P,)``; a scalar 0 for none).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.dual import Dual
    >>> x = Dual(np.array([3.0, 4.0]), np.array([[1.0, 0.0], [1.0, 0.0]]))   # ∂x/∂p1 = 1
    >>> r = np.hypot(x, 4.0)                  # |(x, 4)| and its derivatives
    >>> [round(float(v), 6) for v in r.val], [round(float(v), 6) for v in r.der[:, 0]]  # r, x/r
    ([5.0, 5.656854], [0.6, 0.707107])
    >>> [float(v) for v in r.der[:, 1]]       # no dependence on p2
    [0.0, 0.0]
    """

    __slots__ = ("val", "der")
    __array_priority__ = 1000

    def __init__(self, val, der):
        self.val = val
        self.der = der

    @property
    def shape(self):
        """The shape of the plain value (under any nesting of duals).

        Examples
        --------
        >>> import numpy as np
        >>> from assur.synthesis.sensitivity.dual import variables
        >>> x, y = variables([np.zeros((2, 3)), 1.0])
        >>> x.shape, y.shape, x.der.shape          # der: one more axis, the 2 variables
        ((2, 3), (), (2, 3, 2))
        """
        return np.shape(base(self))

    def __getitem__(self, idx):
        if not isinstance(idx, tuple):
            idx = (idx,)
        der = self.der
        if np.ndim(base(der)) > 0:  # a derivative broadcast as a scalar stays one
            der = der[idx + (slice(None),)] if Ellipsis in idx else der[idx]
        return Dual(self.val[idx], der)

    # arithmetic --------------------------------------------------------------------
    def __add__(self, o):
        return _add(self, o)

    def __radd__(self, o):
        return _add(o, self)

    def __sub__(self, o):
        return _add(self, o, -1.0)

    def __rsub__(self, o):
        return _add(o, self, -1.0)

    def __mul__(self, o):
        return _mul(self, o)

    def __rmul__(self, o):
        return _mul(o, self)

    def __truediv__(self, o):
        return _div(self, o)

    def __rtruediv__(self, o):
        return _div(o, self)

    def __pow__(self, o):
        return _pow(self, o)

    def __neg__(self):
        return Dual(-self.val, -self.der)

    def __pos__(self):
        return self

    def __abs__(self):
        return where(base(self) >= 0, self, -self)

    # comparisons act on the plain value (branch choices, failure checks)
    def __lt__(self, o):
        return base(self) < base(o)

    def __le__(self, o):
        return base(self) <= base(o)

    def __gt__(self, o):
        return base(self) > base(o)

    def __ge__(self, o):
        return base(self) >= base(o)

    def __eq__(self, o):
        return base(self) == base(o)

    def __ne__(self, o):
        return base(self) != base(o)

    __hash__ = None

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            return NotImplemented
        if ufunc in _COMPARE:
            return ufunc(*(base(x) for x in inputs))
        if ufunc is np.add:
            return _add(*inputs)
        if ufunc is np.subtract:
            return _add(*inputs, -1.0)
        if ufunc is np.multiply:
            return _mul(*inputs)
        if ufunc is np.true_divide:
            return _div(*inputs)
        if ufunc is np.power:
            return _pow(*inputs)
        if ufunc is np.square:
            return _mul(inputs[0], inputs[0])
        if ufunc is np.negative:
            return -inputs[0]
        if ufunc is np.positive:
            return inputs[0]
        if ufunc is np.absolute:
            return abs(inputs[0])
        if ufunc is np.arctan2:
            return _atan2(*inputs)
        if ufunc is np.hypot:
            a, b = inputs
            return np.sqrt(a * a + b * b)
        if ufunc in (np.maximum, np.minimum):
            a, b = inputs
            pick = base(a) >= base(b) if ufunc is np.maximum else base(a) <= base(b)
            return where(pick, a, b)
        if ufunc is np.copysign:
            a, b = inputs
            same = np.signbit(base(a)) == np.signbit(base(b))
            return where(same, a, -a)
        if ufunc in _UNARY:
            f, fp = _UNARY[ufunc]
            return _unary(inputs[0], f, fp)
        return NotImplemented

    def __repr__(self):
        return f"Dual(shape={self.shape})"


def variables(values, inner=None):
    """Duals of P independent variables, ``values`` a sequence of arrays (or numbers):
    the i-th has derivative 1 in direction i (trailing axis of length P) and 0 in the
    others. With ``inner`` (a function of a value) each value is first made a dual
    in other directions (nesting).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.dual import variables
    >>> a, b = variables([2.0, np.array([1.0, 3.0])])
    >>> f = a * b + np.sin(a)                 # ∂f/∂a = b + cos a, ∂f/∂b = a
    >>> [round(float(v), 6) for v in f.der[:, 0]], [float(v) for v in f.der[:, 1]]   # [-]
    ([0.583853, 2.583853], [2.0, 2.0])
    """
    P = len(values)
    out = []
    for i, v in enumerate(values):
        e = np.zeros(P)
        e[i] = 1.0
        val = np.asarray(v, dtype=float)
        der = np.broadcast_to(e, val.shape + (P,)).copy()
        out.append(Dual(val if inner is None else inner(val), der))
    return out
