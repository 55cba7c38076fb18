"""The tables of the machine: D (crank dynamics), V (velocities and accelerations at
the crank's speed), 6.1 (stability) and L (the standard lift test)
(:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import numpy as np

from ....texts import LANGS
from ..labels import TEXT
from ._data import Column, Table, _both


def _table_d(v):
    """The crank dynamics over the positions: rates, reduced moment of inertia, reduced
    moments, driving moment, kinetic energy, common centre of mass (and the motion
    with the flywheel)."""
    dyn = getattr(v.a, "dynamics", None)
    if dyn is None:
        return None
    c = dyn.coordinate
    cols = v.coord_columns()
    cols += [Column("omega", "rad/s", v.pick(dyn.qdot), _both("c_omega", c)),
             Column("eps", "rad/s²", v.pick(dyn.qddot), _both("c_eps", c)),
             Column("J_red", "kg·m²", v.pick(dyn.reduced_inertia), _both("c_Jred")),
             Column("dJ_red", "kg·m²/rad", v.pick(dyn.reduced_inertia_derivative),
                    _both("c_dJred")),
             Column("M_red", "N·m", v.pick(dyn.reduced_moment), _both("c_Mred")),
             Column("M_red_loads", "N·m", v.pick(dyn.reduced_moment_without_inertia),
                    _both("c_Mred_loads")),
             Column("M_red_inertia", "N·m", v.pick(dyn.reduced_moment_of_inertia_loads),
                    _both("c_Mred_inertia")),
             Column("M_d", "N·m", v.pick(dyn.driving_moment), _both("c_Md")),
             Column("T", "J", v.pick(dyn.kinetic_energy), _both("c_T")),
             Column("Xc", "m", v.pick(dyn.centre.x), _both("c_Xc")),
             Column("Yc", "m", v.pick(dyn.centre.y), _both("c_Yc"))]
    fw = getattr(v.a, "flywheel", None)
    if fw is not None and np.shape(fw.omega) == (v.n,):
        cols.append(Column("omega_fw", "rad/s", v.pick(fw.omega), _both("c_omega_fw")))
    notes = [{"en": "M_red: reduced moment on the crank of all loads (inertia included) by "
                    "virtual work; M_d = −M_red, the moment the drive applies",
              "ru": "M_red — приведённый к кривошипу момент всех сил (с силами инерции) по "
                    "принципу возможных перемещений; M_d = −M_red — момент привода"}]
    return Table("D", _both("tD"), tuple(cols), tuple(notes))


def _table_v(v):
    """Velocities and accelerations at the crank's speed of ``[motion]`` (the rates the
    crank dynamics and its inertia loads use): ω, ε of every link (ω = φ'·q̇,
    ε = φ'·q̈ + φ''·q̇², :meth:`~assur.core.transfer.Transfer.angular_velocity`) and the
    magnitudes of the velocity and acceleration of every moving point (v = J·q̇,
    a = J·q̈ + q̇ᵀ·H·q̇)."""
    dyn = getattr(v.a, "dynamics", None)
    if dyn is None or v.design is not None and np.ndim(dyn.qdot) > 1:
        return None
    kin = v.kin
    qd, qdd = dyn.qdot, dyn.qddot
    cols = v.coord_columns()
    for link in kin.links:
        cols.append(Column(f"omega{link}", "rad/s", v.pick(kin.angular_velocity(link, qd)),
                           _both("c_omega_link", link)))
    for link in kin.links:
        cols.append(Column(f"eps{link}", "rad/s²",
                           v.pick(kin.angular_acceleration(link, qd, qdd)),
                           _both("c_eps_link", link)))
    frame = set(v.mech.frame_points)
    for p in kin.points:
        if p in frame:
            continue
        cols.append(Column(f"v{p}", "m/s", v.pick(np.hypot(*np.moveaxis(
            kin.velocity(p, qd), -1, 0))), _both("c_v_point", p)))
    for p in kin.points:
        if p in frame:
            continue
        cols.append(Column(f"a{p}", "m/s²", v.pick(np.hypot(*np.moveaxis(
            kin.acceleration(p, qd, qdd), -1, 0))), _both("c_a_point", p)))
    return Table("V", _both("tV"), tuple(cols), (_both("n_rates"),))


def _table_6_1(v):
    st = v.a.stability
    if st is None:
        return None
    cols = v.coord_columns()
    names = list(st.reactions)
    lower = [n.lower() for n in names]
    labels = lower if len(set(lower)) == len(lower) else names  # as StabilityResult.to_frame
    for n, lab in zip(names, labels):
        cols.append(Column(f"R{lab}", "N", v.pick(st.reactions[n]), _both("c_Raxle", n)))
    for n, lab in zip(names, labels):
        cols.append(Column(f"dR{lab}", "%", v.pick(st.shares[n]), _both("c_dRaxle", n)))
    cols.append(Column("G_max", "N", v.pick(st.max_implement_weight),
                       _both("c_Gmax", 100.0 * st.min_share)))
    cols.append(Column("G_max_no_cw", "N", v.pick(st.max_implement_weight_without_counterweights),
                       _both("c_Gmax_no_cw")))
    cols.append(Column("steerable", "-", v.pick(st.steerable).astype(int), _both("c_steerable")))
    notes = []
    if v.k > 1:  # over several coordinates: the limits' minima (seed 001 lab 1 eqs. 16, 18)
        g = v.mech.g
        for sym, vals in (("G_max", st.max_implement_weight),
                          ("G_max_no_cw", st.max_implement_weight_without_counterweights)):
            vals = v.pick(vals)
            i = int(np.argmin(vals))
            if np.isfinite(vals[i]):
                notes.append({lang: TEXT["gmax_min"][lang].format(
                    sym, v.text(vals[i], "N", lang), v.text(vals[i] / g, "kg", lang),
                    v.text(g, "m/s²", lang), v.at_text(i, lang)) for lang in LANGS})
    return Table("6.1", _both("t6.1"), tuple(cols), tuple(notes))


def _table_l(v):
    """The standard lift test (ISO 789-2 / SAE J283): its own rows, the test positions
    evenly spaced over the lift range of the hitch points."""
    lt = getattr(v.a, "lift_test", None)
    if lt is None:
        return None
    h, f = lt.test.hitch, lt.test.frame
    cols = [Column(lt.coordinate, "m", lt.s, v.coord_label(lt.coordinate)),
            Column(f"Y{h}", "m", lt.height, _both("c_y", h)),
            Column(f"G{h}_test", "N", lt.hitch_force, _both("c_Gtest", h))]
    if f is not None:
        cols.append(Column(f"G{f}_test", "N", lt.frame_force, _both("c_Gtest_frame", f)))
    notes = [{lang: TEXT["lift_test_note"][lang].format(
                  v.text(100 * lt.test.pressure_share, "%", lang), v.text(lt.pressure, "Pa", lang),
                  v.text(lt.force_cylinder, "N", lang), len(lt.s)) for lang in LANGS},
             {lang: TEXT["lift_test_min"][lang].format(h, v.text(lt.hitch_minimum, "N", lang))
              for lang in LANGS}]
    if f is not None:
        notes.append({lang: TEXT["lift_test_min_frame"][lang].format(
            f, v.text(lt.frame_minimum, "N", lang)) for lang in LANGS})
    return Table("L", _both("tL"), tuple(cols), tuple(notes))
