"""The standard lift-capacity test of a three-point hitch, in the manner of
ISO 789-2 and SAE J283.

The test measures the vertical force the hitch can lift, at a hydraulic pressure of
90 % of the relief-valve setting, at no fewer than six positions evenly spaced over
the lift range of the lower-link hitch points: at the hitch points themselves and
on a test frame whose load point lies 610 mm behind them. Here the same numbers come
from the model (the frame's load point is a point of the model file, e.g. a
``rigid_point`` on the implement link 610 mm behind the hitch point):

* the positions: heights of the hitch point evenly spaced from its lowest to its
  highest over the coordinate's range, each solved for the cylinder length S by
  Newton's method on Y(S) = h with the exact transmission number I = dY/dS (the lift
  range must be monotonic in S: a hitch point that rises and falls is an error);
* the available cylinder force F = k·(share·p_relief)·A·η_h, with the share of the
  relief pressure instead of the working pressure;
* the force available at a point P, G_P = (σ·F·η_m − F_dead)/I_P [N] (virtual work:
  the vertical force at P that the cylinder force balances), with I_P = dY_P/dS —
  the lift capacity of :func:`assur.core.cylinders.capacity`, the same formula as
  the reports' and the design criteria's, with the working chamber of the model's
  ``side`` (``"auto"``: of the test's stroke), counts and dead loads (``[tables] dead_loads``: the hitch's
  own links, which a test stand lifts too).

The mechanism's other loads (the implement's weight) are not part of the test: it
reports what the hitch can lift, as a test stand measures it. Units: SI inside
(m, N, Pa); the report shows them in the model's units.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core import cylinders as C
from ..errors import ModelError

__all__ = ["LiftTest", "LiftTestResult", "lift_test", "check_lift_memory"]


@dataclass(frozen=True)
class LiftTest:
    """The test as a model file's ``[lift_test]`` section declares it.

    Parameters
    ----------
    hitch : str
        The lower-link hitch point (seed 003: the suspension axis 56).
    frame : str or None
        The test frame's load point, a point of the model 610 mm behind the hitch
        points (declared in the model file); None: the hitch points only.
    cylinder : str or None
        The cylinder group tested (default: the model's only one).
    pressure_share : float
        Share of the relief-valve setting the test runs at [-] (ISO 789-2: 0.9).
    positions : int
        Number of positions evenly spaced over the lift range (at least 6).

    Examples
    --------
    The test the bundled seed-003 hitch declares, and the standard's minimum of six
    positions enforced:

    >>> from assur import io
    >>> from assur.machines.hitch_lift import LiftTest
    >>> io.load(io.bundled("hitch_003")).lift_test
    LiftTest(hitch='56', frame='F610', cylinder=None, pressure_share=0.9, positions=6)
    >>> LiftTest("56", positions=5)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: lift test: at least 6 positions over the lift range (ISO 789-2), got 5
    """

    hitch: str
    frame: str | None = None
    cylinder: str | None = None
    pressure_share: float = 0.9
    positions: int = 6

    def __post_init__(self):
        if not 0 < self.pressure_share <= 1:
            raise ModelError(f"lift test: pressure_share must be in (0, 1], got "
                             f"{self.pressure_share!r}")
        if int(self.positions) != self.positions or self.positions < 6:
            raise ModelError(f"lift test: at least 6 positions over the lift range (ISO 789-2), "
                             f"got {self.positions!r}")


@dataclass(frozen=True)
class LiftTestResult:
    """The test's positions and forces.

    Attributes
    ----------
    test : LiftTest
    coordinate : str
        The cylinder's coordinate S.
    s : ndarray, shape (n,)
        Cylinder length at each test position [m].
    height : ndarray, shape (n,)
        Height of the hitch point Y [m], evenly spaced from the lowest to the highest.
    force_cylinder : float or ndarray
        Available force of the cylinders at the test pressure [N] (per position for a
        cylinder that picks its chamber, ``side = "auto"``).
    pressure : float
        The test pressure, share·p_relief [Pa].
    hitch_force : ndarray, shape (n,)
        Vertical force available at the hitch points [N].
    frame_force : ndarray, shape (n,) or None
        Vertical force available at the frame's load point [N].

    Examples
    --------
    The bundled seed-003 hitch over its travel S = 0.420 … 0.670 m: the hitch point
    56 rises from 0.2 m (the seed's condition Y56(Smin) = 0.2 m) in six even steps.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.machines.hitch_lift import lift_test
    >>> model = io.load(io.bundled("hitch_003"))
    >>> r = lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
    >>> np.round(r.height, 4).tolist()  # Y56 [m]
    [0.2, 0.3686, 0.5373, 0.7059, 0.8745, 1.0432]
    >>> round(r.pressure / 1e6, 2), round(r.force_cylinder / 1e3, 1)  # [MPa], [kN]
    (15.75, 133.0)
    """

    test: LiftTest
    coordinate: str
    s: np.ndarray
    height: np.ndarray
    force_cylinder: float
    pressure: float
    hitch_force: np.ndarray
    frame_force: np.ndarray | None

    @property
    def hitch_minimum(self) -> float:
        """The smallest force at the hitch points over the lift range [N].

        Examples
        --------
        The bundled seed-003 hitch lifts least at its lowest position:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.machines.hitch_lift import lift_test
        >>> model = io.load(io.bundled("hitch_003"))
        >>> r = lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
        >>> round(r.hitch_minimum / 1e3, 2)  # [kN]
        29.83
        >>> int(np.argmin(r.hitch_force))  # the position
        0
        """
        return float(self.hitch_force.min())

    @property
    def frame_minimum(self) -> float | None:
        """The smallest force at the frame over the lift range [N] (None without one).

        Examples
        --------
        The bundled seed-003 hitch's test frame (point F610, 610 mm behind 56), and
        the same test without a frame:

        >>> from assur import io
        >>> from assur.machines.hitch_lift import LiftTest, lift_test
        >>> model = io.load(io.bundled("hitch_003"))
        >>> r = lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
        >>> round(r.frame_minimum / 1e3, 2)  # [kN]
        28.67
        >>> print(lift_test(model.mechanism, LiftTest("56"), (0.42, 0.67)).frame_minimum)
        None
        """
        return None if self.frame_force is None else float(self.frame_force.min())


def _cylinder(mech, name):
    cyls = {c.name: c for c in mech.cylinders}
    if not cyls:
        raise ModelError(f"lift test of {mech.name!r}: the model has no cylinders")
    if name is None:
        if len(cyls) != 1:
            raise ModelError(f"lift test of {mech.name!r}: name the cylinder tested, one of "
                             f"{sorted(cyls)}")
        return next(iter(cyls.values()))
    if name not in cyls:
        raise ModelError(f"lift test of {mech.name!r}: no cylinder {name!r}; the model has "
                         f"{sorted(cyls)}")
    return cyls[name]


def check_lift_memory(mech, positions) -> None:
    """Refuse a lift test of ``positions`` positions whose analysis (kinematics,
    statics and the cylinder's forces at every position) would exceed
    :func:`assur.core.inputs.max_memory`, before anything is allocated.

    Raises
    ------
    ModelError
        Naming ``[lift_test] positions``, the estimate and the limit.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur import examples
    >>> from assur.machines.hitch_lift import check_lift_memory
    >>> check_lift_memory(examples.hitch_003(), 6)  # fine
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "1 MiB"}):
    ...     check_lift_memory(examples.hitch_003(), 10**6)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: lift test of 'hitch_003': positions = 1000000: 1e+06 positions would need about 2.31 GiB of memory (limit 1 MiB; set ASSUR_MAX_MEMORY to change it, or reduce [lift_test] positions)
    """
    from ..core.inputs import bytes_per_position, check_memory
    check_memory(float(positions), bytes_per_position(mech),
                 f"lift test of {mech.name!r}: positions = {positions}",
                 reduce="[lift_test] positions")


def lift_test(mech, test: LiftTest, s_range, iterations=50) -> LiftTestResult:
    """Run the standard lift test on one design of ``mech`` over ``s_range``.

    Parameters
    ----------
    mech : Mechanism
        One design, with the cylinder of ``test`` (its coordinate the only one).
    test : LiftTest
    s_range : (float, float)
        The cylinder's travel: lowest and highest S [m] (the model's range).
    iterations : int
        Newton steps at most to place each position (it converges in a few).

    Raises
    ------
    ModelError
        Without such a cylinder or points, with a hitch point whose height is not
        monotonic in S over the range, or with a position that does not converge.

    Examples
    --------
    The bundled seed-003 hitch (its model file's ``[lift_test]``: hitch point 56,
    frame point F610, 90 % of the relief pressure, six positions):

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.machines.hitch_lift import LiftTest, lift_test
    >>> model = io.load(io.bundled("hitch_003"))
    >>> r = lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
    >>> np.round(r.s, 4).tolist()  # cylinder length at the positions [m]
    [0.42, 0.4611, 0.5071, 0.5567, 0.6103, 0.67]
    >>> np.round(r.hitch_force / 1e3, 1).tolist()  # at the hitch points [kN]
    [29.8, 34.6, 37.7, 40.6, 44.2, 50.7]
    >>> np.round(r.frame_force / 1e3, 1).tolist()  # at the frame [kN]
    [28.7, 31.2, 31.8, 31.6, 30.8, 30.3]
    >>> lift_test(model.mechanism, LiftTest("99"), (0.42, 0.67))
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: lift test of 'hitch_003': no point '99' in the model
    """
    cyl = _cylinder(mech, test.cylinder)
    c = cyl.coordinate
    if len(mech.coordinates) != 1:
        raise ModelError(f"lift test of {mech.name!r}: one coordinate only, the model has "
                         f"{list(mech.coordinates)}")
    for p in (test.hitch, test.frame):
        if p is not None and p not in mech.points and p not in mech.frame_points:
            raise ModelError(f"lift test of {mech.name!r}: no point {p!r} in the model")
    lo, hi = sorted(float(v) for v in s_range)
    # the lift range: a dense scan finds the extreme heights and checks monotonicity
    scan = mech.solve(np.linspace(lo, hi, 201))
    y, dy = np.ravel(scan.y(test.hitch)), np.ravel(scan.transmission(test.hitch))
    if not np.any(dy):
        raise ModelError(f"lift test of {mech.name!r}: the hitch point {test.hitch!r} does not "
                         f"move with {c} (a frame point, or a point the cylinder does not "
                         f"drive): name the point the implement hangs on")
    if not (np.all(dy > 0) or np.all(dy < 0)):
        k = int(np.flatnonzero(np.sign(dy) != np.sign(dy[0]))[0])
        raise ModelError(f"lift test of {mech.name!r}: the hitch point {test.hitch!r} does not "
                         f"rise monotonically with {c} over {lo:.6g} … {hi:.6g} m (dY/d{c} "
                         f"changes sign near {c} = {float(np.ravel(scan.q())[k]):.6g} m)")
    check_lift_memory(mech, test.positions)
    heights = np.linspace(y.min(), y.max(), int(test.positions))
    s = np.interp(heights, y, np.ravel(scan.q())) if dy[0] > 0 else \
        np.interp(heights, y[::-1], np.ravel(scan.q())[::-1])
    for _ in range(iterations):  # Newton on Y(S) = h with the exact I = dY/dS
        kin = mech.solve(s)
        r = np.ravel(kin.y(test.hitch)) - heights
        step = r / np.ravel(kin.transmission(test.hitch))
        s = np.clip(s - step, lo, hi)
        if np.all(np.abs(r) <= 1e-12 * max(1.0, float(np.abs(heights).max()))):
            break
    else:
        raise ModelError(f"lift test of {mech.name!r}: the positions did not converge "
                         f"(largest height error {float(np.abs(r).max()):.3g} m)")
    kin = mech.solve(s)

    # the test's capacities: the cylinder's formulas (assur.core.cylinders) at the test
    # pressure, with the chamber, counts and dead loads of the model
    from ..core.statics import solve as statics_solve
    from .cylinders import CylinderResult
    res = CylinderResult(kin, statics_solve(kin), cyl)
    pressure = test.pressure_share * float(np.ravel(np.asarray(mech.value_of(cyl.p_relief),
                                                               float))[0])
    # the working chamber's force: the one the capacities below use (side = "auto": of
    # the stroke's working direction, CylinderResult.stroke_load)
    force = C.force_max(res.terms, res.stroke_load, C.select_array, pressure)
    force = float(force) if np.ndim(force) == 0 else np.ravel(force)

    def available(point):
        G = np.ravel(res.capacity(point, pressure=pressure))
        if np.any(G <= 0):
            k = int(np.flatnonzero(G <= 0)[0])
            I = float(np.ravel(kin.transmission(point))[k])
            raise ModelError(f"lift test of {mech.name!r}: the point {point!r} does not rise "
                             f"with {c} at {c} = {s[k]:.6g} m (dY/d{c} = {I:.3g}): no "
                             f"lifting force there")
        return G

    return LiftTestResult(test, c, s, np.ravel(kin.y(test.hitch)), force, pressure,
                          available(test.hitch),
                          available(test.frame) if test.frame is not None else None)
