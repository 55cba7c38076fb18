"""M(q), ∂M/∂q and Q(q) for the simulation: tabulated over one coordinate
(:class:`ReducedTable`) or evaluated exactly at the states (:class:`ExactEquations`)
(:mod:`assur.dynamics.simulate`)."""

from __future__ import annotations

import numpy as np

from .eom import equations_of_motion

__all__ = ["ReducedTable", "ExactEquations"]


class ReducedTable:
    """m(S), m'(S) and Q(S) of a one-coordinate mechanism at evenly spaced nodes,
    interpolated (cubic Hermite for m with its exact m', cubic spline for Q).

    Parameters
    ----------
    S : ndarray, shape (n,)
        Evenly spaced nodes [m].
    m, dm : ndarray, shape (n,)
        Reduced mass [kg] and its exact derivative [kg/m] at the nodes.
    Q : ndarray, shape (n,)
        Generalized force of the loads [N] at the nodes.

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics import equations_of_motion
    >>> from assur.dynamics.simulate import ReducedTable
    >>> mech = io.load(io.bundled("adapter_lab6")).mechanism     # seed 001 lab 6
    >>> S = np.linspace(0.55, 0.8, 51)                            # nodes [m]
    >>> eom = equations_of_motion(mech, S)
    >>> m, dm = eom.reduced_mass()
    >>> table = ReducedTable(S, m, dm, eom.generalized_forces)
    >>> m_mid, dm_mid, Q_mid = table(0.6775)                      # between two nodes [m]
    >>> round(float(m_mid), 2), round(float(Q_mid), 2)            # m [kg], Q [N]
    (39358.64, -58977.48)
    >>> exact = equations_of_motion(mech, [0.6775])               # solved there
    >>> round(float(exact.reduced_mass()[0][0]), 2), round(float(exact.generalized_forces[0]), 2)
    (39358.64, -58977.48)
    """

    def __init__(self, S, m, dm, Q):
        from scipy.interpolate import CubicSpline
        self.S = np.asarray(S, dtype=float)
        self.h = float(self.S[1] - self.S[0])
        self.m, self.dm, self.Q = (np.asarray(a, dtype=float) for a in (m, dm, Q))
        self.dQ = CubicSpline(self.S, self.Q)(self.S, 1)

    @classmethod
    def from_mechanism(cls, mech, s_min, s_max, nodes=801, g=None):
        """Solve ``mech`` at ``nodes`` lengths on [s_min, s_max] and tabulate.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics.simulate import ReducedTable
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism    # seed 001 lab 6
        >>> table = ReducedTable.from_mechanism(mech, 0.55, 0.8, nodes=51)   # stops [m]
        >>> table.S.size, round(table.h * 1e3, 6)                    # nodes, spacing [mm]
        (51, 5.0)
        >>> round(float(table.m[0]), 1)                              # m(S_min) [kg]
        51646.3
        """
        S = np.linspace(s_min, s_max, int(nodes))
        eom = equations_of_motion(mech.solve(S), g=g)
        m, dm = eom.reduced_mass()
        return cls(S, m, dm, eom.generalized_forces)

    def _hermite(self, s, y, dy):
        n = self.S.size
        x = (np.asarray(s, dtype=float) - self.S[0]) / self.h
        i = np.clip(np.floor(x), 0, n - 2).astype(int)
        t = x - i
        t2, t3 = t * t, t * t * t
        y0, y1, d0, d1 = y[i], y[i + 1], dy[i] * self.h, dy[i + 1] * self.h
        val = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * d0 + (3 * t2 - 2 * t3) * y1 \
            + (t3 - t2) * d1
        der = ((6 * t2 - 6 * t) * (y0 - y1) + (3 * t2 - 4 * t + 1) * d0
               + (3 * t2 - 2 * t) * d1) / self.h
        return val, der

    def __call__(self, s):
        """(m, dm/dS, Q) at the lengths ``s`` [kg, kg/m, N]."""
        m, dm = self._hermite(s, self.m, self.dm)
        Q, _ = self._hermite(s, self.Q, self.dQ)
        return m, dm, Q


    def mechanics(self, q):
        """M, ∂M/∂q and Q at the states' coordinates ``q`` (shape (1, m)) as arrays of
        shapes (m, 1, 1), (m, 1, 1, 1), (m, 1) [kg, kg/m, N].

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.simulate import ReducedTable
        >>> mech = io.load(io.bundled("adapter_lab6")).mechanism    # seed 001 lab 6
        >>> table = ReducedTable.from_mechanism(mech, 0.55, 0.8, nodes=51)
        >>> M, dM, Q = table.mechanics(np.array([[0.55, 0.675, 0.8]]))   # S [m]
        >>> M.shape, dM.shape, Q.shape
        ((3, 1, 1), (3, 1, 1, 1), (3, 1))
        >>> (M[:, 0, 0] / 1e3).round(3).tolist()      # m(S) at the nodes [t]
        [51.646, 39.313, 52.709]
        """
        if q.shape[1] == 1:  # the solver's hot path: one state, on Python floats
            m, dm, Q = self._scalar(float(q[0, 0]))
            return np.array([[[m]]]), np.array([[[[dm]]]]), np.array([[Q]])
        m, dm, Q = self(q[0])
        return m[:, None, None], dm[:, None, None, None], Q[:, None]

    def _scalar(self, s):
        """(m, dm/dS, Q) at one length, the same cubic Hermite as :meth:`__call__`."""
        if not hasattr(self, "_lists"):
            h = self.h
            self._lists = (self.m.tolist(), (self.dm * h).tolist(), self.Q.tolist(),
                           (self.dQ * h).tolist())
        mv, dmv, Qv, dQv = self._lists
        h = self.h
        x = (s - self.S[0]) / h
        i = min(max(int(x // 1), 0), self.S.size - 2)
        u = x - i
        u2 = u * u
        u3 = u2 * u
        h00, h10, h01, h11 = 2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, 3 * u2 - 2 * u3, u3 - u2
        Q = h00 * Qv[i] + h10 * dQv[i] + h01 * Qv[i + 1] + h11 * dQv[i + 1]
        m = h00 * mv[i] + h10 * dmv[i] + h01 * mv[i + 1] + h11 * dmv[i + 1]
        dm = ((6 * u2 - 6 * u) * (mv[i] - mv[i + 1]) + (3 * u2 - 4 * u + 1) * dmv[i]
              + (3 * u2 - 2 * u) * dmv[i + 1]) / h
        return m, dm, Q


class ExactEquations:
    """M(q), ∂M/∂q and Q(q) of a mechanism of k coordinates evaluated exactly at the
    states (the engine solved there, :func:`assur.dynamics.equations_of_motion`).

    Parameters
    ----------
    mechanism : Mechanism
    g : float
        Gravity [m/s²].

    Examples
    --------
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.dynamics.simulate import ExactEquations
    >>> exact = ExactEquations(io.load(io.bundled("adapter_lab6")).mechanism, g=9.81)
    >>> M, dM, Q = exact.mechanics(np.array([[0.675]]))    # S [m], one state
    >>> round(float(M[0, 0, 0]), 1), round(float(Q[0, 0]), 1)   # m [kg], Q [N]
    (39313.4, -58944.8)
    """

    def __init__(self, mechanism, g):
        self.mechanism = mechanism
        self.g = float(g)
        self.k = len(mechanism.coordinates)

    def mechanics(self, q):
        """M (m, k, k), ∂M/∂q (m, k, k, k) and Q (m, k) at the coordinates ``q``
        (shape (k, m)) [kg or kg·m², their derivatives, N or N·m].

        Raises
        ------
        AssemblyError
            A state where the mechanism does not assemble.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.dynamics.simulate import ExactEquations
        >>> exact = ExactEquations(io.load(io.bundled("adapter_lab6")).mechanism, g=9.81)
        >>> M, dM, Q = exact.mechanics(np.array([[0.55, 0.8]]))   # two states, S [m]
        >>> (M[:, 0, 0] / 1e3).round(3).tolist(), (Q[:, 0] / 1e3).round(2).tolist()  # [t], [kN]
        ([51.646, 52.709], [-58.56, -59.05])
        >>> exact.mechanics(np.array([[2.0]]))   # far past the stroke [m]  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        assur.errors.AssemblyError: cylinder–lever group 'I (2,3)' (links 2, 3) cannot assemble at position 0 (S = 2): ...
        """
        k, m = self.k, q.shape[1]
        pos = q[0] if k == 1 else q.T
        eom = equations_of_motion(self.mechanism.solve(pos, check_continuity=False),
                                  g=self.g)
        return (eom.mass_matrix.reshape(m, k, k), eom.mass_matrix_derivative.reshape(m, k, k, k),
                np.reshape(eom.generalized_forces, (m, k)))
