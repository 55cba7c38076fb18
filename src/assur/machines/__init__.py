"""Machine formula libraries built on the core (docs/architecture.md): cylinders'
pressures and lift capacity (:mod:`~assur.machines.cylinders`,
:mod:`~assur.machines.capacity`), machine stability, steering geometry, the
conditioner's pressing device and the standard hitch lift test."""
