"""The contract of a hydraulic component and the registry of component types.

A component is an immutable description (a frozen dataclass) of one element of the
open hydraulic circuit of seed 001 lab 6 (fig. 6.1: pump 1, relief valve 2,
directional valve 3, lines 4, cylinder 5; the oil of the lines and the cylinder
lumped in one node, fig. 6.2). Each one

* has ``type_name`` — the model file's ``type`` (``[[drive]]`` entries);
* has ``title`` — what reports call the type, a :class:`assur.texts.Text` in every
  language (``Text("gear pump", ru="шестерённый насос")``; default: ``type_name``),
  and may have ``words`` — ``{word: Text}`` for the words its fields take in the file
  (a valve's ``position = "raise"``);
* has ``role`` — its place in the circuit: ``"pump"``, ``"relief"``, ``"valve"``,
  ``"line"``, ``"volume"``, ``"cylinder"`` or ``"divider"``;
* has ``quantities`` — ``{field: kind}`` of its value fields (the units the file
  may give them in, :mod:`assur.io._drive`), and may have ``spans`` — ``{field:
  (low, high)}`` [SI] where a field's physical span is narrower or wider than its
  kind's (:data:`assur.core.inputs.SPANS`, :func:`span`): a file's value outside is refused at its key;
* states its equation and the unit of every field in its docstring, SI inside;
* checks its values on construction (:meth:`check`), raising
  :class:`assur.errors.ModelError` that names the component, the field and value.

The role's methods (``flow``, ``relief_flow``, ``loss_coefficients``, …) are what
:class:`assur.dynamics.drive.Circuit` calls; nothing else looks inside a component.
Adding a component type is one new module registering itself here and imported
in :mod:`assur.dynamics.drive`.
"""

from __future__ import annotations

import math

from ...errors import ModelError

__all__ = ["register", "registry", "component_type", "ROLES", "positive", "nonneg", "span"]

#: the places a component can take in the circuit
ROLES = ("pump", "relief", "valve", "line", "volume", "cylinder", "divider")

_REGISTRY: dict[str, type] = {}

def span(cls, field) -> tuple:
    """``(low, high)`` [SI]: the physical span of the value field ``field`` of the
    component type ``cls`` — its own ``spans`` entry, else its kind's
    (:data:`assur.core.inputs.SPANS`: up to its largest magnitude, from its smallest
    positive value; a kind without a span: any finite number).

    Examples
    --------
    >>> from assur.dynamics.drive import DriveCylinder, GearPump
    >>> from assur.dynamics.drive.base import span
    >>> span(GearPump, "displacement")        # [m³]
    (1e-09, 10.0)
    >>> span(DriveCylinder, "count")             # cylinders working as one [-]
    (1, 100)
    """
    from ...core.inputs import SPANS
    own = getattr(cls, "spans", {})
    if field in own:
        return own[field]
    big, small = SPANS.get(cls.quantities[field], (math.inf, -math.inf))
    return small, big


def register(cls):
    """Class decorator: register a component type under ``cls.type_name``.

    Raises
    ------
    ValueError
        A role not in :data:`ROLES`, or another class under the same ``type_name``.

    Examples
    --------
    >>> from assur.dynamics.drive import GearPump, register
    >>> register(GearPump) is GearPump          # the same class again: no change
    True
    >>> class Tank:
    ...     type_name, role = "tank", "reservoir"
    >>> register(Tank)
    Traceback (most recent call last):
    ...
    ValueError: component 'tank': role must be one of: ['pump', 'relief', 'valve', 'line', 'volume', 'cylinder', 'divider']
    """
    name = cls.type_name
    if cls.role not in ROLES:
        raise ValueError(f"component {name!r}: role must be one of: {list(ROLES)}")
    if name in _REGISTRY and _REGISTRY[name] is not cls:
        raise ValueError(f"component type {name!r} is registered twice")
    _REGISTRY[name] = cls
    return cls


def registry() -> dict[str, type]:
    """The registered component types by model-file ``type`` name (a copy).

    Examples
    --------
    >>> from assur.dynamics.drive import registry
    >>> sorted(registry())
    ['cylinder', 'directional_valve', 'flow_divider', 'gear_pump', 'line', 'line_losses', 'oil_volume', 'relief_valve']
    >>> registry()["gear_pump"].role
    'pump'
    """
    return dict(_REGISTRY)


def component_type(name: str) -> type:
    """The component type of a ``type`` name; a ValueError lists the valid ones.

    Examples
    --------
    >>> from assur.dynamics.drive import component_type
    >>> cls = component_type("oil_volume")
    >>> cls.__name__, cls.role
    ('OilVolume', 'volume')
    >>> component_type("tank")
    Traceback (most recent call last):
    ...
    ValueError: component type must be one of: ['cylinder', 'directional_valve', 'flow_divider', 'gear_pump', 'line', 'line_losses', 'oil_volume', 'relief_valve'], got 'tank'
    """
    try:
        return _REGISTRY[name]
    except KeyError:
        raise ValueError(f"component type must be one of: {sorted(_REGISTRY)}, "
                         f"got {name!r}") from None


def _check(obj, field, ok, rule):
    v = getattr(obj, field)
    if not (isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            and ok(v)):
        who = " ".join(x for x in (obj.type_name, getattr(obj, "name", None) or "") if x)
        raise ModelError(f"{who}: {field} = {v!r} must be a finite number"
                         + (f" {rule}" if rule else ""))


def positive(obj, *fields):
    """Raise ModelError unless every field of ``obj`` is a finite number > 0.

    Examples
    --------
    >>> from assur.dynamics.drive import GearPump
    >>> from assur.dynamics.drive.base import positive
    >>> pump = GearPump(32e-6, 188.5, 0.9)     # [m³], [rad/s], [-]
    >>> positive(pump, "displacement", "speed")   # passes: returns None
    >>> GearPump(32e-6, 0.0, name="P1")       # speed = 0 rad/s
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: gear_pump P1: speed = 0.0 must be a finite number > 0
    """
    for f in fields:
        _check(obj, f, lambda x: x > 0, "> 0")


def nonneg(obj, *fields):
    """Raise ModelError unless every field of ``obj`` is a finite number ≥ 0.

    Examples
    --------
    >>> from assur.dynamics.drive import LineLosses
    >>> from assur.dynamics.drive.base import nonneg
    >>> nonneg(LineLosses(a1=0.0, a3=2.0e9), "a1", "a3")   # 0 is allowed: returns None
    >>> LineLosses(a2=float("nan"), name="hose")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: line_losses hose: a2 = nan must be a finite number ≥ 0
    """
    for f in fields:
        _check(obj, f, lambda x: x >= 0, "≥ 0")
