"""The engine's modules split by concern (issue 22): each of the split modules is at
most ~600 lines with no function over ~80 lines of code, and every name is importable
where it was before the split (the old module re-exports what moved)."""
from __future__ import annotations

import ast
import importlib
from pathlib import Path

import pytest

#: the modules made by the split of core.outputs, kinematics, statics, program and of
#: kernel.compose's generate_composed
SPLIT = ["assur.core.outputs", "assur.core.outputs._notation", "assur.core.outputs._context",
         "assur.core.outputs._kernel", "assur.core.outputs._evaluation",
         "assur.core.kinematics", "assur.core.analogs", "assur.core.transfer",
         "assur.core.kinematic_checks", "assur.core.statics", "assur.core.virtual_work",
         "assur.core.reverse_pass", "assur.core.program", "assur.core.compile_context",
         "assur.kernel.compose"]
MAX_LINES = 600
MAX_CODE = 80

#: the names the old modules exported (their __all__ before the split, and the names
#: other modules and the tests read from them)
BEFORE = {
    "assur.core.outputs": ["evaluate", "Fused", "OutputContext", "OUTPUT_UNITS", "REDUCTIONS",
                           "parse_output", "resolve_output", "output_unit", "display_unit",
                           "formula_of", "statics_outputs", "joint_list", "has_actuator"],
    "assur.core.kinematics": ["Kinematics", "SINGULAR_RTOL", "kinematics_of"],
    "assur.core.statics": ["Statics", "GRAVITY", "gravity_unit", "applied_loads",
                           "virtual_work_forces", "spring_states", "solve",
                           "ReactionContextBase", "ReactionContext", "BLOCK", "FUSED_MIN",
                           "FUSED_AFTER", "_solve_fused"],
    "assur.core.program": ["Program", "CompileContext", "compile_program", "execute",
                           "trig_table", "REFINE_DEPTH", "REFINE_POINTS", "REFINE_MAX",
                           "_KERNELS", "_PROGRAMS"],
    "assur.kernel.compose": ["THRESHOLD", "BLOCK", "canonical", "generate_composed",
                             "is_fused", "checks_continuity", "load_kernel"],
}

#: Kinematics' public methods and properties before the split
KINEMATICS = ["output_buffer", "points", "value", "jacobian", "hessian", "has_point",
              "first_nonfinite", "has_all_points", "positions", "body_rates", "reshape",
              "links", "q", "q_table", "x", "y", "point", "dx", "dy", "ddx", "ddy",
              "transmission", "phi", "dphi", "ddphi", "length", "dlength", "ddlength", "ratio",
              "dratio", "velocity", "acceleration", "angular_velocity",
              "angular_acceleration", "direction_rate", "instant_centre", "closure_residual",
              "transmission_angle", "to_frame"]


def _code_lines(lines, fn):
    """Lines of code of a function: without its docstring, blank and comment lines."""
    doc = set()
    first = fn.body[0]
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) \
            and isinstance(first.value.value, str):
        doc = set(range(first.lineno, first.end_lineno + 1))
    return sum(1 for i in range(fn.lineno, fn.end_lineno + 1)
               if i not in doc and lines[i - 1].strip()
               and not lines[i - 1].strip().startswith("#"))


@pytest.mark.parametrize("name", SPLIT)
def test_split_module_is_small(name):
    path = Path(importlib.import_module(name).__file__)
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    assert len(lines) <= MAX_LINES, f"{name}: {len(lines)} lines"
    long = [(fn.name, _code_lines(lines, fn)) for fn in ast.walk(ast.parse(text))
            if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef))
            and _code_lines(lines, fn) > MAX_CODE]
    assert not long, f"{name}: functions over {MAX_CODE} lines of code: {long}"


@pytest.mark.parametrize("module", sorted(BEFORE))
def test_old_names_importable(module):
    mod = importlib.import_module(module)
    missing = [n for n in BEFORE[module] if not hasattr(mod, n)]
    assert not missing, f"{module} lost {missing}"
    for n in getattr(mod, "__all__", ()):
        assert hasattr(mod, n)


def test_moved_names_are_the_same_objects():
    from assur.core import compile_context, kinematics, outputs, program, reverse_pass, \
        statics, transfer, virtual_work
    from assur.core.outputs import _context, _evaluation, _kernel, _notation
    assert program.CompileContext is compile_context.CompileContext
    assert statics.ReactionContext is reverse_pass.ReactionContext
    assert statics.applied_loads is virtual_work.applied_loads
    assert statics.spring_states is virtual_work.spring_states
    assert statics.virtual_work_forces is virtual_work.virtual_work_forces
    assert kinematics.SINGULAR_RTOL == transfer.SINGULAR_RTOL
    assert outputs.OutputContext is _context.OutputContext
    assert outputs.evaluate is _evaluation.evaluate and outputs.Fused is _evaluation.Fused
    assert outputs.statics_outputs is _evaluation.statics_outputs
    assert outputs.joint_list is _kernel.joint_list
    assert outputs.parse_output is _notation.parse_output


def test_kinematics_keeps_its_methods():
    from assur.core.kinematics import Kinematics
    missing = [n for n in KINEMATICS if not hasattr(Kinematics, n)]
    assert not missing, f"Kinematics lost {missing}"
    assert Kinematics.__module__ == "assur.core.kinematics"
