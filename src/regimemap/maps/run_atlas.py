"""Many maps at once: the panels of an atlas and the frames of an animation, as records.

:func:`run_atlas` computes what ``regimemap atlas`` draws: the block of every
panel (rows gamma, columns k' or a load), the views they can share
(:func:`regimemap.maps.sweeps.resolve_share`) and the map of each
(:func:`regimemap.maps.mapdata.compute_map`), in an :class:`AtlasRecord`;
:func:`run_animation` the frames of ``regimemap animate``
(:func:`regimemap.maps.sweeps.sweep_frames`), in an :class:`AnimationRecord`.
:func:`regimemap.maps.figures.atlas.atlas_figure` and
:func:`regimemap.maps.figures.animation.write_animation` draw them.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

from ..mechanics.block import Parameters
from ..records.fields import Field, Record
from ..records.notices import Notice
from .mapdata import MapData, compute_map
from .sweeps import (
    MAX_PANELS,
    SAMPLES,
    SweepFrames,
    checked_values,
    points_outside,
    resolve_share,
    sweep_frames,
    sweep_params,
)

__all__ = ["AnimationRecord", "AtlasRecord", "run_animation", "run_atlas"]


def _label(sweep: str) -> str:
    return "k'" if sweep == "kprime" else sweep


def _lost_note(lost: Sequence[str]) -> tuple[Notice, ...]:
    """A note naming the maps whose point A lies outside the shared view."""
    if not lost:
        return ()
    shown = ", ".join(lost[:6]) + (f" and {len(lost) - 6} more" if len(lost) > 6 else "")
    return (Notice("outside-view", f"point A lies outside the shared view for {shown}; "
                   "give --k-max/--mu-max to widen it", "k_A", len(lost)),)


@dataclass(frozen=True)
class AtlasRecord(Record):
    """The panels of an atlas: rows gamma, columns k' (or a load), each with its map.

    Attributes
    ----------
    gammas, values : tuple of float
        The rows' aspect ratios and the columns' values of ``sweep``, checked.
    sweep : str
        What the columns vary: ``"kprime"`` or a load of :data:`regimemap.maps.sweeps.SWEEPS`.
    fixed : dict or None
        What every panel shares (``kprime`` when a load is swept, the other loads).
    share : str
        How the axes are shared: ``"all"``, ``"row"`` or ``"none"`` (``"none"`` when a
        shared view would cram a panel into a corner).
    view : str
        The panels' own views: ``"designer"`` or ``"report"``.
    extents : tuple of tuple of (float, float)
        The view (k_max, mu_max) of every panel, by row.
    crammed : tuple of (float, float)
        The panels (gamma, value) that a shared view would cram.
    blocks : tuple of tuple of Parameters
        The block of every panel, by row.
    maps : tuple of tuple of MapData
        The map of every panel in its view, by row.
    notices : tuple of Notice
        ``crammed`` (each panel has its own view) and ``outside-view`` (point A
        outside the shared view of the report's panels).
    """

    gammas: tuple[float, ...]
    values: tuple[float, ...]
    sweep: str
    fixed: dict[str, Any] | None
    share: str
    view: str
    extents: tuple[tuple[tuple[float, float], ...], ...]
    crammed: tuple[tuple[float, float], ...]
    blocks: tuple[tuple[Parameters, ...], ...]
    maps: tuple[tuple[MapData, ...], ...]
    notices: tuple[Notice, ...] = ()

    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("gammas", "gamma", "", "aspect ratios H/B of the rows"),
        Field("sweep", "sweep", "", "what the columns vary"),
        Field("values", "values", "", "the columns' values"),
        Field("share", "share", "", "axes shared: all, row or none"),
        Field("view", "view", "", "the panels' own views"),
        Field("crammed", "crammed", "", "panels a shared view would cram (gamma, value)"),
    )
    CAPTION: ClassVar[str] = "Atlas of regime maps"

    @property
    def loaded(self) -> bool:
        """Whether any panel's block has loads."""
        return any(p.loaded for row in self.blocks for p in row)


# The atlas's request, one keyword each as ``regimemap atlas`` gives them (PLR0913 accepted here).
def run_atlas(gammas: Sequence[float], values: Sequence[float], *, sweep: str = "kprime",  # noqa: PLR0913
              fixed: dict[str, Any] | None = None, share: str = "all",
              k_max: float | None = None, mu_max: float | None = None, view: str = "designer",
              samples: int = SAMPLES, curves: bool = True,
              extents: Sequence[Sequence[tuple[float, float]]] | None = None) -> AtlasRecord:
    """The panels of an atlas: every block, the views they share and every map.

    Parameters
    ----------
    gammas, values : sequence of float
        Aspect ratios (rows) and the values of the columns: force heights k' by
        default (in [-1, 1], or up to ``fixed["crest"]``); at most ``MAX_PANELS``
        panels in all
        (:data:`regimemap.maps.sweeps.MAX_PANELS`).
    sweep : str
        What the columns vary: ``"kprime"`` or a load of :data:`regimemap.maps.sweeps.SWEEPS`.
    fixed : dict, optional
        What every panel shares: ``kprime`` when a load is swept, and the other
        loads (keywords of :class:`~regimemap.mechanics.block.Parameters`).
    share : {"all", "row", "none"}
        Share the axes over the whole figure, within each row, or not at all;
        panels that a shared view would cram get views of their own
        (:func:`regimemap.maps.sweeps.resolve_share`).
    k_max, mu_max : float, optional
        Fix the view of every panel.
    view : {"designer", "report"}
        The panels' own views (:func:`regimemap.maps.designer_view.view_extent`).
    samples : int
        Samples of k per panel.
    curves : bool
        Compute the boundary curves and named points.
    extents : rows of (k_max, mu_max), optional
        The view of every panel, as :func:`regimemap.maps.sweeps.atlas_extents`
        returns it (``share`` is then kept as given).

    Returns
    -------
    AtlasRecord

    Raises
    ------
    ValueError
        Invalid gamma or value, an empty list, or too many panels.

    Examples
    --------
    >>> rec = run_atlas([1.0, 3.0], [-0.6, 0.4], samples=31)
    >>> len(rec.maps), len(rec.maps[0]), rec.share, rec.crammed
    (2, 2, 'none', ((3.0, 0.4),))
    """
    gs, vals = checked_values(gammas, values, sweep, fixed)
    nr, nc = len(gs), len(vals)
    if nr == 0 or nc == 0:
        raise ValueError("an atlas needs at least one gamma and one kprime")
    if nr * nc > MAX_PANELS:
        raise ValueError(f"{nr} x {nc} = {nr * nc} panels exceed the limit of {MAX_PANELS}")
    crammed: list[tuple[float, float]] = []
    if extents is None:
        share, ext, crammed = resolve_share(gs, vals, share, k_max, mu_max, view=view,
                                            sweep=sweep, fixed=fixed)
    else:
        ext = [list(row) for row in extents]
    blocks = [[sweep_params(g, sweep, v, fixed) for v in vals] for g in gs]
    maps = tuple(tuple(compute_map(p, k_max=ext[i][j][0], mu_max=ext[i][j][1], samples=samples,
                                   curves=curves) for j, p in enumerate(row))
                 for i, row in enumerate(blocks))
    notices: tuple[Notice, ...] = ()
    label = _label(sweep)
    if crammed:
        names = ", ".join(f"({g:g}, {v:g})" for g, v in crammed[:4])
        more = f" and {len(crammed) - 4} more" if len(crammed) > 4 else ""
        notices += (Notice("crammed", f"each panel has its own view; a shared view would cram "
                           f"the panels (gamma, {label}) = {names}{more} into a corner",
                           "share", len(crammed)),)
    if share != "none" and view == "report":
        notices += _lost_note([f"gamma = {g:g}, {label} = {v:g}" for i, g in enumerate(gs)
                               for j, v in enumerate(vals)
                               if points_outside([blocks[i][j]], *ext[i][j])])
    return AtlasRecord(gammas=tuple(gs), values=tuple(vals), sweep=sweep, fixed=fixed,
                       share=share, view=view,
                       extents=tuple(tuple((e[0], e[1]) for e in row) for row in ext),
                       crammed=tuple(crammed), blocks=tuple(tuple(r) for r in blocks), maps=maps,
                       notices=notices)


@dataclass(frozen=True)
class AnimationRecord(Record):
    """The frames of an animation of the map: one block and one map each, on one view.

    Attributes
    ----------
    frames : SweepFrames
        The frames' values, blocks, shared view and maps
        (:func:`regimemap.maps.sweeps.sweep_frames`; the maps of a block without loads
        are computed as the frames are drawn).
    view : str
        The default view asked for: ``"designer"`` or ``"report"``.
    notices : tuple of Notice
        ``outside-view``: the frames whose point A lies outside the report's view.
    """

    frames: SweepFrames
    view: str
    notices: tuple[Notice, ...] = ()

    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("frames.gamma", "gamma", "", "aspect ratio H/B"),
        Field("frames.sweep", "sweep", "", "what the frames vary"),
        Field("frames.values", "values", "", "the frames' values"),
        Field("frames.k_max", "k_max", "", "right end of the k axis"),
        Field("frames.mu_max", "mu_max", "", "top of the mu axis"),
    )
    CAPTION: ClassVar[str] = "Animation of the regime map"


def run_animation(gamma: float, values: Sequence[float], *, sweep: str = "kprime",
                  fixed: dict[str, Any] | None = None, k_max: float | None = None,
                  mu_max: float | None = None, view: str = "designer",
                  samples: int = SAMPLES) -> AnimationRecord:
    """The frames of an animation of the map of ``gamma`` as k' (or the load ``sweep``)
    runs through ``values``, on one view (:func:`regimemap.maps.sweeps.sweep_frames`).

    Raises
    ------
    ValueError
        For a gamma or a value out of range.

    Examples
    --------
    >>> rec = run_animation(3.0, [-0.5, 0.5], samples=31)
    >>> rec.frames.values, rec.notices
    ((-0.5, 0.5), ())
    """
    frames = sweep_frames(gamma, values, k_max=k_max, mu_max=mu_max, view=view, samples=samples,
                          sweep=sweep, fixed=fixed)
    notices: tuple[Notice, ...] = ()
    if view == "report":
        label = _label(sweep)
        notices = _lost_note([f"{label} = {v:g}" for v, p in zip(frames.values, frames.blocks)
                              if points_outside([p], frames.k_max, frames.mu_max)])
    return AnimationRecord(frames=frames, view=view, notices=notices)
