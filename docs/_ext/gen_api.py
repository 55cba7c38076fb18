"""The API reference pages: one page per public module, its members from the
numpydoc docstrings (autodoc), grouped by concern."""

from __future__ import annotations

from pathlib import Path

#: (section, [(module, one line)]) — the public modules, in reading order
SECTIONS = [
    ("The package and its base", [
        ("assur", "the package: the builder, the results, the errors"),
        ("assur.errors", "typed exceptions"),
        ("assur.texts", "English and Russian user text"),
        ("assur.examples", "the seed machines, loaded from the bundled model files"),
    ]),
    ("Groups and the kernel", [
        ("assur.groups", "structural group types behind one contract and registry"),
        ("assur.kernel", "generated, compiled kernels: code emission and the disk cache"),
    ]),
    ("Core: a mechanism and what follows from it alone", [
        ("assur.core.mechanism", "Mechanism: frame points, structural groups, loads; solve, analyze"),
        ("assur.core.topology", "the bodies (links) of a mechanism"),
        ("assur.core.kinematics", "positions and exact analogs as named arrays"),
        ("assur.core.analogs", "positions and analogs of points, links and distances by name"),
        ("assur.core.transfer", "transfer ratios, real-time velocities and accelerations"),
        ("assur.core.kinematic_checks", "instantaneous centre, transmission angle, closure residual"),
        ("assur.core.loads", "load types behind one contract and registry; masses, dead loads"),
        ("assur.core.memo", "what is kept with a mechanism: the memo's keys and owners"),
        ("assur.core.cylinders", "hydraulic cylinders: the one home of their quantities"),
        ("assur.core.wheels", "wheels drawn on a link: a steered wheel, a tractor's wheel"),
        ("assur.core.gravity", "the mechanism's gravity"),
        ("assur.core.reactions", "the reverse pass's context (the groups' statics contract)"),
        ("assur.core.statics", "virtual work and joint reactions by Assur groups: the result, solve"),
        ("assur.core.virtual_work", "the applied loads over arrays and the actuator forces by virtual work"),
        ("assur.core.reverse_pass", "joint reactions by Assur groups in reverse order, over arrays"),
        ("assur.core.outputs", "the outputs contract and the fused kernel: only the outputs asked for"),
        ("assur.core.program", "the compiled form of a mechanism: Program, compile_program, execute"),
        ("assur.core.compile_context", "what a group's compile works with: slots, rows, pre-passes"),
        ("assur.core.columns", "extra table columns: formulas and sign maps"),
        ("assur.core.motion", "a crank's direction and speed"),
        ("assur.core.held", "held outputs along a path: a coordinate solved so that an output keeps its value, the path's analogs"),
    ]),
    ("Machines", [
        ("assur.machines.cylinders", "areas, pressure, available force, lift capacity"),
        ("assur.machines.capacity", "lift capacity of several cylinders"),
        ("assur.machines.stability", "axle reactions and the 20 % steerability rule"),
        ("assur.machines.hitch_lift", "the standard lift test of a three-point hitch"),
        ("assur.machines.steering", "Ackermann relation, turning radius, resisting moment"),
        ("assur.machines.conditioner", "the spring pressing device (lab 2)"),
        ("assur.machines.ratings", "ratings of the standards: one contract and registry"),
        ("assur.machines.ratings.base", "the contract of a rating: parameters, result"),
        ("assur.machines.ratings.crane", "a crane's load chart: capacity over the reach"),
        ("assur.machines.ratings.digging", "digging forces of an excavator's arm (ISO 6015)"),
        ("assur.machines.ratings.loader", "tipping load, breakout forces, lift (ISO 14397)"),
        ("assur.machines.ratings.stability", "the static tipping load of a machine"),
    ]),
    ("Dynamics", [
        ("assur.dynamics", "equations of motion, simulation, work cycles"),
        ("assur.dynamics.masses", "link masses and their values over designs"),
        ("assur.dynamics.crank", "inertia loads, reduced moment of crank machines"),
        ("assur.dynamics.flywheel", "the flywheel (energy–mass method)"),
        ("assur.dynamics.balancing", "common centre of mass and counter-masses"),
        ("assur.dynamics.drive", "hydraulic drive components"),
    ]),
    ("The whole worksheet", [
        ("assur.analysis", "one call for the whole worksheet"),
    ]),
    ("Synthesis", [
        ("assur.synthesis.conditions", "design conditions (Given/Find)"),
        ("assur.synthesis.fitting", "parameters fitted to a printed table"),
        ("assur.synthesis.sensitivity", "exact sensitivities to the parameters"),
        ("assur.synthesis.refine", "the local refiner: SLSQP with exact gradients"),
        ("assur.synthesis.tolerance", "tolerance analysis"),
        ("assur.synthesis.search", "searching the design space"),
    ]),
    ("Files", [
        ("assur.io", "model files: TOML, units, validation"),
    ]),
    ("Views", [
        ("assur.views.report", "tables, figures, drawings, HTML"),
        ("assur.views.notebook", "how results show themselves in a notebook"),
        ("assur.views.geometry", "the mechanism's drawing as plain data"),
        ("assur.views.cli", "the command line"),
        ("assur.views.page", "the interactive page, inline displays, DXF drawings"),
    ]),
]


#: modules whose classes are put together from base classes of other modules (by
#: concern, issue 22): their pages list the inherited methods too
INHERITED = {"assur.core.kinematics"}


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
    if mod in INHERITED:
        return head + "   :members:\n   :inherited-members:\n"
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
