"""The result of a simulation in time (:mod:`assur.dynamics.simulate`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["SimulationResult"]


@dataclass
class SimulationResult:
    """The motion of the machine in time, in the manner of scipy's OdeResult.

    Arrays over the coordinates have shape (n,) for one coordinate and (n, k) for
    k > 1 (columns in the order of :attr:`coordinates`).

    Attributes
    ----------
    status : int
        0: reached ``t_end``; −1: the integration failed (``message`` says why).
    message : str
    success : bool
    t : ndarray, shape (n,)
        Times [s].
    q, qdot, qddot : ndarray
        q [m], q̇ [m/s], q̈ [m/s²].
    p1, p2 : ndarray
        Pressure at each branch's node and at its cylinder [Pa] (lab 6 fig. 6.3;
        eq. 3).
    p1dot : ndarray
        ṗ1 [Pa/s] (fig. 6.4).
    pump_pressure : ndarray, shape (n,)
        The pump's pressure max_j p1_j [Pa] (= p1 for one cylinder).
    flows : dict of ndarray
        ``pump`` (n,), and per branch ``relief``, ``cylinder`` (A·u), ``compression``
        (ṗ1·V/E) [m³/s].
    force : ndarray
        The cylinders' forces σ·A·p2 along the coordinates [N].
    load : ndarray
        The loads on the rods −Q(q) (lab 6: P6·I(S)) [N].
    reduced_mass, reduced_mass_derivative : ndarray
        m(S) [kg], m'(S) [kg/m]; for k > 1 the diagonal M_jj and ∂M_jj/∂q_j.
    mass_matrix : ndarray, shape (n, k, k)
        M(q) [kg].
    phase : ndarray of str
        ``"rest"`` or ``"moving"`` at each time (k > 1: shape (n, k)).
    events : dict of list of float
        Times of ``lift-off``, ``end of stroke``, ``relief opens`` [s] (every
        coordinate's).
    event_log : list of (float, str, str)
        (time [s], event, coordinate), in time order.
    energy : dict of float
        The balance's terms at the end [J] (module docstring) and ``residual``.
    nfev, njev, nlu : int
        Right-hand-side and Jacobian evaluations, LU decompositions (all phases).
    coordinates : tuple of str
    coordinate : str
        The first coordinate.
    steady_speed : float or ndarray
        s_j·Q_p/A_j along the coordinates [m/s] (lab 6: Q/A; seed 004 eqs. 65–66).

    Examples
    --------
    >>> from assur import io
    >>> from assur.dynamics import simulate
    >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
    >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
    >>> r.status, r.message
    (0, 'reached t_end')
    >>> r.q.round(4).tolist()                   # S [m]
    [0.55, 0.5576, 0.5818]
    >>> [round(t, 3) for t in r.events["lift-off"]]   # [s]
    [0.083]
    """

    status: int
    message: str
    t: np.ndarray
    q: np.ndarray
    qdot: np.ndarray
    qddot: np.ndarray
    p1: np.ndarray
    p2: np.ndarray
    p1dot: np.ndarray
    flows: dict
    force: np.ndarray
    load: np.ndarray
    reduced_mass: np.ndarray
    reduced_mass_derivative: np.ndarray
    phase: np.ndarray
    events: dict
    energy: dict
    nfev: int
    njev: int
    nlu: int
    coordinates: tuple
    steady_speed: object
    pump_pressure: np.ndarray = field(repr=False, default=None)
    mass_matrix: np.ndarray = field(repr=False, default=None)
    event_log: list = field(default_factory=list)
    states: np.ndarray = field(repr=False, default=None)

    @property
    def success(self) -> bool:
        """True unless the integration failed (``status`` ≥ 0).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.success, r.status
        (True, 0)
        """
        return self.status >= 0

    @property
    def coordinate(self) -> str:
        """The first coordinate.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.coordinate, r.coordinates
        ('S', ('S',))
        """
        return self.coordinates[0]

    @property
    def k(self) -> int:
        """The number of coordinates (cylinders) k.

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> r.k, r.q.shape                # one coordinate: arrays of shape (n,)
        (1, (3,))
        """
        return len(self.coordinates)

    def column(self, a, j):
        """The coordinate ``j``'s column of an array over the coordinates (the array
        itself for one coordinate).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> (r.column(r.p1, 0) / 1e6).round(2).tolist()   # p1 of S [MPa]
        [0.0, 8.18, 3.07]
        """
        a = np.asarray(a)
        return a if self.k == 1 else a[:, j]

    def to_frame(self):
        """A pandas DataFrame of the time series (SI units, the seed's symbols; with
        k > 1 coordinates a branch's columns end with its coordinate).

        Examples
        --------
        >>> from assur import io
        >>> from assur.dynamics import simulate
        >>> model = io.load(io.bundled("adapter_lab6"))              # seed 001 lab 6
        >>> r = simulate(model.mechanism, model.drive, 0.5, t_eval=[0.0, 0.25, 0.5])  # [s]
        >>> df = r.to_frame()
        >>> df.shape, list(df.columns[:7])
        ((3, 15), ['t', 'S', 'dS', 'ddS', 'p1', 'p2', 'dp1'])
        >>> round(float(df["Q_pump"].iloc[0]) * 60e3, 2)   # [l/min]
        51.84
        """
        import pandas as pd
        cols = {"t": self.t}
        for j, c in enumerate(self.coordinates):
            sfx = "" if self.k == 1 else f"_{c}"
            col = lambda a: self.column(a, j)  # noqa: E731
            cols.update({c: col(self.q), f"d{c}": col(self.qdot), f"dd{c}": col(self.qddot),
                         f"p1{sfx}": col(self.p1), f"p2{sfx}": col(self.p2),
                         f"dp1{sfx}": col(self.p1dot), f"F{sfx}": col(self.force),
                         f"P_load{sfx}": col(self.load), f"m_red{sfx}": col(self.reduced_mass),
                         f"dm_red{sfx}": col(self.reduced_mass_derivative)})
            cols.update({f"Q_{name}{sfx}": col(v) for name, v in self.flows.items()
                         if name != "pump"})
        cols["Q_pump"] = self.flows["pump"]
        if self.k > 1:
            cols["p_pump"] = self.pump_pressure
        return pd.DataFrame(cols)
