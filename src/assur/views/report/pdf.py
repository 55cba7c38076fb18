"""The HTML report as a PDF: the same file printed by Chromium's headless print-to-PDF.

The PDF is the report's print layout (``report.css``, ``@media print``): A4 pages, the
tables section on landscape pages when a table is too wide for portrait, every row of
a long table, wide tables cut into parts that fit the page, no animation. Nothing is
laid out twice: what a browser prints from ``report.html`` is what the PDF holds.

Chromium is found as ``$ASSUR_CHROMIUM`` (a path or a command name) or, when that is
not set, as the first of :data:`CANDIDATES` on ``PATH``. Without it :func:`write_pdf`
raises :class:`PdfError`, whose message says what to install; the HTML report needs
no browser to be written.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path

__all__ = ["write_pdf", "find_chromium", "PdfError", "CANDIDATES", "TIMEOUT"]

#: the command names tried on ``PATH``, in order, when ``$ASSUR_CHROMIUM`` is not set
CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")

#: seconds Chromium may take to print one report (a full crank turn's report, about
#: 2 MB with every row of its tables, prints in a few seconds)
TIMEOUT = 120.0

#: the characters of Chromium's standard error quoted in a :class:`PdfError`
_STDERR_TAIL = 2000

_INSTALL = ("install Chromium (Debian/Ubuntu: `apt-get install chromium`) or set "
            "ASSUR_CHROMIUM to the path of a Chromium or Google Chrome executable; "
            "`--format html` writes the report without it, and any browser prints "
            "that file to PDF")


class PdfError(RuntimeError):
    """The PDF could not be made: no Chromium found, Chromium failed or timed out.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur.views.report.pdf import PdfError, write_pdf
    >>> with tempfile.TemporaryDirectory() as d:
    ...     html = Path(d) / "report.html"
    ...     _ = html.write_text("<!DOCTYPE html><p>One page.</p>")
    ...     try:
    ...         write_pdf(html, Path(d) / "report.pdf", chromium=Path(d) / "no-browser")
    ...     except PdfError as e:
    ...         error = e
    >>> isinstance(error, RuntimeError), "apt-get install chromium" in str(error)
    (True, True)
    """


def find_chromium() -> str:
    """The Chromium executable that prints the PDF.

    Returns
    -------
    str
        Absolute path of ``$ASSUR_CHROMIUM`` when set (a path, or a command name
        looked up on ``PATH``), else of the first of :data:`CANDIDATES` on ``PATH``.

    Raises
    ------
    PdfError
        When ``$ASSUR_CHROMIUM`` names no executable, or none of the candidates is
        on ``PATH``; the message says what to install.

    Examples
    --------
    >>> from assur.views.report.pdf import find_chromium
    >>> find_chromium().endswith(("chromium", "chromium-browser", "chrome",
    ...                           "google-chrome", "google-chrome-stable"))
    True
    """
    env = os.environ.get("ASSUR_CHROMIUM")
    if env:
        found = shutil.which(env)
        if found is None:
            raise PdfError(f"ASSUR_CHROMIUM={env!r} is not an executable: {_INSTALL}")
        return os.path.abspath(found)
    for name in CANDIDATES:
        found = shutil.which(name)
        if found is not None:
            return os.path.abspath(found)
    raise PdfError(f"no Chromium found to print the PDF (looked for "
                   f"{', '.join(CANDIDATES)} on PATH; ASSUR_CHROMIUM is not set): {_INSTALL}")


def write_pdf(html_path, pdf_path, chromium=None, timeout=TIMEOUT, tagged=False) -> Path:
    """Print an HTML report to a PDF file with headless Chromium.

    Parameters
    ----------
    html_path : str or Path
        The report to print (``report.html`` of :func:`assur.views.report.html.write_html`;
        any HTML file). Its A4 page size and margins come from its own ``@page`` rules;
        Chromium's header and footer (date, file address, page numbers) are left out.
    pdf_path : str or Path
        The ``.pdf`` file to write (replaced if present; its directory must exist). It
        is written only when Chromium succeeded: a failure leaves no partial file.
    chromium : str or Path, optional
        The browser's executable; default :func:`find_chromium`.
    timeout : float
        Seconds to wait for Chromium [s]; then it is stopped (with the processes it
        started) and :class:`PdfError` is raised.
    tagged : bool
        A tagged PDF (its structure for screen readers, and a bookmark per heading)
        instead of a plain one. Every table cell is then an element of the file: a
        full crank turn's report (``cleaning_lab3``, 115 pages) takes 19.8 MB and
        25 s instead of 1.2 MB and 12 s.

    Returns
    -------
    Path
        ``pdf_path``.

    Raises
    ------
    FileNotFoundError
        When ``html_path`` does not exist.
    PdfError
        When no Chromium is found (the message says what to install), Chromium exits
        with an error (the message ends with its standard error), times out, or
        writes no PDF.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur.views.report.pdf import write_pdf
    >>> with tempfile.TemporaryDirectory() as d:
    ...     html = Path(d) / "report.html"
    ...     _ = html.write_text("<!DOCTYPE html><title>t</title><p>One page.</p>")
    ...     pdf = write_pdf(html, Path(d) / "report.pdf")  # needs Chromium
    ...     head = pdf.read_bytes()[:5]
    >>> pdf.name, head
    ('report.pdf', b'%PDF-')
    """
    html_path = Path(html_path).resolve()
    pdf_path = Path(pdf_path)
    if not html_path.is_file():
        raise FileNotFoundError(f"{html_path}: no such HTML file to print")
    exe = str(chromium) if chromium is not None else find_chromium()
    with tempfile.TemporaryDirectory(prefix="assur-pdf-") as tmp:
        out = Path(tmp) / "report.pdf"
        cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
               "--no-default-browser-check", "--disable-extensions",
               # a profile of its own: never the user's, never handed to a running browser
               f"--user-data-dir={Path(tmp) / 'profile'}",
               "--no-pdf-header-footer", "--print-to-pdf-no-header",  # new and old name
               *(["--generate-pdf-document-outline"] if tagged else ["--disable-pdf-tagging"]),
               f"--print-to-pdf={out}", html_path.as_uri()]
        try:
            proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                    stderr=subprocess.PIPE, start_new_session=os.name == "posix")
        except OSError as e:
            raise PdfError(f"cannot start {exe}: {e.strerror or e}; {_INSTALL}") from e
        try:
            _, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            _stop(proc)
            raise PdfError(f"{exe} did not print {html_path.name} within {timeout:g} s "
                           f"(stopped); try a larger timeout") from None
        tail = err.decode("utf-8", "replace").strip()[-_STDERR_TAIL:]
        if proc.returncode != 0:
            raise PdfError(f"{exe} failed to print {html_path.name} (exit code "
                           f"{proc.returncode}); its standard error ends with:\n{tail}")
        if not out.is_file() or out.read_bytes()[:5] != b"%PDF-":
            raise PdfError(f"{exe} exited without writing a PDF of {html_path.name}; its "
                           f"standard error ends with:\n{tail}")
        shutil.move(str(out), pdf_path)
    return pdf_path


def _stop(proc):
    """Stop Chromium and every process it started (its own session), then reap it."""
    try:
        if os.name == "posix":
            os.killpg(proc.pid, signal.SIGKILL)
        else:
            proc.kill()
    except (ProcessLookupError, PermissionError):
        pass
    try:
        proc.communicate(timeout=10)
    except subprocess.TimeoutExpired:  # a process that left the session holds the pipes
        pass
