"""Disk cache of generated kernels: one module per structure, compiled once per
machine by numba's own on-disk cache.

The directory is ``$ASSUR_CACHE_DIR`` when set, else ``$XDG_CACHE_HOME/assur`` or
``~/.cache/assur``; :func:`set_cache_dir` changes it for the process (the tests use
a temporary one).
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import threading
from pathlib import Path

__all__ = ["cache_dir", "set_cache_dir", "load_source", "load_keyed", "helpers_tag"]

_lock = threading.RLock()  # a driver's import loads its group functions
_loaded: dict[str, object] = {}
_override: list = []


def set_cache_dir(path) -> None:
    """Use ``path`` for generated kernels in this process (None: back to the default).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur.kernel import cache_dir, set_cache_dir
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         print(cache_dir() == Path(tmp) / "kernels")
    ...     finally:
    ...         set_cache_dir(None)            # back to $ASSUR_CACHE_DIR or ~/.cache/assur
    True
    """
    _override[:] = [] if path is None else [str(path)]


def cache_dir() -> Path:
    """Directory of generated kernels (created when missing).

    Examples
    --------
    >>> from assur.kernel import cache_dir
    >>> d = cache_dir()                        # $ASSUR_CACHE_DIR/kernels, ~/.cache/assur/kernels
    >>> d.name, d.is_dir()
    ('kernels', True)
    """
    base = (_override[0] if _override else None) or os.environ.get("ASSUR_CACHE_DIR") or \
        os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "assur")
    p = Path(base) / "kernels"
    p.mkdir(parents=True, exist_ok=True)
    return p


_tag: list = []


def helpers_tag() -> str:
    """Hash of the modules whose numba intrinsics the generated kernels call
    (:mod:`assur.kernel.select`, :mod:`assur.kernel.stream`). Generated sources carry
    it in their first line: numba's disk cache checks a kernel's own file only, so a
    change to an intrinsic must change the file.

    Examples
    --------
    >>> from assur.kernel.cache import helpers_tag
    >>> len(helpers_tag()), helpers_tag() == helpers_tag()
    (12, True)
    """
    if not _tag:
        from . import select, stream
        h = hashlib.sha1()
        for m in (select, stream):
            h.update(Path(m.__file__).read_bytes())
        _tag.append(h.hexdigest()[:12])
    return _tag[0]


def load_source(src: str, name: str = "kernel"):
    """Write ``src`` to the cache (by its hash) and import it; returns ``module.<name>``.

    A module is loaded once per process; writes are atomic (a temporary file
    replaced), so processes sharing the cache never read half a file.

    Examples
    --------
    >>> import tempfile
    >>> from assur.kernel.cache import cache_dir, load_source, set_cache_dir
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         twice = load_source("def kernel(x):\\n    return 2 * x\\n")
    ...         files = sorted(p.name[:2] for p in cache_dir().glob("*.py"))
    ...     finally:
    ...         set_cache_dir(None)
    >>> twice(21), files                       # the module, written as k_<hash of source>.py
    (42, ['k_'])
    """
    key = hashlib.sha1(src.encode()).hexdigest()[:20]
    with _lock:
        mod = _loaded.get(key)
        if mod is None:
            path = cache_dir() / f"k_{key}.py"
            if not path.exists() or path.read_text() != src:
                _write(path, src)
            mod = _loaded[key] = _import(path, f"assur_kernel_{key}")
        return getattr(mod, name)


def load_keyed(what: str, make, name: str = "kernel"):
    """Import the module cached under the description ``what`` (which must name
    everything its source depends on), writing it from ``make()`` (the source) on
    the first use on this machine; returns ``module.<name>``.

    Examples
    --------
    >>> import tempfile
    >>> from assur.kernel.cache import load_keyed, set_cache_dir
    >>> made = []
    >>> def make():
    ...     made.append(1)
    ...     return "def kernel(x):\\n    return x + 1\\n"
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         f = load_keyed("doc example: add one, v1", make)
    ...         g = load_keyed("doc example: add one, v1", make)   # loaded: make not called
    ...     finally:
    ...         set_cache_dir(None)
    >>> f(41), f is g, len(made)
    (42, True, 1)
    """
    key = hashlib.sha1(what.encode()).hexdigest()[:20]
    with _lock:
        mod = _loaded.get(key)
        if mod is None:
            path = cache_dir() / f"v_{key}.py"
            if not path.exists():
                _write(path, make())
            mod = _loaded[key] = _import_code(path, f"assur_vector_{key}")
        return getattr(mod, name)


def _import_code(path: Path, modname: str):
    """Import ``path`` through its code object, cached beside it (marshal, per Python
    version) even where Python writes no bytecode (``PYTHONDONTWRITEBYTECODE``)."""
    import marshal
    import types

    src = path.read_text()
    tag = hashlib.sha1(src.encode() + importlib.util.MAGIC_NUMBER).hexdigest()[:12]
    cpath = path.with_suffix(f".{tag}.code")
    code = None
    if cpath.exists():
        try:
            code = marshal.loads(cpath.read_bytes())
        except (EOFError, ValueError, TypeError):  # a damaged file: compiled again
            code = None
    if code is None:
        code = compile(src, str(path), "exec")
        tmp = cpath.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_bytes(marshal.dumps(code))
        os.replace(tmp, cpath)
    mod = types.ModuleType(modname)
    mod.__file__ = str(path)
    sys.modules[modname] = mod
    exec(code, mod.__dict__)
    return mod


def _write(path: Path, src: str) -> None:
    tmp = path.with_suffix(f".{os.getpid()}.tmp")
    tmp.write_text(src)
    os.replace(tmp, path)


def _import(path: Path, modname: str):
    spec = importlib.util.spec_from_file_location(modname, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[modname] = mod
    spec.loader.exec_module(mod)
    return mod
