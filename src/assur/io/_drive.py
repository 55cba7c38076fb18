"""The ``[[drive]]`` entries and the ``[simulation]`` section of a model file: the
hydraulic circuit driving the mechanism and the simulation of its motion in time
(:mod:`assur.dynamics.drive`, :mod:`assur.dynamics.simulate`, docs/simulation.md).

```toml
[[drive]]
type = "gear_pump"                 # one entry per component, by type (assur.dynamics.drive.registry)
displacement = "32 cm^3"           # НШ-32
speed = "1800 rpm"
eta_volumetric = 0.9

[[drive]]
type = "cylinder"
coordinate = "S"
bore = "125 mm"
rod = "50 mm"
s_min = "Smin"
s_max = "Smax"

[simulation]
duration = "4.5 s"
p0 = "0 MPa"                       # pressure in the line at t = 0 (or "hold")
# start = { S2 = "1.8 m" }         # coordinates at t = 0 (default: on the stops)
method = "Radau"                   # Radau | BDF | LSODA
outputs = 2001                     # output times, evenly spaced
```

Kept apart from the rest of the schema: :mod:`assur.io._schema` only admits the
entries, :mod:`assur.io._build` calls :func:`build_drive` once the mechanism is
built, and the results are :attr:`assur.io.Model.drive` (an
:class:`assur.dynamics.drive.Circuit`) and :attr:`assur.io.Model.simulation`. Values take
units (or are parameter names), and every error names the file, line and key.
"""

from __future__ import annotations

import dataclasses
import re
import typing
from dataclasses import dataclass

from pydantic import BaseModel, ConfigDict, Field, StrictInt

from ..dynamics import drive as _drive
from ..dynamics.simulate import METHODS
from ..errors import ModelError
from . import _schema as S
from ._units import ANGULAR_VELOCITY, LENGTH, NUMBER, PRESSURE, TIME, Kind

__all__ = ["SimulationSpec", "build_drive", "KINDS"]

VOLUME = Kind("volume", "a volume", "m**3", '"32 cm^3"')
FLOW = Kind("flow", "a flow", "m**3/s", '"80 l/min"')
DENSITY = Kind("density", "a density", "kg/m**3", '"870 kg/m^3"')
VISCOSITY = Kind("kinematic viscosity", "a kinematic viscosity", "m**2/s", '"46 mm^2/s"')
INERTANCE = Kind("inertance", "an inertia coefficient", "Pa*s**2/m", '"2.6e5 Pa*s^2/m"')
RESISTANCE = Kind("resistance", "a laminar loss coefficient", "Pa*s/m", '"1.5e6 Pa*s/m"')
TURBULENT = Kind("turbulent resistance", "a turbulent loss coefficient", "Pa*s**2/m**2",
                 '"3.5e7 Pa*s^2/m^2"')

#: the unit kind of each quantity a component declares (``quantities``)
KINDS = {k.name: k for k in (VOLUME, FLOW, DENSITY, VISCOSITY, INERTANCE, RESISTANCE,
                             TURBULENT, LENGTH, PRESSURE, NUMBER, ANGULAR_VELOCITY)}


class SimulationSection(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=False)

    duration: S.Value
    p0: S.Value = 0.0
    start: dict[str, S.Value] = {}
    method: typing.Literal[METHODS] = "Radau"
    outputs: StrictInt = Field(2001, ge=2, le=1_000_000)


@dataclass(frozen=True)
class SimulationSpec:
    """The ``[simulation]`` section in SI.

    Attributes
    ----------
    duration : float
        t_end [s].
    p0 : float or "hold"
        Pressure in the lines at t = 0 [Pa], or ``"hold"``: in each branch the
        pressure that holds its rod against the loads.
    start : dict of str to float
        Coordinates at t = 0 [m] (the others start on their stops).
    method : str
        solve_ivp method (:data:`assur.dynamics.simulate.METHODS`).
    outputs : int
        Number of evenly spaced output times.
    """

    duration: float
    p0: object
    method: str
    outputs: int
    start: dict = dataclasses.field(default_factory=dict)


def build_drive(builder, mech):
    """``(circuit, simulation)`` of the file ``builder`` reads: an
    :class:`assur.dynamics.drive.Circuit` (None without ``[[drive]]`` entries) and a
    :class:`SimulationSpec` (None without a ``[simulation]`` table)."""
    raw = builder.data.get("drive")
    sim = builder.data.get("simulation")
    circuit = None
    if raw is not None:
        if not isinstance(raw, list):
            raise builder.error(("drive",), "expected a list of components ([[drive]] "
                                            "entries)")
        types = _drive.registry()
        comps = []
        for i, entry in enumerate(raw):
            comps.append(_component(builder, mech, types, entry, ("drive", i)))
        try:
            circuit = _drive.Circuit(tuple(comps))
        except ModelError as e:
            raise builder.error(("drive",), str(e)) from None
    spec = None
    if sim is not None:
        if circuit is None:
            raise builder.error(("simulation",), "a [simulation] needs the circuit: add "
                                                 "[[drive]] entries")
        sec, errors = S.validate(SimulationSection, sim, ("simulation",))
        if errors:
            path, problem = errors[0]
            raise builder.error(path, problem)
        dur = _si(builder, mech, ("simulation", "duration"), sec.duration, TIME, "positive")
        p0 = "hold" if sec.p0 == "hold" else _si(builder, mech, ("simulation", "p0"), sec.p0,
                                                   PRESSURE, "nonneg")
        start = {}
        for c, v in sec.start.items():
            if c not in mech.coordinates:
                raise builder.error(("simulation", "start", c),
                                    f'expected a generalized coordinate (one of: '
                                    f'{", ".join(mech.coordinates)}), found "{c}"')
            start[c] = _si(builder, mech, ("simulation", "start", c), v, LENGTH)
        spec = SimulationSpec(dur, p0, sec.method, sec.outputs, start)
    return circuit, spec


def _si(builder, mech, path, v, kind, flag=None):
    if isinstance(v, bool) or not isinstance(v, (str, int, float)):
        raise builder.error(path, f"expected {kind.article} (e.g. {kind.example}) or a "
                                  f"parameter name, found {S.show(v)}")
    si = builder.value(path, v, kind, flag)
    return float(mech.params[si]) if isinstance(si, str) else float(si)


def _in_span(builder, path, cls, key, v, si, kind):
    """``si`` [SI] within the physical span of ``cls``'s field ``key``
    (:func:`assur.dynamics.drive.span`), else the located error."""
    lo, hi = _drive.span(cls, key)
    if not lo <= si <= hi:
        unit = kind.si.replace("**", "^") if kind.si else ""
        raise builder.error(path, f"{key} = {S.show(v)} is outside the physical span of "
                                  f"{kind.article}, {lo:g} … {hi:g}{' ' + unit if unit else ''}"
                                  f" (is its unit or exponent right?)")
    return si


def _field_named(message, fields):
    """The field a component's error names (``"… bore = 0.0 must be …"``), or None."""
    for f in fields:
        if re.search(rf"(^|[\s:]){re.escape(f)} = ", message):
            return f
    return None


def _shown_name(builder, path, v):
    """A component's name as the reader sees it (:class:`assur.texts.Text` for a table
    of languages), or the builder's located error."""
    from pydantic_core import PydanticCustomError

    from ._schema_values import _shown_name as shown
    try:
        return shown(v)
    except PydanticCustomError as e:
        raise builder.error(path, e.message()) from None


def _component(builder, mech, types, entry, at):
    if not isinstance(entry, dict):
        raise builder.error(at, "expected a table (a [[drive]] entry)")
    options = ", ".join(types)
    t = entry.get("type")
    if t is None:
        raise builder.error(at, f'missing required key "type" (one of: {options})')
    if not isinstance(t, str) or t not in types:
        raise builder.error(at + ("type",), f'unknown component type {S.show(t)}'
                                            f'{S.did_you_mean(str(t), types)} (one of: '
                                            f'{options})')
    cls = types[t]
    fields = {f.name: f for f in dataclasses.fields(cls)}
    kw = {}
    for key, v in entry.items():
        if key == "type":
            continue
        path = at + (key,)
        if key not in fields:
            raise builder.error(path, f'unknown key "{key}" of a {t}'
                                      f'{S.did_you_mean(key, fields)} (keys: '
                                      f'{", ".join(fields)})')
        q = cls.quantities.get(key)
        if q is not None:
            kw[key] = _in_span(builder, path, cls, key, v,
                               _si(builder, mech, path, v, KINDS[q]), KINDS[q])
        elif key == "coordinate":
            if v not in mech.coordinates:
                raise builder.error(path, f'expected a generalized coordinate (one of: '
                                          f'{", ".join(mech.coordinates)}), found {S.show(v)}')
            kw[key] = v
        elif key == "shares":
            if not isinstance(v, list):
                raise builder.error(path, f"expected a list of numbers, found {S.show(v)}")
            kw[key] = tuple(_si(builder, mech, path + (j,), x, NUMBER) for j, x in enumerate(v))
        elif key == "name":  # a name shown in reports: a string or { en = …, ru = … }
            kw[key] = _shown_name(builder, path, v)
        else:
            if not isinstance(v, str):
                raise builder.error(path, f"expected a string, found {S.show(v)}")
            kw[key] = v
    missing = [f.name for f in fields.values()
               if f.default is dataclasses.MISSING and f.name not in kw]
    if missing:
        raise builder.error(at, f'missing required key "{missing[0]}" of a {t}')
    try:
        return cls(**kw)
    except ModelError as e:  # at the key the message names, else at the entry
        f = _field_named(str(e), fields)
        raise builder.error(at + (f,) if f in entry else at, str(e)) from None
