"""The test suite of assur: ``tests/<package>/test_<module>.py`` mirrors ``src/assur``
(``tests/test_layout.py`` keeps it so); whole machines against their seeds are in
``tests/seeds/``, cross-cutting checks in ``tests/docs/`` and ``tests/robustness/``,
shared code in ``tests/helpers/``, shared fixtures in ``tests/conftest.py``."""
