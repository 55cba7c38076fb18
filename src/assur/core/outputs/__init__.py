"""The fused kinematics + statics kernel: only the outputs asked for, reductions over
positions in the kernel (DESIGN.md §10).

:func:`evaluate` (``Mechanism.evaluate``, or ``Mechanism.analyze(..., outputs=…)``)
generates one kernel per structure and set of outputs. For every element (design,
position) it runs the groups' position and jet code (forward), the loads and the
actuator forces by virtual work, the joint reactions group by group in reverse order
(each group's own :meth:`~assur.groups.base.Group.reactions`, traced into the kernel
by :mod:`assur.kernel.sym`, the same code that the array pass of :mod:`assur.core.statics`
runs), and writes only the requested outputs — or, with ``reduce``, only their
minimum/maximum and where they occur over the positions of each design, so that a
sweep of millions of designs stores no positions at all.

Outputs are written as function calls (units SI):

=======================  ==============================================================
``X(p)``, ``Y(p)``       coordinates of point p [m]
``dX(p)``, ``dY(p)``     first analogs ∂x/∂q, ∂y/∂q (``dY(p, S)`` for k > 1) [m/m, m/rad]
``I(p)``                 transmission number dY/dq of p (= ``dY(p)``)
``phi(l)``               angle of link l in (−π, π] (unwrapped along stored positions) [rad]
``dphi(l)``              its analog dφ/dq [rad/m or rad/rad]
``length(d)``            a named distance [m]; ``dlength(d)`` its analog dd/dq [m/m, m/rad]
``F(c)``                 actuator force of coordinate c by virtual work [N or N·m]
``Fr(c)``                the same from the joint reactions [N or N·m]
``Rx(i, j)``, ``Ry``     force of link i on link j [N]; ``R(i, j)`` its magnitude,
                         ``Rm(i, j)`` the moment at a prismatic pair or crank drive [N·m]
``p(cyl)``               pressure of cylinder ``cyl``, σ·F/(η_m·k·A·η_h), or of its
                         supply line [Pa]
``G(cyl, p)``            lift capacity at point p in the working direction,
                         (σ_w·k·p_max·A_w·η_h·η_m − F_dead)/I(p) [N]
``reserve(cyl, p, P)``   capacity reserve (G − P)/P·100 for a payload P (number or
                         parameter; G carried the dead loads) [%]
``Xc``, ``Yc``           the common centre of mass of the masses on moving links,
                         Σ m_i·r_i / Σ m_i (001 lab 3, :mod:`assur.dynamics.balancing`) [m]
``name``                 a formula of the model's ``[[tables.formulas]]`` by its name
                         (:class:`assur.core.columns.Formula`), e.g. ``p_c`` [SI of its unit]
=======================  ==============================================================

The cylinder outputs are the formulas of :mod:`assur.core.cylinders` (the one home of
a cylinder's quantities: the chamber of ``side``, ``"auto"`` included, double rods,
counts, supply lines, the model's dead loads ``[tables] dead_loads``), evaluated in
the context's kind of number; the reports' :class:`assur.machines.cylinders.CylinderResult`
calls the same formulas over arrays.

The capacity's working chamber of a ``side = "auto"`` cylinder is one per stroke
(design): the sign of W, the payload's actuator force summed over the design's
positions (:func:`assur.core.cylinders.stroke_work`). The kernel is per position, so
:func:`evaluate` runs a first pass for the forces of all the loads and of the dead
loads, sums them per design and writes W into a row of the parameter table; asking
for ``G`` or ``reserve`` of an ``auto`` cylinder thus costs one more kernel run that
stores two values per position.

Static loads only (weights, forces, moments, springs, the weights of masses); the
fused kernel does not check continuity between positions (``solve`` does).

The package holds, by concern: the notation of the outputs and their units
(``_notation``), every output's formula (:class:`OutputContext`, ``_context``), the
fused kernel's code generation (``_kernel``) and :func:`evaluate` with its result
(``_evaluation``); every name is exported here.
"""

from __future__ import annotations

from ._context import OutputContext
from ._evaluation import Fused, evaluate, statics_outputs  # noqa: F401 (statics calls it)
from ._kernel import has_actuator, joint_list  # noqa: F401 (statics calls them)
from ._notation import (OUTPUT_UNITS, REDUCTIONS, display_unit, formula_of, output_unit,
                        parse_output, resolve_output)

__all__ = ["evaluate", "Fused", "OutputContext", "OUTPUT_UNITS", "REDUCTIONS", "parse_output",
           "resolve_output", "output_unit", "display_unit", "formula_of"]
