"""One design of an analysis as 1-D arrays over the positions, in the tables'
conventions (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import numpy as np

from ....core.loads import Weight
from ....texts import LANGS, localize
from ..labels import TEXT, unit
from ._data import Column, _both, wrap_degrees

#: how angle columns are shown (``tables["angles"]``)
ANGLE_CONVENTIONS = ("continuous", "wrapped")
#: how analogs with respect to a crank angle are shown (``tables["analogs"]``)
ANALOG_CONVENTIONS = ("coordinate", "rotation")


class _View:
    """One design of an Analysis as 1-D arrays over the positions."""

    def __init__(self, analysis, design=None, angles=None, analogs=None, units=None):
        from ....core.display import unit_system
        self.a = analysis
        self.kin = analysis.kinematics
        self.mech = analysis.mechanism
        tabs = self.mech.tables
        #: the units notes and labels are written in (:class:`assur.core.display.DisplayUnits`)
        self.units = unit_system(self.mech, units)
        #: angle columns: "continuous" (along the positions) or "wrapped" to [0°, 360°)
        self.angles = angles or tabs.get("angles", "continuous")
        #: analogs of a crank angle: per its "coordinate", or along its "rotation"
        self.analogs = analogs or tabs.get("analogs", "coordinate")
        if self.angles not in ANGLE_CONVENTIONS:
            raise ValueError(f"angles must be one of: {list(ANGLE_CONVENTIONS)}; got "
                             f"{self.angles!r}")
        if self.analogs not in ANALOG_CONVENTIONS:
            raise ValueError(f"analogs must be one of: {list(ANALOG_CONVENTIONS)}; got "
                             f"{self.analogs!r}")
        shape = self.kin.shape
        if len(shape) == 2:
            if design is None:
                raise ValueError(f"this analysis holds a batch of {shape[0]} designs: choose one "
                                 f"with design=<index>")
            if not -shape[0] <= design < shape[0]:
                raise ValueError(f"design must be in 0…{shape[0] - 1}, got {design}")
        elif design not in (None, 0):
            raise ValueError(f"this analysis holds one design; design must be None or 0, "
                             f"got {design}")
        self.design = design
        self.n = shape[-1]
        self.k = self.kin.k
        self.coords = self.kin.coordinates

    def pick(self, a):
        """Array over positions, shape (n,), of this design (NaN where masked)."""
        if np.ma.isMaskedArray(a):
            a = np.ma.filled(a.astype(float), np.nan)
        a = np.asarray(a)
        if a.ndim >= 2:
            a = a[self.design]
        if a.ndim == 1 and a.shape[0] not in (1, self.n):
            a = a[self.design]  # an array over designs, shape (m,)
        return np.array(np.broadcast_to(a.reshape(-1) if a.ndim else a, (self.n,)))

    def scalar(self, a):
        """A parameter value (scalar or per design) of this design."""
        a = np.asarray(a, dtype=float)
        if a.ndim and a.size > 1:
            return float(a.reshape(-1)[self.design])
        return float(a.reshape(-1)[0]) if a.ndim else float(a)

    # coordinates ---------------------------------------------------------------------
    def coord_kind(self, c):
        kind = self.mech.coordinate_kind(c)
        if kind != "length":
            return kind
        for cyl in self.mech.cylinders:
            if cyl.coordinate == c:
                return "cylinder"
        return "length"

    def is_angle(self, c):
        return self.coord_kind(c) == "angle"

    def coord_unit(self, c):
        return "deg" if self.is_angle(c) else "m"

    def degrees(self, a):
        """Angles [°] in the view's convention (continuous, or wrapped to [0°, 360°))."""
        return wrap_degrees(a) if self.angles == "wrapped" else np.asarray(a)

    def coord_values(self, c):
        v = self.pick(self.kin.q(c))
        return self.degrees(np.degrees(v)) if self.is_angle(c) else v

    def phi_values(self, link):
        """φ of a link [°] over the positions, in the view's convention."""
        return self.degrees(self.pick(self.kin.phi(link, degrees=True)))

    def rate_sign(self, c):
        """+1, or the sign of the crank's rotation (−1: clockwise) when analogs are shown
        along the direction of rotation (``analogs = "rotation"``) and ``c`` is a crank
        angle with a :class:`assur.core.motion.Motion`."""
        if self.analogs != "rotation" or not self.is_angle(c):
            return 1
        mo = self.mech.motion(c)
        return mo.direction if mo is not None else 1

    def convention_notes(self, analogs=False):
        """Notes of the conventions in force (wrapped angles; analogs along a rotation)."""
        notes = []
        if self.angles == "wrapped":
            notes.append({lang: TEXT["wrapped"][lang].format(
                self.text(0.0, "deg", lang), self.text(360.0, "deg", lang)) for lang in LANGS})
        if analogs:
            for c in self.coords:
                if self.analogs == "rotation" and self.is_angle(c):
                    mo = self.mech.motion(c)
                    d = mo.direction if mo is not None else 1
                    notes.append({lang: TEXT["rotation"][lang].format(
                        c, TEXT["cw" if d < 0 else "ccw"][lang], d) for lang in LANGS})
        return notes

    def coord_label(self, c):
        key = {"angle": "c_crank", "slider": "c_slider", "cylinder": "c_cyl_len"}.get(
            self.coord_kind(c), "c_coord")
        return {lang: f"{txt} {c}" for lang, txt in TEXT[key].items()}

    def analog_unit(self, c):
        return "-" if self.is_angle(c) else "rad/m"

    def transmission_unit(self, c):
        return "m/rad" if self.is_angle(c) else "-"

    def wrts(self):
        """[(symbol suffix, wrt argument, coordinate)]"""
        if self.k == 1:
            return [("", None, self.coords[0])]
        return [(f"_{c}", c, c) for c in self.coords]

    def coord_columns(self):
        return [Column(c, self.coord_unit(c), self.coord_values(c), self.coord_label(c))
                for c in self.coords]

    def positions_text(self, bad, lang="en"):
        """'S = 420 mm; S = 450 mm' for the positions where ``bad``."""
        idx = np.flatnonzero(bad)
        parts = [self.at_text(i, lang) for i in idx[:6]]
        return "; ".join(parts) + ("; …" if len(idx) > 6 else "")

    # loads ---------------------------------------------------------------------------
    def weights_at(self, point):
        """[(name, P [N])] of the payload weights acting at ``point``: the loads a
        capacity there lifts, its reserve's P — not the dead loads
        (``[tables] dead_loads``), which the capacity has carried already."""
        from ....core.loads import is_dead
        out = []
        for ld in self.mech.loads:
            if isinstance(ld, Weight) and ld.point == point and not is_dead(self.mech, ld):
                name = ld.name or (ld.P if isinstance(ld.P, str) else "P")
                out.append((name, self.scalar(self.mech.value_of(ld.P))))
        return out

    # chains: which coordinate moves what (:mod:`assur.core.chains`) ---------------------
    def moves_point(self, c, point):
        """True if coordinate ``c`` moves ``point``."""
        from ....core.chains import point_coordinates
        return c in point_coordinates(self.mech, point)

    def moves_link(self, c, link):
        """True if coordinate ``c`` turns ``link``."""
        from ....core.chains import link_coordinates
        return c in link_coordinates(self.mech, link)

    def absent_note(self, c, points=(), links=(), what="absent_analogs", *args):
        """The note for quantities along ``c`` left out because ``c`` does not move
        ``points`` or turn ``links``; None when nothing is left out."""
        if not points and not links:
            return None
        out = {}
        for lang in LANGS:
            parts = []
            if points:
                parts.append(f"{TEXT['absent_points'][lang]} {', '.join(points)}")
            if links:
                parts.append(f"{TEXT['absent_links'][lang]} {', '.join(links)}")
            what_text = TEXT[what][lang].format(*(localize(a, lang) for a in args))
            out[lang] = TEXT["absent"][lang].format(c, "; ".join(parts), what_text)
        return out

    def at_text(self, i, lang="en"):
        """'S = 1.2 m, S1 = 0.8 m' of position ``i`` (in the display units, for ``lang``)."""
        return ", ".join(f"{c} = {self.text(self.coord_values(c)[i], self.coord_unit(c), lang)}"
                         for c in self.coords)

    def text(self, value, unit_text, lang="en"):
        """A value given in ``unit_text`` (``"m"``, ``"deg"``, ``"N"``…) with its unit,
        in the display units and ``lang`` (:func:`assur.views.report.numbers.value_text`)."""
        from ..numbers import value_text
        return value_text(value, unit_text, self.units, lang)

    def transmission_points(self):
        pts = list(self.mech.tables.get("transmissions", ()))
        if not pts:
            pts = [ld.point for ld in self.mech.loads if isinstance(ld, Weight)]
        return list(dict.fromkeys(pts))


def _singular_note(view, what, values):
    bad = ~np.isfinite(values)
    if not bad.any():
        return None
    return {lang: TEXT["singular"][lang].format(what, int(bad.sum()),
                                                view.positions_text(bad, lang))
            for lang in TEXT["singular"]}
