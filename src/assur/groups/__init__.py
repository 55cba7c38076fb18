"""Structural (Assur) group types, one module each, behind one contract.

The contract and the registry are in :mod:`assur.groups.base`; each module below
registers its type under the model file's ``type`` name (which is also the name of
the :class:`~assur.Mechanism` builder method). :func:`registry` lists them; adding a
type is one new module imported here (``docs/adding-a-group.md``).
"""

from .base import Failure, Field, Group, group_type, register, registry, unregister
from .measures import Distance, Link
from .frame import Frame
from .cylinder_lever import CylinderLever
from .rrr import Dyad
from .crank import Crank
from .slider_input import SliderInput
from .rrp import SliderDyad
from .rigid import RigidPoint
from .pose import PosePoint
from .rpr import SleeveDyad
from .prp import DoubleSliderDyad

__all__ = ["Group", "Field", "Failure", "register", "unregister", "registry", "group_type", "Link",
           "Distance", "Frame", "CylinderLever", "Dyad", "Crank", "SliderInput", "SliderDyad",
           "RigidPoint", "PosePoint", "SleeveDyad", "DoubleSliderDyad"]
