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
from . import groups
from .core import kinematics
from .errors import AssemblyError, ModelError, SingularPositionError
from .groups import (Crank, CylinderLever, DoubleSliderDyad, Dyad, Frame, PosePoint, RigidPoint,
                     SleeveDyad, SliderDyad, SliderInput)
from .core.kinematics import Kinematics
from .core.mechanism import Mechanism
from .core.topology import Topology
from . import examples

__all__ = ["Mechanism", "Kinematics", "Topology", "AssemblyError", "ModelError",
           "SingularPositionError", "Frame", "CylinderLever", "Dyad", "Crank", "SliderInput",
           "SliderDyad", "RigidPoint", "PosePoint", "SleeveDyad", "DoubleSliderDyad", "groups",
           "kinematics", "examples", "__version__"]

_moved.install()


def __getattr__(name):
    """An old module name of the package (``assur.hydraulics``…): its new module, with
    a :class:`DeprecationWarning` (:mod:`assur._moved`)."""
    import importlib
    if _moved.new_name(f"{__name__}.{name}") is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return importlib.import_module(f"{__name__}.{name}")
