"""Complex-step derivatives of any output with respect to a parameter: the
independent reference the exact sensitivities are checked against (tests) and timed
against (``benchmarks/sensitivity.py``).

The plain-numpy group, load and reaction code (:func:`assur.synthesis.sensitivity.jet_outputs`
without parameter jets) runs with one parameter given an imaginary step ``h·i``;
``Im(f)/h`` is ∂f/∂p exact to rounding for h = 1e-30 (Squire & Trapp 1998). Numpy has
no complex ``arctan2``, ``hypot``, ``abs``, ``maximum``, ``minimum`` or ``copysign``,
and compares complex numbers differently: :class:`CStep` gives their analytic
continuations near the real axis and compares real parts.
"""

from __future__ import annotations

import numpy as np

__all__ = ["CStep", "complex_step", "H"]

#: the imaginary step [parameter unit]
H = 1e-30


class CStep(np.ndarray):
    """A complex array whose ufuncs numpy lacks for complex numbers (``arctan2``,
    ``hypot``, ``abs``, ``maximum``, ``minimum``, ``copysign``) are their analytic
    continuations near the real axis, and whose comparisons look at the real parts:
    complex step through code written for real arrays.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.sensitivity.cstep import CStep
    >>> h = 1e-30                                        # the imaginary step [rad]
    >>> y = np.array([1.0 + 1j * h, -2.0]).view(CStep)   # a step in y[0] only
    >>> a = np.arctan2(y, 1.0)                           # numpy has no complex arctan2 [rad]
    >>> [round(float(v), 6) for v in a.real]             # atan2(1, 1) = π/4, atan2(−2, 1)
    [0.785398, -1.107149]
    >>> [float(v) for v in a.imag / h]                   # ∂atan2(y, 1)/∂y = 1/(1 + y²) [1/rad]
    [0.5, 0.0]
    >>> bool(np.maximum(y, 0.0)[1] == 0.0), bool((y > 0)[0])   # compared by their real parts
    (True, True)
    """

    def __array_ufunc__(self, ufunc, method, *inputs, **kw):
        if any(hasattr(type(x), "__array_ufunc__") and not isinstance(x, np.ndarray)
               for x in inputs):
            return NotImplemented  # a dual: its own rules
        args = [np.asarray(x) for x in inputs]
        res = None
        if method == "__call__" and not kw:
            res = _cs_call(ufunc, args)
        if res is None:
            res = getattr(ufunc, method)(*args, **kw)
        if np.iscomplexobj(res):  # 0-d results too (numpy would give a scalar)
            return np.asarray(res).view(CStep)
        return res


def _cs_call(ufunc, args):
    re = [np.real(a) for a in args]
    if ufunc is np.arctan2:
        y, x = args
        yr, xr = re
        off = np.arctan2(yr, xr)
        # each branch divides by the larger of the two where it is taken; where it is
        # not, by 1 (a tiny other component must not overflow the discarded quotient)
        wide = (np.abs(xr) >= np.abs(yr)) & (xr != 0)
        xs, ys = np.where(wide, x, 1.0), np.where(np.abs(xr) < np.abs(yr), y, 1.0)
        a = np.arctan(y / xs) + (off - np.arctan(yr / np.real(xs)))
        b = -np.arctan(x / ys) + (off + np.arctan(xr / np.real(ys)))
        return np.where(np.abs(xr) >= np.abs(yr), a, b)
    if ufunc is np.hypot:
        return np.sqrt(args[0] * args[0] + args[1] * args[1])
    if ufunc is np.absolute:
        return np.where(re[0] >= 0, args[0], -args[0])
    if ufunc in (np.maximum, np.minimum):
        pick = re[0] >= re[1] if ufunc is np.maximum else re[0] <= re[1]
        return np.where(pick, args[0], args[1])
    if ufunc is np.copysign:
        return np.where(np.signbit(re[0]) == np.signbit(re[1]), args[0], -args[0])
    if ufunc in (np.less, np.less_equal, np.greater, np.greater_equal, np.equal,
                 np.not_equal):
        return ufunc(*re)
    return None


def _cs(v):
    return np.asarray(np.asarray(v, dtype=complex) + 1j * H).view(CStep)


def complex_step(mech, q, params, outputs):
    """∂output/∂parameter by complex step, shape (*positions, outputs, params)
    [output unit / parameter unit, SI], as :attr:`Sensitivities.jacobian`.

    Parameters
    ----------
    mech : Mechanism
    q : array_like
        Positions as for :meth:`Mechanism.solve` [m or rad].
    params : sequence of str
        Parameters, one complex-step pass each.
    outputs : sequence of str
        :mod:`assur.core.outputs` output names.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import sensitivities
    >>> from assur.synthesis.sensitivity.cstep import complex_step
    >>> m = examples.hitch_003()
    >>> j = complex_step(m, [0.42, 0.67], ["L4"], ["Y(56)"])   # S [m]
    >>> j.shape, [round(float(v), 4) for v in j[:, 0, 0]]      # ∂Y56/∂L4 [m/m]
    ((2, 1, 1), [-2.1958, -1.9565])
    >>> exact = sensitivities(m, [0.42, 0.67], params=["L4"], outputs=["Y(56)"]).jacobian
    >>> float(abs(j - exact).max()) < 1e-12                    # the jets agree [m/m]
    True
    """
    from . import jet_outputs

    cols, shape = [], None
    for p in params:
        res, _, shape, _ = jet_outputs(mech, q, (), outputs, step=(p, _cs))
        cols.append(np.stack([np.imag(v) / H for v, _ in res], -1))   # (m, n, O)
    return np.stack(cols, -1).reshape(tuple(shape) + (len(outputs), len(params)))
