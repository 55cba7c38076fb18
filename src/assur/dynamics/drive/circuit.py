"""A circuit: the components of one hydraulic drive, checked to fit together, and
its branches (one per cylinder)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import ModelError
from .base import ROLES

__all__ = ["Circuit", "Branch"]

#: how many components of each role a circuit takes: (least, most); per branch for
#: the roles of :data:`BRANCH_ROLES`
_COUNTS = {"pump": (1, 1), "relief": (0, None), "valve": (0, None), "line": (0, None),
           "volume": (1, None), "cylinder": (1, None), "divider": (0, 1)}
#: the roles a branch has one of (a line: any number)
BRANCH_ROLES = {"volume": (1, 1), "valve": (0, 1), "relief": (0, 1)}


@dataclass(frozen=True)
class Branch:
    """The part of a circuit that feeds one cylinder: its lines and valve, its
    lumped oil volume and relief valve, and its share of the pump's flow.

    Attributes
    ----------
    coordinate : str
        The cylinder's generalized coordinate S [m].
    cylinder, volume : component
    valve, relief : component or None
    lines : tuple of component
        The lines (and the valve) in series to the cylinder.
    share : float
        The branch's share of the pump's flow [-] (1 without a divider).
    sense : int
        +1: the piston side is fed and the force pushes S up; −1: the rod side
        (the valve's ``lower`` position) [-].
    area : float
        The pressurised area of the branch's cylinders [m²].
    stop : float
        The stop where the fed chamber is smallest (s_min when raising, s_max
        when lowering): V = V0 there [m].

    Examples
    --------
    >>> from assur import io
    >>> crane = io.load(io.bundled("crane_lv184a")).drive   # seed 004: boom and stick
    >>> [(b.coordinate, b.share, b.sense) for b in crane.branches]   # share, sense [-]
    [('S1', 0.5, 1), ('S2', 0.5, -1)]
    >>> [b.valve.name for b in crane.branches]
    ['boom valve', 'stick valve']
    """

    coordinate: str
    cylinder: object
    volume: object
    valve: object
    relief: object
    lines: tuple
    share: float

    @property
    def sense(self) -> int:
        """+1: the piston side fed (S grows); −1: the rod side (the valve's
        ``lower``) [-].

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive   # seed 004
        >>> [b.sense for b in crane.branches]    # the boom raised, the stick lowered
        [1, -1]
        """
        return 1 if self.valve is None else self.valve.sense

    @property
    def area(self) -> float:
        """The fed area of the branch's cylinders: count·A raising, count·π·(D² −
        d²)/4 lowering [m²].

        Examples
        --------
        >>> from assur import io
        >>> stick = io.load(io.bundled("crane_lv184a")).drive.branches[1]   # seed 004
        >>> stick.valve.position, round(stick.area * 1e4, 2)     # the annulus [cm²]
        ('lower', 30.63)
        >>> round(stick.cylinder.area * 1e4, 2)                 # its piston [cm²]
        50.27
        """
        c = self.cylinder
        return c.area if self.sense > 0 else c.count * c.rod_side_area

    @property
    def stop(self) -> float:
        """The stop where the fed chamber is smallest, V = V0: s_min raising, s_max
        lowering [m].

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive   # seed 004
        >>> [tuple(round(x, 3) for x in (b.cylinder.s_min, b.cylinder.s_max, b.stop))
        ...  for b in crane.branches]          # (s_min, s_max, stop) [m]
        [(1.075, 1.705, 1.075), (1.362, 2.179, 2.179)]
        """
        return self.cylinder.s_min if self.sense > 0 else self.cylinder.s_max

    def flow(self, pump_flow) -> float:
        """The branch's supply share·Q [m³/s] of the pump's flow ``pump_flow``.

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive   # seed 004: Q_h = 80 l/min
        >>> [round(b.flow(crane.pump_flow()) * 60e3, 3) for b in crane.branches]  # [l/min]
        [40.0, 40.0]
        """
        return self.share * pump_flow

    def loss_coefficients(self, pump_flow):
        """(a1, a2, a3) of lab 6 eq. (3) summed over the branch's lines and valve,
        referred to the rod's speed at the branch's working flow [Pa·s²/m, Pa·s/m,
        Pa·s²/m²].

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive   # seed 004
        >>> boom = crane.branches[0]
        >>> a1, a2, a3 = boom.loss_coefficients(crane.pump_flow())
        >>> round(a1), round(a2), round(a3 / 1e6, 3)   # [Pa·s²/m, Pa·s/m, MPa·s²/m²]
        (135938, 781641, 13.064)
        """
        a = [0.0, 0.0, 0.0]
        for c in self.lines:
            for i, v in enumerate(c.loss_coefficients(self.area, self.flow(pump_flow))):
                a[i] += v
        return tuple(a)


@dataclass(frozen=True)
class Circuit:
    """The open circuit of seed 001 lab 6 (fig. 6.1) — a pump, optionally a relief
    valve and a directional valve, lines, the lumped oil volume and the working
    cylinder(s) on one generalized coordinate — or several such branches, one per
    cylinder coordinate, fed by one pump through a flow divider (seed 004 eqs.
    63–68: the crane's boom and stick).

    With more than one cylinder every volume, valve and line names its branch by
    ``coordinate``; a relief valve without one guards every branch (port relief
    valves of one setting). The divider's ``shares`` follow the cylinders' order.

    Parameters
    ----------
    components : tuple
        Component objects (:func:`assur.dynamics.drive.registry`).

    Raises
    ------
    ModelError
        A role missing or given twice, a component on no branch or on an unknown
        one, two cylinders on one coordinate, several cylinders without a flow
        divider, or a divider whose shares do not match the cylinders.

    Examples
    --------
    >>> import math
    >>> from assur.dynamics.drive import Circuit, DriveCylinder, GearPump, OilVolume
    >>> pump = GearPump(32e-6, 1800 * 2 * math.pi / 60, 0.9)       # НШ-32, 1800 rpm
    >>> cyl = DriveCylinder("S", bore=0.125, rod=0.05, s_min=0.55, s_max=0.8)   # [m]
    >>> circuit = Circuit((pump, OilVolume(3e-3), cyl))
    >>> circuit.coordinates, round(circuit.steady_speed() * 1e3, 1)   # lab 6's 70.4 mm/s
    (('S',), 70.4)
    >>> Circuit((pump, cyl))
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: drive: expected at least 1 component(s) of role 'volume', found 0 []
    """

    components: tuple

    def __post_init__(self):
        object.__setattr__(self, "components", tuple(self.components))
        by = {r: [] for r in ROLES}
        for c in self.components:
            by[c.role].append(c)
        for role, (lo, hi) in _COUNTS.items():
            n = len(by[role])
            if n < lo or (hi is not None and n > hi):
                want = f"exactly {lo}" if lo == hi else (f"at most {hi}" if lo == 0
                                                         else f"at least {lo}")
                names = [c.type_name for c in by[role]]
                raise ModelError(f"drive: expected {want} component(s) of role {role!r}, "
                                 f"found {n} {names}")
        object.__setattr__(self, "_branches", self._build_branches(by))

    def _build_branches(self, by):
        cyls = by["cylinder"]
        coords = [c.coordinate for c in cyls]
        if len(set(coords)) != len(coords):
            raise ModelError(f"drive: two cylinders on one coordinate: {coords}")
        k = len(cyls)
        div = by["divider"][0] if by["divider"] else None
        if k > 1 and div is None:
            raise ModelError(f"drive: {k} cylinders ({', '.join(coords)}) need a flow_divider "
                             f"to share the pump's flow (seed 004 eqs. 63–68)")
        if div is not None and len(div.shares) != k:
            raise ModelError(f"drive: the flow_divider has {len(div.shares)} shares for {k} "
                             f"cylinders ({', '.join(coords)})")
        shares = (1.0,) if div is None else tuple(float(s) for s in div.shares)
        members = {c: {"line": [], "valve": [], "volume": [], "relief": []} for c in coords}
        for role in ("line", "valve", "volume", "relief"):
            for comp in by[role]:
                at = comp.coordinate
                if at is None:
                    if k == 1 or role == "relief":
                        for c in coords:
                            members[c][role].append(comp)
                        continue
                    raise ModelError(f"drive: the {comp.type_name} "
                                     f"{comp.name or ''} must name its branch with coordinate"
                                     f" = one of {coords} (the circuit has {k} "
                                     f"cylinders)".replace("  ", " "))
                if at not in members:
                    raise ModelError(f"drive: the {comp.type_name} {comp.name or ''} is on "
                                     f"coordinate {at!r}, which no cylinder moves (cylinders:"
                                     f" {coords})".replace("  ", " "))
                members[at][role].append(comp)
        out = []
        for cyl, share in zip(cyls, shares):
            m = members[cyl.coordinate]
            for role, (lo, hi) in BRANCH_ROLES.items():
                n = len(m[role])
                if not lo <= n <= hi:
                    want = f"exactly {lo}" if lo == hi else f"at most {hi}"
                    raise ModelError(f"drive: the branch of {cyl.coordinate!r} needs {want} "
                                     f"component(s) of role {role!r}, found {n}")
            valve = m["valve"][0] if m["valve"] else None
            lines = tuple(c for c in self.components
                          if c in m["line"] or (valve is not None and c is valve))
            out.append(Branch(cyl.coordinate, cyl, m["volume"][0], valve,
                              m["relief"][0] if m["relief"] else None, lines, share))
        return tuple(out)

    @property
    def branches(self) -> tuple:
        """The :class:`Branch` of each cylinder, in the cylinders' order.

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive     # seed 004
        >>> [(b.coordinate, b.cylinder.name) for b in crane.branches]
        [('S1', 'boom cylinder'), ('S2', 'stick cylinder')]
        """
        return self._branches

    @property
    def coordinates(self) -> tuple:
        """The coordinates the cylinders move.

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive     # seed 004
        >>> crane.coordinates
        ('S1', 'S2')
        """
        return tuple(b.coordinate for b in self._branches)

    def _one(self, role):
        return next((c for c in self.components if c.role == role), None)

    def _single(self, what):
        if len(self._branches) != 1:
            raise ValueError(f"the circuit has {len(self._branches)} branches "
                             f"({', '.join(self.coordinates)}): use .branches for its {what}")
        return self._branches[0]

    @property
    def pump(self):
        """The pump.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> circuit.pump.type_name, round(circuit.pump.displacement * 1e6, 3)   # [cm³]
        ('gear_pump', 32.0)
        """
        return self._one("pump")

    @property
    def divider(self):
        """The flow divider, or None.

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive     # seed 004
        >>> crane.divider.shares                            # [-]
        (0.5, 0.5)
        >>> io.load(io.bundled("adapter_lab6")).drive.divider is None   # one cylinder
        True
        """
        return self._one("divider")

    @property
    def relief(self):
        """The relief valve of a one-cylinder circuit, or None.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> circuit.relief.setting / 1e6                    # [MPa]
        16.0
        >>> io.load(io.bundled("crane_lv184a")).drive.relief   # two branches
        Traceback (most recent call last):
        ...
        ValueError: the circuit has 2 branches (S1, S2): use .branches for its relief valve
        """
        return self._single("relief valve").relief

    @property
    def valve(self):
        """The directional valve of a one-cylinder circuit, or None.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> circuit.valve.position, circuit.valve.dp_nominal / 1e6   # [MPa]
        ('raise', 0.3)
        """
        return self._single("valve").valve

    @property
    def volume(self):
        """The lumped oil volume of a one-cylinder circuit.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> round(circuit.volume.volume * 1e3, 6)           # V0 [l]
        3.0
        """
        return self._single("oil volume").volume

    @property
    def cylinder(self):
        """The cylinder of a one-cylinder circuit.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> c = circuit.cylinder
        >>> c.coordinate, c.bore, c.rod                      # D, d [m]
        ('S', 0.125, 0.05)
        """
        return self._single("cylinder").cylinder

    @property
    def lines(self):
        """The components in series between the pump and the cylinder whose pressure
        losses make up a1, a2, a3: the lines and the directional valve.

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> [c.type_name for c in circuit.lines]
        ['directional_valve', 'line']
        """
        return self._single("lines").lines

    @property
    def area(self) -> float:
        """Pressurised area of the cylinders of a one-cylinder circuit [m²].

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> round(circuit.area * 1e4, 1)                    # [cm²], lab 6's 122.7 cm²
        122.7
        """
        return self._single("area").area

    def pump_flow(self) -> float:
        """Q of the pump [m³/s].

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> round(circuit.pump_flow() * 60e3, 2)   # [l/min]: 32 cm³ · 1800 rpm · 0.9
        51.84
        """
        return self.pump.flow()

    def steady_speeds(self):
        """The rod speeds the pump's flow sets, s_j·Q/A_j [m/s] (lab 6: "the steady
        speed is set by the pump's flow and the area of the cylinders"; seed 004
        eqs. 65–66 with a divider), signed along the coordinates, shape (k,).

        Examples
        --------
        >>> from assur import io
        >>> crane = io.load(io.bundled("crane_lv184a")).drive     # seed 004
        >>> crane.steady_speeds().round(4).tolist()   # [m/s]: the stick's rod retracts
        [0.0849, -0.2176]
        """
        Q = self.pump_flow()
        return np.array([b.sense * b.flow(Q) / b.area for b in self._branches])

    def steady_speed(self) -> float:
        """The rod speed Q/A of a one-cylinder circuit [m/s].

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> round(circuit.steady_speed(), 4)        # lab 6: 0.0704 m/s
        0.0704
        """
        self._single("steady speed")
        return float(abs(self.steady_speeds()[0]))

    def relief_flow(self, p):
        """Flow through the relief valve of a one-cylinder circuit at the pressure p
        [m³/s] (0 without one).

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> [round(float(circuit.relief_flow(p)) * 60e3, 2) for p in (15e6, 16.5e6)]  # [l/min]
        [0.0, 25.92]
        """
        b = self._single("relief valve")
        return 0.0 * p if b.relief is None else b.relief.flow(p, b.flow(self.pump_flow()))

    def loss_coefficients(self):
        """(a1, a2, a3) of lab 6 eq. (3) of a one-cylinder circuit, summed over the
        lines and the valve at the pump's flow [Pa·s²/m, Pa·s/m, Pa·s²/m²].

        Examples
        --------
        >>> from assur import io
        >>> circuit = io.load(io.bundled("adapter_lab6")).drive   # seed 001 lab 6
        >>> a1, a2, a3 = circuit.loss_coefficients()
        >>> u = circuit.steady_speed()                      # [m/s]
        >>> round((a2 * u + a3 * u * abs(u)) / 1e6, 3)      # steady loss Δp [MPa]
        0.282
        """
        return self._single("loss coefficients").loss_coefficients(self.pump_flow())
