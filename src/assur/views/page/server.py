"""The FastAPI application behind ``assur serve``.

Routes (all JSON unless noted):

========================  ==============================================================
``GET /``                 the page (``static/index.html``; ``?lang=ru`` for Russian)
``GET /static/…``         its script and style sheet
``GET /api/model``        title, coordinates, parameters by group with units, the
                          page's labels in both languages
``POST /api/analyze``     :class:`~assur.views.page.api.AnalyzeRequest` → the drawing over the
                          positions, the tables, the solved conditions; or
                          ``{"ok": false, "error": {"kind", "message"}}`` when the edited
                          model cannot be built or assembled (HTTP 200: the request was
                          valid, the design is not)
``POST /api/export/csv``  one table of the edited model over the file's range (file)
``POST /api/export/xlsx`` all its tables (file)
``POST /api/export/toml`` the edited model file (file)
``POST /api/export/dxf``  the drawing at chosen coordinate values (file)
========================  ==============================================================

Safety: request bodies over :data:`~assur.views.page.api.MAX_BODY` bytes are refused with
413 before they are read whole; request models forbid unknown keys and bound every
array; values are only written into the model's TOML text (never evaluated);
errors are messages, never tracebacks (an unexpected exception answers 500 with a
fixed text and is logged on the server). ``assur serve`` binds to 127.0.0.1.
"""

from __future__ import annotations

import json
import logging
from importlib import resources

from ..._extras import require

require("page", "the interactive page (assur serve)")

from fastapi import FastAPI  # noqa: E402 — after the check that says what to install
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response

from ...errors import AssemblyError, ModelError, SingularPositionError
from .api import MAX_BODY, AnalyzeRequest, DxfRequest, ExportRequest
from .session import PageModel
from .texts import page_texts

__all__ = ["create_app", "running"]

log = logging.getLogger("assur.views.page")


def _static(name: str) -> bytes:
    return (resources.files("assur.views.page") / "static" / name).read_bytes()


class _BodyLimit:
    """ASGI middleware: refuse a request body longer than ``MAX_BODY`` bytes with 413,
    by its declared length or while it is read (the body is then replayed)."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or scope["method"] not in ("POST", "PUT", "PATCH"):
            return await self.app(scope, receive, send)
        headers = dict(scope.get("headers") or [])
        length = headers.get(b"content-length")
        if length is not None:
            try:
                declared = int(length)
            except ValueError:
                return await JSONResponse({"detail": "bad Content-Length"},
                                          status_code=400)(scope, receive, send)
            if declared > MAX_BODY:
                return await _too_large()(scope, receive, send)
        body, more = b"", True
        while more:
            message = await receive()
            if message["type"] == "http.disconnect":
                return None
            body += message.get("body", b"")
            more = message.get("more_body", False)
            if len(body) > MAX_BODY:
                return await _too_large()(scope, receive, send)
        sent = False

        async def replay():
            nonlocal sent
            if sent:
                return await receive()
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}
        return await self.app(scope, replay, send)


def _too_large():
    return JSONResponse({"detail": f"request body larger than {MAX_BODY} bytes"},
                        status_code=413)


def _download(data: bytes, media: str, filename: str) -> Response:
    return Response(data, media_type=media, headers={
        "Content-Disposition": f'attachment; filename="{filename}"',
        "Cache-Control": "no-store"})


def _user_error(e) -> JSONResponse:
    kind = ("assembly" if isinstance(e, AssemblyError) else
            "singular" if isinstance(e, SingularPositionError) else "model")
    return JSONResponse({"ok": False, "error": {"kind": kind, "message": str(e)}})


def _warm(pm, compiled=False):
    """Compute the page's first answer, a first change and the tables' export once in a
    background thread, so the first request, the first edit and the first download of
    the model do not wait for kernels to compile or load, the conditions' solver to be
    imported or the workbook writer to load. With ``compiled``, then switch the process
    to compiled kernels (:func:`assur.kernel.vector.serving`: the new ones compiled in
    the background) and compute the answers again once they are there, so that every
    later answer runs compiled."""
    import threading

    def answers(positions):
        pm.compute({}, positions=positions)
        # a first change: the design conditions solved again (their solver and
        # kernels loaded), as after the user's first edit
        for name, p in list(pm.editable.items())[:1]:
            pm.compute({name: p["value"] * (1 + 1e-7) + 1e-12}, positions=positions)

    def run():
        try:
            from .api import AnalyzeRequest
            positions = AnalyzeRequest().positions
            answers(positions)
            if pm.model.solved:
                # the conditions' root finder (scipy.optimize, ~0.2 s to import): the first
                # change above may have found its roots in the solve cache on disk and not
                # loaded it, which the user's first new value would then wait for
                import scipy.optimize  # noqa: F401
            pm.export_tables({}, "xlsx", positions=positions)
            if compiled:
                from ...kernel import vector
                vector.serving()
                answers(positions)  # ready kernels loaded; new ones start compiling
                vector.compiling(wait=True)
                answers(positions)  # and the newly compiled ones loaded
        except (ModelError, AssemblyError, SingularPositionError):
            pass  # the design's own error: the page shows it when it asks
        except Exception:  # noqa: BLE001 - a thread's last resort: logged, never silent
            log.exception("warming the model failed")

    t = threading.Thread(target=run, name="assur-warm", daemon=True)
    t.start()
    return t


def create_app(model, lang: str = "en", warm: bool = True, compiled: bool = False) -> FastAPI:
    """The application serving one model file.

    Parameters
    ----------
    model : str, Path or PageModel
        The model file (read once; the page edits a copy of its text).
    lang : {"en", "ru"}
        The page's language by default.
    warm : bool
        Compute the first answer and the tables' export in the background at once
        (:func:`_warm`), so the first ones the page asks for are not slow; the
        warming thread is ``app.state.warming``.
    compiled : bool
        After warming, switch this process to compiled kernels
        (:func:`assur.kernel.vector.serving`): for a server that runs for long
        (``assur serve``), whose answers then take the compiled kernels' time; it
        costs numba's start-up and, on a new structure, compilations in the background.

    Raises
    ------
    ModelError, FileNotFoundError
        When the file cannot be read or is not a valid model.

    Examples
    --------
    >>> from assur.io import bundled
    >>> from assur.views.page.server import create_app
    >>> app = create_app(bundled("hitch_003"), lang="ru")
    >>> sorted(r.path for r in app.routes if r.path.startswith("/api/"))
    ['/api/analyze', '/api/export/dxf', '/api/export/{fmt}', '/api/model', '/api/openapi.json']
    >>> route = {r.path: r.endpoint for r in app.routes}
    >>> info = route["/api/model"]()              # what GET /api/model answers
    >>> info["file"], info["lang"], info["coordinates"]
    ('hitch_003.toml', 'ru', [{'name': 'S', 'kind': 'length'}])
    >>> create_app(bundled("hitch_003"), lang="de")
    Traceback (most recent call last):
    ...
    ValueError: lang must be one of: ['en', 'ru']; got 'de'
    """
    pm = model if isinstance(model, PageModel) else PageModel.from_path(model)
    if lang not in ("en", "ru"):
        raise ValueError(f"lang must be one of: ['en', 'ru']; got {lang!r}")
    app = FastAPI(title="assur", docs_url=None, redoc_url=None, openapi_url="/api/openapi.json")
    app.add_middleware(_BodyLimit)
    app.state.page_model = pm
    app.state.warming = _warm(pm, compiled) if warm else None
    _add_error_handlers(app)
    _add_page_routes(app, lang)
    _add_api_routes(app, pm, lang)
    _add_export_routes(app, pm)
    return app


def _add_error_handlers(app):
    """A validation error as one message (the input not echoed back); an unexpected
    exception as 500 with a fixed text, logged on the server."""

    @app.exception_handler(RequestValidationError)
    async def _invalid(request, exc):
        # the messages without the input echoed back (it may be large)
        errors = [{"loc": list(e.get("loc", ())), "msg": e.get("msg", "")}
                  for e in exc.errors()][:20]
        return JSONResponse({"ok": False, "error": {
            "kind": "validation",
            "message": "; ".join(f"{'.'.join(str(x) for x in e['loc'][1:]) or 'body'}: "
                                 f"{e['msg']}" for e in errors)},
            "detail": errors}, status_code=422)

    @app.exception_handler(Exception)
    async def _unexpected(request, exc):  # pragma: no cover - a bug: no traceback out
        log.exception("unexpected error on %s", request.url.path)
        return JSONResponse({"ok": False, "error": {
            "kind": "internal", "message": "internal error (logged by the server)"}},
            status_code=500)


def _add_page_routes(app, lang):
    """``GET /`` (the page in ``lang`` unless ``?lang=`` says otherwise), its static
    files and the favicon."""

    @app.get("/", response_class=HTMLResponse)
    def index(lang: str = lang):
        import html as markup
        html = _static("index.html").decode("utf-8")
        lg = lang if lang in ("en", "ru") else "en"
        # what the page says when the API does not answer (its texts come from the API)
        down = markup.escape(page_texts()["server_down"][lg], quote=True)
        return HTMLResponse(html.replace("{{LANG}}", lg).replace("{{SERVER_DOWN}}", down))

    @app.get("/favicon.ico")
    def favicon():
        return Response(status_code=204)

    @app.get("/static/{name}")
    def static(name: str):
        types = {"page.js": "text/javascript", "plot.js": "text/javascript",
                 "page.css": "text/css"}
        if name not in types:
            return JSONResponse({"detail": "not found"}, status_code=404)
        return Response(_static(name), media_type=f"{types[name]}; charset=utf-8")


def _add_api_routes(app, pm, lang):
    """``GET /api/model`` and ``POST /api/analyze`` of the page model ``pm``."""

    @app.get("/api/model")
    def model_info():
        m = pm.model.mechanism
        from ...texts import localize
        return {
            "name": m.name,
            "file": pm.name,
            "title": {lg: localize(m.title, lg) for lg in ("en", "ru")},
            "coordinates": [{"name": c, "kind": m.coordinate_kind(c)} for c in m.coordinates],
            "parameters": pm.parameters(),
            "texts": page_texts(),
            "lang": lang,
            "units": m.display.get("units") or "file",
        }

    @app.post("/api/analyze")
    def analyze(req: AnalyzeRequest):
        out = pm.compute(dict(req.params), positions=req.positions, lang=req.lang,
                         units=req.units, packed=req.packed)
        # serialized here: the payload is plain (lists of floats, None for NaN), and
        # FastAPI's generic encoder would walk it element by element
        return Response(json.dumps(out, allow_nan=False, separators=(",", ":")),
                        media_type="application/json")


def _add_export_routes(app, pm):
    """``POST /api/export/dxf`` and ``POST /api/export/{fmt}`` (csv, xlsx, toml) of the
    page model ``pm``: files, or a user error as JSON."""

    @app.post("/api/export/dxf")
    def export_dxf(req: DxfRequest):
        from .dxf import dxf_bytes
        try:
            model = pm.model_on(pm.load(dict(req.params)), req.positions)
            kin = model.mechanism.solve(model.range)
            idx = _nearest(model, kin, list(req.at))
            data = dxf_bytes(kin, positions=idx)
        except (ModelError, AssemblyError, SingularPositionError) as e:
            return _user_error(e)
        stem = pm.name.removesuffix(".toml") or "model"
        return _download(data, "image/vnd.dxf", f"{stem}.dxf")

    @app.post("/api/export/{fmt}")
    def export(fmt: str, req: ExportRequest):
        try:
            if fmt == "toml":
                text = pm.edited_text(dict(req.params))
                return _download(text.encode("utf-8"), "application/toml; charset=utf-8",
                                 pm.name if pm.name.endswith(".toml") else "model.toml")
            if fmt not in ("csv", "xlsx"):
                return JSONResponse({"ok": False, "error": {
                    "kind": "validation",
                    "message": f"format must be one of: csv, xlsx, toml, dxf; got {fmt!r}"}},
                    status_code=404)
            data, media, name = pm.export_tables(dict(req.params), fmt, req.table, req.lang,
                                                 req.units, positions=req.positions)
            return _download(data, media, name)
        except (ModelError, AssemblyError, SingularPositionError) as e:
            return _user_error(e)

def _nearest(model, kin, at):
    """Indices of the positions nearest the coordinate values ``at`` (m, or degrees
    for a crank): one coordinate — a position per value; more — ``at`` holds one
    value per coordinate and names one position (the nearest, each coordinate
    measured against its span); all positions' first and last when ``at`` is empty."""
    import numpy as np
    n = kin.shape[-1]
    if not at:
        return sorted({0, n - 1})
    mech = model.mechanism
    qs = []
    for c in kin.coordinates:
        q = np.ravel(kin.q(c))
        qs.append(np.degrees(q) if mech.coordinate_kind(c) == "angle" else q)
    if kin.k != 1 and len(at) != kin.k:
        raise ModelError(f"at: one value per coordinate {list(kin.coordinates)} names a "
                         f"position; got {len(at)} values")
    values = [[v] for v in at] if kin.k != 1 else [list(at)]
    for c, q, vs in zip(kin.coordinates, qs, values):
        lo, hi = float(np.min(q)), float(np.max(q))
        bad = [v for v in vs if not lo - 1e-9 <= v <= hi + 1e-9]
        if bad:
            raise ModelError(f"at: {bad} outside the range of {c}: {lo:.6g} … {hi:.6g}")
    if kin.k == 1:  # a value asked twice is one position (one DXF group)
        return list(dict.fromkeys(int(np.abs(qs[0] - v).argmin()) for v in at))
    d = sum(((q - v) / max(float(np.ptp(q)), 1e-12)) ** 2 for q, v in zip(qs, at))
    return [int(np.argmin(d))]


class running:
    """A context manager that serves ``app`` with uvicorn in a background thread on
    ``host`` (loopback) and a free port; ``with running(app) as url: …`` — for tests,
    benchmarks and notebooks. The server stops when the block ends.

    Examples
    --------
    Nothing is served until the ``with`` block starts (``url`` is then
    ``http://127.0.0.1:<port>``); the defaults bind to the loopback only, on a port
    the system picks:

    >>> from assur.io import bundled
    >>> from assur.views.page.server import create_app, running
    >>> server = running(create_app(bundled("hitch_003")))
    >>> server.host, server.port               # port 0: any free port
    ('127.0.0.1', 0)
    """

    def __init__(self, app, host: str = "127.0.0.1", port: int = 0):
        self.app, self.host, self.port = app, host, port

    def __enter__(self) -> str:
        import socket
        import threading
        import time

        import uvicorn
        sock = socket.socket(socket.AF_INET)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((self.host, self.port))
        self.sock = sock
        port = sock.getsockname()[1]
        config = uvicorn.Config(self.app, log_level="warning", lifespan="off")
        self.server = uvicorn.Server(config)
        self.server.install_signal_handlers = lambda: None  # not the main thread
        self.thread = threading.Thread(target=self.server.run, kwargs={"sockets": [sock]},
                                       daemon=True)
        self.thread.start()
        t0 = time.monotonic()
        while not self.server.started:
            if not self.thread.is_alive() or time.monotonic() - t0 > 30:
                raise RuntimeError("the server did not start")
            time.sleep(0.02)
        return f"http://{self.host}:{port}"

    def __exit__(self, *exc):
        self.server.should_exit = True
        self.thread.join(timeout=10)
        self.sock.close()
        return False
