"""What an atlas or an animation sweeps: the values, the block of each panel, the shared views.

No matplotlib: the command line parses the lists (:func:`parse_values`) and
checks the blocks (:func:`sweep_params`) before anything is drawn, and the
drawing layer (:mod:`regimemap.maps.figures.atlas`, :mod:`regimemap.maps.figures.animation`)
draws the panels and frames in the views chosen here (:func:`resolve_share`,
:func:`sweep_extent`); an animation's frames, their blocks and maps, are computed here
(:func:`sweep_frames`) and handed to :func:`regimemap.maps.figures.animation.write_animation`.

The value lists use the syntax of the command line: ``1,2,3`` (a list) or
``-1:1:41`` (start:stop:count, both ends included, as ``numpy.linspace``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.validation import check_gamma, check_kprime
from .describe import LOAD_SYMBOLS
from .mapdata import MapData, compute_map

__all__ = [
    "CRAMMED",
    "MAX_PANELS",
    "MAX_VALUES",
    "SAMPLES",
    "SHARE",
    "SWEEPS",
    "SweepFrames",
    "atlas_extents",
    "checked_values",
    "parse_values",
    "points_outside",
    "resolve_share",
    "shared_extent",
    "sweep_extent",
    "sweep_frames",
    "sweep_params",
]

#: Samples of k per atlas panel / animation frame (fewer than a single map: the panels are small).
SAMPLES = 401
#: Largest number of panels of an atlas (rows x columns); :mod:`regimemap.drawing.limits`
#: repeats it for the command line's options, importable without numpy.
MAX_PANELS = 48
#: Largest number of values in one list (rows or columns of an atlas).
MAX_VALUES = 400
#: How the axes of an atlas are shared: one view for the whole figure, one per row, or none.
SHARE: tuple[str, ...] = ("all", "row", "none")

#: What the columns of an atlas or the frames of an animation may sweep: k' or a load,
#: with its symbol (mathtext) and what it is.
SWEEPS: dict[str, tuple[str, str]] = {
    "kprime": ("k'", "force height h/H"),
    **{name: (tex, what) for name, (_, tex, what) in LOAD_SYMBOLS.items()},
}


def sweep_params(gamma: float, sweep: str, value: float,
                 fixed: dict[str, Any] | None = None) -> Parameters:
    """The block of one panel or frame: ``gamma``, ``sweep = value`` and the ``fixed`` rest.

    ``fixed`` holds ``kprime`` (when the sweep is a load) and the loads that do not vary.
    Raises ValueError (from :class:`Parameters`) for a value out of range.
    """
    if sweep not in SWEEPS:
        raise ValueError(f"sweep must be one of {', '.join(SWEEPS)}, got {sweep!r}")
    kw = dict(fixed or {})
    kw[sweep] = value
    kp = kw.pop("kprime", 0.0)
    return Parameters(gamma, kp, **kw)


def parse_values(text: str, name: str, check: Callable[[float], float],
                 max_count: int = MAX_VALUES) -> list[float]:
    """Parse ``"a,b,c"`` or ``"start:stop:count"`` into a list of checked floats.

    Parameters
    ----------
    text : str
        A comma-separated list of numbers, or ``start:stop:count`` (count
        values from start to stop, both included; count >= 1, and count = 1
        needs start == stop).
    name : str
        Parameter name for messages (``gamma``, ``kprime``).
    check : callable
        Validates one value (e.g. :func:`regimemap.validation.check_kprime`),
        raising ValueError naming the allowed range.
    max_count : int
        Most values accepted.

    Returns
    -------
    list of float

    Raises
    ------
    ValueError
        With the offending piece and the expected syntax.

    Examples
    --------
    >>> from regimemap.mechanics.validation import check_gamma, check_kprime
    >>> parse_values("-1:1:5", "kprime", check_kprime)
    [-1.0, -0.5, 0.0, 0.5, 1.0]
    >>> parse_values("1, 2,3", "gamma", check_gamma)
    [1.0, 2.0, 3.0]
    """
    s = text.strip()
    if not s:
        raise ValueError(f"{name}: empty; give {_SYNTAX}")
    values = _parse_range(text, name, check, max_count) if ":" in s else _parse_list(text, name, max_count)
    return [check(v) for v in values]


_SYNTAX = "a list like 1,2,3 or a range start:stop:count like -1:1:41"


def _parse_range(text: str, name: str, check: Callable[[float], float], max_count: int) -> list[float]:
    """``start:stop:count``: ``count`` values from start to stop (both checked), both included."""
    parts = text.strip().split(":")
    if len(parts) != 3:
        raise ValueError(f"{name}: {text!r} is not start:stop:count ({_SYNTAX})")
    try:
        start, stop = float(parts[0]), float(parts[1])
    except ValueError:
        raise ValueError(f"{name}: start and stop of {text!r} must be numbers ({_SYNTAX})") from None
    try:
        count = int(parts[2])
    except ValueError:
        raise ValueError(f"{name}: the count of {text!r} must be a whole number >= 1, "
                         f"got {parts[2]!r}") from None
    if count < 1:
        raise ValueError(f"{name}: the count of {text!r} must be a whole number >= 1, got {count}")
    if count > max_count:
        raise ValueError(f"{name}: {count} values in {text!r} exceed the limit of {max_count}")
    if count == 1 and start != stop:
        raise ValueError(f"{name}: {text!r} asks for 1 value between two different ends; "
                         f"use a count >= 2 or start == stop")
    for v, what in ((start, "start"), (stop, "stop")):
        try:
            check(v)
        except ValueError as exc:
            raise ValueError(f"{what} of {text!r}: {exc}") from None
    values: list[float] = np.linspace(start, stop, count).tolist()
    return values


def _parse_list(text: str, name: str, max_count: int) -> list[float]:
    """``a,b,c``: the numbers of a comma-separated list."""
    values = []
    for piece in text.strip().split(","):
        piece = piece.strip()
        if not piece:
            raise ValueError(f"{name}: empty item in {text!r} ({_SYNTAX})")
        try:
            values.append(float(piece))
        except ValueError:
            raise ValueError(f"{name}: {piece!r} is not a number ({_SYNTAX})") from None
    if len(values) > max_count:
        raise ValueError(f"{name}: {len(values)} values exceed the limit of {max_count}")
    return values


def _extent_of(p: Parameters, view: str = "designer") -> tuple[float, float]:
    from .designer_view import view_extent  # imported when used: the command line starts fast

    return view_extent(p, view)


#: A panel whose own view is this many times smaller than the shared one (in k or
#: in mu) would be crammed into a corner: the atlas then gives each panel its own view.
CRAMMED = 3.0


def resolve_share(gammas: Sequence[float], kprimes: Sequence[float], share: str = "all",
                  k_max: float | None = None, mu_max: float | None = None,
                  view: str = "designer", *, sweep: str = "kprime",
                  fixed: dict[str, Any] | None = None
                  ) -> tuple[str, list[list[tuple[float, float]]], list[tuple[float, float]]]:
    """The sharing an atlas can afford, its views, and the panels sharing would cram.

    A shared view (``share`` ``"all"`` or ``"row"``) that is more than
    :data:`CRAMMED` times wider or taller than a panel's own view would squeeze
    that panel into a corner; then every panel gets its own view
    (``"none"``), and the crammed panels are returned as (gamma, k') pairs so
    that the caller can say why.  Fixed ``k_max`` and ``mu_max`` always share.

    Returns
    -------
    (share, extents, crammed)
    """
    ext = atlas_extents(gammas, kprimes, share, k_max, mu_max, sweep=sweep, fixed=fixed,
                        view=view)
    if share == "none" or (k_max is not None and mu_max is not None):
        return share, ext, []
    own = atlas_extents(gammas, kprimes, "none", k_max, mu_max, sweep=sweep, fixed=fixed,
                        view=view)
    crammed = [(g, kp) for i, g in enumerate(gammas) for j, kp in enumerate(kprimes)
               if ext[i][j][0] > CRAMMED * own[i][j][0] or ext[i][j][1] > CRAMMED * own[i][j][1]]
    if crammed:
        return "none", own, crammed
    return share, ext, []


def atlas_extents(gammas: Sequence[float], kprimes: Sequence[float], share: str = "all",
                  k_max: float | None = None, mu_max: float | None = None, *,
                  sweep: str = "kprime", fixed: dict[str, Any] | None = None,
                  view: str = "designer") -> list[list[tuple[float, float]]]:
    """The view (k_max, mu_max) of every panel: rows gamma, columns k'.

    ``share="all"``: one view for every panel, :func:`shared_extent` of all
    panels' automatic views (:func:`regimemap.maps.view.auto_extent`); ``"row"``:
    one per row; ``"none"``: each panel's own automatic view.  A given
    ``k_max`` or ``mu_max`` overrides the automatic value everywhere.  The
    columns are the values of ``sweep`` (k' by default, or a load; see
    :func:`sweep_params`).
    """
    if share not in SHARE:
        raise ValueError(f"share must be one of {', '.join(SHARE)}, got {share!r}")
    own = [[_extent_of(sweep_params(g, sweep, v, fixed), view) for v in kprimes] for g in gammas]
    if share == "all":
        km, mm = shared_extent([e for row in own for e in row])
        own = [[(km, mm) for _ in row] for row in own]
    elif share == "row":
        own = [[shared_extent(row)] * len(row) for row in own]
    return [[(k_max if k_max is not None else e[0], mu_max if mu_max is not None else e[1])
             for e in row] for row in own]


def shared_extent(extents: Sequence[tuple[float, float]]) -> tuple[float, float]:
    """One view for several maps: the upper quartile of their automatic views, rounded up.

    The automatic view of a single map (:func:`regimemap.maps.view.auto_extent`)
    reaches out to far points such as D or B', which run off to infinity as
    k' nears 0 or -1; the largest of several views would shrink every other
    map into a corner, the median would cut point A off too many of them.
    The 75th percentile (of k_max and of mu_max separately, rounded up to a
    nice number) keeps A in view for most maps; :func:`points_outside` tells
    which maps lose it.
    """
    from .view import nice_ceil

    ks = np.array([e[0] for e in extents], dtype=float)
    ms = np.array([e[1] for e in extents], dtype=float)
    if ks.size == 1:
        return float(ks[0]), float(ms[0])
    return (float(nice_ceil(float(np.percentile(ks, 75.0)))),
            float(nice_ceil(float(np.percentile(ms, 75.0)))))


def points_outside(params: Sequence[Parameters], k_max: float, mu_max: float) -> list[Parameters]:
    """The maps whose point A (k_A, mu_A) exists but lies outside [0, k_max] x [0, mu_max]."""
    return [p for p in params
            if math.isfinite(p.k_A) and (p.k_A > k_max or p.mu_A > mu_max)]


def sweep_extent(gamma: float, kprimes: Sequence[float], view: str = "designer", *,
                 sweep: str = "kprime", fixed: dict[str, Any] | None = None
                 ) -> tuple[float, float]:
    """One view for every frame: :func:`shared_extent` of the frames' own views."""
    return shared_extent([_extent_of(sweep_params(gamma, sweep, v, fixed), view) for v in kprimes])


def checked_values(gammas: Sequence[float], values: Sequence[float], sweep: str = "kprime",
                   fixed: dict[str, Any] | None = None) -> tuple[list[float], list[float]]:
    """The rows' gamma and the columns' (or frames') values, checked; ValueError naming the range.

    A k' may reach the crest when one is given (``fixed["crest"]``; 1 by default):
    :func:`regimemap.mechanics.validation.check_kprime` with the crest, the rule of every
    map.  A swept load is checked with its block (:func:`sweep_params`).
    """
    gs = [check_gamma(g) for g in gammas]
    if sweep == "kprime":
        return gs, [check_kprime(k, (fixed or {}).get("crest", 1.0)) for k in values]
    return gs, [float(v) for v in values]


@dataclass(frozen=True)
class SweepFrames:
    """The frames of an animation: the block and the map of each, on one view.

    Attributes
    ----------
    gamma : float
        The aspect ratio of every frame.
    values : tuple of float
        The swept value of each frame (k', or the load ``sweep``), checked.
    blocks : tuple of Parameters
        The block of each frame (:func:`sweep_params`).
    sweep : str
        What the frames vary, a key of :data:`SWEEPS`.
    fixed : dict or None
        What every frame shares (``kprime`` when a load is swept, the other loads).
    k_max, mu_max : float
        The view of every frame.
    maps : iterable of MapData
        The map of each frame in that view (:func:`~regimemap.maps.mapdata.compute_map`),
        computed as the frames are drawn; all at once (a list) when the blocks have loads,
        since the key of every frame lists the modes any frame shows.
    """

    gamma: float
    values: tuple[float, ...]
    blocks: tuple[Parameters, ...]
    sweep: str
    fixed: dict[str, Any] | None
    k_max: float
    mu_max: float
    maps: Iterable[MapData]

    @property
    def loaded(self) -> bool:
        """Whether any frame's block has loads."""
        return any(p.loaded for p in self.blocks)


def sweep_frames(gamma: float, values: Sequence[float], *, k_max: float | None = None,
                 mu_max: float | None = None, view: str = "designer", samples: int = SAMPLES,
                 sweep: str = "kprime", fixed: dict[str, Any] | None = None) -> SweepFrames:
    """The frames of an animation of the map of ``gamma`` as k' (or the load ``sweep``) runs
    through ``values``: each frame's block and map, on one view.

    Parameters
    ----------
    gamma : float
    values : sequence of float
        k' of each frame (in [-1, 1], or up to ``fixed["crest"]``), or the value of ``sweep``.
    k_max, mu_max : float, optional
        The view of every frame (default :func:`sweep_extent` of ``view``).
    view : {"designer", "report"}
    samples : int
        Samples of k per frame.
    sweep, fixed : str, dict
        What the frames vary and what they share (:func:`sweep_params`).

    Raises
    ------
    ValueError
        For a gamma or a value out of range.
    """
    (g,), vals = checked_values([gamma], values, sweep, fixed)
    blocks = tuple(sweep_params(g, sweep, v, fixed) for v in vals)
    if k_max is None or mu_max is None:
        ek, em = sweep_extent(g, vals, view, sweep=sweep, fixed=fixed)
        k_max = ek if k_max is None else k_max
        mu_max = em if mu_max is None else mu_max
    kx, mx = k_max, mu_max
    maps: Iterable[MapData] = (compute_map(p, k_max=kx, mu_max=mx, samples=samples) for p in blocks)
    if any(p.loaded for p in blocks):
        maps = list(maps)
    return SweepFrames(gamma=g, values=tuple(vals), blocks=blocks, sweep=sweep, fixed=fixed,
                       k_max=k_max, mu_max=mu_max, maps=maps)
