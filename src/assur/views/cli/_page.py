"""The commands of the interactive page and the drawing: ``assur serve``,
``assur dxf`` (:mod:`assur.views.cli`)."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.text import Text

from ._common import (_assemble, _check_lang, _fail, _load, _ok, _positions, _unique, console,
                      err)
from ._types import Count, Numbers


def serve(file: Path = typer.Argument(..., help="Model file (TOML)."),
          port: int = typer.Option(8000, "--port", parser=Count(0, 65535),
                                   help="TCP port, 0 … 65535 (0: any free port)."),
          host: str = typer.Option("127.0.0.1", "--host",
                                   help="Address to bind (default: loopback only)."),
          no_browser: bool = typer.Option(False, "--no-browser",
                                          help="Do not open the page in a browser."),
          lang: str = typer.Option("en", "--lang", help="The page's language: ru or en.")):
    """Serve an interactive page for a model: parameters as sliders, the mechanism's
    drawing moved by a stroke slider, live plots and tables (docs/page.md)."""
    _check_lang(lang)
    _load(file)  # one message for a bad file, before the server starts
    from ..._extras import require
    require("page", "assur serve")  # FastAPI, uvicorn: else which extra to install
    from ..page.server import create_app
    from ...errors import ModelError

    try:
        application = create_app(file, lang=lang, compiled=True)
    except (ModelError, OSError) as e:
        _fail(str(e))
    import socket

    import uvicorn

    try:  # the port first, so that a busy one is one message and the URL is known
        sock = socket.socket(socket.AF_INET6 if ":" in host else socket.AF_INET)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
    except OSError as e:
        _fail(f"cannot listen on {host}:{port}: {e.strerror or e}")
    port = sock.getsockname()[1]
    shown = f"[{host}]" if ":" in host else host
    url = f"http://{shown}:{port}/?lang={lang}"
    if host not in ("127.0.0.1", "::1", "localhost"):
        err.print(Text.assemble(("warning:", "bold yellow"), " ", f"serving on {host}: "
                                "anyone who can reach this address can use the page"))
    console.print(f"assur: serving {file} at {url} (Ctrl+C stops)", soft_wrap=True)
    if not no_browser:
        import threading
        import webbrowser
        threading.Timer(0.8, lambda: webbrowser.open(url)).start()
    config = uvicorn.Config(application, log_level="warning")
    uvicorn.Server(config).run(sockets=[sock])


def dxf(file: Path = typer.Argument(..., help="Model file (TOML)."),
        at: str = typer.Option("", "--at", parser=Numbers(),
                               help="Coordinate values to draw, finite numbers: cylinder "
                               "lengths in m (0.42,0.67), crank angles in degrees; "
                               "default: first and last."),
        output: str = typer.Option("", "-o", "--output",
                                   help="The DXF file (default: <model>.dxf).")):
    """Write the mechanism's drawing at chosen positions as DXF (millimetres, one layer
    per link, pivots as points; docs/page.md)."""
    import numpy as np

    from ..page.dxf import write_dxf
    from ...errors import AssemblyError, ModelError, SingularPositionError

    model = _load(file)
    out = Path(output or (file.stem + ".dxf"))
    if out.exists() and out.is_dir():
        _fail(f"{out}: is a directory; expected a .dxf file name")
    mech = model.mechanism
    kin, idx = None, None
    if at and len(mech.coordinates) == 1 and mech.coordinate_kind(mech.coordinates[0]) != \
            "angle":
        values = list(dict.fromkeys(float(v) for v in at))  # each position once
        r = np.asarray(model.range, dtype=float)
        lo, hi = float(r.min()), float(r.max())
        bad = [v for v in values if not lo <= v <= hi]
        if bad or not values:
            _fail(f"--at {bad or list(at)}: give values in the range {lo:.6g} … {hi:.6g} m")
        # a fine grid through the values keeps the assembly mode continuous between them
        q = np.unique(np.concatenate([np.linspace(r[0], r[-1], 201), values]))
        q = q if r[-1] >= r[0] else q[::-1]
        try:
            kin = mech.solve(q)
        except (AssemblyError, ModelError, SingularPositionError) as e:
            _fail(f"{file}: {e}")
        idx = _unique([int(np.abs(q - v).argmin()) for v in values])
    else:
        analysis = _assemble(model)
        kin = analysis.kinematics
        idx = _unique(_positions(analysis, at, option="--at") or [0, kin.shape[-1] - 1])
    from ...core.inputs import check_table
    try:  # the drawn positions' every point: no NaN or infinity in the file
        check_table(f"{out.name} (positions drawn) [m]",
                    {**{c: kin.q(c)[idx] for c in kin.coordinates},
                     **{f"{a}{p}": getattr(kin, a.lower())(p)[idx]
                        for p in kin.points for a in ("X", "Y")}})
    except ModelError as e:
        _fail(f"{file}: {e}")
    try:
        write_dxf(kin, out, positions=idx)
    except OSError as e:
        _fail(f"{out}: cannot write the DXF file: {e.strerror or e}")
    _ok(f"wrote {out} ({len(idx)} positions)")
