"""Where the equations of motion admit several modes at once (non-uniqueness).

Below the centre of mass (k' < 0) the report's regions overlap (Section IV.7):
for mu > mu_B' = (4+g^2)/(3g), (4.49), the slide-rock about O equations have a
second branch ((4.69)-(4.70), (4.80)-(4.81)) and the rigid-body equations with
Coulomb friction admit more than one motion at the same (k, mu) - the
non-uniqueness known as Painleve's paradox.  Section 4.7 keeps one mode (see
:data:`regimemap.mechanics.modes.PRIORITY`): slide inside the slide region, slide-rock
about O' below the line DC.  The independent solver (:mod:`regimemap.mechanics.solver`)
confirms the overlaps: with parameters tried so far the admissible sets are
{SL, RO, SRO-} (chosen: SL) and {RO, SRO-, SRO'-} (chosen: SRO'-).

This module finds those parts of the map exactly, from the per-column
intervals of the raw regions (:func:`regimemap.maps.geometry.raw_intervals`, whose
predicates equal the solver's admissibility away from boundaries): along each
vertical line k = const every raw region is one interval of mu, so the column
is cut at every interval end and each piece is covered by a known set of
modes.  Pieces covered by two or more modes (with positive length) are the
ambiguous parts; they are joined across columns into polygons whose vertices
lie on the boundary curves.  Boundaries themselves (where the modes of both
sides are admissible, a set of zero area) are not ambiguity.  Nothing here
imports matplotlib.

With loads the intervals are those of every hypothesis
(:func:`regimemap.mechanics.regions.column_intervals`), the sets may hold RO',
SRO'+ and lift-off (e.g. {LO, RO, SRO-} where the block lifts off while rocking
would also be consistent), and the mode chosen is Gauss's least constraint,
the first of the set in :data:`~regimemap.mechanics.modes.SELECTION_ORDER`:
labels read ``{LO, RO, SRO-} -> LO (least constraint)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.modes import MAP_MODES, PRIORITY, SELECTION_ORDER, Mode
from ..mechanics.regions import column_intervals
from .bisection import bisect_edge
from .geometry import DEFAULT_SAMPLES, extend_run, raw_intervals, run_outline, sample_k

__all__ = [
    "AmbiguousRegion",
    "ambiguous_in_view",
    "ambiguous_regions",
    "column_pieces",
    "admissible_set",
    "set_label",
    "RULE_LEAST_CONSTRAINT",
    "RULE_SECTION_4_7",
]

_MODES: tuple[Mode, ...] = tuple(m for m in PRIORITY if m in MAP_MODES)


#: How the chosen mode of a set is decided: Section 4.7 on the report's block, Gauss's
#: least constraint with loads (the same choice wherever both apply).
RULE_SECTION_4_7 = "Section 4.7"
RULE_LEAST_CONSTRAINT = "least constraint"


def set_label(modes: tuple[Mode, ...], chosen: Mode, tex: bool = False,
              rule: str = RULE_SECTION_4_7) -> str:
    """``"{SL, RO, SRO-} -> SL (Section 4.7)"``, or its mathtext form for figures."""
    if tex:
        body = ", ".join(m.tex.strip("$") for m in modes)
        short = "§4.7" if rule == RULE_SECTION_4_7 else rule
        return rf"$\{{{body}\}}$" + "\n" + rf"$\rightarrow {chosen.tex.strip('$')}$ ({short})"
    return "{" + ", ".join(m.label for m in modes) + "} -> " + chosen.label + f" ({rule})"


@dataclass(frozen=True)
class AmbiguousRegion:
    """One connected part of the map where several modes are admissible.

    Attributes
    ----------
    modes : tuple of Mode
        The admissible set, in code order (RE, SL, RO, SRO-, SRO+, SRO'-) on the
        report's block, in :data:`~regimemap.mechanics.modes.SELECTION_ORDER` with loads.
    chosen : Mode
        The mode Section 4.7 (least constraint with loads; :func:`regimemap.classify`)
        gives these points.
    polygon : ndarray, shape (n, 2)
        Closed polygon of (k, mu) vertices: the lower edge left to right, then
        the upper edge right to left.
    k, lo, hi : ndarray
        The columns the polygon was built from: at each k the part spans
        lo <= mu <= hi.
    """

    modes: tuple[Mode, ...]
    chosen: Mode
    polygon: np.ndarray
    k: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    rule: str = RULE_SECTION_4_7

    @property
    def label(self) -> str:
        """Plain-text label, e.g. ``{SL, RO, SRO-} -> SL (Section 4.7)``."""
        return set_label(self.modes, self.chosen, rule=self.rule)

    @property
    def tex(self) -> str:
        """Mathtext label for figures, on two lines (the set, then "-> chosen (§4.7)")."""
        return set_label(self.modes, self.chosen, tex=True, rule=self.rule)

    def area(self) -> float:
        """Area of the polygon (shoelace formula)."""
        x, y = self.polygon[:, 0], self.polygon[:, 1]
        return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))

    def anchor(self, k_max: float = np.inf, mu_max: float = np.inf) -> tuple[float, float] | None:
        """A point well inside the part and inside the view [0, k_max] x [0, mu_max].

        The middle of the widest column (after clipping to the view); None if
        no column of the part is in the view.
        """
        inview = self.k <= k_max
        lo = self.lo
        hi = np.minimum(self.hi, mu_max)
        w = np.where(inview, hi - lo, -np.inf)
        if w.size == 0 or not np.isfinite(w).any() or w.max() <= 0.0:
            return None
        # prefer columns away from the ends of the part (a more central label)
        centrality = np.minimum(np.abs(self.k - self.k[0]), np.abs(self.k[-1] - self.k)) ** 0.5
        score = np.where(w > 0.0, np.where(w > 0.0, w, 0.0) * centrality, -np.inf)
        i = int(np.argmax(score)) if np.isfinite(score).any() and score.max() > 0 else int(np.argmax(w))
        return float(self.k[i]), float(0.5 * (lo[i] + hi[i]))

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: labels, the chosen mode and the polygon as [[k, mu], ...]."""
        return {
            "modes": [m.label for m in self.modes],
            "chosen": self.chosen.label,
            "label": self.label,
            "polygon": self.polygon.tolist(),
        }


def _mask_modes(mask: int, loaded: bool = False) -> tuple[Mode, ...]:
    """The modes of a bit mask, in code order (RE, SL, RO, SRO-, SRO+, SRO'-); with loads
    in :data:`SELECTION_ORDER`."""
    return tuple(m for m in (SELECTION_ORDER if loaded else MAP_MODES) if mask >> int(m) & 1)


def _intervals(p: Parameters, k: np.ndarray, mu_cap: float) -> list[tuple[Mode, np.ndarray, np.ndarray]]:
    """Every raw interval of every mode per column, clipped to [0, mu_cap] (empty: lo == hi)."""
    if not p.loaded:
        return [(m, *raw_intervals(m, p, k, mu_cap)) for m in _MODES]
    out = []
    for m, lo, hi in column_intervals(k, p.constants):
        lo_c = np.clip(lo, 0.0, mu_cap)
        out.append((m, lo_c, np.maximum(np.clip(hi, 0.0, mu_cap), lo_c)))
    return out


def column_pieces(p: Parameters, k: np.ndarray, mu_cap: float
                  ) -> list[list[tuple[int, float, float]]]:
    """Cut each column at every raw-interval end; return its ambiguous pieces.

    Parameters
    ----------
    p : Parameters
    k : ndarray, 1-D
        Columns.
    mu_cap : float
        Top of the columns (intervals are clipped to [0, mu_cap]).

    Returns
    -------
    list (one per column) of lists of ``(mask, lo, hi)``
        ``mask`` has bit ``int(mode)`` set for each admissible mode; only
        pieces of positive length covered by two or more modes are listed,
        from the bottom up; adjacent pieces with the same set are merged.
    """
    k = np.asarray(k, dtype=np.float64)
    ivs = _intervals(p, k, mu_cap)
    ends = [np.zeros_like(k), np.full_like(k, mu_cap)]
    for _, lo, hi in ivs:
        ends += [lo, hi]
    E = np.sort(np.stack(ends, axis=1), axis=1)  # (n, 2 + 2*intervals)
    a, b = E[:, :-1], E[:, 1:]
    mid = 0.5 * (a + b)
    mask = np.zeros(mid.shape, dtype=np.int64)
    for m, lo, hi in ivs:
        inside = (hi[:, None] > lo[:, None]) & (lo[:, None] <= mid) & (mid <= hi[:, None])
        mask |= inside.astype(np.int64) << int(m)
    positive = b > a
    pop = np.zeros(mask.shape, dtype=np.int64)
    for m in Mode:
        pop += (mask >> int(m)) & 1
    multi = positive & (pop >= 2)
    out: list[list[tuple[int, float, float]]] = []
    for j in range(k.size):
        pieces: list[tuple[int, float, float]] = []
        for s in np.flatnonzero(multi[j]):
            m_, lo_, hi_ = int(mask[j, s]), float(a[j, s]), float(b[j, s])
            if pieces and pieces[-1][0] == m_ and pieces[-1][2] == lo_:
                pieces[-1] = (m_, pieces[-1][1], hi_)
            else:
                pieces.append((m_, lo_, hi_))
        out.append(pieces)
    return out


def admissible_set(p: Parameters, k: float, mu: float) -> tuple[Mode, ...]:
    """The modes whose raw region contains (k, mu) (exact, from the column intervals).

    Equal to the solver's admissible set off the boundaries.
    """
    mu_cap = max(2.0 * mu, 1.0)
    ivs = _intervals(p, np.array([float(k)]), mu_cap)
    found = {m for m, lo, hi in ivs if hi[0] > lo[0] and lo[0] <= mu <= hi[0]}
    return tuple(m for m in (SELECTION_ORDER if p.loaded else _MODES) if m in found)


def _extra_breaks(p: Parameters) -> list[float]:
    """Abscissae where an edge of an ambiguous part may have a corner (besides breakpoints)."""
    mb = p.mu_Bprime
    out = [mb]  # OA meets mu = mu_B'
    c = p.constants
    den = c.aO - mb * c.cO
    if den != 0.0:
        out.append((mb * c.dO - c.bO) / den)  # mu* meets mu = mu_B'
    if p.kprime != 0.0:
        out.append((-1.0 / p.gamma - mb) / p.kprime)  # DC meets mu = mu_B'
        # DC meets OA (mu = k): k = -1/g - k k'
        if 1.0 + p.kprime != 0.0:
            out.append((-1.0 / p.gamma) / (1.0 + p.kprime))
    return [float(x) for x in out if np.isfinite(x) and x >= 0.0]


def _pieces_at(p: Parameters, k: float, mu_cap: float) -> list[tuple[int, float, float]]:
    return column_pieces(p, np.array([k]), mu_cap)[0]


def _refine(p: Parameters, mask: int, track: int, k_in: float, k_out: float, mu_cap: float
            ) -> float:
    """Bisect between a column holding the part (k_in) and one without (k_out)."""
    def has(kk: float) -> bool:
        return sum(1 for m, _, _ in _pieces_at(p, kk, mu_cap) if m == mask) > track

    return bisect_edge(has, k_in, k_out)


def _end(p: Parameters, mask: int, track: int, k_in: float, k_out: float, mu_cap: float
         ) -> tuple[float, float, float] | None:
    """The column ``(k, lo, hi)`` where the part's run ends between k_in (in it) and k_out; None
    when the end is k_in itself or the part has no piece there."""
    ke = _refine(p, mask, track, k_in, k_out, mu_cap)
    if ke == k_in:
        return None
    pieces = [pc for pc in _pieces_at(p, ke, mu_cap) if pc[0] == mask]
    return (ke, pieces[track][1], pieces[track][2]) if len(pieces) > track else None


def ambiguous_regions(p: Parameters, k_max: float, mu_max: float,
                      samples: int = DEFAULT_SAMPLES) -> list[AmbiguousRegion]:
    """The parts of [0, k_max] x [0, mu_max] where several modes are admissible.

    Parameters
    ----------
    p : Parameters
    k_max, mu_max : float
        The view.  Polygons are clipped to it (mu to [0, mu_max], k to
        [0, k_max]); pass a larger extent and clip when drawing if the edges
        of the view should not appear as edges of a part.
    samples : int
        Columns on [0, k_max] (the abscissae of every corner are added, and
        the ends of each part are located by bisection).

    Returns
    -------
    list of AmbiguousRegion
        Sorted by the chosen mode (in :data:`PRIORITY` order, lift-off first),
        the set, then k; empty above C (k' >= 0) on the report's block, where
        the regions do not overlap.

    Examples
    --------
    >>> from regimemap.mechanics.block import Parameters
    >>> [r.label for r in ambiguous_regions(Parameters(3.0, -0.6), 4.0, 3.0)]
    ['{SL, RO, SRO-} -> SL (Section 4.7)']
    >>> ambiguous_regions(Parameters(3.0, 0.4), 4.0, 3.0)
    []
    >>> q = Parameters(1.5, 0.0, uplift=0.4, uplift_ratio=0.5, uplift_arm=0.0)
    >>> sorted({r.label for r in ambiguous_regions(q, 4.0, 3.0)})[0]
    '{LO, RO, SRO-} -> LO (least constraint)'
    """
    if not (np.isfinite(k_max) and np.isfinite(mu_max)) or k_max <= 0 or mu_max <= 0:
        raise ValueError(f"k_max and mu_max must be finite numbers > 0, got {k_max!r}, {mu_max!r}")
    k = sample_k(p, float(k_max), int(samples), _extra_breaks(p))
    cols = column_pieces(p, k, float(mu_max))
    # tracks: (mask, t) -> per-column (lo, hi) or NaN
    tracks: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
    for j, pieces in enumerate(cols):
        seen: dict[int, int] = {}
        for m_, lo_, hi_ in pieces:
            t = seen.get(m_, 0)
            seen[m_] = t + 1
            if (m_, t) not in tracks:
                tracks[(m_, t)] = (np.full(k.size, np.nan), np.full(k.size, np.nan))
            tracks[(m_, t)][0][j] = lo_
            tracks[(m_, t)][1][j] = hi_
    out: list[AmbiguousRegion] = []
    for (mask, t), (lo, hi) in tracks.items():
        present = np.isfinite(lo)
        idx = np.flatnonzero(present)
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
        modes = _mask_modes(mask, p.loaded)
        chosen = next(m for m in SELECTION_ORDER if m in modes)
        rule = RULE_LEAST_CONSTRAINT if p.loaded else RULE_SECTION_4_7
        for run in runs:
            i0, i1 = run[0], run[-1]
            front = _end(p, mask, t, k[i0], k[i0 - 1], float(mu_max)) if i0 > 0 else None
            back = _end(p, mask, t, k[i1], k[i1 + 1], float(mu_max)) if i1 < k.size - 1 else None
            kk, ll, hh = extend_run(k[run], lo[run], hi[run], front, back)
            if kk[-1] - kk[0] <= 1e-12 * max(1.0, float(k_max)):
                # a single column, e.g. k = k_A where the RE and RO regions share
                # their boundary: a line, not an area
                continue
            out.append(AmbiguousRegion(modes, chosen, run_outline(kk, ll, hh), kk, ll, hh, rule))
    order = {m: i for i, m in enumerate(SELECTION_ORDER)}
    out.sort(key=lambda r: (order[r.chosen], tuple(int(m) for m in r.modes), float(r.k[0])))
    return out


def ambiguous_in_view(p: Parameters, k_max: float, mu_max: float,
                      samples: int = DEFAULT_SAMPLES) -> list[AmbiguousRegion]:
    """The parts where several modes are admissible that a drawing of [0, k_max] x [0, mu_max] shows.

    :func:`ambiguous_regions` of a view 2 % larger (clipped by the axes, so that the
    edges of the view are not drawn as edges of a part), less the parts with no
    anchor for their label in the view (:meth:`AmbiguousRegion.anchor`).
    """
    regions = ambiguous_regions(p, k_max * 1.02, mu_max * 1.02, samples=samples)
    return [r for r in regions if r.anchor(k_max, mu_max) is not None]
