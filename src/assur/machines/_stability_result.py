"""The result of the stability check: axle reactions, shares and the limits over
positions and designs (:mod:`assur.machines.stability`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["StabilityResult"]


@dataclass(frozen=True)
class StabilityResult:
    """Axle reactions and steerability over positions (and designs).

    Every array has the broadcast shape of ``implement_weight`` and ``implement_x``
    passed to :func:`axle_reactions`.

    Attributes
    ----------
    reactions : dict of str to ndarray
        Upward reaction of each axle [N], in the machine's axle order.
    shares : dict of str to ndarray
        Each axle's share of the total weight, ``100·R/ΣP`` [%] (seed 003 ΔR_A, ΔR_B).
    steered : str
        Name of the steered axle.
    min_share : float
        The rule's minimum share of the steered axle [-].
    total_weight : ndarray
        Machine, counterweights and implement [N].
    steered_share : ndarray
        ``shares[steered]`` [%].
    steerable : ndarray of bool
        ``R_steered ≥ min_share·total_weight``.
    max_implement_weight : ndarray
        Largest implement weight at this ``x`` that keeps the rule, with the
        counterweights [N]; ``np.inf`` when there is no upper limit, 0 when no
        weight satisfies the rule (see the module notes).
    max_implement_weight_without_counterweights : ndarray
        The same limit with the counterweights removed [N].

    Examples
    --------
    >>> from assur import examples
    >>> st = examples.hitch_003().analyze([0.42, 0.67]).stability
    >>> [round(float(v)) for v in st.reactions["B"]]      # Rb, seed 003 table 6.1 [N]
    [69739, 67513]
    >>> [round(float(v), 1) for v in st.steered_share]    # ΔRa, table 6.1 [%]
    [23.8, 26.2]
    >>> st.steered, st.steerable.tolist()
    ('A', [True, True])
    """

    reactions: dict[str, np.ndarray]
    shares: dict[str, np.ndarray]
    steered: str
    min_share: float
    total_weight: np.ndarray
    steered_share: np.ndarray
    steerable: np.ndarray
    max_implement_weight: np.ndarray
    max_implement_weight_without_counterweights: np.ndarray

    def _pick(self, table: dict, name: str) -> np.ndarray:
        if name not in table:
            raise ValueError(f"axle must be one of: {list(table)}; got {name!r}")
        return table[name]

    def reaction(self, axle: str) -> np.ndarray:
        """Reaction of ``axle`` [N].

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).stability
        >>> [round(float(v)) for v in st.reaction("A")]   # Ra, seed 003 table 6.1 [N]
        [21761, 23987]
        >>> st.reaction("C")
        Traceback (most recent call last):
        ...
        ValueError: axle must be one of: ['A', 'B']; got 'C'
        """
        return self._pick(self.reactions, axle)

    def share(self, axle: str) -> np.ndarray:
        """Share of the total weight on ``axle`` [%].

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).stability
        >>> [round(float(v), 1) for v in st.share("B")]   # ΔRb, seed 003 table 6.1 [%]
        [76.2, 73.8]
        """
        return self._pick(self.shares, axle)

    def to_frame(self, index: ArrayLike | None = None, index_name: str = "S"):
        """Seed-like table (seed 003, table 6.1) as a pandas DataFrame.

        Parameters
        ----------
        index : array_like, shape (n,), optional
            Row labels, e.g. the generalized coordinate S [m]. Default 0…n−1.
        index_name : str, optional
            Name of the index column. Default ``"S"``.

        Returns
        -------
        pandas.DataFrame
            Columns ``R<axle>`` [N], ``dR<axle>`` [%] per axle, ``G_max`` and
            ``G_max_no_cw`` [N], ``steerable``. Axle names are lower-cased as in the
            seed (axles "A", "B" give ``Ra``, ``dRa``, ``Rb``, ``dRb``) unless two
            names differ only in case, then they are kept as given.

        Raises
        ------
        ValueError
            If the result has more than one axis (select one design first) or
            ``index`` has the wrong length.

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).stability
        >>> df = st.to_frame(index=[0.42, 0.67])    # S [m]
        >>> list(df.columns)
        ['Ra', 'Rb', 'dRa', 'dRb', 'G_max', 'G_max_no_cw', 'steerable']
        >>> row = df.loc[0.67]
        >>> round(float(row["Ra"])), round(float(row["dRa"]), 1)   # table 6.1 [N], [%]
        (23987, 26.2)
        """
        import pandas as pd

        shape = self.total_weight.shape
        if len(shape) > 1:
            raise ValueError(f"to_frame needs a result over one axis (positions); this one "
                             f"has shape {shape}: compute it for one design at a time")
        names = list(self.reactions)
        lower = [n.lower() for n in names]
        labels = lower if len(set(lower)) == len(lower) else names
        cols = {}
        for n, lab in zip(names, labels):
            cols[f"R{lab}"] = np.atleast_1d(self.reactions[n])
        for n, lab in zip(names, labels):
            cols[f"dR{lab}"] = np.atleast_1d(self.shares[n])
        cols["G_max"] = np.atleast_1d(self.max_implement_weight)
        cols["G_max_no_cw"] = np.atleast_1d(self.max_implement_weight_without_counterweights)
        cols["steerable"] = np.atleast_1d(self.steerable)
        n = len(cols["G_max"])
        if index is not None:
            index = np.atleast_1d(np.asarray(index))
            if index.shape != (n,):
                raise ValueError(f"index must have shape ({n},), got {index.shape}")
            index = pd.Index(index, name=index_name)
        return pd.DataFrame(cols, index=index)


def _stack_results(rows):
    """One StabilityResult from per-design results (arrays stacked over designs)."""
    import dataclasses
    first = rows[0]
    kw = {}
    for f in dataclasses.fields(first):
        vals = [getattr(r, f.name) for r in rows]
        if isinstance(vals[0], dict):
            kw[f.name] = {k: np.stack([np.asarray(v[k]) for v in vals]) for k in vals[0]}
        elif isinstance(vals[0], np.ndarray):
            kw[f.name] = np.stack(vals)
        else:
            kw[f.name] = vals[0]
    return dataclasses.replace(first, **kw)
