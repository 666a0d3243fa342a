"""The curves and named points of a map: sampled in the view, split into boundary runs.

The curves are those of the catalogue :func:`regimemap.mechanics.curves.map_curves`,
sampled within the view.  Each is split into runs that *bound* a region of the
map (the mode, or the membership of the raw region, differs on its two sides)
and runs that are only *construction* lines (the same region on both sides),
which the renderer draws solid and dashed respectively.  :func:`curve_data`,
:func:`drawn_points` and :func:`line_ends` are the steps of
:func:`regimemap.maps.mapdata.compute_map` that find them.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from ..mechanics.block import Parameters
from ..mechanics.curves import Curve, NamedPoint, map_curves, named_points
from ..mechanics.modes import Mode
from ..mechanics.regions import raw_region
from .classify import classify
from .geometry import breakpoints
from .view import simplify

__all__ = ["CurveData", "curve_data", "drawn_points", "line_ends"]


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
        starts, ends = _runs(self.boundary)
        return [(self.points[s:e + 1], bool(self.boundary[s])) for s, e in zip(starts, ends)]

    @property
    def is_boundary(self) -> bool:
        """True when some part of the curve bounds a region."""
        return bool(self.boundary.any())


def _runs(flags: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The runs of equal ``flags``: their starts and their ends (exclusive)."""
    cuts = np.flatnonzero(flags[1:] != flags[:-1]) + 1
    return np.concatenate([[0], cuts]), np.concatenate([cuts, [flags.size]])


def _side_key(p: Parameters, k: np.ndarray, mu: np.ndarray, raw: bool,
              modes: Sequence[Mode]) -> np.ndarray:
    """A code of 'which region' at each point: the mode (final map) or raw memberships."""
    k = np.maximum(k, 0.0)
    mu = np.maximum(mu, 0.0)
    if not raw:
        return classify(k, mu, p.gamma, p.kprime, **p.loads).astype(np.int64)
    key = np.zeros(k.shape, dtype=np.int64)
    for i, m in enumerate(modes):
        key |= raw_region(m, p, k, mu).astype(np.int64) << i
    return key


def _boundary_flags(p: Parameters, pts: np.ndarray, vertical: bool, raw: bool,
                    modes: Sequence[Mode], k_max: float, mu_max: float,
                    func: Callable[[np.ndarray], np.ndarray] | None = None) -> np.ndarray:
    """For each segment: do its two sides belong to different regions?

    The sides are probed at the middle of the segment, 1e-6 of the view away
    from the curve, so that only the segments that touch another curve within
    that distance can be misjudged; :func:`_drop_short_runs` removes those.
    A graph ``mu = func(k)`` is probed on the curve itself, at the middle of the
    segment's k: the middle of its chord lies off a curved graph (mu*, mu**, and
    every line of a loaded map whose uplift grows with the push) by more than
    the probes' distance, so that both probes would fall on one side of it and a
    boundary would be drawn as a construction line.
    """
    mid = 0.5 * (pts[1:] + pts[:-1])
    if func is not None:  # a graph: probe on the curve, not on its chord
        with np.errstate(divide="ignore", invalid="ignore"):
            on = np.asarray(func(mid[:, 0]), dtype=np.float64)
        mid[:, 1] = np.where(np.isfinite(on), on, mid[:, 1])
    if vertical:
        d = 1e-6 * k_max
        a = _side_key(p, mid[:, 0] - d, mid[:, 1], raw, modes)
        b = _side_key(p, mid[:, 0] + d, mid[:, 1], raw, modes)
        return np.asarray(a != b)
    d = 1e-6 * mu_max
    up = _side_key(p, mid[:, 0], mid[:, 1] + d, raw, modes)
    down = _side_key(p, mid[:, 0], mid[:, 1] - d, raw, modes)
    flags = np.asarray(up != down)
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
        starts, ends = _runs(flags)
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


def _graph(f: Callable[[np.ndarray], np.ndarray], p: Parameters, k0: float,
           k1: float, n: int, k: np.ndarray | None = None) -> np.ndarray:
    """Vertices (k, f(k)) for k in [k0, k1], with the map's breakpoints among them."""
    if k is None:
        k = np.linspace(k0, k1, n)
    bp = [x for x in breakpoints(p) if k0 < x < k1]
    k = np.unique(np.concatenate([k, bp]))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.column_stack([k, f(k)])


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


def _sampled(c: Curve, p: Parameters, k_max: float, mu_max: float, n: int) -> np.ndarray | None:
    """Vertices of the catalogue curve ``c`` within the view (None: nothing to draw).

    Graphs are sampled from ``c.k_from`` to ``c.k_to`` (or a little beyond the
    view) and cut exactly where they leave the band of mu; the vertical k = k_A
    runs from its foot to the top; mu** is sampled densely towards its pole.
    """
    top = mu_max * 1.02
    k_end = k_max * 1.02
    kA = p.k_A
    if c.vertical_k is not None and c.name in ("LO", "LO_end"):
        if not 0.0 <= c.vertical_k <= k_max:
            return None
        mu = np.linspace(0.0, top, n)
        return np.column_stack([np.full_like(mu, c.vertical_k), mu])
    if c.vertical_k is not None:
        mu0 = p.mu_A if p.above else 0.0
        if p.above and not (kA <= k_max and kA < top):
            return None
        if not p.above and not (math.isfinite(kA) and kA <= k_max):
            return None
        mu = np.unique(np.concatenate([np.linspace(mu0, top, n), [kA] if mu0 < kA < top else []]))
        return np.column_stack([np.full_like(mu, c.vertical_k), mu])
    assert c.func is not None
    if c.name == "OA":
        if p.loaded:
            pts = _graph(c.func, p, 0.0, min(c.k_to, k_end), n)
            return _clip_mu(pts[np.isfinite(pts[:, 1])], 0.0, top)
        return _graph(c.func, p, 0.0, min(c.k_to, k_end, top), n)
    if c.name == "mu_star_star":
        kF = c.k_from
        if not 0.0 <= kF < k_max:
            return None
        # mu** = (ak - b)/(d - ck) reaches the top of the view at k = (b + M d)/(a + M c)
        cst = p.constants
        k_top = (cst.bP + top * cst.dP) / (cst.aP + top * cst.cP)
        k1 = min(k_top, k_end, c.k_to)
        kk = kF + (k1 - kF) * np.sin(np.linspace(0.0, 0.5 * np.pi, n))  # dense near the pole
        pts = _graph(c.func, p, kF, k1, n, k=kk)
        pts = pts[np.isfinite(pts[:, 1]) & (pts[:, 1] >= -1e-12)]
        if len(pts) < 2:
            return None
        pts[:, 1] = np.maximum(pts[:, 1], 0.0)
        return _clip_mu(pts, 0.0, top)
    # a curve that starts right of the view is not drawn (mu* from A: up to the edge)
    if c.k_from > 0.0 and not (c.k_from <= k_max if c.name == "mu_star" else c.k_from < k_max):
        return None
    pts = _graph(c.func, p, c.k_from, min(c.k_to, k_end), n)
    if p.loaded:  # a loaded curve may have a pole (W = 0, f_y = 0): keep its finite part
        pts = pts[np.isfinite(pts[:, 1])]
    return _clip_mu(pts, 0.0, top)


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


def _point(xy: np.ndarray) -> tuple[float, float]:
    return (float(xy[0]), float(xy[1]))


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


def curve_data(p: Parameters, k_max: float, mu_max: float, n_curve: int, raw: bool,
               raw_mode: Mode | None, modes: tuple[Mode, ...], tolerance: float
               ) -> dict[str, CurveData]:
    """The curves drawn on the map, sampled with ``n_curve`` points in the view and simplified,
    each point flagged as a boundary or a construction line."""
    scale = (k_max, mu_max)
    out: dict[str, CurveData] = {}
    for name, curve in map_curves(p).items():
        pts = _sampled(curve, p, k_max, mu_max, n_curve)
        if pts is None or len(pts) < 2:
            continue
        # every graph is probed on the curve, not on its chords (curved: mu*, mu**, loaded lines)
        func = None if curve.vertical else curve.func
        flags = _drop_short_runs(
            _boundary_flags(p, pts, curve.vertical, raw, modes, k_max, mu_max, func), pts, scale)
        if not _keep_curve(p, name, flags, raw, raw_mode):
            continue
        pts, flags = _simplify_runs(pts, flags, tolerance, scale)
        out[name] = CurveData(name, curve.tex, pts, flags, curve.dotted,
                              f"{curve.equation} {curve.report}")
    # OA (kept for context in raw figures) only where it leads to a drawn point A
    oa = out.get("OA")
    if raw and oa is not None and not oa.is_boundary and math.isfinite(p.k_A):
        others = [c for key, c in out.items() if key != "OA"]
        if not any(_on_polyline((p.k_A, p.k_A), c.points, scale) for c in others):
            del out["OA"]
    return out


def _keep_curve(p: Parameters, name: str, flags: np.ndarray, raw: bool, raw_mode: Mode | None) -> bool:
    """Whether the map draws the curve: every curve that bounds something on the final map; on
    a raw figure the curves of its mode's region and their context (all of them for every mode)."""
    if not raw:
        return not (name == "dotted" and p.above)  # (3.44) bounds nothing on the final map
    return (raw_mode is None or bool(flags.any()) or name == "OA"
            or name in _CONTEXT.get((raw_mode, p.above), ()))


def _simplify_runs(pts: np.ndarray, flags: np.ndarray, tolerance: float, scale: tuple[float, float]
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Simplify each boundary / construction run on its own, so runs keep their ends."""
    cut = np.flatnonzero(np.diff(flags.astype(np.int8))) + 1
    bounds = np.concatenate([[0], cut, [len(pts) - 1]])
    pieces: list[np.ndarray] = []
    piece_flags: list[np.ndarray] = []
    for i, j in zip(bounds[:-1], bounds[1:]):
        if j > i:
            sub = simplify(pts[i:j + 1], tolerance, scale)
            pieces.append(sub if not pieces else sub[1:])
            piece_flags.append(np.full(len(sub) - 1, flags[i]))
    return np.concatenate(pieces), np.concatenate(piece_flags)


def drawn_points(p: Parameters, curves: dict[str, CurveData], k_max: float, mu_max: float
                 ) -> dict[str, NamedPoint]:
    """The report's points that are drawn: where two drawn curves meet, or a drawn curve meets
    an axis (D, E, F, G on the k axis, C on the mu axis)."""
    scale = (k_max, mu_max)
    points: dict[str, NamedPoint] = {}
    for name, pt in named_points(p).items():
        if not (0.0 <= pt.k <= k_max and 0.0 <= pt.mu <= mu_max):
            continue
        if name == "B'" and not (math.isfinite(p.k_A) and pt.k >= p.k_A):
            continue  # Delta < 0: mu* from A never meets AB again (Section IV.3)
        n_on = sum(_on_polyline((pt.k, pt.mu), c.points, scale) for c in curves.values())
        on_axis = pt.k <= 1e-12 * k_max or pt.mu <= 1e-12 * mu_max
        if name == "O" or n_on >= 2 or (on_axis and n_on >= 1):
            points[name] = pt
    return points


def line_ends(p: Parameters, curves: dict[str, CurveData], points: dict[str, NamedPoint]
              ) -> dict[str, tuple[float, float]]:
    """Names at the far ends of lines (as in the report's sketches)."""
    ends: dict[str, tuple[float, float]] = {}
    if "AB" in curves and len(curves["AB"].points):
        ends["B"] = _point(curves["AB"].points[-1])
    if not p.above and "DC" in curves and len(curves["DC"].points):
        ends["C"] = _point(curves["DC"].points[-1])
    if not p.above and "C'" in points and "mu_star" in curves:
        ends["C''"] = _point(curves["mu_star"].points[-1])
    return ends
