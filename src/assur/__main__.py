"""``python -m assur …`` is the ``assur`` command (see :mod:`assur.views.cli`)."""

from .views.cli import app

if __name__ == "__main__":
    app(prog_name="assur")
