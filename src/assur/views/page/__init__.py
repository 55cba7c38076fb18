"""The interactive page (``assur serve``), inline displays and DXF drawings.

Views of a model and its analysis for people who work in a browser, a notebook
or a CAD system (DESIGN.md §6: nothing here computes the mechanism):

* :mod:`assur.views.page.server` — the FastAPI application behind ``assur serve``: the
  page, its JSON API (:mod:`assur.views.page.api`, bounded pydantic requests) and the
  downloads (tables as CSV/XLSX, the edited model file, the drawing as DXF);
* :mod:`assur.views.page.session` — one model file being edited: its parameters by
  group with units, the edited TOML text, the analysis as the page's payload;
* :mod:`assur.views.geometry` — the mechanism's drawing as plain data (points,
  bodies, joints over the positions), shared by the page, the SVG and the DXF;
* :mod:`assur.views.svg` — the drawing as inline SVG (no matplotlib);
* :mod:`assur.views.page.dxf` — the drawing at chosen positions as DXF (ezdxf).

Importing this package imports none of FastAPI, uvicorn or ezdxf; the server
and the DXF writer import them when used.
"""
