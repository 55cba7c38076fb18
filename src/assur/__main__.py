"""``python -m assur …`` and the ``assur`` console script: the command line of
:mod:`assur.views.cli` in a process that ends without Python's teardown.

When a command returns, its answer is printed and its files are closed; what Python
then does by default — freeing, one by one, the objects of the five hundred modules a
command imports, and a last garbage collection — takes about 50 ms, a sixth of a warm
``assur check`` (``benchmarks/latency.py``), for nothing the user sees. So the process
ends after every other exit handler has run (threads joined, multiprocessing's
children reaped, temporary directories removed, loggers flushed), its standard streams
flushed, with the command's exit status (mypy ends its runs the same way). A process
ended by an exception that is not an exit (an error of Python itself: the command line
turns every other error into a message and status 1) ends as Python ends it.

The endings are tested in ``tests/views/cli/test_cli_exit.py`` (pytest runs no
doctest of a ``__main__`` module): the same status, output and files as Python's own
ending, exit handlers run first, an escaping error ended by Python.
"""

from __future__ import annotations

import atexit
import os
import sys


def main() -> None:
    """Run the ``assur`` command line with ``sys.argv`` and end the process with its
    exit status, skipping Python's teardown (see the module's text)."""
    status: list = []
    atexit.register(_end, status)  # registered first, so run last of the exit handlers
    from .views.cli import app

    try:
        app(prog_name="assur")
    except SystemExit as e:
        code = e.code
        status.append(0 if code is None else code if isinstance(code, int) else 1)
        raise


def _end(status: list) -> None:
    """The last exit handler: flush the standard streams and end the process with the
    command's status (none known: Python's own ending)."""
    if not status:
        return
    for stream in (sys.stdout, sys.stderr):
        try:
            if stream is not None:
                stream.flush()
        except (OSError, ValueError):  # a closed pipe (``| head``) or a closed stream
            pass
    os._exit(status[0])


if __name__ == "__main__":
    main()
