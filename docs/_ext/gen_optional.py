"""The guide pages written by other work in progress (design, tolerance, page): a
toctree of those that exist when the documentation is built, so the build never
depends on them."""

from __future__ import annotations

from pathlib import Path

#: optional guide pages, in the order shown
OPTIONAL = ("design.md", "tolerance.md", "page.md")


def render(docs: Path) -> str:
    present = [name[:-3] for name in OPTIONAL if (docs / name).is_file()]
    if not present:
        return ""
    return "```{toctree}\n:maxdepth: 1\n\n" + "".join(f"/{p}\n" for p in present) + "```\n"


def write(path: Path, docs: Path) -> None:
    text = render(docs)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
