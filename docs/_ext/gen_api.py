"""The API reference pages: one page per public module, its members from the
numpydoc docstrings (autodoc), grouped by concern."""

from __future__ import annotations

from pathlib import Path

#: (section, [(module, one line)]) — the public modules, in reading order
SECTIONS = [
    ("Building and solving a mechanism", [
        ("assur", "the package: the builder, the results, the errors"),
        ("assur.mechanism", "Mechanism: frame points, structural groups, loads; solve, analyze"),
        ("assur.groups", "structural group types behind one contract and registry"),
        ("assur.kinematics", "positions and exact analogs as named arrays"),
        ("assur.topology", "the bodies (links) of a mechanism"),
        ("assur.errors", "typed exceptions"),
        ("assur.examples", "the seed machines, loaded from the bundled model files"),
        ("assur.io", "model files: TOML, units, validation"),
        ("assur.synthesis", "design conditions (Given/Find)"),
        ("assur.fitting", "parameters fitted to a printed table"),
        ("assur.design", "synthesis: searching the design space"),
        ("assur.sensitivity", "exact sensitivities to the parameters"),
        ("assur.tolerance", "tolerance analysis"),
    ]),
    ("Forces, cylinders, machines", [
        ("assur.analysis", "one call for the whole worksheet"),
        ("assur.loads", "loads and actuators (descriptions)"),
        ("assur.statics", "virtual work and joint reactions by Assur groups"),
        ("assur.fused", "the fused kernel: only the outputs asked for"),
        ("assur.hydraulics", "areas, pressure, available force, lift capacity"),
        ("assur.capacity", "lift capacity of several cylinders"),
        ("assur.stability", "axle reactions and the 20 % steerability rule"),
        ("assur.lift_test", "the standard lift test of a three-point hitch"),
        ("assur.steering", "Ackermann relation, turning radius, resisting moment"),
        ("assur.conditioner", "the spring pressing device (lab 2)"),
    ]),
    ("Crank machines and dynamics", [
        ("assur.motion", "a crank's direction and speed"),
        ("assur.inertia", "masses, inertia loads, reduced moment"),
        ("assur.flywheel", "the flywheel (energy–mass method)"),
        ("assur.balancing", "common centre of mass and counter-masses"),
        ("assur.dynamics", "equations of motion, simulation, work cycles"),
        ("assur.drive", "hydraulic drive components"),
    ]),
    ("Outputs", [
        ("assur.report", "tables, figures, drawings, HTML"),
        ("assur.columns", "extra table columns: formulas and sign maps"),
        ("assur.texts", "English and Russian user text"),
        ("assur.cli", "the command line"),
        ("assur.app", "the interactive page, inline displays, DXF drawings"),
    ]),
]


def render_index() -> str:
    lines = ["# API reference", "",
             "Generated from the numpydoc docstrings. Units are SI and angles radians "
             "inside (the unit of each parameter ends its description); arrays are over "
             "`(designs, positions)` (a single design drops the first axis).", ""]
    toc = []
    for title, mods in SECTIONS:
        lines += [f"## {title}", "", "| module | what |", "|---|---|"]
        for mod, what in mods:
            lines.append(f"| {{mod}}`{mod}` | {what} |")
            toc.append(f"api/{mod}")
        lines.append("")
    lines += ["```{toctree}", ":hidden:", ":maxdepth: 1", ""] + toc + ["```", ""]
    return "\n".join(lines)


def render_module(mod: str) -> str:
    head = f"{mod}\n{'=' * len(mod)}\n\n.. automodule:: {mod}\n"
    if mod == "assur":  # its names are documented where they live
        import assur
        names = "\n".join(f"   {n}" for n in assur.__all__
                          if not n.startswith("_") and n[0].isupper())
        return (head + "\nThe names the package exports:\n\n.. autosummary::\n\n"
                + names + "\n")
    return head + "   :members:\n"


def _write(path: Path, text: str) -> None:
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def write(docs: Path) -> None:
    folder = docs / "api"
    folder.mkdir(exist_ok=True)
    _write(docs / "api.md", render_index())
    for _, mods in SECTIONS:
        for mod, _ in mods:
            _write(folder / f"{mod}.rst", render_module(mod))
