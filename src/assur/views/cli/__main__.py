"""``python -m assur.views.cli …`` runs the ``assur`` command line."""

import sys

from . import main

sys.exit(main())
