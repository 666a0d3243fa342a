"""A caisson under its design wave, placed on the loaded regime map.

:func:`caisson_report` runs Goda's procedure (:func:`regimemap.waves.analyse_caisson`)
for a design, turns the caisson into the loaded block (``gamma``, ``k``,
``k'``, buoyancy, uplift ratio and arm, gyration), finds its mode and margins
on the loaded map, and follows the point as the wave grows: ``H1/3`` and
``Hmax`` both scaled by a factor ``s`` from 0.5 to 1.5 (period, direction and
everything else unchanged), the loads recomputed at each ``s``.

Along that path the map itself changes: ``k'`` (the height of the wave
force's resultant, since ``eta*`` grows with ``Hmax``) and the uplift ratio
``U/P`` depend on ``s``.  Each point of the path is therefore classified on
*its own* map (:attr:`WavePath.modes`), and also on the design wave's map
(:attr:`WavePath.design_map_modes`), the one a sheet draws.

Every call to the loaded map goes through :mod:`regimemap.maps.loadedmap`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..maps.loadedmap import LoadedMap, Margin, classify_at, margins, mode_grid, named_points
from ..maps.mapdata import MapData, compute_map
from ..maps.point_result import margin_words
from ..mechanics.modes import Mode
from ..records.checks import Check
from ..records.htmltable import html_table
from ..records.numbers import number
from ..waves import CaissonAnalysis, analyse_caisson

__all__ = [
    "PATH_FACTORS",
    "REQUIRED_SF",
    "CaissonReport",
    "MapView",
    "WavePath",
    "caisson_checks",
    "caisson_report",
    "loaded_map_of",
    "map_view",
    "sheet_map",
    "stability_checks",
]

#: Wave-height factors of the path (``H1/3`` and ``Hmax`` times s).
PATH_FACTORS: NDArray[np.float64] = np.round(np.linspace(0.5, 1.5, 101), 12)

_RE = int(Mode.RE)

#: The safety factors a design must reach by default, sliding and overturning (Goda 2000, Sect. 4.2).
REQUIRED_SF = (1.2, 1.2)


def loaded_map_of(a: CaissonAnalysis, index: Any = ()) -> LoadedMap:
    """The loaded map of one caisson of an analysis (``index`` into its arrays).

    ``crest`` (the height of the crest above C over ``H_C``) comes from the
    section: ``(h' + hc - H_C)/H_C``.  The gyration is always given (1 +
    gamma^2)/3 for a uniform block, exactly, but written out: it is the one
    the section has.
    """
    b, s = a.block, a.section
    top = float(s.base_depth[index] + s.crest[index])
    hc_ = float(b.H[index])
    return LoadedMap(gamma=float(b.gamma[index]), kprime=float(b.kprime[index]),
                     buoyancy=float(b.buoyancy[index]), uplift_ratio=float(b.uplift_ratio[index]),
                     uplift_arm=float(b.uplift_arm[index]), gyration=float(b.gyration[index]),
                     crest=(top - hc_) / hc_)


@dataclass(frozen=True)
class WavePath:
    """The design point as the wave grows (arrays over :attr:`factors`).

    Attributes
    ----------
    factors : ndarray
        ``s``: ``H1/3`` and ``Hmax`` are ``s`` times the design values.
    analysis : CaissonAnalysis
        Goda's procedure at every ``s`` (arrays).
    maps : tuple of LoadedMap
        The loaded map at every ``s``.
    modes : ndarray of uint8
        Mode code of each point on its own map.
    design_map_modes : ndarray of uint8
        Mode code of each point on the design wave's map.
    onset : float or None
        The smallest ``s`` of the path at which the caisson leaves rest
        (bisected to 1e-9 between two samples); None if it rests all along.
        ``factors[0]`` if it already moves there.
    onset_mode : int or None
        Mode code just beyond :attr:`onset`.
    """

    factors: NDArray[np.float64]
    analysis: CaissonAnalysis
    maps: tuple[LoadedMap, ...]
    modes: NDArray[np.uint8]
    design_map_modes: NDArray[np.uint8]
    onset: float | None
    onset_mode: int | None

    @property
    def k(self) -> NDArray[np.float64]:
        return np.asarray(self.analysis.block.k, dtype=np.float64)

    @property
    def kprime(self) -> NDArray[np.float64]:
        return np.asarray(self.analysis.block.kprime, dtype=np.float64)

    @property
    def uplift_ratio(self) -> NDArray[np.float64]:
        return np.asarray(self.analysis.block.uplift_ratio, dtype=np.float64)


@dataclass(frozen=True)
class CaissonReport:
    """Everything a caisson report or design sheet shows.

    Attributes
    ----------
    inputs : dict
        The keyword arguments of :func:`~regimemap.waves.analyse_caisson`.
    analysis : CaissonAnalysis
        Goda's procedure for the design wave (0-d arrays).
    map : LoadedMap
        The loaded map of the design wave.
    k, mu : float
        The design point.
    mode : int
        Its mode code on :attr:`map`.
    margin_k, margin_mu : Margin
        The smallest change of k (mu fixed) and of mu (k fixed) that changes the mode.
    path : WavePath
        The point as the wave grows.
    """

    inputs: dict[str, Any]
    analysis: CaissonAnalysis
    map: LoadedMap
    k: float
    mu: float
    mode: int
    margin_k: Margin
    margin_mu: Margin
    path: WavePath

    @property
    def safe_by_goda(self) -> bool:
        """Both of Goda's safety factors are at least 1."""
        st = self.analysis.stability
        return bool(st.sliding >= 1.0) and bool(st.overturning >= 1.0)

    @property
    def consistent(self) -> bool:
        """Goda's ``SF >= 1`` (both) agrees with rest on the loaded map."""
        return self.safe_by_goda == (self.mode == _RE)

    # -- display: a readable repr and a table for Jupyter -------------------------------------
    def _onset_words(self) -> str:
        p = self.path
        if p.onset is None:
            return "rests along the whole wave path"
        to = "" if p.onset_mode is None else f" ({Mode(p.onset_mode).label})"
        return f"leaves rest at {p.onset:.3g} x the design wave{to}"

    def __repr__(self) -> str:
        """Two lines: the mode and its margins on the loaded map; Goda's factors and the wave path."""
        m, st = self.map, self.analysis.stability
        mode = Mode(self.mode)
        return (f"CaissonReport({mode.label} ({mode.description}) at k={self.k:.4g}, "
                f"mu={self.mu:.4g} on the loaded map gamma={m.gamma:.4g}, k'={m.kprime:.4g}, "
                f"beta={m.buoyancy:.4g}, nu={m.uplift_ratio:.4g}; margin "
                f"{margin_words(self.margin_k)}, {margin_words(self.margin_mu)};\n  Goda SF sliding "
                f"{number(float(st.sliding))}, overturning {number(float(st.overturning))}: "
                f"{'consistent' if self.consistent else 'NOT consistent'} with the map; "
                f"{self._onset_words()})")

    def _repr_html_(self) -> str:
        """The design point on its loaded map and Goda's factors as a small table."""
        m, st = self.map, self.analysis.stability
        mode = Mode(self.mode)
        rows: list[tuple[object, ...]] = [
            ("mode", mode.label, mode.description),
            ("k", self.k, "P / (m g), the push of the design wave"),
            ("mu", self.mu, "friction coefficient"),
            ("margin k", margin_words(self.margin_k, with_name=False), "mu fixed"),
            ("margin mu", margin_words(self.margin_mu, with_name=False), "k fixed"),
            ("gamma", m.gamma, "H_C / B"),
            ("k'", m.kprime, "height of the wave force above C / H_C"),
            ("beta", m.buoyancy, "buoyancy / dry weight"),
            ("nu", m.uplift_ratio, "uplift ratio U / P"),
            ("SF sliding", float(st.sliding), "Goda"),
            ("SF overturning", float(st.overturning), "Goda"),
            ("consistent", self.consistent, "Goda's SF >= 1 agrees with rest on the map"),
            ("wave path", self._onset_words(), "H1/3 and Hmax scaled by 0.5 ... 1.5"),
        ]
        return html_table(rows, caption=f"Caisson on the loaded map: {mode.label} at "
                          f"k = {self.k:.4g}, mu = {self.mu:.4g}", header=("", "value", ""))


def _path_inputs(inputs: Mapping[str, Any], a: CaissonAnalysis, factors: NDArray[np.float64]
                 ) -> dict[str, Any]:
    out = dict(inputs)
    out["H0"] = None
    out["H13"] = factors * float(a.heights.H13)
    out["Hmax"] = factors * float(a.heights.Hmax)
    return out


def _wave_path(inputs: Mapping[str, Any], a: CaissonAnalysis, factors: NDArray[np.float64],
               design_map: LoadedMap) -> WavePath:
    pa = analyse_caisson(**_path_inputs(inputs, a, factors))
    maps = tuple(loaded_map_of(pa, i) for i in range(factors.size))
    k = np.asarray(pa.block.k, dtype=np.float64)
    mu = np.asarray(pa.block.mu, dtype=np.float64)
    modes = np.array([int(classify_at(k[i], mu[i], mp)) for i, mp in enumerate(maps)], dtype=np.uint8)
    on_design = classify_at(k, mu, design_map)
    onset: float | None = None
    onset_mode: int | None = None
    moving = np.flatnonzero(modes != _RE)
    if moving.size:
        j = int(moving[0])
        onset, onset_mode = float(factors[j]), int(modes[j])
        if j > 0:
            lo, hi = float(factors[j - 1]), float(factors[j])
            while hi - lo > 1e-9:
                mid = 0.5 * (lo + hi)
                m_mid = _mode_at_factor(inputs, a, mid)
                if m_mid == _RE:
                    lo = mid
                else:
                    hi, onset_mode = mid, m_mid
            onset = hi
    return WavePath(factors=factors, analysis=pa, maps=maps, modes=modes,
                    design_map_modes=on_design, onset=onset, onset_mode=onset_mode)


def _mode_at_factor(inputs: Mapping[str, Any], a: CaissonAnalysis, s: float) -> int:
    one = analyse_caisson(**_path_inputs(inputs, a, np.array(s)))
    return int(classify_at(float(one.block.k), float(one.block.mu), loaded_map_of(one)))


def caisson_report(inputs: Mapping[str, Any], factors: NDArray[np.float64] | None = None
                   ) -> CaissonReport:
    """Goda's procedure, the loaded block, its mode and margins, and the wave path.

    Parameters
    ----------
    inputs : mapping
        Keyword arguments of :func:`regimemap.waves.analyse_caisson` for one
        caisson (scalars), e.g. ``Design.analysis_inputs()`` of
        :mod:`regimemap.caisson.file`.
    factors : array, optional
        Wave-height factors of the path (default :data:`PATH_FACTORS`).

    Returns
    -------
    CaissonReport

    Raises
    ------
    ValueError
        If the inputs are not one caisson, or the block is outside the
        loaded map's ranges.
    """
    a = analyse_caisson(**inputs)
    if a.block.k.shape != ():
        raise ValueError("caisson_report takes one caisson (scalar inputs)")
    m = loaded_map_of(a)
    m.check()
    k, mu = float(a.block.k), float(a.block.mu)
    mode = int(classify_at(k, mu, m))
    mk, mm = margins(k, mu, m)
    fac = PATH_FACTORS if factors is None else np.asarray(factors, dtype=np.float64)
    path = _wave_path(inputs, a, fac, m)
    return CaissonReport(inputs=dict(inputs), analysis=a, map=m, k=k, mu=mu, mode=mode,
                         margin_k=mk, margin_mu=mm, path=path)


def caisson_checks(r: CaissonReport, required: tuple[float, float] = REQUIRED_SF) -> list[Check]:
    """The requirements of a caisson's design check: its safety factors at least the required ones.

    Goda's (2000, Sect. 4.2) safety factors against sliding, ``mu (W' - U)/P``, and against
    overturning, ``(W' t - M_U)/M_P``, of the design wave, each at least ``required``
    (sliding, overturning; 1.2 and 1.2 by default).

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> r = caisson_report(parse_design(example_design_text()).analysis_inputs())
    >>> [(c.name, round(c.value, 3), c.verdict) for c in caisson_checks(r)]
    [('sliding safety factor', 1.16, 'FAIL'), ('overturning safety factor', 2.559, 'PASS')]
    """
    return stability_checks(r.analysis, required)


def stability_checks(a: CaissonAnalysis, required: tuple[float, float] = REQUIRED_SF) -> list[Check]:
    """:func:`caisson_checks` of an analysis of one caisson (Goda's procedure alone)."""
    st = a.stability
    return [Check.at_least("sliding safety factor", float(st.sliding), required[0]),
            Check.at_least("overturning safety factor", float(st.overturning), required[1])]


@dataclass(frozen=True)
class MapView:
    """The design wave's loaded map, sampled for a drawing.

    Attributes
    ----------
    k_axis, mu_axis : ndarray
        Sample positions (increasing, from 0 to ``k_max`` / ``mu_max``).
    grid : ndarray of uint8
        Mode codes, shape ``(len(mu_axis), len(k_axis))``.
    k_max, mu_max : float
        The view.
    points : dict
        Named points of the map inside the view, ``{name: (k, mu)}``.
    """

    k_axis: NDArray[np.float64]
    mu_axis: NDArray[np.float64]
    grid: NDArray[np.uint8]
    k_max: float
    mu_max: float
    points: dict[str, tuple[float, float]]


def map_view(r: CaissonReport, samples: int = 600) -> MapView:
    """The view of a report's map: the whole path, point A if it is near, and the grid of modes.

    The view reaches 15 % beyond the path's largest k and 60 % above mu;
    the corner A of the rest region is included when it lies within twice
    the path's reach (so that the rest region is seen whole).
    """
    k_path = float(np.max(r.path.k))
    k_max = 1.15 * max(k_path, r.k)
    mu_max = 1.6 * r.mu
    pts = named_points(r.map)
    if "A" in pts:
        ka, ma = pts["A"]
        if ka <= 2.0 * k_max:
            k_max = max(k_max, 1.12 * ka)
        if ma <= 3.0 * r.mu:
            mu_max = max(mu_max, 1.12 * ma)
    k_axis = np.linspace(0.0, k_max, samples)
    mu_axis = np.linspace(0.0, mu_max, samples)
    inside = {n: p for n, p in pts.items() if n != "O" and p[0] <= k_max and p[1] <= mu_max}
    return MapView(k_axis=k_axis, mu_axis=mu_axis, grid=mode_grid(k_axis, mu_axis, r.map),
                   k_max=k_max, mu_max=mu_max, points=inside)


def sheet_map(r: CaissonReport, view: MapView | None = None) -> tuple[MapView, MapData]:
    """What the design sheet's panel (d) draws: its view and the design wave's loaded map in it.

    :func:`~regimemap.maps.mapdata.compute_map` of the report's loaded map
    (:meth:`regimemap.maps.loadedmap.LoadedMap.parameters`) over ``[0, k_max] x
    [0, mu_max]`` of ``view`` (default :func:`map_view`): the exact region polygons,
    boundary curves and named points, as ``regimemap plot`` draws them.
    """
    view = map_view(r) if view is None else view
    return view, compute_map(r.map.parameters(), k_max=view.k_max, mu_max=view.mu_max)
