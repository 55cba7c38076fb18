"""assur — hydraulic-cylinder driven planar linkages solved by Assur groups.

>>> from assur import examples
>>> m = examples.hitch_003()
>>> r = m.solve([0.42, 0.67])
>>> [round(float(v), 3) for v in r.transmission("56")]
[4.459, 2.621]
"""

from . import groups, kinematics
from .errors import AssemblyError, ModelError, SingularPositionError
from .groups import Crank, CylinderLever, Dyad, Frame, RigidPoint, SliderDyad, SliderInput
from .kinematics import Kinematics
from .mechanism import Mechanism
from . import examples

__version__ = "0.1.0"
