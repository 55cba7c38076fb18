"""Every structural group type drawn: a page generated from the group registry.

For each type of :func:`assur.groups.registry` the page shows the type's fields (from
its :class:`~assur.groups.base.Field` list, as the model file reads them), a small model
file that uses it, and the drawing of that model at two positions made by
:func:`assur.views.report.drawing.draw` — the engine's own drawing code. The model files
below are the samples: a registered type without one stops the build, so a new group
type cannot be left out of the documentation.
"""

from __future__ import annotations

from pathlib import Path

HEAD = """[model]
name = "{name}"
title = "{title}"
coordinates = ["{q}"]
"""

#: one small model file per group type (the TOML after the [model] header):
#: (coordinate, what it shows, body)
SAMPLES: dict[str, tuple[str, str, str]] = {
    "frame": ("j1", "frame pivots: O1 by coordinates, O3 by length and angle from O1", """
[range]
j1 = { from = "0 deg", to = "300 deg", count = 6 }

[frame]
O1 = [0, 0]
O3 = { origin = "O1", length = "0.40 m", angle = "-15 deg" }   # polar form

[[groups]]
type = "crank"
name = "crank 1"
pivot = "O1"
out = "A"
radius = "0.12 m"
q = "j1"
links = ["1"]

[[groups]]
type = "dyad"
name = "dyad 2-3"
a = "A"
b = "O3"
out = "B"
ra = "0.40 m"
rb = "0.30 m"
branch = 1
links = ["2", "3"]
"""),
    "crank": ("j1", "a crank driven by its angle j1", """
[range]
j1 = { from = "0 deg", to = "270 deg", count = 4 }

[frame]
O1 = [0, 0]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "O1"
out = "A"
radius = "0.15 m"
q = "j1"
links = ["1"]
"""),
    "cylinder_lever": ("S", "a cylinder 01–23 turning the lever 03–23", """
[range]
S = { from = "0.36 m", to = "0.52 m", count = 5 }

[frame]
"01" = [0, 0]
"03" = [0.40, 0.25]

[[groups]]
type = "cylinder_lever"
name = "I (2,3)"
base = "01"
pivot = "03"
out = "23"
lever = "0.22 m"
s = "S"
branch = -1
links = ["2", "3"]
"""),
    "slider_input": ("s", "a slider moved along a line at 30° by its travel s", """
[range]
s = { from = "0 m", to = "0.3 m", count = 4 }

[frame]
C0 = [0, 0]

[[groups]]
type = "slider_input"
name = "slider 1"
origin = "C0"
out = "P"
s = "s"
offset = "0.05 m"
direction = "30 deg"
links = ["1"]
"""),
    "dyad": ("j1", "an RRR dyad closing a four-bar: C from A and B0", """
[range]
j1 = { from = "0 deg", to = "300 deg", count = 6 }

[frame]
A0 = [0, 0]
B0 = [0.40, 0]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "A0"
out = "A"
radius = "0.12 m"
q = "j1"
links = ["1"]

[[groups]]
type = "dyad"
name = "II (2,3)"
a = "A"
b = "B0"
out = "C"
ra = "0.40 m"
rb = "0.30 m"
branch = 1
links = ["2", "3"]
"""),
    "slider_dyad": ("j1", "an RRP dyad: the slider C on a fixed horizontal line (slider-crank)", """
[range]
j1 = { from = "0 deg", to = "300 deg", count = 6 }

[frame]
A0 = [0, 0]
L0 = [0, -0.05]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "A0"
out = "A"
radius = "0.12 m"
q = "j1"
links = ["1"]

[[groups]]
type = "slider_dyad"
name = "II (2,3)"
a = "A"
out = "C"
radius = "0.40 m"
line_point = "L0"
direction = "0 deg"
branch = 1
links = ["2", "3"]
"""),
    "rpr_dyad": ("j1", "an RPR dyad: the rod from A slides through the sleeve pivoted at B", """
[range]
j1 = { from = "0 deg", to = "300 deg", count = 6 }

[frame]
A0 = [0, 0]
B = [0.30, 0]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "A0"
out = "A"
radius = "0.12 m"
q = "j1"
links = ["1"]

[[groups]]
type = "rpr_dyad"
name = "II (2,3)"
a = "A"
b = "B"
out = "E"
length = "0.55 m"
branch = 1
links = ["2", "3"]
"""),
    "prp_dyad": ("s", "a PRP dyad: C where the vertical line through P meets the line at 10° through B0", """
[range]
s = { from = "0.05 m", to = "0.3 m", count = 4 }

[frame]
C0 = [0, 0]
B0 = [-0.1, 0.25]

[[groups]]
type = "slider_input"
name = "slider 1"
origin = "C0"
out = "P"
s = "s"
links = ["1"]

[[groups]]
type = "prp_dyad"
name = "II (2,3)"
a = "P"
b = "B0"
out = "C"
direction_a = "90 deg"
direction_b = "10 deg"
links = ["2", "3"]
"""),
    "rigid_point": ("j1", "a rigid point D on the crank, at 0.2 m and 40° from O1→A", """
[range]
j1 = { from = "0 deg", to = "270 deg", count = 4 }

[frame]
O1 = [0, 0]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "O1"
out = "A"
radius = "0.15 m"
q = "j1"
links = ["1"]

[[groups]]
type = "rigid_point"
name = "arm D"
origin = "O1"
toward = "A"
out = "D"
length = "0.20 m"
angle = "40 deg"
links = ["1"]
"""),
    "pose_point": ("j1", "a point S1 of the crank fixed by its offset (dx, dy) from O1 at j1 = 0°", """
[range]
j1 = { from = "0 deg", to = "270 deg", count = 4 }

[frame]
O1 = [0, 0]

[[groups]]
type = "crank"
name = "crank 1"
pivot = "O1"
out = "A"
radius = "0.15 m"
q = "j1"
links = ["1"]

[[groups]]
type = "pose_point"
name = "centre of mass S1"
origin = "O1"
toward = "A"
out = "S1"
dx = "0.06 m"
dy = "0.04 m"
at = { j1 = "0 deg" }
links = ["1"]
"""),
}


def model_text(type_name: str) -> str:
    """The whole sample model file of ``type_name``."""
    q, title, body = SAMPLES[type_name]
    return HEAD.format(name=f"sample_{type_name}", title=title, q=q) + body


def _fields_table(cls) -> list[str]:
    rows = ["| field | role | unit (plain numbers) | meaning |", "|---|---|---|---|"]
    for f in cls.fields:
        unit = {"length": "m", "angle": "°"}.get(f.quantity or "", "")
        doc = " ".join(str(f.doc).split()).replace("|", "\\|")
        rows.append(f"| `{f.name}` | {f.role} | {unit} | {doc} |")
    return rows


def write(page: Path, folder: Path) -> None:
    """Draw every registered group type into ``folder`` and write the page."""
    import matplotlib.pyplot as plt

    from assur import io
    from assur.groups import registry
    from assur.views.report.drawing import draw

    missing = sorted(set(registry()) - set(SAMPLES))
    if missing:
        raise RuntimeError(f"docs/_ext/gen_groups_drawn.py: no sample model for the group "
                           f"type(s) {missing}: add one to SAMPLES")
    folder.mkdir(parents=True, exist_ok=True)
    lines = ["# Every group type, drawn", "",
             "Generated from the group registry (`assur.groups.registry()`) when the "
             "documentation is built: for each structural group type its fields as the "
             "model file's `[[groups]]` entry reads them, a small model file using it, and "
             "the drawing of that model (`assur.views.report.drawing.draw`, the drawing of the "
             "reports) at its first position in colour and its last one as an outline. "
             "Lengths in metres, angles in degrees in the file (`\"30 deg\"`), branches "
             "`+1`/`-1` as the [model file format](../model-format.md) explains.", ""]
    for name, cls in registry().items():
        model = io.loads(model_text(name), name=f"sample_{name}.toml")
        m = model.mechanism
        a = m.analyze(model.range)
        fig = draw(a, width=5.6, height=4.2)
        png = folder / f"{name}.png"
        fig.savefig(png, dpi=90)
        plt.close(fig)
        kind = " ".join(str(cls.kind).split())
        lines += [f"## `{name}` — {kind} ({cls.kind_ru})", ""]
        doc = " ".join((cls.__doc__ or "").strip().split("\n\n")[0].split())
        lines += [doc[:-1] if doc.endswith("::") else doc, ""]
        lines += _fields_table(cls) + [""]
        lines += ["```toml", model_text(name).strip(), "```", ""]
        lines += [f"![{name}](groups/{name}.png)", ""]
    text = "\n".join(lines) + "\n"
    if not page.exists() or page.read_text(encoding="utf-8") != text:
        page.write_text(text, encoding="utf-8")
