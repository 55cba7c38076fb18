"""The ``[[rating]]`` tables of a model file: the ratings a machine is reported with
(:mod:`assur.machines.ratings`, docs/ratings.md).

```toml
[[rating]]
type = "crane_chart"      # a rating kind (assur.machines.ratings.registry())
point = "D"               # its parameters, by role: points, cylinders, values, flags
axis = "O"
```

Kept apart from the rest of the schema: :mod:`assur.io._schema` admits the tables,
:mod:`assur.io._build` calls :func:`build_ratings` once the mechanism is built, and the
result is :attr:`assur.io.Model.ratings`. Every error names the file, line and key.
"""

from __future__ import annotations

from ..machines.ratings import check_names, registry
from ..texts import Text
from . import _schema as S
from ._units import KINDS

__all__ = ["build_ratings"]


def _text(builder, path, v):
    if isinstance(v, str):
        return v
    if isinstance(v, dict) and set(v) <= {"en", "ru"} and "en" in v and all(
            isinstance(x, str) for x in v.values()):
        return Text(v["en"], **{k: x for k, x in v.items() if k != "en"})
    raise builder.error(path, f'expected a title: a string or {{ en = "…", ru = "…" }}, found '
                              f"{S.show(v)}")


def _field(builder, path, p, v):
    """The value of the rating parameter ``p`` (a :class:`assur.machines.ratings.Param`)
    written ``v`` at ``path``, checked by its role."""
    role = p.role
    if role in ("point", "cylinder"):
        if not isinstance(v, str):
            raise builder.error(path, f"expected the name of a {role}, found {S.show(v)}")
        return v
    if role == "cylinders":
        if not (isinstance(v, list) and v and all(isinstance(x, str) for x in v)):
            raise builder.error(path, f"expected a list of cylinder names, found {S.show(v)}")
        return tuple(v)
    if role == "flag":
        if not isinstance(v, bool):
            raise builder.error(path, f"expected true or false, found {S.show(v)}")
        return v
    if role == "count":
        if isinstance(v, bool) or not isinstance(v, int) or v < 1:
            raise builder.error(path, f"expected a whole number ≥ 1, found {S.show(v)}")
        return v
    if role == "text":
        return _text(builder, path, v)
    return builder.value(path, v, KINDS[p.quantity])   # "value"


def build_ratings(builder, mech) -> tuple:
    """The ratings (instances of the registered kinds) of the file ``builder`` reads,
    in the file's order; ``mech`` is the mechanism built from it.

    Raises
    ------
    ModelFileError
        At the key: an unknown type (listing the valid ones) or key, a missing key, a
        value of the wrong kind, a name that is not a point or cylinder of the model.
    """
    raw = builder.data.get("rating")
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise builder.error(("rating",), "expected [[rating]] tables (an array of tables)")
    types = registry()
    out = []
    for i, entry in enumerate(raw):
        path = ("rating", i)
        if not isinstance(entry, dict):
            raise builder.error(path, f"expected a table, found {S.show(entry)}")
        t = entry.get("type")
        if t is None:
            raise builder.error(path, f'missing the key "type" (one of: {", ".join(types)})')
        if t not in types:
            raise builder.error(path + ("type",), f'expected one of: {", ".join(types)}; found '
                                                  f'"{t}"{S.did_you_mean(t, types)}')
        cls = types[t]
        params = {p.name: p for p in cls.fields}
        for k in entry:
            if k != "type" and k not in params:
                raise builder.error(path + (k,), f'unknown key "{k}" of a {t} rating (keys: '
                                                 f'{", ".join(params)})'
                                                 f"{S.did_you_mean(k, params)}")
        kw = {}
        for p in cls.fields:
            if p.name not in entry:
                if p.required:
                    raise builder.error(path, f'missing the key "{p.name}" of a {t} rating '
                                              f"({p.doc})")
                continue
            kw[p.name] = _field(builder, path + (p.name,), p, entry[p.name])
        rating = cls(**kw)
        problem = check_names(mech, rating) or rating.check(mech)
        if problem:
            key, message = problem
            v = entry.get(key)
            choices = (list(mech.points) + list(mech.frame_points)
                       if params[key].role == "point" else [c.name for c in mech.cylinders])
            hint = S.did_you_mean(v, choices) if isinstance(v, str) else ""
            raise builder.error(path + (key,), message + hint)
        out.append(rating)
    return tuple(out)
