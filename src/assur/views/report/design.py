"""Reports of a design search: the best design against the original (HTML with
tables and curves) and the Pareto front's figure. Figures only here (matplotlib);
the numbers come from :mod:`assur.synthesis.search`.
"""

from __future__ import annotations

import html

import numpy as np

__all__ = ["curves", "comparison_html", "pareto_figure", "write_comparison", "TEXT"]

#: the report's words: key -> {lang: text}
TEXT = {
    "title": {"en": "{name}: best design against the original",
              "ru": "{name}: лучший вариант в сравнении с исходным"},
    "feasible": {"en": "The best design is feasible.",
                 "ru": "Лучший вариант допустим."},
    "infeasible": {"en": "The best design is infeasible: {why}",
                   "ru": "Лучший вариант недопустим: {why}"},
    "work": {"en": "{n} designs evaluated in {calls} batches over {gens} generations; "
                   "{pos} positions each.",
             "ru": "Рассчитано вариантов: {n} ({calls} пакетов, {gens} поколений); "
                   "положений в каждом: {pos}."},
    "polish": {"en": "Polish (SLSQP with exact gradients) from the differential-evolution "
                     "optimum: {de} → {pol} ({nit} iterations, {njev} gradient evaluations)"
                     "{kept}.",
               "ru": "Уточнение (SLSQP с точными градиентами) от оптимума дифференциальной "
                     "эволюции: {de} → {pol} (итераций: {nit}, вычислений градиента: {njev})"
                     "{kept}."},
    "polish_kept": {"en": "; kept the differential-evolution optimum: {why}",
                    "ru": "; оставлен оптимум дифференциальной эволюции: {why}"},
    "polish_skipped": {"en": "Polish skipped: {why}.", "ru": "Уточнение не выполнено: {why}."},
    "variables": {"en": "Variables", "ru": "Переменные проектирования"},
    "objective": {"en": "Objective", "ru": "Целевая функция"},
    "constraints": {"en": "Constraints", "ru": "Ограничения"},
    "curves": {"en": "Curves", "ru": "Графики"},
    "variable": {"en": "variable", "ru": "переменная"},
    "bounds": {"en": "bounds", "ru": "границы"},
    "original": {"en": "original", "ru": "исходный"},
    "best": {"en": "best", "ru": "лучший"},
    "holds": {"en": "holds", "ru": "выполнено"},
    "constraint": {"en": "constraint", "ru": "ограничение"},
    "yes": {"en": "yes", "ru": "да"},
    "no": {"en": "no", "ru": "нет"},
    "maximize": {"en": "maximize", "ru": "максимизировать"},
    "minimize": {"en": "minimize", "ru": "минимизировать"},
}


def curves(problem, x):
    """The outputs the criteria read, over the problem's positions, for the design
    ``x`` [SI]: ``{output: array (n,)}`` (SI).

    Examples
    --------
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.criteria import criterion
    >>> from assur.core.quantities import Unit
    >>> base = load_problem(io.bundled("hitch_003_design"))  # seed 003's hitch
    >>> m = base.mechanism
    >>> objectives = [criterion("pressure", {"cylinder": "ГЦ"}, m, sense="minimize",
    ...                         unit=Unit("MPa", 1e6)),
    ...               criterion("bound", {"quantity": "Y(56)", "of": "max"}, m,
    ...                         sense="maximize")]
    >>> # the pivot 01 moved within ±30 mm, over 8 of the 50 positions (S = 0.42…0.67 m)
    >>> pb = Problem(m, base.positions[::7], base.variables[:2], objectives=objectives)
    >>> from assur.views.report.design import curves
    >>> c = curves(pb, pb.x0)  # the original design
    >>> list(c)
    ['p(ГЦ)', 'Y(56)']
    >>> round(float(c["p(ГЦ)"][-1]) / 1e6, 3)  # at S = 0.670 m [MPa], seed 003 table 4.1: 16.064
    16.064
    >>> [round(float(y), 3) for y in c["Y(56)"][[0, -1]]]  # lift range of 56 [m], seed: 0.200 low
    [0.2, 1.043]
    """
    mech = problem.mechanism.with_params(**{v.name: float(xi)
                                            for v, xi in zip(problem.variables, x)})
    f = mech.evaluate(problem.positions_of(x), outputs=list(problem.outputs))  # its own path
    return {o: np.asarray(f[o]) for o in problem.outputs if not o.startswith("length(__")}


def _unit_of(problem, output):
    for c in problem.constraints + problem.objectives:
        if output in c.outputs and c.unit is not None:
            return c.unit
    from ...core.outputs import display_unit
    return display_unit(problem.mechanism, output)


def comparison_html(problem, result, title=None, lang="en"):
    """HTML comparing the best design of ``result`` (an
    :class:`~assur.synthesis.search.search.OptimizeResult`) with the original: the variables,
    the objective, the constraints, and the curves of both over the positions;
    labels in ``lang`` ("en" or "ru").

    Examples
    --------
    >>> import re
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.criteria import criterion
    >>> from assur.core.quantities import Unit
    >>> base = load_problem(io.bundled("hitch_003_design"))  # seed 003's hitch
    >>> m = base.mechanism
    >>> objectives = [criterion("pressure", {"cylinder": "ГЦ"}, m, sense="minimize",
    ...                         unit=Unit("MPa", 1e6)),
    ...               criterion("bound", {"quantity": "Y(56)", "of": "max"}, m,
    ...                         sense="maximize")]
    >>> # the pivot 01 moved within ±30 mm, over 8 of the 50 positions (S = 0.42…0.67 m)
    >>> pb = Problem(m, base.positions[::7], base.variables[:2], objectives=objectives)
    >>> from assur.synthesis.search.search import optimize
    >>> res = optimize(pb, popsize=3, maxiter=2, seed=0, polish=False)  # a short search
    >>> from assur.views.report.design import comparison_html
    >>> page = comparison_html(pb, res)
    >>> summary = re.search(r"<p>(.*?)</p>", page).group(1)   # the counts are the search's
    >>> summary.startswith("The best design is feasible."), f"{res.evaluations} designs" in summary
    (True, True)
    >>> row = re.search(r"<td>minimize max p\\(ГЦ\\)</td><td>(.*?)</td>", page)
    >>> row.group(1), res.value < 16.0637e6  # the original's peak pressure; the best is lower [Pa]
    ('16.0637 MPa', True)
    >>> page.count("<figure>")  # a curve of each output, original and best
    2
    """
    from ._canvas import new_figure, to_png_bytes   # matplotlib when a report is made
    from .html import data_uri
    if lang not in ("en", "ru"):
        raise ValueError("lang must be one of: ['en', 'ru']")

    def t(key, **kw):
        return TEXT[key][lang].format(**kw)

    esc = html.escape
    best, orig = result.batch, result.original
    rows_v = "".join(
        f"<tr><td>{esc(v.name)}</td><td>{esc(v.show(v.low))} … {esc(v.show(v.high))}</td>"
        f"<td>{esc(v.show(problem.x0[j]))}</td><td>{esc(v.show(result.x[j]))}</td></tr>"
        for j, v in enumerate(problem.variables))
    rows_o = "".join(
        f"<tr><td>{esc(t(c.sense))} {esc(c.name)}</td><td>{esc(c.show(orig.objectives[0, j]))}</td>"
        f"<td>{esc(c.show(best.objectives[0, j]))}</td></tr>"
        for j, c in enumerate(problem.objectives))

    def lim(c, b):
        val, mg = b.values[0, j_], b.margins[0, j_]
        return val - mg if c.limit.sense == "at_least" else val + mg

    rows_c = ""
    for j_, c in enumerate(problem.constraints):
        rel = "≥" if c.limit.sense == "at_least" else "≤"
        rows_c += (f"<tr><td>{esc(c.name)} {rel} {esc(c.show(lim(c, orig)))}</td>"
                   f"<td>{esc(c.show(orig.values[0, j_]))}</td>"
                   f"<td>{esc(c.show(best.values[0, j_]))}</td>"
                   f"<td>{t('yes') if best.margins[0, j_] >= 0 else t('no')}</td></tr>")
    c0, c1 = curves(problem, problem.x0), curves(problem, result.x)
    mech = problem.mechanism
    coord = mech.coordinates[0]
    q = problem.positions if problem.positions.ndim == 1 else np.arange(len(problem.positions))
    figs = ""
    for o in c0:
        u = _unit_of(problem, o)
        fig = new_figure(5.5, 3.2)
        ax = fig.add_subplot()
        ax.plot(q, u.of(c0[o]), label=t("original"), color="0.4")
        ax.plot(q, u.of(c1[o]), label=t("best"), color="C0")
        ax.set_xlabel(f"{coord} [m]" if mech.coordinate_kind(coord) != "angle" else
                      f"{coord} [rad]")
        ax.set_ylabel(f"{o} [{u.text}]")
        ax.grid(alpha=0.3)
        ax.legend()
        uri = data_uri(to_png_bytes(fig, bbox_inches="tight"))
        figs += f'<figure><img alt="{esc(o)}" src="{uri}"></figure>'
    ttl = esc(title or t("title", name=problem.name))
    status = t("feasible") if result.feasible else t("infeasible", why=best.reason(0))
    work = t("work", n=result.evaluations, calls=result.calls, gens=result.generations,
             pos=len(problem.positions))
    pol = getattr(result, "polished", None)
    if pol is not None:
        c = problem.objectives[0]
        if not pol.ran:
            work += " " + t("polish_skipped", why=pol.note)
        else:
            kept = "" if pol.accepted else t("polish_kept", why=pol.note)
            work += " " + t("polish", de=c.show(pol.start_value), pol=c.show(pol.value),
                            nit=pol.nit, njev=pol.njev, kept=kept)
    return f"""<!DOCTYPE html>
<html lang="{lang}"><head><meta charset="utf-8"><title>{ttl}</title>
<style>body{{font-family:sans-serif;max-width:60em;margin:2em auto}}
table{{border-collapse:collapse;margin:1em 0}}td,th{{border:1px solid #bbb;padding:.2em .6em}}
figure{{display:inline-block;margin:.5em}}</style></head><body>
<h1>{ttl}</h1>
<p>{esc(status)} {esc(work)}</p>
<h2>{t("variables")}</h2><table><tr><th>{t("variable")}</th><th>{t("bounds")}</th>
<th>{t("original")}</th><th>{t("best")}</th></tr>
{rows_v}</table>
<h2>{t("objective")}</h2><table><tr><th>{t("objective")}</th><th>{t("original")}</th>
<th>{t("best")}</th></tr>{rows_o}</table>
<h2>{t("constraints")}</h2><table><tr><th>{t("constraint")}</th><th>{t("original")}</th>
<th>{t("best")}</th><th>{t("holds")}</th></tr>
{rows_c}</table>
<h2>{t("curves")}</h2>{figs}
</body></html>
"""


def write_comparison(path, problem, result, title=None, lang="en"):
    """Write :func:`comparison_html` to ``path``; returns the path.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.criteria import criterion
    >>> from assur.core.quantities import Unit
    >>> base = load_problem(io.bundled("hitch_003_design"))  # seed 003's hitch
    >>> m = base.mechanism
    >>> objectives = [criterion("pressure", {"cylinder": "ГЦ"}, m, sense="minimize",
    ...                         unit=Unit("MPa", 1e6)),
    ...               criterion("bound", {"quantity": "Y(56)", "of": "max"}, m,
    ...                         sense="maximize")]
    >>> # the pivot 01 moved within ±30 mm, over 8 of the 50 positions (S = 0.42…0.67 m)
    >>> pb = Problem(m, base.positions[::7], base.variables[:2], objectives=objectives)
    >>> from assur.synthesis.search.search import optimize
    >>> res = optimize(pb, popsize=3, maxiter=2, seed=0, polish=False)  # a short search
    >>> from assur.views.report.design import write_comparison
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = write_comparison(Path(d) / "design.html", pb, res, lang="ru")
    ...     page = p.read_text(encoding="utf-8")
    >>> p.name, "Переменные проектирования" in page, "минимизировать max p(ГЦ)" in page
    ('design.html', True, True)
    """
    from pathlib import Path
    p = Path(path)
    p.write_text(comparison_html(problem, result, title, lang), encoding="utf-8")
    return p


def pareto_figure(problem, result, path):
    """The Pareto front (two first objectives, in their units) with the original
    design, saved to ``path`` (PNG or SVG).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.criteria import criterion
    >>> from assur.core.quantities import Unit
    >>> base = load_problem(io.bundled("hitch_003_design"))  # seed 003's hitch
    >>> m = base.mechanism
    >>> objectives = [criterion("pressure", {"cylinder": "ГЦ"}, m, sense="minimize",
    ...                         unit=Unit("MPa", 1e6)),
    ...               criterion("bound", {"quantity": "Y(56)", "of": "max"}, m,
    ...                         sense="maximize")]
    >>> # the pivot 01 moved within ±30 mm, over 8 of the 50 positions (S = 0.42…0.67 m)
    >>> pb = Problem(m, base.positions[::7], base.variables[:2], objectives=objectives)
    >>> from assur.synthesis.search.search import pareto
    >>> from assur.views.report.design import pareto_figure
    >>> front = pareto(pb, pop_size=8, generations=3, seed=2)  # NSGA-II, short
    >>> F = front.batch.objectives  # max p [Pa], max Y(56) [m] of each front design
    >>> bool(F[:, 0].max() < 16.0637e6 and F[:, 1].min() > 1.043)  # both better than the original
    True
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pareto_figure(pb, front, Path(d) / "front.png")
    ...     png = p.read_bytes()
    >>> p.name, png[1:4]
    ('front.png', b'PNG')
    """
    from ._canvas import new_figure, plain_texts
    a, b = problem.objectives[:2]
    fig = new_figure(5.5, 4)
    ax = fig.add_subplot()
    if result.batch is not None:
        F = result.batch.objectives
        order = np.argsort(F[:, 0])
        ax.plot(a.unit.of(F[order, 0]), b.unit.of(F[order, 1]), "o-", ms=4, label="Pareto front")
    O = result.original.objectives
    ax.plot(a.unit.of(O[:, 0]), b.unit.of(O[:, 1]), "s", color="C3", label="original")
    ax.set_xlabel(f"{a.sense} {a.name} [{a.unit.text}]")
    ax.set_ylabel(f"{b.sense} {b.name} [{b.unit.text}]")
    ax.grid(alpha=0.3)
    ax.legend()
    plain_texts(fig)  # the objectives' names as the user wrote them
    fig.savefig(path, bbox_inches="tight")
    return path
