"""assur — hydraulic-cylinder driven planar linkages solved by Assur groups.

>>> from assur import examples
>>> m = examples.hitch_003()
>>> r = m.solve([0.42, 0.67])
>>> [round(float(v), 3) for v in r.transmission("56")]
[4.459, 2.621]
"""

#: the package's version: the one place it is written (pyproject.toml reads it)
__version__ = "0.1.0"

from . import _moved
from .errors import AssemblyError, ModelError, SingularPositionError

#: the package's names, made when first used (``import assur`` loads no numpy: a script's
#: or the CLI's start-up pays only for what it uses), name → module
_LAZY = {
    **{n: "assur.groups" for n in ("Crank", "CylinderLever", "DoubleSliderDyad", "Dyad",
                                   "Frame", "PosePoint", "RigidPoint", "SleeveDyad",
                                   "SliderDyad", "SliderInput")},
    "Kinematics": "assur.core.kinematics", "Mechanism": "assur.core.mechanism",
    "Topology": "assur.core.topology",
}
_SUBMODULES = {"groups": "assur.groups", "kinematics": "assur.core.kinematics",
               "examples": "assur.examples"}

__all__ = ["Mechanism", "Kinematics", "Topology", "AssemblyError", "ModelError",
           "SingularPositionError", "Frame", "CylinderLever", "Dyad", "Crank", "SliderInput",
           "SliderDyad", "RigidPoint", "PosePoint", "SleeveDyad", "DoubleSliderDyad", "groups",
           "kinematics", "examples", "__version__"]

_moved.install()


def __getattr__(name):
    """A name of the package, imported on first use (:data:`_LAZY`); an old module name
    (``assur.hydraulics``…): its new module, with a :class:`DeprecationWarning`
    (:mod:`assur._moved`)."""
    import importlib
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
    elif name in _SUBMODULES:
        value = importlib.import_module(_SUBMODULES[name])
    elif _moved.new_name(f"{__name__}.{name}") is not None:
        return importlib.import_module(f"{__name__}.{name}")
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
