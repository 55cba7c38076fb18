"""A model file of a structure that no bundled model has, for the latency tests and
``benchmarks/latency.py``: the seed-003 hitch (``extends`` its bundled file: its
conditions, loads, cylinder and lift test come along) with extra rigid points on its
links 3, 5 and 6 in turn — 7 + ``extra`` groups — at lengths and angles drawn from
``seed`` (a new structure for its kernels: a cold cache compiles it from nothing)."""

from __future__ import annotations

import random
from pathlib import Path

__all__ = ["new_structure_model"]

_CARRIERS = (("03", "23", "3"), ("05", "56", "5"), ("56", "67", "6"))


def new_structure_model(directory, extra: int = 1, seed: int = 0) -> Path:
    """Write ``hitch_plus_<extra>_<seed>.toml`` in ``directory``; returns its path."""
    from assur import io

    rnd = random.Random(seed)
    name = f"hitch_plus_{extra}_{seed}"
    base = io.bundled("hitch_003").as_posix()
    lines = [f'extends = "{base}"', "", "[model]", f'name = "{name}"',
             f'title = "Hitch with {extra} more points (a new structure)"', "", "[params]"]
    groups = []
    for i in range(extra):
        origin, toward, link = _CARRIERS[i % 3]
        lines.append(f'lx{i} = "{rnd.randint(50, 300)} mm"')
        groups += ["", "[[groups]]", 'type = "rigid_point"', f'name = "extra {i}"',
                   f'origin = "{origin}"', f'toward = "{toward}"', f'out = "X{i}"',
                   f'length = "lx{i}"', f"angle = {rnd.randint(-170, 170)}",
                   f'links = ["{link}"]']
    path = Path(directory) / f"{name}.toml"
    path.write_text("\n".join(lines + groups) + "\n", encoding="utf-8")
    return path
