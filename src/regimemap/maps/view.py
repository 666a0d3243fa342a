"""What a map shows: its extent, boundary curves, named points and label anchors.

This module computes everything a drawing needs and imports no matplotlib,
after the split of pycalphad's ``mapping`` package (strategies compute,
``plotting.py`` draws).  :func:`compute_map` returns a :class:`MapData`; the
renderer (:mod:`regimemap.render`) only turns it into artists, so the numbers
behind every line and fill of a figure stay reachable.

Curves are named as in the report.  Above C (Chapter III): ``OA`` (mu = k, from
O to A), ``AB`` (the vertical k = k_A from A up), ``CD`` (mu = 1/gamma - k k'),
``mu_star`` (3.24) from A on and, in cases 2/3, ``dotted`` (3.44) mu = k k' -
1/gamma (Fig 3.8).  Below C (Chapter IV): ``OA``, ``AE`` (the vertical k = k_A),
``AB`` (4.21), ``DC`` (4.20), ``dotted`` (4.22) mu = k|k'|, ``mu_star`` (4.40)
from A on and ``mu_star_star`` (4.96) from F up to its pole.

Each curve is split into runs that *bound* a region of the map (the mode, or
the membership of the raw region, differs on its two sides) and runs that are
only *construction* lines (the same region on both sides), which the renderer
draws solid and dashed respectively.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Iterable, Sequence

import numpy as np

from .classify import classify
from ..mechanics.curves import (
    NamedPoint,
    dotted_line,
    line_OA,
    lower_line,
    mu_star,
    named_points,
    upper_line,
)
from .geometry import breakpoints, region_polygons
from ..mechanics.modes import MAP_MODES, Mode
from ..mechanics.block import Parameters
from ..mechanics.regions import raw_region

__all__ = [
    "CurveData",
    "MapData",
    "auto_extent",
    "compute_map",
    "label_anchor",
    "interior_point",
    "curve_label_anchor",
    "leader_label_anchor",
    "view_points",
    "box_hits",
    "nice_ceil",
    "simplify",
    "CURVE_LABELS",
]

#: Mathtext labels of the curves that carry one (the straight lines are named
#: by their end points, as in the report).
CURVE_LABELS: dict[str, str] = {
    "mu_star": r"$\mu^*(k)$",
    "mu_star_star": r"$\mu^{**}(k)$",
    "dotted_below": r"$\mu = k|k'|$",
    "dotted_above": r"$\mu = kk' - 1/\gamma$",
}

#: How far (in multiples of the reference scale k_A) a characteristic point may
#: lie and still be pulled into the automatic view.
_CAP = 12.0
#: Relative margin added around the characteristic points.
_MARGIN = 0.15


# -- small numeric helpers ----------------------------------------------------------


def nice_ceil(x: float, divisions: int = 8) -> float:
    """Round ``x > 0`` up to a multiple of a 'nice' step (1, 2, 2.5 or 5 x 10^n).

    The step is the smallest nice number >= ``x / divisions``, so an axis that
    ends at the result ends on a tick.

    Examples
    --------
    >>> nice_ceil(2.13), nice_ceil(0.53), nice_ceil(6.4)
    (2.5, 0.6, 7.0)
    """
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"nice_ceil needs a finite number > 0, got {x!r}")
    raw = x / divisions
    exp = math.floor(math.log10(raw))
    step = None
    for mant in (1.0, 2.0, 2.5, 5.0, 10.0):
        step = mant * 10.0**exp
        if step >= raw * (1.0 - 1e-12):
            break
    assert step is not None
    n = math.ceil(x / step - 1e-9)
    return float(round(n * step, 12))


def simplify(points: np.ndarray, tol: float, scale: tuple[float, float] = (1.0, 1.0)) -> np.ndarray:
    """Ramer-Douglas-Peucker simplification of a polyline.

    Parameters
    ----------
    points : ndarray, shape (n, 2)
        Vertices (k, mu).
    tol : float
        Largest allowed distance of a removed vertex from the simplified line,
        measured after dividing k and mu by ``scale``.
    scale : (float, float)
        Units of the two coordinates (the view extent), so that ``tol`` is a
        fraction of the view.

    Returns
    -------
    ndarray, shape (m, 2), m <= n
        A subset of the vertices, first and last kept.
    """
    pts = np.asarray(points, dtype=np.float64)
    n = len(pts)
    if n <= 2:
        return pts.copy()
    q = pts / np.asarray(scale, dtype=np.float64)
    keep = np.zeros(n, dtype=bool)
    keep[0] = keep[-1] = True
    stack = [(0, n - 1)]
    while stack:
        i, j = stack.pop()
        if j <= i + 1:
            continue
        seg = q[i + 1:j]
        a, b = q[i], q[j]
        d = b - a
        norm = math.hypot(d[0], d[1])
        if norm == 0.0:
            dist = np.hypot(seg[:, 0] - a[0], seg[:, 1] - a[1])
        else:
            dist = np.abs(d[0] * (seg[:, 1] - a[1]) - d[1] * (seg[:, 0] - a[0])) / norm
        m = int(np.argmax(dist))
        if dist[m] > tol:
            idx = i + 1 + m
            keep[idx] = True
            stack.append((i, idx))
            stack.append((idx, j))
    return pts[keep]


# -- extent ------------------------------------------------------------------------------


def _reference_scale(p: Parameters) -> float:
    """k_A when it is finite, else the abscissa of D (k' = -1)."""
    if math.isfinite(p.k_A):
        return p.k_A
    return p.k_D if math.isfinite(p.k_D) else 1.0 / p.gamma


def _mu_on_view(p: Parameters, k_max: float) -> float:
    """The largest mu* (from A on, where it is drawn) within [0, k_max]."""
    if not math.isfinite(p.k_A):
        return 0.0  # k' = -1: no rocking, mu* is not drawn
    k0 = min(p.k_A, k_max)
    if k0 >= k_max:
        return 0.0
    k = np.linspace(k0, k_max, 64)
    return float(np.max(mu_star(p, k)))


def auto_extent(params: Parameters, raw_mode: Mode | None = None, *,
                include: Iterable[tuple[float, float]] = (),
                k_max: float | None = None, mu_max: float | None = None) -> tuple[float, float]:
    """A view ``[0, k_max] x [0, mu_max]`` that shows the map's characteristic points.

    Parameters
    ----------
    params : Parameters
    raw_mode : Mode, optional
        For a single-mode figure of the report's raw region: also show what
        bounds that region (C' for RO and SRO- below C; the range beyond G for
        SRO+).
    include : iterable of (k, mu)
        Extra points to keep in view (design points).
    k_max, mu_max : float, optional
        User choices; the other limit is computed to fit.

    Returns
    -------
    (k_max, mu_max) : tuple of float
        Both finite and > 0, rounded up to a nice number.

    Notes
    -----
    Shown: A (and E), C above C, D, the point G = b/|a| and some of the range
    beyond it (cases 2/3, SRO+), B' with mu_B' when Delta >= 0, room right of D
    for SRO'- below C, and mu*(k) over the view (for the raw rest region, only
    the strip around A: Figs 3.1 and 4.2).  Points farther than 12 k_A
    (k' near 0 puts D and B' far away; k' = -1 puts A at infinity) are left out,
    so the neighbourhood of A never shrinks to a corner.
    """
    p = params
    ref = _reference_scale(p)
    cap = _CAP * ref
    ks: list[float] = []
    mus: list[float] = [1.0 / p.gamma]
    kA = p.k_A
    if math.isfinite(kA):
        ks += [kA, 1.6 * kA]
        mus.append(kA)
    if raw_mode is not None and Mode(raw_mode) is Mode.RE:
        # Figs 3.1 and 4.2: the rest region is the strip left of A, above OA
        ks = [2.2 * kA if math.isfinite(kA) else 2.0 / p.gamma]
        mus = [1.6 * kA if math.isfinite(kA) else 2.0 / p.gamma]
    elif p.above:
        if p.kprime > 0.0 and p.k_D <= cap:
            ks.append(p.k_D)
        G = p.b_over_abs_a
        if math.isfinite(G) and G <= cap:
            ks.append(G)
            if raw_mode is None or Mode(raw_mode) is Mode.SRO_PLUS:
                ks.append(min(3.0 * G, cap))
    else:
        if math.isfinite(p.k_D) and p.k_D <= cap:
            ks += [p.k_D, 2.0 * p.k_D]
        kB = p.k_Bprime
        if math.isfinite(kB) and (not math.isfinite(kA) or kB >= kA) and kB <= cap:
            ks.append(kB)
            mus.append(p.mu_Bprime)
        if raw_mode is not None and Mode(raw_mode) in (Mode.RO, Mode.SRO_MINUS):
            # the raw regions reach below DC beyond C' (the report's sector CC'C'')
            cp = named_points(p).get("C'")
            if cp is not None and cp.k <= max(cap, 2.5 * max(ks, default=0.0)):
                ks.append(cp.k)
                mus.append(cp.mu)
    for k, mu in include:
        if math.isfinite(k) and math.isfinite(mu):
            ks.append(float(k))
            mus.append(float(mu))
    if not ks:
        ks.append(ref)
    if k_max is None:
        k_max = nice_ceil((1.0 + _MARGIN) * max(max(ks), 1e-12))
    if mu_max is None:
        if raw_mode is None or Mode(raw_mode) is not Mode.RE:
            mus.append(_mu_on_view(p, k_max))
        if not math.isfinite(kA):  # rest up to mu = k everywhere: show OA to mid height
            mus.append(0.5 * k_max)
        mu_max = nice_ceil((1.0 + _MARGIN) * max(max(mus), 1e-12))
    return float(k_max), float(mu_max)


# -- curves ------------------------------------------------------------------------------


@dataclass(frozen=True)
class CurveData:
    """One boundary curve of a map, sampled within the view.

    Attributes
    ----------
    name : str
        Key: ``OA``, ``AB``, ``CD``, ``DC``, ``AE``, ``dotted``, ``mu_star``,
        ``mu_star_star``.
    label : str
        Mathtext label drawn next to the curve, or ``""`` (lines named by
        their end points).
    points : ndarray, shape (n, 2)
        Vertices (k, mu).
    boundary : ndarray of bool, shape (n - 1,)
        Whether each segment separates two regions (else a construction line).
    dotted : bool
        True for the report's dotted lines ((3.44) and (4.22)).
    equation : str
        Where the curve comes from in the report.
    """

    name: str
    label: str
    points: np.ndarray
    boundary: np.ndarray
    dotted: bool = False
    equation: str = ""

    def runs(self) -> list[tuple[np.ndarray, bool]]:
        """Consecutive pieces ``(vertices, is_boundary)`` of the curve."""
        if len(self.points) < 2:
            return []
        b = self.boundary
        cuts = np.flatnonzero(b[1:] != b[:-1]) + 1
        starts = np.concatenate([[0], cuts])
        ends = np.concatenate([cuts, [b.size]])
        return [(self.points[s:e + 1], bool(b[s])) for s, e in zip(starts, ends)]

    @property
    def is_boundary(self) -> bool:
        """True when some part of the curve bounds a region."""
        return bool(self.boundary.any())


def _side_key(p: Parameters, k: np.ndarray, mu: np.ndarray, raw: bool,
              modes: Sequence[Mode]) -> np.ndarray:
    """A code of 'which region' at each point: the mode (final map) or raw memberships."""
    k = np.maximum(k, 0.0)
    mu = np.maximum(mu, 0.0)
    if not raw:
        return classify(k, mu, p.gamma, p.kprime).astype(np.int64)
    key = np.zeros(k.shape, dtype=np.int64)
    for i, m in enumerate(modes):
        key |= raw_region(m, p, k, mu).astype(np.int64) << i
    return key


def _boundary_flags(p: Parameters, pts: np.ndarray, vertical: bool, raw: bool,
                    modes: Sequence[Mode], k_max: float, mu_max: float,
                    func: Callable[[Parameters, np.ndarray], np.ndarray] | None = None) -> np.ndarray:
    """For each segment: do its two sides belong to different regions?

    The sides are probed at the middle of the segment, 1e-6 of the view away
    from the curve, so that only the segments that touch another curve within
    that distance can be misjudged; :func:`_drop_short_runs` removes those.
    """
    mid = 0.5 * (pts[1:] + pts[:-1])
    if func is not None:  # a curved graph: probe on the curve, not on its chord
        with np.errstate(divide="ignore", invalid="ignore"):
            mid[:, 1] = func(p, mid[:, 0])
        mid[:, 1] = np.where(np.isfinite(mid[:, 1]), mid[:, 1], 0.0)
    if vertical:
        d = 1e-6 * k_max
        a = _side_key(p, mid[:, 0] - d, mid[:, 1], raw, modes)
        b = _side_key(p, mid[:, 0] + d, mid[:, 1], raw, modes)
        return a != b
    d = 1e-6 * mu_max
    up = _side_key(p, mid[:, 0], mid[:, 1] + d, raw, modes)
    down = _side_key(p, mid[:, 0], mid[:, 1] - d, raw, modes)
    flags = up != down
    # On the k axis itself there is nothing below: not a boundary of the map.
    flags &= mid[:, 1] > 2.0 * d
    return flags


def _drop_short_runs(flags: np.ndarray, pts: np.ndarray, scale: tuple[float, float],
                     min_len: float = 0.01) -> np.ndarray:
    """Flip runs of equal flags shorter than ``min_len`` (fraction of the view) to their neighbours'."""
    if flags.size < 3:
        return flags
    q = pts / np.asarray(scale)
    seg = np.hypot(*np.diff(q, axis=0).T)
    flags = flags.copy()
    for _ in range(3):
        cuts = np.flatnonzero(flags[1:] != flags[:-1]) + 1
        starts = np.concatenate([[0], cuts])
        ends = np.concatenate([cuts, [flags.size]])
        lengths = np.array([seg[s:e].sum() for s, e in zip(starts, ends)])
        changed = False
        for s, e, L in sorted(zip(starts, ends, lengths), key=lambda r: r[2]):
            if L >= min_len or len(starts) == 1:
                break
            if s == 0 and e == flags.size:
                break
            flags[s:e] = ~flags[s]
            changed = True
            break
        if not changed:
            break
    return flags


def _graph(f: Callable[[Parameters, np.ndarray], np.ndarray], p: Parameters, k0: float,
           k1: float, n: int, k: np.ndarray | None = None) -> np.ndarray:
    """Vertices (k, f(k)) for k in [k0, k1], with the map's breakpoints among them."""
    if k is None:
        k = np.linspace(k0, k1, n)
    bp = [x for x in breakpoints(p) if k0 < x < k1]
    k = np.unique(np.concatenate([k, bp]))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.column_stack([k, f(p, k)])


def _mu_star_star(p: Parameters, k: np.ndarray) -> np.ndarray:
    return (p.a * k - p.b) / (p.d - p.c * k)


def _dotted_344(p: Parameters, k: np.ndarray) -> np.ndarray:
    return -upper_line(p, k)


def _clip_mu(pts: np.ndarray, mu_lo: float, mu_hi: float) -> np.ndarray:
    """Keep the part of a graph (k increasing) with mu_lo <= mu <= mu_hi, cut exactly."""
    if len(pts) < 2:
        return pts
    k, mu = pts[:, 0], pts[:, 1]
    inside = (mu >= mu_lo) & (mu <= mu_hi)
    if inside.all():
        return pts
    out: list[tuple[float, float]] = []
    for i in range(len(pts)):
        if inside[i]:
            if i > 0 and not inside[i - 1]:
                out.append(_cut(k[i - 1], mu[i - 1], k[i], mu[i], mu_lo, mu_hi))
            out.append((k[i], mu[i]))
        elif i > 0 and inside[i - 1]:
            out.append(_cut(k[i - 1], mu[i - 1], k[i], mu[i], mu_lo, mu_hi))
            break  # the graphs used here leave the band once
    return np.asarray(out, dtype=np.float64).reshape(-1, 2)


def _cut(k0: float, m0: float, k1: float, m1: float, lo: float, hi: float) -> tuple[float, float]:
    level = hi if max(m0, m1) > hi else lo
    t = (level - m0) / (m1 - m0) if m1 != m0 else 0.0
    return (k0 + t * (k1 - k0), level)


_Curve = tuple[np.ndarray, bool, bool, str, "Callable[[Parameters, np.ndarray], np.ndarray] | None"]


def _curves(p: Parameters, k_max: float, mu_max: float, n: int) -> dict[str, _Curve]:
    """Geometry of every curve: name -> (points, vertical, dotted, equation, function).

    ``function`` is given for the curved graphs (mu*, mu**), whose chords are
    not on the curve; straight lines and verticals have None.
    """
    top = mu_max * 1.02
    k_end = k_max * 1.02
    kA = p.k_A
    out: dict[str, _Curve] = {}
    finite_A = math.isfinite(kA) and kA <= k_max

    def vertical(k: float, mu0: float, mu1: float) -> np.ndarray:
        mu = np.unique(np.concatenate([np.linspace(mu0, mu1, n), [kA] if mu0 < kA < mu1 else []]))
        return np.column_stack([np.full_like(mu, k), mu])

    k_oa = min(kA, k_end, top) if math.isfinite(kA) else min(k_end, top)
    out["OA"] = (_graph(line_OA, p, 0.0, k_oa, n), False, False, "mu = k (3.4), (4.7)", None)
    if p.above:
        if finite_A and kA < top:
            out["AB"] = (vertical(kA, kA, top), True, False, "k = k_A (3.5), (3.17)", None)
        k1 = min(p.k_D, k_end) if p.kprime > 0 else k_end
        out["CD"] = (_clip_mu(_graph(upper_line, p, 0.0, k1, n), 0.0, top), False, False,
                     "mu = 1/gamma - k k' (Section III.2)", None)
        if finite_A:
            out["mu_star"] = (_clip_mu(_graph(mu_star, p, kA, k_end, n), 0.0, top), False, False,
                              "mu*(k) (3.24)", mu_star)
        if p.a < 0.0 and p.k_D < k_max:
            out["dotted"] = (_clip_mu(_graph(_dotted_344, p, p.k_D, k_end, n), 0.0, top), False,
                             True, "mu = k k' - 1/gamma (3.44)", None)
    else:
        if finite_A:
            out["AE"] = (vertical(kA, 0.0, top), True, False, "k = k_A (4.10), (4.37)", None)
        out["AB"] = (_clip_mu(_graph(upper_line, p, 0.0, k_end, n), 0.0, top), False, False,
                     "mu = 1/gamma + k|k'| (4.21)", None)
        if math.isfinite(p.k_D) and p.k_D < k_max:
            out["DC"] = (_clip_mu(_graph(lower_line, p, p.k_D, k_end, n), 0.0, top), False, False,
                         "mu = -1/gamma + k|k'| (4.20)", None)
        out["dotted"] = (_clip_mu(_graph(dotted_line, p, 0.0, k_end, n), 0.0, top), False, True,
                         "mu = k|k'| (4.22)", None)
        if finite_A:
            out["mu_star"] = (_clip_mu(_graph(mu_star, p, kA, k_end, n), 0.0, top), False, False,
                              "mu*(k) (4.40)", mu_star)
        kF = p.k_F
        if 0.0 <= kF < k_max:
            # mu** = (ak - b)/(d - ck) reaches the top of the view at k = (b + M d)/(a + M c)
            k_top = (p.b + top * p.d) / (p.a + top * p.c)
            k1 = min(k_top, k_end, p.k_pole)
            kk = kF + (k1 - kF) * np.sin(np.linspace(0.0, 0.5 * np.pi, n))  # dense near the pole
            pts = _graph(_mu_star_star, p, kF, k1, n, k=kk)
            pts = pts[np.isfinite(pts[:, 1]) & (pts[:, 1] >= -1e-12)]
            if len(pts) >= 2:
                pts[:, 1] = np.maximum(pts[:, 1], 0.0)
                out["mu_star_star"] = (_clip_mu(pts, 0.0, top), False, False,
                                       "mu**(k) (4.96)-(4.97)", _mu_star_star)
    return out


# Which curves a single-mode (raw) figure draws although they bound nothing there:
# (mode, above C) -> curve names.
_CONTEXT: dict[tuple[Mode, bool], tuple[str, ...]] = {
    (Mode.SRO_PLUS, True): ("dotted",),  # Fig 3.8: "the dotted line lies above mu*(k)"
    (Mode.SL, False): ("dotted",),  # Fig 4.3: xi <= 0 above the dotted line (4.22)
    # Figs 4.4a-b and 4.5a-b draw mu* "together with lines AB and DC" (Section IV.3);
    # the Discussion names regions BB'C'C and CC'C'' by them.
    (Mode.RO, False): ("AB", "DC"),
    (Mode.SRO_MINUS, False): ("AB", "DC"),
    (Mode.SRO_PRIME_MINUS, False): ("mu_star_star",),  # Fig 4.6: mu**(k) of (4.96)
}


# -- the whole map -------------------------------------------------------------------------


@dataclass(frozen=True)
class MapData:
    """Everything a map shows, in data coordinates (no matplotlib).

    Attributes
    ----------
    params : Parameters
    k_max, mu_max : float
        The view ``[0, k_max] x [0, mu_max]``.
    modes : tuple of Mode
        The modes whose regions are shaded.
    raw : bool
        True for the report's raw regions (single-mode figures), False for
        the final map (one mode per point, Section 4.7).
    polygons : dict[Mode, list[ndarray]]
        Region polygons from :func:`regimemap.geometry.region_polygons`,
        simplified; they extend above the view and are clipped when drawn.
    curves : dict[str, CurveData]
        The boundary curves drawn (see the module docstring for the names).
    points : dict[str, NamedPoint]
        The report's named points that lie in view on a drawn curve.
    line_ends : dict[str, tuple[float, float]]
        Names written at the far end of a line, as the report's sketches do
        (``B`` on AB, ``C`` on DC below C).
    """

    params: Parameters
    k_max: float
    mu_max: float
    modes: tuple[Mode, ...]
    raw: bool
    polygons: dict[Mode, list[np.ndarray]]
    curves: dict[str, CurveData]
    points: dict[str, NamedPoint]
    line_ends: dict[str, tuple[float, float]] = field(default_factory=dict)

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(0, k_max, 0, mu_max)``, as matplotlib's ``extent``."""
        return (0.0, self.k_max, 0.0, self.mu_max)


def _on_polyline(pt: tuple[float, float], pts: np.ndarray, scale: tuple[float, float],
                 tol: float = 2e-3) -> bool:
    q = np.asarray(pt) / scale
    s = pts / np.asarray(scale)
    a, b = s[:-1], s[1:]
    d = b - a
    L2 = np.einsum("ij,ij->i", d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", q - a, d) / L2, 0.0), 0.0, 1.0)
    proj = a + t[:, None] * d
    return bool(np.min(np.hypot(*(proj - q).T)) <= tol)


def compute_map(params: Parameters, *, k_max: float | None = None, mu_max: float | None = None,
                modes: Iterable[Mode] | None = None, raw: bool = False, samples: int = 801,
                curves: bool = True, include: Iterable[tuple[float, float]] = (),
                tolerance: float = 2e-4) -> MapData:
    """Compute the polygons, curves and named points of one map.

    Parameters
    ----------
    params : Parameters
    k_max, mu_max : float, optional
        The view; computed by :func:`auto_extent` when omitted.
    modes : iterable of Mode, optional
        Modes to shade (default: the six map modes).
    raw : bool
        The report's raw region of each mode instead of the final map.
    samples : int
        Samples of k for the region polygons and the curves (>= 2).
    curves : bool
        Compute the boundary curves and named points (else empty).
    include : iterable of (k, mu)
        Points to keep in the automatic view.
    tolerance : float
        Simplification tolerance of the polygons, as a fraction of the view.

    Returns
    -------
    MapData
    """
    p = params
    modes_t = tuple(MAP_MODES if modes is None else (Mode(m) for m in modes))
    raw_mode = modes_t[0] if raw and len(modes_t) == 1 else None
    include = list(include)
    if k_max is None or mu_max is None:
        k_max, mu_max = auto_extent(p, raw_mode, include=include, k_max=k_max, mu_max=mu_max)
    samples = max(int(samples), 2)
    polys = region_polygons(p, k_max, mu_max, modes=modes_t, raw=raw, samples=samples)
    scale = (k_max, mu_max)
    polys = {m: [simplify(poly, tolerance, scale) for poly in lst] for m, lst in polys.items()}

    curve_data: dict[str, CurveData] = {}
    points: dict[str, NamedPoint] = {}
    ends: dict[str, tuple[float, float]] = {}
    if curves:
        n_curve = max(16, min(samples, 400))
        for name, (pts, vertical, dotted, eq, func) in _curves(p, k_max, mu_max, n_curve).items():
            if len(pts) < 2:
                continue
            flags = _drop_short_runs(
                _boundary_flags(p, pts, vertical, raw, modes_t, k_max, mu_max, func), pts, scale)
            label_key = name
            if name == "dotted":
                label_key = "dotted_above" if p.above else "dotted_below"
            keep = (not raw) or flags.any() or name == "OA" or (
                raw_mode is not None and name in _CONTEXT.get((raw_mode, p.above), ()))
            if raw and raw_mode is None:
                keep = True
            if not raw and name == "dotted" and p.above:
                keep = False  # (3.44) bounds nothing on the final map
            if not keep:
                continue
            # simplify each boundary / construction run on its own, so runs keep their ends
            cut = np.flatnonzero(np.diff(flags.astype(np.int8))) + 1
            bounds = np.concatenate([[0], cut, [len(pts) - 1]])
            pieces, piece_flags = [], []
            for i, j in zip(bounds[:-1], bounds[1:]):
                if j > i:
                    sub = simplify(pts[i:j + 1], tolerance, scale)
                    pieces.append(sub if not pieces else sub[1:])
                    piece_flags.append(np.full(len(sub) - 1, flags[i]))
            pts = np.concatenate(pieces)
            flags = np.concatenate(piece_flags)
            curve_data[name] = CurveData(name, CURVE_LABELS.get(label_key, ""), pts, flags,
                                         dotted, eq)
        # OA (kept for context in raw figures) only where it leads to a drawn point A
        oa = curve_data.get("OA")
        if raw and oa is not None and not oa.is_boundary and math.isfinite(p.k_A):
            others = [c for key, c in curve_data.items() if key != "OA"]
            if not any(_on_polyline((p.k_A, p.k_A), c.points, scale) for c in others):
                del curve_data["OA"]
        # the report's points that are drawn: where two drawn curves meet, or a drawn
        # curve meets an axis (D, E, F, G on the k axis, C on the mu axis)
        for name, pt in named_points(p).items():
            if not (0.0 <= pt.k <= k_max and 0.0 <= pt.mu <= mu_max):
                continue
            if name == "B'" and not (math.isfinite(p.k_A) and pt.k >= p.k_A):
                continue  # Delta < 0: mu* from A never meets AB again (Section IV.3)
            n_on = sum(_on_polyline((pt.k, pt.mu), c.points, scale) for c in curve_data.values())
            on_axis = pt.k <= 1e-12 * k_max or pt.mu <= 1e-12 * mu_max
            if name == "O" or n_on >= 2 or (on_axis and n_on >= 1):
                points[name] = pt
        # names at the far ends of lines (as in the report's sketches)
        if p.above:
            if "AB" in curve_data:
                ends["B"] = tuple(curve_data["AB"].points[-1])  # type: ignore[assignment]
        else:
            if "AB" in curve_data and len(curve_data["AB"].points):
                ends["B"] = tuple(curve_data["AB"].points[-1])  # type: ignore[assignment]
            if "DC" in curve_data and len(curve_data["DC"].points):
                ends["C"] = tuple(curve_data["DC"].points[-1])  # type: ignore[assignment]
            if "C'" in points and "mu_star" in curve_data:
                ends["C''"] = tuple(curve_data["mu_star"].points[-1])  # type: ignore[assignment]
    return MapData(p, float(k_max), float(mu_max), modes_t, bool(raw), polys, curve_data,
                   points, ends)


# -- labels ----------------------------------------------------------------------------------


Box = tuple[float, float, float, float]


def _overlaps(box: Box, others: Sequence[Box]) -> bool:
    x0, y0, x1, y1 = box
    return any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in others)


def _polygon_columns(polygon: np.ndarray, k_max: float, mu_max: float, columns: int
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Column centres x and the polygon's interval [lo, hi] on each, in view fractions."""
    poly = np.asarray(polygon, dtype=np.float64)
    x = poly[:, 0] / k_max
    y = np.clip(poly[:, 1] / mu_max, 0.0, 1.0)
    xs = (np.arange(columns) + 0.5) / columns
    lo, hi = _column_intervals(x, y, xs)
    return xs, lo, hi


def label_anchor(polygon: np.ndarray, k_max: float, mu_max: float, box: tuple[float, float],
                 columns: int = 400, obstacles: Sequence[Box] = (),
                 lines: Sequence[np.ndarray] = ()) -> tuple[float, float] | None:
    """A point well inside a region polygon, clipped to the view, where a label fits.

    Parameters
    ----------
    polygon : ndarray, shape (n, 2)
        A polygon of :func:`regimemap.geometry.region_polygons` (one interval
        of mu per k, as every region of the report is).
    k_max, mu_max : float
        The view.
    box : (float, float)
        Width and height of the label, as fractions of the view.
    columns : int
        Resolution of the search along k.
    obstacles : sequence of (x0, y0, x1, y1)
        Boxes (fractions of the view) the label must not overlap, e.g. the
        names of points.
    lines : sequence of ndarray
        Dense polylines (view fractions, :func:`view_points`) the label should
        not cover; ignored if that leaves no room.

    Returns
    -------
    (k, mu) or None
        The centre of the label: among the windows of columns 1.5 label
        widths wide (then 1 width), the one with the tallest common interval
        of mu, moved up or down to clear the obstacles; None when the label
        does not fit.
    """
    if len(polygon) < 3:
        return None
    if len(lines):
        dense = np.concatenate(list(lines))
        found = _label_anchor(polygon, k_max, mu_max, box, columns, obstacles, dense)
        if found is not None:
            return found
    return _label_anchor(polygon, k_max, mu_max, box, columns, obstacles, np.empty((0, 2)))


def _label_anchor(polygon: np.ndarray, k_max: float, mu_max: float, box: tuple[float, float],
                  columns: int, obstacles: Sequence[Box], dense: np.ndarray
                  ) -> tuple[float, float] | None:
    xs, lo, hi = _polygon_columns(polygon, k_max, mu_max, columns)
    w, h = box
    win = np.lib.stride_tricks.sliding_window_view
    for factor in (1.5, 1.0):
        half = max(1, int(math.ceil(0.5 * factor * w * columns)))
        if 2 * half + 1 > columns:
            continue
        L = win(lo, 2 * half + 1).max(axis=1)
        U = win(hi, 2 * half + 1).min(axis=1)
        room = U - L
        ok = np.flatnonzero(room >= h * 1.15)
        if ok.size == 0:
            continue
        # best room first; among near-equal rooms, the middle of the run first
        mid = ok[len(ok) // 2]
        order = sorted(ok.tolist(), key=lambda c: (-round(float(room[c]) / 0.02), abs(c - mid)))
        for c in order[:200]:
            cx = float(xs[c + half])
            y_lo, y_hi = L[c] + 0.55 * h, U[c] - 0.55 * h
            centre = 0.5 * (L[c] + U[c])
            steps = [0.0] + [s * j * 0.25 * h for j in range(1, 40) for s in (1, -1)]
            for dy in steps:
                cy = centre + dy
                if cy < y_lo - 1e-12 or cy > y_hi + 1e-12:
                    continue
                b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                if not _overlaps(b, obstacles) and not box_hits(b, dense):
                    return cx * k_max, float(cy) * mu_max
    return None


def interior_point(polygon: np.ndarray, k_max: float, mu_max: float,
                   columns: int = 400) -> tuple[float, float] | None:
    """A point inside a (thin) polygon within the view, for the tip of a leader line.

    The middle of the median column among those at least 60 % as tall as the
    tallest; None if the polygon has no part in the view.
    """
    if len(polygon) < 3:
        return None
    xs, lo, hi = _polygon_columns(polygon, k_max, mu_max, columns)
    room = hi - lo
    if room.max() <= 0.0:
        return None
    good = np.flatnonzero(room >= 0.6 * room.max())
    c = int(good[len(good) // 2])
    return float(xs[c] * k_max), float(0.5 * (lo[c] + hi[c]) * mu_max)


def view_points(points: np.ndarray, k_max: float, mu_max: float, step: float = 0.003
                ) -> np.ndarray:
    """A polyline in view fractions, with vertices at most ``step`` apart (for hit tests)."""
    q = np.asarray(points, dtype=np.float64) / (k_max, mu_max)
    if len(q) < 2:
        return q
    seg = np.hypot(*np.diff(q, axis=0).T)
    n = np.maximum(1, np.ceil(seg / step).astype(int))
    parts = [q[:1]]
    for i, m in enumerate(n):
        t = (np.arange(1, m + 1) / m)[:, None]
        parts.append(q[i] + t * (q[i + 1] - q[i]))
    return np.concatenate(parts)


def box_hits(box: Box, dense: np.ndarray) -> bool:
    """Does any of the points ``dense`` (view fractions) fall inside ``box``?"""
    if dense.size == 0:
        return False
    x0, y0, x1, y1 = box
    return bool(np.any((dense[:, 0] > x0) & (dense[:, 0] < x1) & (dense[:, 1] > y0)
                       & (dense[:, 1] < y1)))


def curve_label_anchor(points: np.ndarray, k_max: float, mu_max: float,
                       box: tuple[float, float], lines: Sequence[np.ndarray] = (),
                       obstacles: Sequence[Box] = (), start: float = 0.2,
                       gap: float = 0.008, clearance: float = 0.025
                       ) -> tuple[float, float] | None:
    """Where to centre a curve's label: beside the curve, clear of lines and other labels.

    Candidates run along the visible part of the curve from near its end back
    to ``start`` of its length, on either side; the first whose box lies in
    the view, overlaps no obstacle, crosses no line (``lines``: dense
    polylines in view fractions, from :func:`view_points`) and has no other
    line within ``clearance`` (so that it cannot be read as another line's
    label) wins; if none has that clearance, the first without it.

    Returns
    -------
    (k, mu) or None
        Centre of the label in data coordinates.
    """
    q = view_points(points, k_max, mu_max, 0.003)
    inside = (q[:, 0] >= 0) & (q[:, 0] <= 1) & (q[:, 1] >= 0) & (q[:, 1] <= 1)
    q = q[inside]
    if len(q) < 2:
        return None
    w, h = box
    own = view_points(points, k_max, mu_max, 0.003)
    others = [ln for ln in lines if not (len(ln) == len(own) and np.array_equal(ln, own))]
    everything = np.concatenate(list(lines)) if len(lines) else np.empty((0, 2))
    other = np.concatenate(others) if others else np.empty((0, 2))
    for clear in (clearance, 0.0):
        found = _beside_curve(q, w, h, gap, start, obstacles, everything, other, clear)
        if found is not None:
            return float(found[0] * k_max), float(found[1] * mu_max)
    return None


def _beside_curve(q: np.ndarray, w: float, h: float, gap: float, start: float,
                  obstacles: Sequence[Box], everything: np.ndarray, other: np.ndarray,
                  clear: float) -> tuple[float, float] | None:
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(q, axis=0).T))])
    if s[-1] <= 0.0:
        return None
    for frac in np.arange(0.96, start - 1e-9, -0.02):
        i = int(np.searchsorted(s, frac * s[-1]))
        i = min(max(i, 1), len(q) - 1)
        t = q[i] - q[i - 1]
        norm = math.hypot(t[0], t[1])
        if norm == 0.0:
            continue
        n = np.array([-t[1], t[0]]) / norm
        if n[1] < 0:
            n = -n  # first try the side above the curve
        reach = 0.5 * (abs(w * n[0]) + abs(h * n[1])) + gap
        for side in (1.0, -1.0):
            cx, cy = q[i] + side * reach * n
            b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
            if b[0] < 0.005 or b[1] < 0.005 or b[2] > 0.995 or b[3] > 0.995:
                continue
            if _overlaps(b, obstacles) or box_hits(b, everything):
                continue
            if clear and box_hits((b[0] - clear, b[1] - clear, b[2] + clear, b[3] + clear),
                                  other):
                continue  # another line this close would make the label ambiguous
            return float(cx), float(cy)
    return None


def leader_label_anchor(target: tuple[float, float], k_max: float, mu_max: float,
                        box: tuple[float, float], lines: Sequence[np.ndarray] = (),
                        obstacles: Sequence[Box] = ()) -> tuple[float, float] | None:
    """Where to put the label of a region too thin to hold it, pointing at ``target``.

    Tries positions around the target at growing distances; the label's box
    must lie in the view, clear of lines and obstacles, and the leader line
    must not cross an obstacle.  Returns the label centre (data) or None.
    """
    x, y = target[0] / k_max, target[1] / mu_max
    w, h = box
    everything = np.concatenate(list(lines)) if len(lines) else np.empty((0, 2))
    # 16 directions, diagonals first (labels beside a thin band read best there)
    angles = [-45, 45, 135, -135, -90, 90, 0, 180, -22.5, 22.5, 157.5, -157.5, -67.5, 67.5,
              112.5, -112.5]
    directions = [(math.cos(math.radians(a)), math.sin(math.radians(a))) for a in angles]
    for strict_lines, strict_leader in ((True, True), (False, True), (False, False)):
        for dist in (0.1, 0.15, 0.22, 0.3, 0.4):
            for ux, uy in directions:
                cx, cy = x + ux * dist, y + uy * dist * 0.8
                b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                if b[0] < 0.01 or b[1] < 0.01 or b[2] > 0.99 or b[3] > 0.99:
                    continue
                if _overlaps(b, obstacles) or (strict_lines and box_hits(b, everything)):
                    continue
                if strict_leader:
                    t = np.linspace(0.0, 1.0, 40)[:, None]
                    leader = np.array([x, y]) + t * (np.array([cx, cy]) - np.array([x, y]))
                    if any(box_hits(o, leader) for o in obstacles):
                        continue
                return float(cx * k_max), float(cy * mu_max)
    return None


def _column_intervals(x: np.ndarray, y: np.ndarray, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """lo, hi of a closed polygon along the vertical lines x = xs (empty: lo = 1, hi = 0)."""
    x0, y0 = x, y
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    xa, xb = np.minimum(x0, x1), np.maximum(x0, x1)
    hit = (xa[:, None] <= xs[None, :]) & (xs[None, :] < xb[:, None])
    dx = np.where(x1 != x0, x1 - x0, 1.0)
    t = (xs[None, :] - x0[:, None]) / dx[:, None]
    yy = y0[:, None] + t * (y1 - y0)[:, None]
    lo = np.where(hit, yy, np.inf).min(axis=0)
    hi = np.where(hit, yy, -np.inf).max(axis=0)
    empty = ~hit.any(axis=0)
    lo[empty] = 1.0
    hi[empty] = 0.0
    return lo, hi
