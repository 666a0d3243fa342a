"""The designer's view of a map: the band of real friction coefficients (no matplotlib).

The report's view (:func:`regimemap.maps.view.auto_extent`) keeps every
characteristic point in sight; near k' = -1 that puts A at (100, 100) and the
friction coefficients of real contacts (mu < 1) in a speck at the origin.
:func:`designer_extent` shows ``0 <= mu <= 1.2`` instead, and k far enough to
the right to show every boundary that crosses that band; :func:`points_off_view`
names the characteristic points left outside, which a drawing marks at the
frame's edge.  :func:`view_extent` chooses between the two views by name.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.curves import NamedPoint, named_points
from ..mechanics.modes import Mode
from ..mechanics.regions import raw_region
from .classify import label_grid
from .view import auto_extent, nice_ceil

__all__ = ["DESIGN_MU", "VIEWS", "designer_extent", "points_off_view", "view_extent"]

#: Top of the designer's view: friction coefficients of real contacts (concrete on
#: rubble ~0.6, steel on steel ~0.8, rubber ~1) with a margin.
DESIGN_MU = 1.2
#: The names of the views: ``designer`` (the default of ``plot``, the atlas, the
#: animation and ``export``) and ``report`` (every characteristic point in sight).
VIEWS: tuple[str, ...] = ("designer", "report")
#: Farthest a boundary crossing is followed, in multiples of the band's height
#: (k' near 0 sends D, where DC meets the k axis, off to infinity).
_REACH = 10.0
#: Margin right of the last boundary crossing (fraction of it).
_MARGIN = 0.15


def _pattern_changes(codes: np.ndarray) -> np.ndarray:
    """Where the sequence of modes met going up a column differs from the next column's.

    ``codes`` is a (mu, k) grid; returns a bool per pair of neighbouring columns.
    """
    n_mu, n_k = codes.shape
    change = np.ones(codes.shape, dtype=bool)
    change[1:] = codes[1:] != codes[:-1]
    # the runs' modes packed at the top of each column, padded with -1
    order = np.argsort(~change, axis=0, kind="stable")
    packed = np.take_along_axis(np.where(change, codes, -1), order, axis=0)
    return np.asarray((packed[:, 1:] != packed[:, :-1]).any(axis=0))


def _last_change(params: Parameters, mu_top: float, k_far: float,
                 raw_mode: Mode | None) -> float:
    """The largest k <= k_far at which a boundary enters or leaves the band [0, mu_top].

    Along each column k the band holds a sequence of modes from mu = 0 up; a
    line that only moves inside the band keeps the sequence, one that crosses
    the band's bottom or top (or a vertical line) changes it.  Columns are
    spaced geometrically (0.5 % apart) from 1e-6 mu_top to k_far.
    """
    p = params
    k = np.geomspace(1e-6 * mu_top, k_far, 3000)
    mu = np.linspace(0.0, mu_top, 241)[1:]
    codes = label_grid(k, mu, p.gamma, p.kprime, **p.loads).astype(np.int64)
    if raw_mode is not None:
        kk, mm = np.meshgrid(k, mu)
        codes = codes * 2 + raw_region(raw_mode, p, kk, mm).astype(np.int64)
    moved = np.flatnonzero(_pattern_changes(codes))
    return float(k[moved[-1] + 1]) if moved.size else 0.0


def designer_extent(params: Parameters, raw_mode: Mode | None = None, *,
                    include: Iterable[tuple[float, float]] = (),
                    k_max: float | None = None, mu_max: float | None = None,
                    mu_band: float = DESIGN_MU) -> tuple[float, float]:
    """The designer's view ``[0, k_max] x [0, mu_max]``: mu up to ``mu_band``.

    Parameters
    ----------
    params : Parameters
    raw_mode : Mode, optional
        A single mode's raw region (``plot --raw --modes X``): its boundaries
        count too.
    include : iterable of (k, mu)
        Design points to keep in view (the view grows to hold them).
    k_max, mu_max : float, optional
        User choices; they win.
    mu_band : float
        Top of the band of friction coefficients (default :data:`DESIGN_MU`).

    Returns
    -------
    (k_max, mu_max) : tuple of float
        ``mu_max = mu_band`` unless a design point lies higher; ``k_max`` 15 %
        beyond the last boundary that crosses the band (followed up to 10
        band heights: beyond, :func:`points_off_view` marks the points),
        rounded up to a nice number.
    """
    p = params
    pts = [(float(k), float(m)) for k, m in include if math.isfinite(k) and math.isfinite(m)]
    if mu_max is None:
        top = max([m for _, m in pts], default=0.0)
        mu_max = mu_band if top <= mu_band else nice_ceil(1.1 * top)
    if k_max is None:
        far = _REACH * mu_max
        last = _last_change(p, mu_max, far, raw_mode)
        last = max([last] + [k for k, _ in pts])
        if last <= 0.0:
            last = mu_max
        k_max = nice_ceil((1.0 + _MARGIN) * last)
    return float(k_max), float(mu_max)


def view_extent(params: Parameters, view: str = "designer", raw_mode: Mode | None = None, *,
                include: Iterable[tuple[float, float]] = (), k_max: float | None = None,
                mu_max: float | None = None) -> tuple[float, float]:
    """The view named ``view``: ``designer`` (:func:`designer_extent`) or ``report`` (:func:`auto_extent`).

    Explicit ``k_max`` / ``mu_max`` win over both.
    """
    if view not in VIEWS:
        raise ValueError(f"view must be one of {', '.join(VIEWS)}, got {view!r}")
    if k_max is not None and mu_max is not None:
        return float(k_max), float(mu_max)
    if view == "report":
        return auto_extent(params, raw_mode, include=include, k_max=k_max, mu_max=mu_max)
    return designer_extent(params, raw_mode, include=include, k_max=k_max, mu_max=mu_max)


def points_off_view(params: Parameters, k_max: float, mu_max: float) -> list[NamedPoint]:
    """The map's characteristic points that lie outside ``[0, k_max] x [0, mu_max]``.

    Those a drawing names: A, B' (where mu* meets AB again, when it does), C,
    C', D, E, F, G; in the order of :func:`regimemap.mechanics.curves.named_points`.
    """
    p = params
    out = []
    for name, pt in named_points(p).items():
        if 0.0 <= pt.k <= k_max and 0.0 <= pt.mu <= mu_max:
            continue
        if name == "B'" and not (math.isfinite(p.k_A) and pt.k >= p.k_A):
            continue  # Delta < 0: mu* from A never meets AB again
        if not (math.isfinite(pt.k) and math.isfinite(pt.mu)):
            continue
        out.append(pt)
    return out
