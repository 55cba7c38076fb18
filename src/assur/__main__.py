"""``python -m assur demo``: solve the bundled seed-003 hitch and print its tables.

(The full command-line interface with reports arrives with the model files.)
"""

from __future__ import annotations

import sys
import time


def _table(frame, columns, title, decimals):
    import numpy as np

    lines = [title]
    widths = [max(8, len(c) + 1) for c in columns]
    lines.append("".join(c.rjust(w) for c, w in zip(columns, widths)))
    for i in range(len(frame)):
        row = []
        for c, w, d in zip(columns, widths, decimals):
            v = float(np.asarray(frame[c], dtype=float)[i])
            row.append(f"{v:.{d}f}".rjust(w))
        lines.append("".join(row))
    return "\n".join(lines)


def demo(out=sys.stdout):
    """Print seed 003 tables 2.1, 2.2 and 3.1 computed by assur."""
    from . import examples

    t0 = time.perf_counter()
    m = examples.hitch_003()
    r = m.solve(examples.hitch_003_range())
    f = r.to_frame()
    dt = time.perf_counter() - t0
    print(f"{m.title}: {len(f)} positions, S = 0.420…0.670 m "
          f"(L4 = {m.params['L4']:.4f} m, L7 = {m.params['L7']:.4f} m, "
          f"Sp = {m.params['Sp']:.4f} m); solved in {dt:.2f} s\n", file=out)
    print(_table(f, ["S", "phi34", "phi3", "phi4", "phi5", "phi6", "phi7"],
                 "Table 2.1 — link angles [deg] (S [m])", [3] + [1] * 6), file=out)
    print(file=out)
    print(_table(f, ["S", "X23", "Y23", "X34", "Y34", "X45", "Y45", "X56", "Y56", "X67", "Y67",
                     "XS6", "YS6"], "Table 2.2 — point coordinates [m]", [3] * 13), file=out)
    print(file=out)
    print(_table(f, ["S", "U43", "U53", "U65", "U75", "I56", "IS6"],
                 "Table 3.1 — transfer ratios U_ij and transmission numbers I = dY/dS [-]",
                 [3] * 7), file=out)
    print(file=out)
    print(_table(f, ["S", "dphi3", "dphi4", "dphi5", "dphi6", "dphi7"],
                 "Table 3.1 (cont.) — angular-velocity analogs dφ/dS [rad/m]", [3] * 6), file=out)
    for note in m.notes:
        print(f"note: {note}", file=out)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["demo"]:
        demo()
        return 0
    print("usage: python -m assur demo", file=sys.stderr)
    return 2


if __name__ == "__main__":
    raise SystemExit(main())
