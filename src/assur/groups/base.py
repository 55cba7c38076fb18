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

Ref = Union[str, float, int]

__all__ = ["Group", "Field", "Failure", "register", "registry", "group_type", "Ref",
           "fmt", "is_number", "signed_name", "ref_value"]


def fmt(v) -> str:
    """A number as printed in messages (6 significant digits)."""
    return f"{float(v):.6g}"


def is_number(x) -> bool:
    """True for real numbers (not bool)."""
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


_SIGNED = re.compile(r"^-\s*([A-Za-z_][A-Za-z0-9_]*)$")


def signed_name(ref):
    """The parameter a *signed reference* negates: ``"-Mc"`` → ``"Mc"``, else None.

    A value may name a parameter with a leading minus wherever it may name one
    (``M = "-Mc"``, a frame coordinate ``"-a"``): its value is −(the parameter's),
    following every change of the parameter (a batch, :meth:`Mechanism.with_params`).
    """
    if isinstance(ref, str):
        m = _SIGNED.match(ref.strip())
        if m:
            return m.group(1)
    return None


def ref_value(params, ref):
    """Value of a reference in ``params``: a number, a parameter name, or a signed
    reference ``"-name"`` (−params[name]); arrays over designs stay arrays."""
    if is_number(ref):
        return float(ref)
    base = signed_name(ref)
    if base is not None:
        v = params[base]
        if isinstance(v, (int, float, np.floating, np.integer, list, tuple)) or (
                isinstance(v, np.ndarray) and not np.iscomplexobj(v)):
            return -np.asarray(v, dtype=float)
        return -v  # a complex step or a jet (assur.sensitivity) keeps its derivatives
    return params[ref]


_MISSING = object()


@dataclass(frozen=True)
class Field:
    """One parameter of a group type.

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
        return self.default is _MISSING


class Failure(NamedTuple):
    """What a group says about a failure: amount [m] (or sin μ at a dead point), the
    message after "at position …: ", and the verb of the message head."""

    amount: float
    text: str
    verb: str = "cannot assemble"


_REGISTRY: dict[str, type] = {}
_BY_OP: list[type] = []


def register(cls):
    """Class decorator: register a group type under ``cls.type_name`` and give it its
    op code (its index in the registry)."""
    name = cls.type_name
    if name in _REGISTRY and _REGISTRY[name] is not cls:
        raise ValueError(f"group type {name!r} is registered twice")
    if name not in _REGISTRY:
        cls.op = len(_BY_OP)
        _BY_OP.append(cls)
        _REGISTRY[name] = cls
    return cls


def registry() -> dict[str, type]:
    """The registered group types by model-file ``type`` name (a copy)."""
    return dict(_REGISTRY)


def group_type(op_or_name) -> type:
    """The group type of an op code or a ``type`` name."""
    if isinstance(op_or_name, str):
        return _REGISTRY[op_or_name]
    return _BY_OP[int(op_or_name)]


@dataclass(frozen=True)
class Group:
    """Base of all structural groups (see the module docstring for the contract)."""

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
        None. The file schema calls it before any value is read."""
        return None

    def inputs(self) -> tuple[str, ...]:
        """Names of the points this group needs solved first."""
        raise NotImplementedError

    def outputs(self) -> tuple[str, ...]:
        """Names of the points this group adds."""
        raise NotImplementedError

    def refs(self) -> dict[str, Ref]:
        """Length/angle references of the group by role."""
        return {}

    def coordinates_driven(self) -> tuple[str, ...]:
        """Names of the generalized coordinates this group is driven by (input groups)."""
        return ()

    def group_links(self) -> tuple[str, ...]:
        """The link names given by the user (may be empty)."""
        return tuple(getattr(self, "links", ()) or ())

    def validate(self, coordinates) -> str | None:
        """A message if the description is inconsistent in itself, else None."""
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
        group's links (see :class:`assur.topology.TopologyBuilder`)."""
        raise NotImplementedError

    # ---- positions ----------------------------------------------------------------
    def evaluate(self, pts: dict, val) -> None:
        """Add the output points to ``pts`` by the closed-form position formulas in
        plain numpy (any dtype, complex included). ``val(ref)`` gives a reference's
        value."""
        raise NotImplementedError

    def compile(self, c) -> tuple[int, ...]:
        """The program row after the op code: integers only (slots, parameter rows,
        coordinate indices, signs). See :class:`assur.program.CompileContext`."""
        raise NotImplementedError

    @classmethod
    def emit(cls, E, i: int, row: tuple[int, ...]) -> None:
        """Emit the kernel code of group ``i`` with program ``row`` (op excluded)."""
        raise NotImplementedError

    # ---- diagnostics ----------------------------------------------------------------
    def failure(self, code: int, pts: dict, v, nm) -> Failure:
        """Explain failure ``code`` at one element. ``pts``: the reference positions
        of the points before this group (floats); ``v(ref)``: a reference's value;
        ``nm(ref)``: how a reference is named in messages."""
        from ..kernel.emit import FAIL_COINCIDENT, FAIL_DEAD_POINT
        if code == FAIL_COINCIDENT:
            return Failure(0.0, "two points that must define a direction coincide "
                                f"({', '.join(self.inputs())})")
        if code == FAIL_DEAD_POINT:
            return Failure(0.0, "dead point: the Jacobian of the group is singular")
        return Failure(0.0, f"failure code {code}")

    def prepare(self, data, ptab, positions_at) -> None:
        """Pre-pass before the kernel runs: fill derived per-design rows of ``ptab``
        registered at compile time (:meth:`assur.program.CompileContext.prepare`).
        ``positions_at(qpose, points)`` solves the groups before this one at other
        coordinates. Only groups that register a pre-pass implement it."""
        raise NotImplementedError

    def closure(self, P, val):
        """Largest violation of the group's closure equations [m] (array), or None
        when the group has none beyond its construction. ``P(point)`` gives (x, y);
        ``val(ref)`` a reference's value."""
        return None

    # ---- kinetostatics --------------------------------------------------------------
    def rod_ends(self, links, is_coord) -> tuple[tuple[str, str], ...]:
        """``(cylinder link, rod-end point)`` of the cylinders inside the group: loads
        applied there on the cylinder are taken off its axial force."""
        return ()

    def reactions(self, r) -> None:
        """Solve the group's joint reactions from the loads on its links (reverse
        order), record them and pass the joint forces on to the links it is attached
        to (see :class:`assur.statics.ReactionContext`)."""
        raise NotImplementedError
