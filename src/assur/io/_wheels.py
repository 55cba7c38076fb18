"""The ``[[wheels]]`` section of a model file: wheels drawn on links
(:class:`assur.core.wheels.Wheel`, :attr:`assur.Mechanism.wheels`).

```toml
[[wheels]]
name = { en = "left wheel", ru = "левое колесо" }   # or a plain string
link = "w3"               # a link of [links]: the heading follows its direction φ
at = "03"                 # the point the wheel is centred on (the kingpin)
heading = "0 deg"         # rolling direction relative to φ (default 0; from +x without a link)
diameter = "1100 mm"      # drawn length along the heading (a parameter name or a value)
width = "B"               # drawn width across it
```

The table's shape is checked by :class:`assur.io._schema.WheelSpec`; here the values'
uses (:func:`use_wheels`, with the other uses, so that a parameter takes the kind of
its use: ``diameter`` and ``width`` positive lengths, ``heading`` an angle) and the
wheels themselves, once the mechanism is built (:func:`build_wheels`: the point and
the link named, then :meth:`assur.Mechanism.wheel`). Every error names the file, line
and key.
"""

from __future__ import annotations

from ..core.wheels import Wheel
from . import _schema as S
from ._entries import kind

#: the wheel's value fields: ``{field: (kind, flag)}``
WHEEL_VALUES = {f: (kind(q), Wheel.flags.get(f)) for f, q in Wheel.quantities.items()}


def use_wheels(builder):
    """Record the uses of the ``[[wheels]]`` values (pass 1 of
    :class:`assur.io._build.Builder`)."""
    for i, w in enumerate(builder.spec.wheels):
        for field, (k, flag) in WHEEL_VALUES.items():
            if field in w.model_fields_set:
                builder.value(("wheels", i, field), getattr(w, field), k, flag)


def build_wheels(builder, mech):
    """``mech`` with the wheels of ``[[wheels]]``: each at a point of the mechanism,
    heading along a link of ``[links]`` (or of the groups), its values resolved."""
    wheels = builder.spec.wheels
    if not wheels:
        return mech
    frame = list(mech.frame_points)
    points = frame + [p for p in mech.points if p not in frame]
    named = [ln.name for ln in mech.links]
    topo = mech.topology
    groups = [b for b in topo.bodies if b != "0" and b not in named
              and topo.angle_points(b) is not None]
    for i, w in enumerate(wheels):
        wp = ("wheels", i)
        builder.point(wp + ("at",), w.at, points)
        if w.link is not None and w.link not in named + groups:
            shown = ", ".join(named) or "none"
            more = f" or of the groups ({', '.join(groups)})" if groups else ""
            raise builder.error(wp + ("link",),
                                f'unknown link "{w.link}": expected a link of [links] '
                                f'({shown}){more}, found "{w.link}"'
                                f"{S.did_you_mean(w.link, named + groups)}")
        kw = {f: builder.resolved[wp + (f,)] for f in WHEEL_VALUES if f in w.model_fields_set}
        mech = builder.guarded(wp, lambda: mech.wheel(w.name, w.at, link=w.link, **kw))
    return mech
