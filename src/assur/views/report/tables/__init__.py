"""The seed worksheets' tables as data, and their CSV and XLSX files.

:func:`seed_tables` turns an :class:`~assur.analysis.Analysis` into the tables a
seed worksheet prints (seed 003: 2.1, 2.2, 3.1, 4.1, 5.1, 6.1 and the check
through the instantaneous centre). Only tables whose data exist are made: a
mechanism without cylinders has no 4.1, without loads no 5.1, without machine
data no 6.1.

Column symbols
--------------
One scheme for every mechanism; for seed 003 it gives the seed's own symbols
except where noted. ``<c>`` is a generalized coordinate, ``<p>`` a point, ``<l>``
a link, ``<i><j>`` a pair of links:

==================  ========  ====================================================
symbol              unit      meaning
==================  ========  ====================================================
``<c>``             m or deg  the generalized coordinate (seed ``S``); crank angles
                              are printed in degrees
``phi<l>``          deg       angle of link l from +x, CCW (seed ``φ3(S)/deg``)
``X<p>``, ``Y<p>``  m         point coordinates (seed ``X23(S)``)
``<d>``             m         a named distance (seed 002 ``l7``, ``l9``); its
                              angle, when named, is a link (``phi7``)
``d<d>``            m/rad, \\-  its analog
``closure``         m         largest closure residual of all groups (assur's
                              check; replaces the seed's ``X23s``… columns)
``U<i><j>``         \\-        transfer ratio φ_i'/φ_j' (seed ``U43``)
``I<p>``            \\-        transmission number dY/dq of point p (seed ``I56``)
``dphi<l>``         rad/m     angular-velocity analog dφ_l/dq (seed ``dφ3``; its
                              ``φ41…φ71`` are ``dphi4…dphi7``)
``F_<c>``           N         cylinder force by virtual work (seed ``Fgc``); in
                              table 5.1 the same force from the reactions
``p_<c>``           Pa        cylinder pressure (seed ``Pgc``)
``G<p>``            N         lift capacity at point p (seed ``G56``, ``GS6``)
``dG<p>``           %         capacity reserve against the weight at p (seed
                              ``ΔGS65``)
``R<ij>x/y``, R…    N         reaction: force of link i on link j and its
                              magnitude; the seed's name when the model gives
                              one (``tables["reactions"]``)
``M<ij>``            N·m       moment of i on j at a driven crank's pivot or a
                              prismatic pair (only where not zero)
``R<axle>``         N         axle reaction (seed ``Ra``, ``Rb``)
``dR<axle>``        %         axle share of the total weight (seed ``ΔRa``)
``G_max``           N         largest implement weight under the 20 % rule
``<name>``          its unit  an extra formula of the model (``tables["formulas"]``,
                              e.g. seed 003's printed ``GS6max``, flagged), in the
                              table it names
``Xp``, ``Yp``      m         instantaneous centre of the checked link
``I<p>_ic``         \\-        φ'·(X<p> − Xp): I<p> through the instantaneous
                              centre (seed ``Imp``, ``lsp``)
==================  ========  ====================================================

Conventions (``tables["angles"]``, ``tables["analogs"]`` of the model, or the
arguments of :func:`seed_tables`): angle columns are continuous along the positions
(default) or wrapped to [0°, 360°) as the seeds print them; analogs with respect to
a crank angle are per the coordinate (default) or along the crank's direction of
rotation, d/dφ1 · sign φ1' (its :class:`assur.core.motion.Motion`; the seeds turn
clockwise and write φ1' = −1). Each table notes the convention in force.

With k > 1 coordinates every analog symbol gets the suffix ``_<c>`` (``dphi3_S1``);
with several cylinders ``G<p>`` and ``dG<p>`` get it too. A quantity along a
coordinate that does not move its point or turn its link (:mod:`assur.core.chains`) has
no column; the table's note says so. Over a full grid of two coordinates table
``G`` holds each capacity of 4.1 as its map: a row per value of the first
coordinate, a column ``G<p>_<c>@<c2>=<value>`` per value of the second. Analogs with respect to
a crank angle are in rad/rad (unit ``-``) and transmission numbers in m/rad.

Sign convention of reactions: ``R<ij>`` is the force of link i on link j (the
frame is link 0). Where the model's sign map says its source prints a column with
the opposite sign (``tables["signs"]``, :class:`assur.core.columns.SignMap`; seed 003
R05, R34, R45) the column carries ``printed_sign = -1`` and the table the model's
note; the numbers are assur's.

Files: :func:`write_csv` writes a header ``symbol [unit]`` per column and every
number with ``repr`` (a float read back is the same float); :func:`write_xlsx`
a workbook for people: a sheet of the inputs, then a sheet per table named by its
id and title (:func:`sheet_name`) with the title, the symbols (bold) and units
above the same numbers stored as floats with a display format per column
(:func:`number_format`; an empty cell where a value is NaN or infinite, which
Excel cannot hold), the table's notes below, the headers frozen.

Modules, by concern: the data (:class:`Column`, :class:`Table`; ``_data``), one
design of the analysis read in the tables' conventions (``_view``), the tables of
the kinematics (2.1, 2.2, 3.1, IC; ``_kinematics``), of the forces (4.1, G, 5.1,
5.2; ``_forces``) and of the machine (D, 6.1, L; ``_machines``), their assembly in
the seed's order (:func:`seed_tables`; ``_assemble``) and the files (``_files``).
"""

from __future__ import annotations

from ....core.columns import TABLE_IDS
from ._assemble import FORMULAS_ID, NUMBERINGS, numbered, seed_tables
from ._data import Column, Table, grid_of, in_units, wrap_degrees
from ._files import CSV_DIALECTS, TABLE_CONTENTS, number_format, sheet_name, table_filename, write_csv, \
    write_frame_csv, write_xlsx
# the report's figures and drawing read an analysis as the tables do
from ._forces import _capacity
from ._view import ANALOG_CONVENTIONS, ANGLE_CONVENTIONS, _View

__all__ = ["Column", "Table", "seed_tables", "numbered", "NUMBERINGS", "write_csv", "write_frame_csv", "write_xlsx", "table_filename", "TABLE_CONTENTS", "CSV_DIALECTS",
           "sheet_name", "number_format", "in_units",
           "TABLE_IDS", "grid_of"]
