"""The contract every structural (Assur) group type implements, and its registry.

A mechanism is a set of frame points followed by an ordered list of groups; each
group is solved from points already known and adds new points (Assur–Artobolevsky
decomposition). A *group type* is one module of :mod:`assur.groups` holding one
frozen dataclass that subclasses :class:`Group` and is registered with
:func:`register` under the ``type`` name of the model file. Everything about the
type lives there — in the spirit of scipy's ``OdeSolver`` subclasses, the rest of
the library only calls the contract:

==========================  =============================================================
member                      what it provides
==========================  =============================================================
``type_name``, ``kind``     registry key (= model-file ``type`` = builder method name);
                            the words used in messages
``fields``                  the parameters, their roles and units (file schema, builder,
                            docs table derive from them): :class:`Field`
``link_roles``              names of the links the group adds (``None``: it puts a point
                            on an existing link)
``out_fields``              the point fields naming the points it adds (default ``out``)
``check_fields(given)``     a message if the keys given together are not a valid form
                            (the file schema's cross-key check), else None
``inputs()``/``outputs()``  the points it needs solved first / the points it adds
``refs()``                  its length/angle references by role (numbers, parameter or
                            coordinate names)
``topology(t)``             the bodies it creates and the owner of each new point
``evaluate(pts, val)``      plain-numpy position formulas for any dtype (complex step)
``compile(c)``              its program row (integers only: the structure)
``emit(E, i, row)``         kernel code for positions, first and second jets
``failure(code, pts, v)``   amount and message of a failure (group, links, values)
``closure(P, val)``         residual of its closure equations [m]
``rod_ends(...)``,          joint reactions of the group in reverse order (kinetostatics)
``reactions(r)``
==========================  =============================================================

Sign conventions
----------------
Right-handed x–y frame, angles from +x, counter-clockwise positive (BRIEF.md).
``branch`` of a dyad: ``+1`` puts the new joint *C* on the left of the directed
line from the first outer joint *A* to the second *B*, ``−1`` on the right.

A *length reference* (``ra``, ``lever``, ``length``…) is a number [m], the name of
a model parameter, or the name of a generalized coordinate (a cylinder length that
drives the group). An *angle reference* is a number [rad] or a parameter name.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, ClassVar, NamedTuple, Union

import numpy as np

from ._registry import group_type, register, registry, unregister

Ref = Union[str, float, int]

__all__ = ["Group", "Field", "Failure", "register", "unregister", "registry", "group_type", "Ref",
           "fmt", "is_number", "signed_name", "ref_value"]


def fmt(v) -> str:
    """A number as printed in messages (6 significant digits).

    Examples
    --------
    >>> from assur.groups.base import fmt
    >>> fmt(0.661283167)          # L4 of seed 003 [m]
    '0.661283'
    >>> fmt(1.0), fmt(4.66e-3)    # [m]
    ('1', '0.00466')
    """
    return f"{float(v):.6g}"


def is_number(x) -> bool:
    """True for real numbers (not bool).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.groups.base import is_number
    >>> is_number(0.42), is_number(np.float64(0.42)), is_number(2)   # S [m], S [m], a count
    (True, True, True)
    >>> is_number(True), is_number("L4"), is_number(np.array([0.42]))
    (False, False, False)
    """
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


_SIGNED = re.compile(r"^-\s*([A-Za-z_][A-Za-z0-9_]*)$")


def signed_name(ref):
    """The parameter a *signed reference* negates: ``"-Mc"`` → ``"Mc"``, else None.

    A value may name a parameter with a leading minus wherever it may name one
    (``M = "-Mc"``, a frame coordinate ``"-a"``): its value is −(the parameter's),
    following every change of the parameter (a batch, :meth:`Mechanism.with_params`).

    Examples
    --------
    >>> from assur.groups.base import signed_name
    >>> signed_name("-h_rod"), signed_name("- Mc")
    ('h_rod', 'Mc')
    >>> print(signed_name("h_rod"), signed_name(-0.35), signed_name("-2x"))
    None None None
    """
    if isinstance(ref, str):
        m = _SIGNED.match(ref.strip())
        if m:
            return m.group(1)
    return None


def ref_value(params, ref):
    """Value of a reference in ``params``: a number, a parameter name, or a signed
    reference ``"-name"`` (−params[name]); arrays over designs stay arrays.

    Examples
    --------
    >>> from assur.groups.base import ref_value
    >>> params = {"h_rod": 0.35, "L4": [0.60, 0.66]}        # [m]
    >>> ref_value(params, 0.2), ref_value(params, "h_rod")   # [m]
    (0.2, 0.35)
    >>> float(ref_value(params, "-h_rod"))                  # [m]
    -0.35
    >>> ref_value(params, "-L4").tolist()                   # a batch of two designs [m]
    [-0.6, -0.66]
    """
    if is_number(ref):
        return float(ref)
    base = signed_name(ref)
    if base is not None:
        v = params[base]
        if isinstance(v, (int, float, np.floating, np.integer, list, tuple)) or (
                isinstance(v, np.ndarray) and not np.iscomplexobj(v)):
            return -np.asarray(v, dtype=float)
        return -v  # a complex step or a jet (assur.synthesis.sensitivity) keeps its derivatives
    return params[ref]


_MISSING = object()


@dataclass(frozen=True)
class Field:
    """One parameter of a group type (load types describe their fields with the same
    record, with the roles of :data:`assur.core.loads.ROLES`).

    Attributes
    ----------
    name : str
        Keyword in the builder and key in the model file.
    role : {"point", "line", "value", "coordinate", "position", "branch"}
        ``point``: a point name; ``line``: an optional pair of point names (a
        direction on a link); ``value``: a number with a unit or a parameter name;
        ``coordinate``: the generalized coordinate the group is driven by;
        ``position``: ``{coordinate = value}``; ``branch``: ±1.
    quantity : {"length", "angle", None}
        Dimension of a value (files give lengths in m/mm…, angles in degrees).
    flag : {"positive", None}
        Further constraint on a value.
    coordinate_ok : bool
        A value that may name a generalized coordinate (a cylinder length).
    default : object
        Default when omitted (absent: required).
    doc : str
        One line for the docs table.

    Examples
    --------
    >>> from assur.groups import Crank
    >>> f = Crank.fields[2]
    >>> f.name, f.role, f.quantity, f.flag, f.coordinate_ok
    ('radius', 'value', 'length', 'positive', True)
    >>> f.doc
    '|pivot–out| [m]'
    >>> Crank.fields[-1].name, Crank.fields[-1].default    # phase [rad]
    ('phase', 0.0)
    """

    name: str
    role: str
    quantity: str | None = None
    flag: str | None = None
    coordinate_ok: bool = False
    default: Any = _MISSING
    doc: str = ""

    @property
    def required(self) -> bool:
        """True if the field has no default (the builder and the file must give it).

        Examples
        --------
        >>> from assur.groups import Crank
        >>> [f.name for f in Crank.fields if f.required]
        ['pivot', 'out', 'radius', 'q']
        """
        return self.default is _MISSING


class Failure(NamedTuple):
    """What a group says about a failure: amount [m] (or sin μ at a dead point), the
    message after "at position …: ", and the verb of the message head.

    Examples
    --------
    Seed 000's bell-crank triangle cannot close (L4 > L3 + L34):

    >>> from assur import examples
    >>> from assur.groups.base import ref_value
    >>> from assur.kernel.emit import FAIL_TRIANGLE
    >>> m = examples.header_000()
    >>> f = m.group("arm 46").failure(FAIL_TRIANGLE, {}, lambda r: ref_value(m.params, r), str)
    >>> round(f.amount * 1e3, 2), f.verb      # L4 − (L3 + L34) [mm]
    (4.66, 'fails')
    """

    amount: float
    text: str
    verb: str = "cannot assemble"


@dataclass(frozen=True)
class Group:
    """Base of all structural groups (see the module docstring for the contract).

    Examples
    --------
    The seed-003 hitch: frame points, then groups solved in order, each from points
    known before it:

    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> for g in m.groups[3:]:
    ...     print(f"{g.type_name:14} {g.name!r}: {g.inputs()} -> {g.outputs()}")
    frame          '07': () -> ('07',)
    cylinder_lever 'I (2,3)': ('01', '03') -> ('23',)
    rigid_point    'arm 34': ('03', '23') -> ('34',)
    dyad           'II (4,5)': ('34', '05') -> ('45',)
    rigid_point    'axis 56': ('05', '45') -> ('56',)
    dyad           'III (6,7)': ('56', '07') -> ('67',)
    pose_point     'centre of mass S6': ('56', '67') -> ('S6',)
    rigid_point    'test frame': ('56', '67') -> ('F610',)
    """

    name: str

    #: model-file ``type`` and builder method name
    type_name: ClassVar[str] = ""
    #: human description used in messages and reports, and its Russian name (reports)
    kind: ClassVar[str] = "group"
    kind_ru: ClassVar[str] = "группа"
    #: how the group's driving coordinate reads: "angle" (a crank), "slider" (a
    #: prismatic input) or "length" (a cylinder length); None for passive groups
    driver_kind: ClassVar[str | None] = None
    #: parameters (besides ``name`` and ``links``)
    fields: ClassVar[tuple[Field, ...]] = ()
    #: names of the links the group adds, in order; None: a point on an existing link
    link_roles: ClassVar[tuple[str, ...] | None] = ()
    #: the ``point`` fields that name the points the group adds (the others are inputs)
    out_fields: ClassVar[tuple[str, ...]] = ("out",)
    #: op code, assigned by :func:`register`
    op: ClassVar[int] = -1
    #: True if the group emits ``g{i}``, ``gd{i}`` (squared triangle height and its
    #: slope) for the continuity check between positions (k = 1)
    continuity: ClassVar[bool] = False

    # ---- description ------------------------------------------------------------
    @classmethod
    def check_fields(cls, given: set[str]) -> str | None:
        """A message if the fields ``given`` (the keys written, of :attr:`fields`) do not
        form a valid description together — e.g. two alternative forms mixed — else
        None. The file schema calls it before any value is read.

        Examples
        --------
        >>> from assur.groups import Crank, Frame
        >>> print(Crank.check_fields({"pivot", "out", "radius", "q"}))   # one form only
        None
        >>> Frame.check_fields({"x", "origin"})
        'give either x and y, or origin, length and angle (not both forms)'
        """
        return None

    def inputs(self) -> tuple[str, ...]:
        """Names of the points this group needs solved first.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.group("II (4,5)").inputs(), m.group("01").inputs()
        (('34', '05'), ())
        """
        raise NotImplementedError

    def outputs(self) -> tuple[str, ...]:
        """Names of the points this group adds.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.group("II (4,5)").outputs(), m.group("01").outputs()
        (('45',), ('01',))
        >>> sum((g.outputs() for g in m.groups), ()) == m.points
        True
        """
        raise NotImplementedError

    def refs(self) -> dict[str, Ref]:
        """Length/angle references of the group by role.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.group("II (4,5)").refs()           # parameter names (lengths [m])
        {'ra': 'L4', 'rb': 'L5'}
        >>> m.group("axis 56").refs()            # a number: the angle 0 [rad]
        {'length': 'L56', 'angle': 0.0}
        """
        return {}

    def coordinates_driven(self) -> tuple[str, ...]:
        """Names of the generalized coordinates this group is driven by (input groups).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> m.group("crank 1").coordinates_driven(), m.group("dyad 2-3").coordinates_driven()
        (('j1',), ())
        """
        return ()

    def group_links(self) -> tuple[str, ...]:
        """The link names given by the user (may be empty).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import Crank
        >>> examples.hitch_003().group("II (4,5)").group_links()
        ('4', '5')
        >>> Crank("crank", pivot="O", out="A", radius=0.15, q="j1").group_links()
        ()
        """
        return tuple(getattr(self, "links", ()) or ())

    def validate(self, coordinates) -> str | None:
        """A message if the description is inconsistent in itself, else None.

        Examples
        --------
        >>> import dataclasses
        >>> from assur import examples
        >>> from assur.groups import Crank
        >>> crank = Crank("crank", pivot="O", out="A", radius=0.15, q="j2")
        >>> crank.validate(("j1",))
        "'j2' is not a generalized coordinate ('j1',)"
        >>> dyad = examples.hitch_003().group("II (4,5)")
        >>> print(dyad.validate(("S",)))
        None
        >>> dataclasses.replace(dyad, branch=0).validate(("S",))
        'branch must be +1 or -1, got 0'
        """
        br = getattr(self, "branch", 1)
        if br not in (1, -1):
            return f"branch must be +1 or -1, got {br!r}"
        for c in self.coordinates_driven():
            if c not in coordinates:
                return (f"{c!r} is not a generalized coordinate {tuple(coordinates)}")
        return None

    # ---- structure --------------------------------------------------------------
    def topology(self, t) -> tuple[str, ...]:
        """Create the group's bodies in the topology builder ``t`` and return the
        group's links (see :class:`assur.core.topology.TopologyBuilder`).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.hitch_003()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> [g.topology(t) for g in m.groups[:6]]      # 4 frame points, group I, arm 34
        [(), (), (), (), ('2', '3'), ('3',)]
        >>> t.bodies["3"], t.owner("34")
        (['03', '23', '34'], '3')
        """
        raise NotImplementedError

    # ---- positions ----------------------------------------------------------------
    def evaluate(self, pts: dict, val) -> None:
        """Add the output points to ``pts`` by the closed-form position formulas in
        plain numpy (any dtype, complex included). ``val(ref)`` gives a reference's
        value.

        Examples
        --------
        The groups of the hitch up to the arm 34 at S = 0.42 m, as
        :meth:`assur.Mechanism.evaluate_positions` runs them, agree with the kernel:

        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.hitch_003()
        >>> pts = {}
        >>> for g in m.groups[:6]:
        ...     g.evaluate(pts, lambda ref: ref_value({**m.params, "S": 0.42}, ref))
        >>> [round(float(v), 4) for v in pts["34"]]                # [m]
        [0.5587, 1.0103]
        >>> [round(float(v), 4) for v in m.solve([0.42]).point("34")[0]]   # [m]
        [0.5587, 1.0103]
        """
        raise NotImplementedError

    def compile(self, c) -> tuple[int, ...]:
        """The program row after the op code: integers only (slots, parameter rows,
        coordinate indices, signs). See :class:`assur.core.program.CompileContext`.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.combine_002()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> rows = [g.compile(c) for g in m.groups[:4]]   # frames O1, O3, O6, crank 1
        >>> rows[3]            # slots of A, O1; row of l1; coordinate j1; literal phase 0
        (3, 0, 0, 0, ('lit', 0.0))
        >>> (m.groups[3].op,) + c.resolve(rows[3]) == m.program().rows[3]
        True
        """
        raise NotImplementedError

    @classmethod
    def emit(cls, E, i: int, row: tuple[int, ...]) -> None:
        """Emit the kernel code of group ``i`` with program ``row`` (op excluded).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import group_type
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.combine_002().program().rows[3]    # the crank: O1 + l1∠j1
        >>> E = Emitter(K=1, order=1)
        >>> group_type(row[0]).emit(E, 3, row[1:])
        >>> for line in E.lines[:3]:
        ...     print(line.strip())
        t3r = params[0, d]
        t3th = q[0, e] + params[10, d]
        t3c = math.cos(t3th)
        """
        raise NotImplementedError

    # ---- diagnostics ----------------------------------------------------------------
    def failure(self, code: int, pts: dict, v, nm) -> Failure:
        """Explain failure ``code`` at one element. ``pts``: the reference positions
        of the points before this group (floats); ``v(ref)``: a reference's value;
        ``nm(ref)``: how a reference is named in messages.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.kernel.emit import FAIL_COINCIDENT, FAIL_DEAD_POINT
        >>> arm = examples.hitch_003().group("arm 34")
        >>> arm.failure(FAIL_COINCIDENT, {}, float, str).text
        'two points that must define a direction coincide (03, 23)'
        >>> arm.failure(FAIL_DEAD_POINT, {}, float, str).amount    # [m]
        0.0
        """
        from ..kernel.emit import FAIL_COINCIDENT, FAIL_DEAD_POINT
        if code == FAIL_COINCIDENT:
            return Failure(0.0, "two points that must define a direction coincide "
                                f"({', '.join(self.inputs())})")
        if code == FAIL_DEAD_POINT:
            return Failure(0.0, "dead point: the Jacobian of the group is singular")
        return Failure(0.0, f"failure code {code}")

    def prepare(self, data, ptab, positions_at) -> None:
        """Pre-pass before the kernel runs: fill derived per-design rows of ``ptab``
        registered at compile time (:meth:`assur.core.program.CompileContext.prepare`).
        ``positions_at(qpose, points)`` solves the groups before this one at other
        coordinates. Only groups that register a pre-pass implement it.

        Examples
        --------
        The hitch's only pre-pass is the centre of mass S6, fixed at the pose S = Sp:

        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program()
        >>> [m.groups[gi].name for gi, data in prog.prepares]
        ['centre of mass S6']
        >>> examples.combine_002().group("crank 1").prepare((), None, None)  # none here
        Traceback (most recent call last):
        ...
        NotImplementedError
        """
        raise NotImplementedError

    def closure(self, P, val):
        """Largest violation of the group's closure equations [m] (array), or None
        when the group has none beyond its construction. ``P(point)`` gives (x, y);
        ``val(ref)`` a reference's value.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.combine_002()
        >>> pts = m.evaluate_positions({"j1": 0.0})
        >>> val = lambda ref: ref_value(m.params, ref)
        >>> print(m.group("O1").closure(pts.get, val))      # (0, 0): nothing to close
        None
        >>> pts["O3"] = (pts["O3"][0] + 0.001, pts["O3"][1])   # move O3 1 mm along x
        >>> round(float(m.group("O3").closure(pts.get, val)), 6)   # |O3 − (O1 + l10∠j10)| [m]
        0.001
        """
        return None

    # ---- kinetostatics --------------------------------------------------------------
    def rod_ends(self, links, is_coord) -> tuple[tuple[str, str], ...]:
        """``(cylinder link, rod-end point)`` of the cylinders inside the group: loads
        applied there on the cylinder are taken off its axial force.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> is_coord = lambda ref: ref in m.coordinates
        >>> m.group("arm 34").rod_ends(("3",), is_coord)
        ()
        >>> m.group("I (2,3)").rod_ends(("2", "3"), is_coord)   # cylinder 2, rod end 23
        (('2', '23'),)
        """
        return ()

    def reactions(self, r) -> None:
        """Solve the group's joint reactions from the loads on its links (reverse
        order), record them and pass the joint forces on to the links it is attached
        to (see :class:`assur.core.statics.ReactionContext`).

        Examples
        --------
        The reverse pass of :mod:`assur.core.statics` by hand: the hitch at S = 0.42 m
        holding the implement's weight P6 at S6:

        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.hitch_003()
        >>> r = statics.ReactionContext(m.solve([0.42]), set())
        >>> r.apply(m.owner("S6"), "S6", 0.0, -27500.0)      # P6 [N]
        >>> for g in reversed(m.groups):
        ...     r.links = m.topology.group_links[g.name]
        ...     g.reactions(r)
        >>> round(float(r.act["S"][0, 0]))     # cylinder force, seed 003 table 4.1 [N]
        129614
        >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))   # the same [N]
        129614
        """
        raise NotImplementedError
