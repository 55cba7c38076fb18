"""The ``[design]`` section of a model file: design variables, constraints and
objectives of a search (:mod:`assur.synthesis.search`, docs/design.md).

```toml
[design]
positions = 50                              # over [range] (default: the range's own)
polish = true                               # SLSQP polish with exact gradients after
                                            # differential evolution (the default)

[design.variables]                          # parameters of [params] and their bounds
X01 = { within = "30 mm" }                  # ± around the file's value
L4 = ["0.60 m", "0.72 m"]                   # [low, high]
X07 = { low = "0.40 m", high = "0.46 m" }   # the same, by name

[[design.constraints]]
quantity = "Y(56)"                          # type = "bound" (the default): an output
of = "min"                                  # min | max | span over the range
at_most = "0.2 m"                           # or at_least; a number with its unit, a
                                            # parameter name, or "original"
[[design.constraints]]
type = "pressure"                           # at most the relief setting by default
cylinder = "ГЦ"

[[design.objectives]]
maximize = "reserve(ГЦ, S6, P6)"            # or minimize = …
of = "min"
```

Kept apart from the rest of the schema like ``[lift_test]``: :mod:`assur.io._schema`
only admits the table; :func:`build_design` checks it against the loaded mechanism.
Every error names the file, line and key. Command-line variables
(``--var "L4=0.6 m:0.72 m"``) are read by :func:`parse_var` with the same units.
"""

from __future__ import annotations

from typing import Literal, Optional, Union

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, StrictBool, StrictInt, StrictStr

from ..errors import ModelError
from . import _schema as S
from ._units import (ANGLE, FORCE, LENGTH, MOMENT, NUMBER, PRESSURE, KINDS, Raw, UnitError,
                     display_unit, parse, to_si)

__all__ = ["DesignSection", "DesignSpec", "build_design", "parse_var", "write_design_file",
           "check_positions"]


class _Within(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    within: S.Value


class _Bounds(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    low: S.Value
    high: S.Value


class _Criterion(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    type: Literal["bound", "capacity", "pressure", "transmission_angle", "box"] = "bound"
    quantity: Optional[StrictStr] = None
    of: Literal["min", "max", "span"] = "min"
    cylinder: Optional[StrictStr] = None
    point: Optional[S.Name] = None
    links: Optional[list[S.Name]] = Field(None, min_length=2, max_length=2)
    x: Optional[list[S.Value]] = Field(None, min_length=2, max_length=2)
    y: Optional[list[S.Value]] = Field(None, min_length=2, max_length=2)


class _Constraint(_Criterion):
    at_least: Optional[S.Value] = None
    at_most: Optional[S.Value] = None


class _Objective(_Criterion):
    maximize: Optional[StrictStr] = None
    minimize: Optional[StrictStr] = None


class DesignSection(BaseModel):
    """The ``[design]`` table as written."""

    model_config = ConfigDict(extra="forbid", frozen=True)
    positions: Optional[StrictInt] = Field(None, ge=2)
    polish: Optional[StrictBool] = None
    variables: dict[str, Union[list[S.Value], _Within, _Bounds]] = {}
    constraints: list[_Constraint] = []
    objectives: list[_Objective] = []


class DesignSpec:
    """The checked ``[design]`` section: variables and criteria in SI.

    Attributes
    ----------
    variables : tuple of assur.synthesis.search.Variable
    constraints, objectives : tuple of assur.synthesis.search.criteria.Criterion
    positions : int or None
        Number of positions over the range (None: the range's own).
    polish : bool or None
        Polish the optimum of differential evolution by SLSQP with exact gradients
        (None: not written, the default of :func:`assur.synthesis.search.search.optimize`).
    """

    def __init__(self, variables, constraints, objectives, positions, polish=None):
        self.variables = tuple(variables)
        self.constraints = tuple(constraints)
        self.objectives = tuple(objectives)
        self.positions = positions
        self.polish = polish


def _kind_of_output(text, mech):
    """The quantity of an output's limits (None for a formula: its value's own unit);
    a point the mechanism does not have is refused here, at the criterion's line (it
    was told later as "the original design does not assemble")."""
    from ..core.outputs import output_unit, resolve_output
    fn, args = resolve_output(mech, text)
    if fn == "formula":
        return None
    points = mech.points
    if fn in ("X", "Y", "dX", "dY", "I") and args and args[0] not in points:
        raise ValueError(f"{text}: unknown point {args[0]!r}"
                         f"{S.did_you_mean(args[0], list(points))} (points: "
                         f"{', '.join(points)})")
    return {"m": LENGTH, "N": FORCE, "N·m": MOMENT, "Pa": PRESSURE, "rad": ANGLE,
            "%": NUMBER}.get(output_unit(mech, text))


_CRITERION_KIND = {"capacity": FORCE, "pressure": PRESSURE, "transmission_angle": ANGLE,
                   "box": LENGTH}


def _param_kind(mech, name):
    from ..core.quantities import parameter_quantities
    q = parameter_quantities(mech).get(name)
    return KINDS.get(q) if q else None


class _KeyProblem(ValueError):
    """A problem of one key of a criterion (told at that key's line, not the entry's)."""

    def __init__(self, key, message):
        super().__init__(message)
        self.key = key


def _at(key, fn, *args):
    """``fn(*args)``, its ValueError told at ``key``."""
    try:
        return fn(*args)
    except _KeyProblem:
        raise
    except ValueError as e:
        raise _KeyProblem(key, str(e)) from None


def _si(text, kind, problem):
    """``(SI value, Unit)`` of a value string, or raise ValueError(problem)."""
    try:
        raw = parse(text)
    except UnitError as e:
        raise ValueError(f"{problem}: {e}" if str(e) else f"{problem}, found {text!r}") \
            from None
    if not isinstance(raw, Raw):
        raise ValueError(f"{problem}, found the name {raw!r}")
    try:
        return float(to_si(raw, kind)), display_unit(raw, kind)
    except UnitError as e:
        said = str(e)
        raise ValueError(f"{problem}, found {text!r}" if said in problem
                         else f"{problem}: {said}") from None


def build_design(builder, mech, path_prefix=("design",)):
    """The :class:`DesignSpec` of the ``[design]`` section of the file ``builder``
    reads (None without one); ``mech`` is the mechanism built from it.

    Raises
    ------
    ModelFileError
        Naming the file, line and key of the problem.
    """
    raw = builder.data.get("design")
    if raw is None:
        return None
    err = builder.error
    spec, errors = S.validate(DesignSection, raw, path_prefix)
    if errors:
        path, problem = errors[0]
        raise err(path, problem)
    from ..synthesis.search.criteria import Limit, criterion
    from ..synthesis.search.problem import Variable
    from ..core.quantities import display_units
    units = display_units(mech)
    variables = []
    for name, b in spec.variables.items():
        p = path_prefix + ("variables", name)
        if name not in mech.params:
            raise err(p, f'expected a parameter of [params], found "{name}"'
                         f"{S.did_you_mean(name, list(mech.params))}")
        value = float(np.asarray(mech.params[name]))
        kind = _param_kind(mech, name)
        try:
            if isinstance(b, _Within):
                d, _ = _si(b.within, kind, f"within: expected {_article(kind)}")
                if d <= 0:
                    raise ValueError(f"within must be positive, found {b.within}")
                lo, hi = value - d, value + d
            else:
                if isinstance(b, _Bounds):  # { low = …, high = … }: [low, high] by name
                    b = [b.low, b.high]
                if len(b) != 2:
                    raise ValueError(f"expected [low, high], found {len(b)} values")
                lo, _ = _si(b[0], kind, f"expected {_article(kind)}")
                hi, _ = _si(b[1], kind, f"expected {_article(kind)}")
            variables.append(Variable(name, lo, hi, units.get(name)))
        except (ValueError, ModelError) as e:
            raise err(p, str(e)) from None
    crits = []
    for key, entries in (("constraints", spec.constraints), ("objectives", spec.objectives)):
        for i, c in enumerate(entries):
            p = path_prefix + (key, i)
            try:
                crits.append((key, _criterion(c, key, mech, criterion, Limit)))
            except _KeyProblem as e:
                raise err(p + (e.key,), str(e)) from None
            except (ValueError, ModelError) as e:
                raise err(p, str(e)) from None
    positions = spec.positions
    if positions is not None:  # one design over the positions must fit in memory
        try:
            check_positions(mech, positions, "[design] positions")
        except ModelError as e:
            raise err(path_prefix + ("positions",), str(e)) from None
    return DesignSpec(variables, [c for k, c in crits if k == "constraints"],
                      [c for k, c in crits if k == "objectives"], positions, spec.polish)


def check_positions(mech, count, key):
    """Refuse ``count`` positions of a design problem that one design alone could not
    be evaluated over within :func:`assur.core.inputs.max_memory` (the positions, the
    coordinates and the status of one kernel call); ``key`` names the option or file
    key that gave them.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur import examples
    >>> from assur.io._design import check_positions
    >>> check_positions(examples.hitch_003(), 50, "--positions")  # fine
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "1 MiB"}):
    ...     check_positions(examples.hitch_003(), 10**6, "--positions")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: design problem 'hitch_003': --positions 1000000: 1e+06 positions would need about 30.5 MiB of memory (limit 1 MiB; set ASSUR_MAX_MEMORY to change it, or reduce --positions)
    """
    from ..core.inputs import check_memory
    check_memory(float(count), 8 * (len(mech.coordinates) + 3),
                 f"design problem {mech.name!r}: {key}{' = ' if key.startswith('[') else ' '}"
                 f"{count}", reduce=key)


def _article(kind):
    return f"{kind.article} (e.g. {kind.example})" if kind is not None else "a number"


def _criterion(c, key, mech, criterion, Limit):
    args = {k: getattr(c, k) for k in ("quantity", "of", "cylinder", "point", "links")
            if getattr(c, k) is not None}
    for ax in ("x", "y"):
        v = getattr(c, ax)
        if v is not None:
            args[ax] = tuple(_si(s, LENGTH, f"{ax}: expected a length (e.g. \"0.4 m\")")[0]
                             for s in v)
    if c.type == "bound" and c.quantity is None and key == "constraints":
        raise ValueError('a bound needs quantity = an output, e.g. "Y(56)" (or give type = '
                         '"capacity", "pressure", "transmission_angle" or "box")')
    if key == "objectives":
        if (c.maximize is None) == (c.minimize is None):
            raise ValueError("an objective has maximize = … or minimize = …")
        sense = "maximize" if c.maximize is not None else "minimize"
        if c.type == "bound":
            args["quantity"] = c.maximize or c.minimize
        kind = _at(sense, _kind_of_output, args["quantity"], mech) if c.type == "bound" else \
            _CRITERION_KIND[c.type]
        unit = _output_unit(args.get("quantity"), mech) or _default_unit(kind)
        return criterion(c.type, args, mech, sense=sense, unit=unit)
    if c.at_least is not None and c.at_most is not None:
        raise ValueError("give at_least or at_most, not both")
    sense = "at_least" if c.at_least is not None else "at_most" if c.at_most is not None \
        else None
    kind = _at("quantity", _kind_of_output, c.quantity, mech) if c.type == "bound" else \
        _CRITERION_KIND[c.type]
    if sense is None:
        if c.type == "pressure":  # the relief setting, shown in the unit the file gave it
            from ..core.quantities import display_units
            cyl = [x for x in mech.cylinders if x.name == (c.cylinder or mech.cylinders[0].name)]
            relief = cyl[0].p_relief if cyl else None
            unit = display_units(mech).get(relief) if isinstance(relief, str) else None
            return criterion(c.type, args, mech, limit=Limit(None, "at_most"),
                             unit=unit or _default_unit(kind))
        if c.type == "box":
            return criterion(c.type, args, mech, limit=Limit(None, "at_least"),
                             unit=_default_unit(kind))
        raise ValueError("a constraint needs at_least = … or at_most = …")
    text = getattr(c, sense)
    if isinstance(text, str) and text.strip() == "original":
        return criterion(c.type, args, mech, limit=Limit("original", sense),
                         unit=_output_unit(c.quantity, mech) or _default_unit(kind))
    try:
        raw = parse(text) if not isinstance(text, str) or text.strip() else None
    except UnitError:  # not a number with a unit ("nan m"): _si below says what is wrong
        raw = None
    if isinstance(raw, str):  # a parameter name
        if raw not in mech.params:
            raise _KeyProblem(sense, f'{sense}: "{raw}" is not a parameter'
                             f"{S.did_you_mean(raw, list(mech.params))}")
        return criterion(c.type, args, mech, limit=Limit(raw, sense), unit=_default_unit(kind))
    v, unit = _at(sense, _si, text, kind, f"expected {_article(kind)}")  # at the key's line
    return criterion(c.type, args, mech, limit=Limit(v, sense), unit=unit)


def _output_unit(quantity, mech):
    """Unit("%") for an output in percent (a reserve), a formula's own unit, else None."""
    from ..core.outputs import display_unit, resolve_output
    if not quantity:
        return None
    u = display_unit(mech, quantity)
    return u if resolve_output(mech, quantity)[0] == "formula" or u.text == "%" else None


def _default_unit(kind):
    from ..core.quantities import DEFAULT_UNITS, Unit
    return DEFAULT_UNITS.get(kind.name, Unit("-")) if kind is not None else Unit("-")


def parse_var(text, mech):
    """A command-line design variable ``"NAME=LOW:HIGH"`` (``"L4=0.6 m:0.72 m"``,
    ``"X01=±30 mm"`` for ± around the model's value), units as in model files.

    Returns
    -------
    assur.synthesis.search.Variable

    Raises
    ------
    ModelError
        Naming the option and what is wrong.
    """
    from ..synthesis.search.problem import Variable
    from ..core.quantities import display_units
    name, sep, rest = str(text).partition("=")
    name = name.strip()
    if not sep or not name:
        raise ModelError(f'--var {text!r}: expected NAME=LOW:HIGH (e.g. "L4=0.6 m:0.72 m") '
                         f'or NAME=±DELTA (e.g. "X01=±30 mm")')
    if name not in mech.params:
        raise ModelError(f"--var {text!r}: {name!r} is not a parameter of {mech.name!r}"
                         f"{S.did_you_mean(name, list(mech.params))}")
    kind = _param_kind(mech, name)
    unit = display_units(mech).get(name)
    try:
        rest = rest.strip()
        if rest.startswith(("±", "+-")):
            d, _ = _si(rest.lstrip("±+-").strip(), kind, f"expected {_article(kind)}")
            v = float(np.asarray(mech.params[name]))
            return Variable(name, v - d, v + d, unit)
        lo, colon, hi = rest.partition(":")
        if not colon:
            raise ValueError("expected LOW:HIGH or ±DELTA")
        return Variable(name, _si(lo, kind, f"expected {_article(kind)}")[0],
                        _si(hi, kind, f"expected {_article(kind)}")[0], unit)
    except (ValueError, ModelError) as e:
        raise ModelError(f"--var {text!r}: {e}") from None


def write_design_file(path, base, values, units, header=()):
    """Write a model file that ``extends`` ``base`` with ``values`` overriding its
    parameters.

    Parameters
    ----------
    path : pathlib.Path
        The file to write.
    base : pathlib.Path
        The original model file (written relative to ``path``'s directory).
    values : mapping of str to float
        Parameter values [SI].
    units : mapping of str to assur.core.quantities.Unit
        The unit to write each value in (the original file's).
    header : sequence of str
        Comment lines at the top.
    """
    import os
    from pathlib import Path
    path, base = Path(path), Path(base)
    rel = os.path.relpath(base.resolve(), path.resolve().parent)
    lines = [f"# {h}" for h in header]
    lines += [f"extends = {_toml_str(Path(rel).as_posix())}", "", "[params]"]
    for k, v in values.items():
        u = units.get(k)
        if u is None or u.text in ("-", ""):
            lines.append(f"{_toml_key(k)} = {float(v)!r}")
        else:
            txt = "deg" if u.is_degrees else u.text.replace("·", "*").replace("²", "^2")
            lines.append(f"{_toml_key(k)} = \"{float(u.of(v))!r} {txt}\"")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _toml_str(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _toml_key(k):
    import re
    return k if re.match(r"^[A-Za-z0-9_-]+$", k) else _toml_str(k)
