"""A two-link arm (two cylinders on two levers) whose ratings follow by hand
(tests/machines/ratings)."""

import math

import numpy as np

from assur.machines.ratings.crane import flat

ARM = '''
[model]
name = "two_link_arm"
coordinates = ["S1", "S2"]

[params]
b1 = "0.5 m"
L1 = "2.0 m"
b2 = "0.3 m"

[range]
S1 = { from = "0.6 m", to = "0.8 m", count = 3 }
S2 = { from = "0.5 m", to = "0.7 m", count = 4 }

[frame]
O = [0, 0]
A = [0.2, -0.4]

[[groups]]
name = "g1"
type = "cylinder_lever"
base = "A"
pivot = "O"
out = "B"
lever = "b1"
s = "S1"
branch = 1
links = ["c1", "1"]

[[groups]]
name = "g2"
type = "rigid_point"
origin = "O"
toward = "B"
out = "O1"
length = "L1"
angle = "0 deg"
links = ["1"]

[[groups]]
name = "g3"
type = "rigid_point"
origin = "O"
toward = "B"
out = "C"
length = "1.0 m"
angle = "0 deg"
links = ["1"]

[[groups]]
name = "g4"
type = "rigid_point"
origin = "O1"
toward = "O"
out = "E"
length = "0.6 m"
angle = "20 deg"
links = ["1"]

[[groups]]
name = "g5"
type = "cylinder_lever"
base = "E"
pivot = "O1"
out = "G"
lever = "b2"
s = "S2"
branch = 1
links = ["c2", "2"]

[[groups]]
name = "g6"
type = "rigid_point"
origin = "O1"
toward = "G"
out = "T"
length = "1.0 m"
angle = "30 deg"
links = ["2"]

[[loads]]
type = "weight"
point = "T"
P = "10 kN"
link = "2"

[[loads]]
type = "weight"
point = "C"
P = "5 kN"
link = "1"

[[cylinders]]
name = "c1"
coordinate = "S1"
bore = "100 mm"
rod = "50 mm"
p_relief = "20 MPa"
eta_mech = 0.95
side = "extend"

[[cylinders]]
name = "c2"
coordinate = "S2"
bore = "80 mm"
rod = "45 mm"
p_relief = "20 MPa"
side = "retract"
'''



def _angle(u, v):
    """Signed angle from vector u to v [rad]."""
    return math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])


def hand_rates(kin, i):
    """dθ1/dS1 and dθ2/dS2 at position i from the cylinder triangles (S² = a² + b² −
    2ab·cos γ ⇒ dγ/dS = S/(a·b·sin γ)), and the points [m]."""
    P = {p: np.array([flat(kin.x(p))[i], flat(kin.y(p))[i]])
         for p in ("B", "O1", "E", "G", "T", "C")}
    O, A = np.zeros(2), np.array([0.2, -0.4])
    S1, S2 = flat(kin.q("S1"))[i], flat(kin.q("S2"))[i]
    g1 = _angle(A - O, P["B"] - O)
    a1, b1 = np.linalg.norm(A - O), 0.5
    assert math.isclose(S1 ** 2, a1 ** 2 + b1 ** 2 - 2 * a1 * b1 * math.cos(g1), rel_tol=1e-12)
    g2 = _angle(P["E"] - P["O1"], P["G"] - P["O1"])
    a2, b2 = np.linalg.norm(P["E"] - P["O1"]), 0.3
    assert math.isclose(S2 ** 2, a2 ** 2 + b2 ** 2 - 2 * a2 * b2 * math.cos(g2), rel_tol=1e-12)
    return S1 / (a1 * b1 * math.sin(g1)), S2 / (a2 * b2 * math.sin(g2)), P


P_RELIEF = 20e6
AREAS = {"c1": (math.pi * 0.1 ** 2 / 4, math.pi * (0.1 ** 2 - 0.05 ** 2) / 4),
         "c2": (math.pi * 0.08 ** 2 / 4, math.pi * (0.08 ** 2 - 0.045 ** 2) / 4)}
ETA = {"c1": 0.95, "c2": 1.0}


def hand_limit(name, I, F_dead):
    """G = (σ·p·A_σ·η − F_dead)/I, σ = sign I: the chamber holding a load at the point."""
    piston, rod = AREAS[name]
    F = P_RELIEF * (piston if I > 0 else -rod) * ETA[name]
    return (F - F_dead) / I


#: a [machine] on two axles for ARM, its implement at T
MACHINE = '''
[machine]
axles = { near = "-0.1 m", far = "2.0 m" }
steered = "far"
weights = [{ name = "body", P = "60 kN", x = "1.2 m" }]
implement = { point = "T", weight = "10 kN" }
'''

#: MACHINE and a loader_tipping rating at T (the reports' tests)
TIPPING = MACHINE + '''
[[rating]]
type = "loader_tipping"
point = "T"
name = { en = "Tipping of the test loader", ru = "Опрокидывание" }
'''
