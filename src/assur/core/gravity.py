"""Gravity of a mechanism: how large (:data:`GRAVITY`, or the model's own) and which
way (:func:`gravity_unit`). :attr:`assur.Mechanism.g` and
:attr:`assur.Mechanism.gravity_unit` are read by every computation that turns a
mass into a weight — statics, the outputs kernel, dynamics, capacity — so there is
one answer to "which g".
"""

from __future__ import annotations

import math

__all__ = ["GRAVITY", "gravity_unit"]

#: default acceleration of gravity g [m/s²] turning masses into weights: 9.81, the
#: value engineering worksheets use (all the seeds do). A model may set its own
#: (``[model] gravity = "9.80665 m/s^2"``), a call its own (``analyze(..., g=…)``).
GRAVITY = 9.81


def gravity_unit(mech) -> tuple[float, float]:
    """The unit vector of gravity of a mechanism, ``(u_x, u_y)`` [-].

    ``[model] gravity = { value = "9.81 m/s^2", direction = -90 }`` (the default
    direction: straight down)::

            y
            ^
            |        a weight m·g acts along u = (cos d, sin d);
            +---> x  d = −90° (default): u = (0, −1)
            |
            v u

    Components within 1e-15 of zero are zero, so that −90° gives exactly (0, −1)
    and the default weights are those of ``(0, −m·g)``.

    Parameters
    ----------
    mech : Mechanism
        Its :attr:`~assur.Mechanism.gravity_direction` [rad] (None: −π/2).

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.gravity import gravity_unit
    >>> gravity_unit(examples.hitch_003())                 # straight down [-]
    (0.0, -1.0)
    >>> gravity_unit(examples.hitch_003().with_gravity(9.81, direction=0.0))  # along +x [-]
    (1.0, 0.0)
    """
    d = getattr(mech, "gravity_direction", None)
    if d is None:
        return 0.0, -1.0
    ux, uy = math.cos(float(d)), math.sin(float(d))
    return (0.0 if abs(ux) < 1e-15 else float(ux)), (0.0 if abs(uy) < 1e-15 else float(uy))
