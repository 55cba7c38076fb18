"""What a group compiles against: the :class:`CompileContext` of
:func:`assur.core.program.compile_program`, which hands out the slots of points, the
rows of parameters, literal numbers and derived values, the coordinates' indices, the
rows of fixed angles and the groups' pre-passes
(:meth:`assur.groups.base.Group.compile`).
"""

from __future__ import annotations

from ..errors import ModelError
from ..groups.base import is_number

__all__ = ["CompileContext"]


class CompileContext:
    """What a group's :meth:`~assur.groups.base.Group.compile` works with: slots of
    points, rows of parameters and literals, coordinate indices, rows of fixed
    angles, derived rows and pre-passes.

    Examples
    --------
    The row of the hitch's cylinder–lever group, compiled by hand:

    >>> from assur import examples
    >>> from assur.core.program import CompileContext
    >>> m = examples.hitch_003()
    >>> c = CompileContext(m.coordinates, tuple(m.params))
    >>> for p in m.group("I (2,3)").inputs():          # 01, 03 in slots 0, 1
    ...     _ = c.slot(p)
    >>> m.group("I (2,3)").compile(c)   # 23 in slot 2; S: coordinate 0 (−1); L3: row 8
    (2, 0, 1, -1, 8, -1)
    >>> tuple(m.params).index("L3")
    8
    """

    def __init__(self, coordinates, param_names):
        self.coordinates = tuple(coordinates)
        self.param_names = tuple(param_names)
        self._pindex = {n: i for i, n in enumerate(self.param_names)}
        self.literals: dict[float, int] = {}
        self.derived = 0
        self.slots: dict[str, int] = {}
        self.trig: list = []
        self.frame_rows: dict = {}
        self.prepares: list = []
        self.current = -1

    # rows: parameters first, then literal numbers, then derived rows (fixed up later)
    def pref(self, ref):
        """Parameter-table row of a number or parameter name (a placeholder for
        literals and derived rows until :meth:`resolve`).

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4"))      # coordinates, parameter names
        >>> c.pref("L4"), c.pref(0.61)
        (1, ('lit', 0.61))
        >>> c.pref("L9")
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: 'L9' is not a parameter
        """
        if is_number(ref):
            key = float(ref)
            if key not in self.literals:
                self.literals[key] = len(self.literals)
            return ("lit", key)
        if ref in self._pindex:
            return self._pindex[ref]
        raise ModelError(f"{ref!r} is not a parameter")

    def lref(self, ref):
        """Length reference: a parameter row ≥ 0, or ``−(j + 1)`` for coordinate j.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4"))      # coordinates, parameter names
        >>> c.lref("S"), c.lref("L3"), c.lref("L4")      # a cylinder length; parameters
        (-1, 0, 1)
        """
        if isinstance(ref, str) and ref in self.coordinates:
            return -(self.coordinates.index(ref) + 1)
        return self.pref(ref)

    def coord(self, name) -> int:
        """Index of a generalized coordinate.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S1", "S2"), ())          # two cylinders
        >>> c.coord("S2")
        1
        """
        return self.coordinates.index(name)

    def slot(self, point) -> int:
        """Slot of a point (new points get the next slot).

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4"))      # coordinates, parameter names
        >>> c.slot("01"), c.slot("03"), c.slot("01")
        (0, 1, 0)
        """
        if point not in self.slots:
            self.slots[point] = len(self.slots)
        return self.slots[point]

    def derived_row(self):
        """A new per-design row filled by a pre-pass (see :meth:`prepare`).

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4"))      # coordinates, parameter names
        >>> rows = c.derived_row(), c.derived_row()
        >>> rows
        (('der', 0), ('der', 1))
        >>> c.resolve(rows)            # after the 2 parameters (no literals)
        (2, 3)
        """
        self.derived += 1
        return ("der", self.derived - 1)

    def trig_angle(self, row) -> int:
        """Trig-table row of cos and sin of the angle in parameter row ``row``.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("phiBD",))
        >>> c.trig_angle(c.pref("phiBD")), c.trig_angle(c.pref(0.0))   # cos; sin next
        (0, 2)
        >>> c.trig
        [('angle', 0), ('angle', ('lit', 0.0))]
        """
        self.trig.append(("angle", row))
        return 2 * (len(self.trig) - 1)

    def trig_triangle(self, pb, pl, po, branch) -> int:
        """Trig-table row of the angle ``branch·acos((b² + l² − o²)/(2bl))``.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4", "L34"))
        >>> c.trig_triangle(c.pref("L3"), c.pref("L4"), c.pref("L34"), -1)
        0
        >>> c.trig
        [('triangle', 0, 1, 2, -1)]
        """
        self.trig.append(("triangle", pb, pl, po, branch))
        return 2 * (len(self.trig) - 1)

    def frame_point(self, name, rx, ry) -> None:
        """Record a frame point's rows (frame points are served from the table).

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("X01", "Y01"))
        >>> c.frame_point("01", c.pref("X01"), c.pref("Y01"))
        >>> c.frame_rows
        {'01': (0, 1)}
        """
        self.frame_rows[name] = (rx, ry)

    def prepare(self, group, data) -> None:
        """Register the group's pre-pass ``group.prepare(data, ptab, positions_at)``.

        Examples
        --------
        The hitch's centre of mass S6 is fixed at the pose S = Sp (group 9): its
        pre-pass fills two derived rows:

        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.hitch_003()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> for i, g in enumerate(m.groups[:10]):
        ...     c.current = i
        ...     _ = g.compile(c)
        >>> len(c.prepares), c.prepares[0][0], c.derived
        (1, 9, 2)
        """
        self.prepares.append((self.current, data))

    def resolve(self, v):
        """Final row number of a placeholder (after all literals are known).

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L3", "L4"))      # coordinates, parameter names
        >>> lit, der = c.pref(0.61), c.derived_row()
        >>> c.resolve(lit), c.resolve(der), c.resolve((1, lit, der))  # params, literals, derived
        (2, 3, (1, 2, 3))
        """
        if isinstance(v, tuple) and v and v[0] == "lit":
            return len(self.param_names) + self.literals[v[1]]
        if isinstance(v, tuple) and v and v[0] == "der":
            return len(self.param_names) + len(self.literals) + v[1]
        if isinstance(v, tuple):
            return tuple(self.resolve(x) for x in v)
        return v
