"""What the user sees (docs/architecture.md): reports (:mod:`~assur.views.report`),
the notebook display (:mod:`~assur.views.notebook`), the interactive page
(:mod:`~assur.views.page`) and the command line (:mod:`~assur.views.cli`). Views
read results; nothing below imports them (the notebook's ``_repr_html_`` hooks are
the named exceptions of the import contracts in ``pyproject.toml``)."""
