"""The ``[tolerances]`` section of a model file: manufacturing tolerances of the
parameters (:mod:`assur.synthesis.tolerance`).

```toml
[tolerances]
X01 = "±0.5 mm"                              # normal, ±3σ = 0.5 mm
L4 = { pm = "1 mm", dist = "uniform" }       # anywhere within ±1 mm
Dgc = { sigma = "0.05 mm" }                  # normal with σ = 0.05 mm
```

A value is written in any unit of the parameter's quantity (the parameter's own use
fixes it: a length, an angle, a pressure…); ``±`` (or ``+-``) is optional. Kept apart
from the rest of the schema: :mod:`assur.io._schema` only admits the table,
:mod:`assur.io._build` calls :func:`build_tolerances` once the mechanism is built, and
the result is :attr:`assur.io.Model.tolerances`. Every error names the file, line and
key.
"""

from __future__ import annotations

from ..errors import ModelError
from ..synthesis.tolerance import DISTRIBUTIONS, Tolerance
from . import _schema as S
from ._units import LENGTH

__all__ = ["build_tolerances"]

_KEYS = ("pm", "sigma", "dist")


def _number(builder, path, text, kind):
    t = str(text).strip()
    for sign in ("±", "+-", "+/-"):
        if t.startswith(sign):
            t = t[len(sign):].strip()
            break
    v = builder.value(path, t, kind, "nonneg")
    if isinstance(v, str):
        raise builder.error(path, f"expected a number with a unit (e.g. \"±0.5 mm\"), found "
                                  f"the name {v!r}")
    return float(v)


def build_tolerances(builder, mech):
    """The tolerances of the file ``builder`` reads, a tuple of
    :class:`assur.synthesis.tolerance.Tolerance` (empty without a ``[tolerances]`` table)."""
    raw = builder.data.get("tolerances")
    if raw is None:
        return ()
    if not isinstance(raw, dict):
        raise builder.error(("tolerances",), f"expected a table, found {S.show(raw)}")
    out = []
    for name, spec in raw.items():
        path = ("tolerances", name)
        if name not in mech.params:
            raise builder.error(path, f"expected a parameter of the model, found "
                                      f"\"{name}\"{S.did_you_mean(name, list(mech.params))}")
        kind = builder.param_use.get(name, (LENGTH,))[0]
        if isinstance(spec, (str, int, float)) and not isinstance(spec, bool):
            out.append(Tolerance(name, _number(builder, path, spec, kind)))
            continue
        if not isinstance(spec, dict):
            raise builder.error(path, f'expected "±<value> <unit>" or a table with pm, '
                                      f"sigma, dist, found {S.show(spec)}")
        extra = [k for k in spec if k not in _KEYS]
        if extra:
            raise builder.error(path + (extra[0],), f"unknown key; expected one of: "
                                                    f"{', '.join(_KEYS)}"
                                                    f"{S.did_you_mean(extra[0], _KEYS)}")
        dist = spec.get("dist", "normal")
        if dist not in DISTRIBUTIONS:
            raise builder.error(path + ("dist",), f"expected one of: "
                                                  f"{', '.join(DISTRIBUTIONS)}, found "
                                                  f"{S.show(dist)}")
        if ("pm" in spec) == ("sigma" in spec):
            raise builder.error(path, "give either pm (the half-width ±t) or sigma (σ)")
        if "sigma" in spec and dist == "uniform":
            raise builder.error(path + ("sigma",), "a uniform tolerance is given by pm "
                                                   "(its half-width), not by sigma")
        try:
            if "pm" in spec:
                out.append(Tolerance(name, _number(builder, path + ("pm",), spec["pm"], kind),
                                     dist))
            else:
                out.append(Tolerance(name, 0.0, dist,
                                     _number(builder, path + ("sigma",), spec["sigma"], kind)))
        except ModelError as e:
            raise builder.error(path, str(e)) from None
    return tuple(out)
