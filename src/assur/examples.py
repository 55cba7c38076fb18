"""The seed machines as ready models.

Each function returns a :class:`~assur.Mechanism` built from the seed's own input
data (``../shared/seeds/``), with the seed's point and link numbering:

* :func:`hitch_003` — mini-tractor mounted-implement hitch (МН of МСХА), seed 003.
* :func:`header_000` — combine header lift, seed 000 (its input cannot assemble).

Each also has a ``*_range()`` giving the seed's positions of the generalized
coordinate. Issue 4 moves these definitions into bundled model files.
"""

from __future__ import annotations

import math

import numpy as np

from .mechanism import Mechanism
from .stability import Machine

#: seed 003: the exact roots of its three Find blocks (printed rounded to 4 digits:
#: L4 = 0.6613, Sp = 0.4694, L7 = 0.7522; the printed tables used these values)
HITCH_003_FOUND = {"L4": 0.661283167, "Sp": 0.469356940, "L7": 0.752169525}


def hitch_003(**params) -> Mechanism:
    """Mounted-implement hitch of a mini-tractor, seed ``003_b1551261b108abd1.txt``.

    Three structural groups (seed §2): I (2,3) the cylinder–lever group — cylinder
    2 from frame pivot 01 to point 23 of the lever 3 pivoted at 03; the lever's arm
    34 at φBD = 22° from it; II (4,5) the RRR dyad brace 4 – lower link 5 (pivot 05),
    with the suspension axis 56 on link 5 at L56; III (6,7) the RRR dyad implement 6
    – top link 7 (pivot 07). The implement's centre of mass S6 is fixed by its offset
    (X6, Y6) from 56 at the working stroke Sp (seed: φS6 := 2π + atan(Y6/X6) − φ6(Sp)).

    Generalized coordinate ``S``: cylinder pin-to-pin length [m], 0.420…0.670.

    Parameters
    ----------
    **params
        Overrides of any parameter, e.g. ``L4=0.6613`` or arrays for a batch.

    Notes
    -----
    Seed slips resolved here (BRIEF.md): ``φBD … [м]`` is an angle (22°);
    L4, L7 and Sp are the exact roots of the seed's Find blocks (issue 4 solves them
    from the conditions Y56(Smin) = 0.2 m, Y56(Sp) = 0.4 m, φ6(Sp) = 90°). The
    seed's check X23s, Y23s uses φ12 = φ13 − acos(…), which is not the cylinder's
    direction; the cylinder angle here is the direction 01 → 23
    (φ12 = π − φ13 − acos((S² + L13² − L3²)/(2·S·L13))) and closes the loop exactly.
    """
    p = dict(
        X01=0.415, Y01=0.563, X03=0.250, Y03=1.112, X05=0.135, Y05=0.480,
        X07=0.415, Y07=0.895,
        L3=0.200, L5=0.480, L6=0.595 - 0.08, L34=0.325, L56=1.035,
        phiBD=math.radians(22.0),
        X6=0.857, Y6=0.156,
        P6=27500.0,  # implement weight [N]
        Dgc=0.08, Pgc_max=17.5e6, eta=0.84, kgc=2,  # §1.5: k_gc is a count, not [м]
        a=0.6, b=1.62, L=2.960, P_gr=8000.0, P_mcxa=56000.0,  # §1.6 machine data
        **HITCH_003_FOUND,
    )
    p.update(params)
    m = (Mechanism("hitch_003", coordinates=("S",), params=p,
                   title="Mini-tractor mounted-implement hitch (seed 003)",
                   tables={"ratios": [("4", "3"), ("5", "3"), ("6", "5"), ("7", "5")],
                           "transmissions": ["56", "S6"],
                           # seed name: (i, j, sign of the printed components relative
                           # to the force of i on j) — see assur.statics.SEED_003_SIGN_NOTE
                           "reactions": {"R56": ("5", "6", 1), "R07": ("0", "7", 1),
                                         "R23": ("2", "3", 1), "R05": ("0", "5", -1),
                                         "R34": ("3", "4", -1), "R45": ("4", "5", -1),
                                         "R03": ("0", "3", 1), "R01": ("0", "2", 1)}},
                   notes=("φBD is an angle (the seed writes [м])",
                          "seed check X23s, Y23s uses φ12 = φ13 − acos(…); the correct "
                          "cylinder angle is π − φ13 − acos(…) (the printed check is off by up "
                          "to 0.37 m)"))
         .frame("01", "X01", "Y01").frame("03", "X03", "Y03")
         .frame("05", "X05", "Y05").frame("07", "X07", "Y07")
         .cylinder_lever("I (2,3)", base="01", pivot="03", out="23", lever="L3", s="S",
                         branch=-1, links=("2", "3"))
         .rigid_point("arm 34", origin="03", toward="23", out="34", length="L34",
                      angle="phiBD", links=("3",))
         .dyad("II (4,5)", a="34", b="05", out="45", ra="L4", rb="L5", branch=1,
               links=("4", "5"))
         .rigid_point("axis 56", origin="05", toward="45", out="56", length="L56", angle=0.0,
                      links=("5",))
         .dyad("III (6,7)", a="56", b="07", out="67", ra="L6", rb="L7", branch=-1,
               links=("6", "7"))
         .pose_point("centre of mass S6", origin="56", toward="67", out="S6", dx="X6",
                     dy="Y6", at="Sp", links=("6",))
         .link("2", "01", "23").link("3", "03", "23").link("34", "03", "34")
         .link("4", "34", "45").link("5", "05", "45").link("6", "56", "67")
         .link("7", "07", "67")
         .weight("S6", "P6", name="P6")
         .cylinder("ГЦ", "S", bore="Dgc", count="kgc", eta_hyd="eta", p_relief="Pgc_max"))
    pp = m.params
    # §6: rear axle B at the hitch origin, front (steered) axle A a wheelbase ahead; the
    # tractor's centre of mass b ahead of B, the ballast a ahead of A. The seed's moment
    # equation "P_гр·(a + Lb)" means (a + L).
    machine = Machine({"A": -float(pp["L"]), "B": 0.0}, steered="A",
                      weights=[("МСХА", float(pp["P_mcxa"]), -float(pp["b"]))],
                      counterweights=[("противовесы", float(pp["P_gr"]),
                                       -(float(pp["a"]) + float(pp["L"])))])
    return m.with_machine(machine, "S6", "P6",
                          seed_gs6max=dict(tractor_weight="P_mcxa", counterweight="P_gr",
                                           a="a", b="b", wheelbase="L"))


def hitch_003_range() -> np.ndarray:
    """Seed 003 §1.3: S from Smin = 0.420 to Smax = 0.670 m in Npol = 10 positions [m]."""
    return np.linspace(0.420, 0.670, 10)


def header_000(**params) -> Mechanism:
    """Combine header lift, seed ``000_04e80bfff5466283.txt``.

    Cylinder from 01 to point 23 of the bell-crank 3 pivoted at 03 (lever L3); the
    bell-crank's second arm L4 ends at 46, its triangle closed by L34
    (DELFI = acos((L3² + L4² − L34²)/(2·L3·L4)), FI4 = FI3 − DELFI); the RRR dyad
    link 6 (46–56) and rocker 5 (05–56) carries the header, centre of mass offset
    (XN − 0.767, YN − 0.355) from 56 at S = 0.650 m (FIS6).

    **The seed's input cannot assemble**: L4 = 0.657 > L3 + L34 = 0.65234 m, so
    DELFI = acos(1.0199) is complex — the source of every ``…i`` in its tables.
    :meth:`~assur.Mechanism.solve` raises :class:`~assur.AssemblyError` saying so.
    """
    p = dict(
        X01=0.196, Y01=0.693, X03=0.049, Y03=1.327, X05=0.283, Y05=0.521,
        L3=0.17194, L4=0.657, L34=0.4804, L5=0.513, L6=0.938,
        XN=1.259, YN=0.482, X56_0=0.767, Y56_0=0.355, S_ref=0.650,
        P=1500 * 9.81,  # header weight: the seed's P = 1500 is in kgf (its Fmax is p·SS·kg/9.81)
        D=0.080, p=15e6, km=0.85, kg=0.96,
    )
    p.update(params)
    p["dXN"] = p["XN"] - p["X56_0"]
    p["dYN"] = p["YN"] - p["Y56_0"]
    m = (Mechanism("header_000", coordinates=("S",), params=p,
                   title="Combine header lift (seed 000)",
                   tables={"ratios": [("5", "3"), ("6", "3")], "transmissions": ["56", "S6"]},
                   notes=("the seed's triangle L3, L34, L4 cannot close (L4 > L3 + L34)",
                          "FIS6 is overwritten by hand in the seed (4.894 rad instead of the "
                          "computed real part 4.866); here it is derived at S = 0.650 m",
                          "the seed's delI = DFI3·U65·LS6·cos(FI6 + FIS6) lacks the factor U54 "
                          "(its U65 is ω6/ω5): IS = dY_S6/dS = DFI3·U54·(L5·cos FI5 + "
                          "U65·LS6·cos(FI6 + FIS6))",
                          "the seed's P = 1500 is in kgf (its Fmax divides by 9.81): "
                          "P = 1500·9.81 N here"))
         .frame("01", "X01", "Y01").frame("03", "X03", "Y03").frame("05", "X05", "Y05")
         .cylinder_lever("I (2,3)", base="01", pivot="03", out="23", lever="L3", s="S",
                         branch=-1, links=("2", "3"))
         .rigid_point("arm 46", origin="03", toward="23", out="46", length="L4", base="L3",
                      opposite="L34", branch=-1, links=("3",))
         .dyad("II (6,5)", a="46", b="05", out="56", ra="L6", rb="L5", branch=1,
               links=("6", "5"))
         .pose_point("centre of mass S6", origin="56", toward="46", out="S6", dx="dXN",
                     dy="dYN", at="S_ref", links=("6",))
         .link("2", "01", "23").link("3", "03", "23").link("4", "03", "46")
         .link("5", "05", "56").link("6", "56", "46")
         .weight("S6", "P", name="P")
         .cylinder("ГЦ", "S", bore="D", count=2, eta_mech="km", eta_hyd="kg", p_relief="p"))
    return m


def header_000_range() -> np.ndarray:
    """Seed 000: S_AA from 0.650 to 0.800 m in steps of 0.010 m [m]."""
    return np.round(np.arange(0.650, 0.8001, 0.010), 10)
