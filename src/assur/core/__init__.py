"""The engine: a mechanism's description and what is computed from it alone.

The layer above the groups and the kernel (docs/architecture.md): the immutable
description (:mod:`~assur.core.mechanism`), its bodies (:mod:`~assur.core.topology`),
the compiled program (:mod:`~assur.core.program`), the positions and analogs
(:mod:`~assur.core.kinematics`), the loads and cylinders it carries
(:mod:`~assur.core.loads`), the kinetostatics (:mod:`~assur.core.statics`) and the
outputs contract with its fused kernel (:mod:`~assur.core.outputs`); what is kept with a
mechanism follows one contract (:mod:`~assur.core.memo`). Nothing here
imports a machine formula library, dynamics, synthesis, files or views.
"""
