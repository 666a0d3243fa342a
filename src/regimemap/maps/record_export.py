"""Export a map as data: a labelled grid (``.npz``, ``.csv``) or vector geometry (``.json``).

Three formats, chosen by the file's suffix (:func:`export_map`):

``.npz`` (numpy)
    ``k`` (1-D, n_k), ``mu`` (1-D, n_mu), ``mode`` (2-D uint8, shape
    (n_mu, n_k): rows mu, columns k, ``mode[i, j]`` is the code of
    :class:`~regimemap.modes.Mode` at ``(k[j], mu[i])``), ``labels`` (the
    mode labels indexed by code: ``labels[mode]`` gives "RE", "SL", ...),
    ``gamma``, ``kprime``, ``k_max``, ``mu_max``, ``case`` and the derived
    constants ``a``, ``b``, ``c``, ``d``, ``k_A``, ``k_Bprime``, ``mu_Bprime``,
    ``b_over_abs_a``, ``delta`` (0-d arrays; inf where undefined).  Read with
    ``numpy.load(path)`` (no pickle needed).
``.csv``
    Header ``k,mu,mode`` and one row per grid point, mu outer and k inner,
    the mode as its label.  Numbers are written with ``repr`` so they read
    back to the very floats that were classified.
``.json``
    Everything needed to redraw the map elsewhere, as vectors: the
    parameters, the case and the derived constants; the boundary curves as
    polylines inside the view with their equations in machine-readable form
    (``line``: mu = c0 + c1 k; ``rational``: mu = s (p k + q)/(r k + t) with
    s = +1 or |.|; ``vertical``: k = k0); the named points; the final map's
    region polygons (:func:`regimemap.geometry.region_polygons`) and the
    parts where several modes are admissible (:mod:`regimemap.ambiguity`).
    Non-finite numbers are written as ``null``.

All files are written atomically (a temporary file renamed into place).  The three formats
share one description of the map (its grid, curves, points and polygons), hence one module
of some length.
"""

from __future__ import annotations

import logging
import math
import os
from collections.abc import Callable
from typing import Any

import numpy as np

from ..io import npz
from ..io.csv import write_csv as write_csv_file
from ..io.formats import format_for, record_formats
from ..io.json import write_json as write_json_file
from ..mechanics.block import Parameters
from ..mechanics.curves import map_curves, named_points
from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES, Mode
from ..mechanics.validation import MAX_GRID_POINTS, check_positive, check_resolution
from ..records.numbers import round_sig, rounded, text
from .ambiguity import ambiguous_regions
from .classify import label_grid
from .geometry import DEFAULT_SAMPLES, region_polygons

__all__ = [
    "FORMATS",
    "DEFAULT_RESOLUTION",
    "grid_axes",
    "map_grid",
    "map_geometry",
    "write_npz",
    "write_csv",
    "write_json",
    "boundary_curves",
    "export_map",
    "format_of",
]

#: Formats by suffix (:data:`.formats.RECORDS`).
FORMATS: tuple[str, ...] = record_formats("map data")
#: Default number of samples along each axis of the grid (npz, csv).
DEFAULT_RESOLUTION = 401
#: Samples of k for the curved polylines (mu*, mu**) in the JSON geometry.
CURVE_SAMPLES = 401
#: Format version written into the JSON file.
JSON_VERSION = 1

_LABELS = np.array([m.label for m in Mode])  # indexed by code


def format_of(path: str | os.PathLike[str], fmt: str | None = None) -> str:
    """The export format of ``path``: ``fmt`` if given, else its suffix (:func:`.formats.format_for`).

    Raises
    ------
    ValueError
        For an unknown ``fmt``, or without it the one :class:`~.formats.SuffixError`.
    """
    if fmt is None:
        return format_for(path, "map data")
    fmt = fmt.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ValueError(f"unknown export format {fmt!r}; use one of {', '.join(FORMATS)}")
    return fmt


def _extent(p: Parameters, k_max: float | None, mu_max: float | None,
            view: str = "designer") -> tuple[float, float]:
    if k_max is None or mu_max is None:
        from .designer_view import view_extent

        k_max, mu_max = view_extent(p, view, k_max=k_max, mu_max=mu_max)
    return check_positive("k_max", k_max), check_positive("mu_max", mu_max)


def _resolution(resolution: int | tuple[int, int]) -> tuple[int, int]:
    if isinstance(resolution, tuple):
        nk, nmu = (check_resolution("resolution", r) for r in resolution)
    else:
        nk = nmu = check_resolution("resolution", resolution)
    if nk * nmu > MAX_GRID_POINTS:
        raise ValueError(f"grid of {nmu} x {nk} points exceeds the limit of {MAX_GRID_POINTS} points")
    return nk, nmu


def grid_axes(k_max: float, mu_max: float, resolution: int | tuple[int, int] = DEFAULT_RESOLUTION
              ) -> tuple[np.ndarray, np.ndarray]:
    """``k = linspace(0, k_max, n_k)`` and ``mu = linspace(0, mu_max, n_mu)``.

    ``resolution`` is one number of samples for both axes or ``(n_k, n_mu)``,
    each in [2, MAX_RESOLUTION], with n_k n_mu <= MAX_GRID_POINTS (checked
    before anything is allocated).
    """
    nk, nmu = _resolution(resolution)
    k_max = check_positive("k_max", k_max)
    mu_max = check_positive("mu_max", mu_max)
    return np.linspace(0.0, k_max, nk), np.linspace(0.0, mu_max, nmu)


def map_grid(p: Parameters, k_max: float | None = None, mu_max: float | None = None,
             resolution: int | tuple[int, int] = DEFAULT_RESOLUTION, *, view: str = "designer"
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The map on a grid: ``(k, mu, mode)`` with ``mode`` of shape (len(mu), len(k)).

    ``mode[i, j] == classify(k[j], mu[i], gamma, kprime)`` exactly
    (:func:`regimemap.label_grid`).  The view defaults to ``view``
    (:func:`regimemap.maps.designer_view.view_extent`: ``designer`` or ``report``).
    """
    _resolution(resolution)  # refuse before computing anything
    k_max, mu_max = _extent(p, k_max, mu_max, view)
    k, mu = grid_axes(k_max, mu_max, resolution)
    logging.getLogger(__name__).info("map grid gamma=%g, k'=%g: %d x %d points (k <= %g, mu <= %g)",
                                     p.gamma, p.kprime, k.size, mu.size, k_max, mu_max)
    return k, mu, label_grid(k, mu, p.gamma, p.kprime, **_loads_of(p))


def _loads_of(p: Parameters) -> dict[str, Any]:
    """The load keywords of ``p`` for the evaluators ({} for the report's block)."""
    return p.loads if (p.loaded or p.crest != 1.0) else {}


def _constants(p: Parameters) -> dict[str, Any]:
    d = p.as_dict()
    for key in ("gamma", "kprime", "case", *p.loads):
        d.pop(key, None)
    d.update({
        "k_D": p.k_D,
        "k_F": p.k_F,
        "k_pole": p.k_pole,
        "kprime_1": p.kprime_1,
        "kprime_2": p.kprime_2,
        "kprime_delta": p.kprime_delta,
    })
    return d


def write_npz(path: str | os.PathLike[str], p: Parameters, k: np.ndarray, mu: np.ndarray,
              mode: np.ndarray, k_max: float, mu_max: float) -> None:
    """Write the grid and the parameters to ``path`` (compressed ``.npz``), atomically."""
    arrays: dict[str, np.ndarray] = {
        "k": np.asarray(k, dtype=np.float64),
        "mu": np.asarray(mu, dtype=np.float64),
        "mode": np.asarray(mode, dtype=np.uint8),
        "labels": _LABELS.copy(),
        "gamma": np.float64(p.gamma),
        "kprime": np.float64(p.kprime),
        "k_max": np.float64(k_max),
        "mu_max": np.float64(mu_max),
        "case": np.array(p.case.value),
    }
    for key, v in _constants(p).items():
        arrays[key] = np.float64(v)
    if _loads_of(p):  # the loads (gyration nan for the uniform block) and the loaded constants
        arrays["loaded"] = np.array(True)
        for key, v in p.loads.items():
            arrays[key] = np.float64(math.nan if v is None else v)
    npz.write_npz(path, arrays)


def write_csv(path: str | os.PathLike[str], k: np.ndarray, mu: np.ndarray, mode: np.ndarray,
              p: Parameters | None = None) -> None:
    """Write ``k,mu,mode`` rows (mu outer, k inner; the mode as its label), atomically.

    For a block with loads (``p``) every row also carries ``gamma``, ``kprime`` and
    the loads the block carries, under the column names ``classify --points`` reads.
    Numbers are written to 12 significant digits.
    """
    k_txt = [text(v) for v in k]
    labels = [m.label for m in Mode]
    tail = ""
    head = ["k", "mu", "mode"]
    if p is not None and _loads_of(p):
        from .describe import load_items

        cols = [("gamma", p.gamma), ("kprime", p.kprime)] + load_items(p)
        head += [name for name, _ in cols]
        tail = "".join(f",{text(v)}" for _, v in cols)
    rows = ("\n".join(f"{kt},{mt},{labels[c]}{tail}" for kt, c in zip(k_txt, mode[i].tolist()))
            for i, mt in enumerate(text(m) for m in mu))
    write_csv_file(path, head, rows)


# --------------------------------------------------------------------------------------
# vector geometry
# --------------------------------------------------------------------------------------
def _graph_in_view(f: Callable[[np.ndarray], np.ndarray], k0: float, k1: float, mu_max: float,
                   n: int = CURVE_SAMPLES, dense_end: bool = False) -> list[np.ndarray]:
    """Polylines of mu = f(k) for k in [k0, k1] where 0 <= mu <= mu_max.

    Every vertex is on the curve (the ends where it leaves the view are
    located by bisection on f), so each point satisfies the curve's equation.
    """
    if not (k1 > k0):
        return []
    t = np.linspace(0.0, 1.0, n)
    if dense_end:  # crowd samples towards k1 (the pole of mu**)
        t = np.sin(0.5 * np.pi * t)
    k = k0 + (k1 - k0) * t
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = f(k)
    tol = 1e-12 * max(1.0, mu_max)
    inside = np.isfinite(mu) & (mu >= -tol) & (mu <= mu_max + tol)

    def cross(ka: float, kb: float) -> float:
        """Bisect between ka (inside) and kb (outside) for the edge of the view."""
        for _ in range(80):
            m = 0.5 * (ka + kb)
            if m in (ka, kb):
                break
            with np.errstate(divide="ignore", invalid="ignore"):
                v = float(f(np.array([m]))[0])
            if math.isfinite(v) and -tol <= v <= mu_max + tol:
                ka = m
            else:
                kb = m
        return ka

    out: list[np.ndarray] = []
    idx = np.flatnonzero(inside)
    if idx.size == 0:
        return out
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    for run in runs:
        ks = list(k[run])
        if run[0] > 0:
            ks.insert(0, cross(k[run[0]], k[run[0] - 1]))
        if run[-1] < k.size - 1:
            ks.append(cross(k[run[-1]], k[run[-1] + 1]))
        kk = np.asarray(ks)
        with np.errstate(divide="ignore", invalid="ignore"):
            mm = f(kk)
        mm = np.clip(mm, 0.0, mu_max)  # only rounding at the very ends
        if kk.size >= 2:
            out.append(np.column_stack([kk, mm]))
    return out


def _line_in_view(c0: float, c1: float, k0: float, k1: float, mu_max: float) -> list[np.ndarray]:
    """The segment of the line mu = c0 + c1 k with k0 <= k <= k1 and 0 <= mu <= mu_max."""
    lo, hi = k0, k1
    if c1 == 0.0:
        if not 0.0 <= c0 <= mu_max:
            return []
    else:
        ka, kb = (0.0 - c0) / c1, (mu_max - c0) / c1
        lo, hi = max(lo, min(ka, kb)), min(hi, max(ka, kb))
    if not hi > lo:
        return []
    kk = np.array([lo, hi])
    return [np.column_stack([kk, np.clip(c0 + c1 * kk, 0.0, mu_max)])]


def boundary_curves(p: Parameters, k_max: float, mu_max: float) -> dict[str, dict[str, Any]]:
    """The map's curves (the catalogue :func:`~regimemap.mechanics.curves.map_curves`) as
    polylines inside the view, with their equations.

    Names as in the report: above C ``OA``, ``AB`` (vertical k = k_A), ``CD``
    (upper line), ``mu_star`` and, in cases 2/3, ``dotted`` (3.44); below C
    ``OA``, ``AE`` (vertical k = k_A), ``AB`` (upper line), ``DC`` (lower
    line), ``dotted`` (4.22), ``mu_star`` and ``mu_star_star`` (the finite
    part, from F up to where it leaves the view before its pole d/c).
    """
    out: dict[str, dict[str, Any]] = {}
    for name, c in map_curves(p).items():
        if c.vertical_k is not None:
            kA = c.vertical_k
            # AB above C starts at A (mu_A = k_A on the report's block); the others at mu = 0
            bottom = p.mu_A if (p.above and name == "AB") else 0.0
            if not (kA <= k_max and bottom <= mu_max):
                continue
            polylines = [np.array([[kA, bottom], [kA, mu_max]])]
        elif c.spec["type"] == "line":
            # every line is cut by the view; OA alone ends inside it, at A
            k1 = min(c.k_to, k_max) if name == "OA" else k_max
            polylines = _line_in_view(c.spec["c0"], c.spec["c1"], 0.0, k1, mu_max)
        elif name == "mu_star":
            if not c.k_from < k_max:
                continue
            polylines = _graph_in_view(c.func, c.k_from, k_max, mu_max)  # type: ignore[arg-type]
        else:  # mu**: from F (or 0) to its pole or the edge of the view
            k1 = min(c.k_to, k_max)
            k0 = max(0.0, c.k_from)
            if not k1 > k0:
                continue
            polylines = _graph_in_view(c.func, k0, k1, mu_max,  # type: ignore[arg-type]
                                       dense_end=k1 == c.k_to)
        out[name] = {
            "name": name,
            "equation": c.equation,
            "report": c.report,
            "role": c.role,
            "spec": c.spec,
            "polylines": [pl.tolist() for pl in polylines],
        }
    return out


def map_geometry(p: Parameters, k_max: float | None = None, mu_max: float | None = None,
                 samples: int = DEFAULT_SAMPLES, *, view: str = "designer") -> dict[str, Any]:
    """The map as vectors (the content of the ``.json`` export), JSON-ready.

    Parameters
    ----------
    p : Parameters
    k_max, mu_max : float, optional
        The view (default: the view named ``view``).
    samples : int
        Columns of k for the region polygons.
    view : {"designer", "report"}
        The default view (:func:`regimemap.maps.designer_view.view_extent`).

    Returns
    -------
    dict
        Keys ``format``, ``version``, ``parameters``, ``case``, ``constants``,
        ``extent``, ``modes``, ``curves``, ``named_points``, ``regions``,
        ``ambiguity``; non-finite numbers are None.
    """
    k_max, mu_max = _extent(p, k_max, mu_max, view)
    polys = region_polygons(p, k_max, mu_max, samples=samples, overshoot=1.0)
    logging.getLogger(__name__).info("map geometry gamma=%g, k'=%g: %d polygons (%d vertices), %d samples",
                                     p.gamma, p.kprime, sum(len(v) for v in polys.values()),
                                     sum(len(q) for v in polys.values() for q in v), samples)
    pts = named_points(p)
    loaded = bool(_loads_of(p))
    modes = LOADED_MAP_MODES if p.loaded else MAP_MODES
    geom = {
        "format": "regimemap-map",
        "version": JSON_VERSION,
        "parameters": {"gamma": p.gamma, "kprime": p.kprime, **(p.loads if loaded else {})},
        "case": {"value": p.case.value, "description": p.case.description},
        "constants": _constants(p),
        "extent": {"k_min": 0.0, "k_max": k_max, "mu_min": 0.0, "mu_max": mu_max},
        "modes": {m.label: {"code": int(m), "description": m.description} for m in modes},
        "curves": boundary_curves(p, k_max, mu_max),
        "named_points": {
            name: dict(pt.as_dict(), in_view=bool(0.0 <= pt.k <= k_max and 0.0 <= pt.mu <= mu_max))
            for name, pt in pts.items()
        },
        "regions": {m.label: [poly.tolist() for poly in polys.get(m, [])] for m in modes},
        "ambiguity": [r.as_dict() for r in ambiguous_regions(p, k_max, mu_max, samples=samples)],
        "notes": {
            "grid": "regions are polygons of (k, mu); each vertical line k = const meets a region "
                    "in one interval of mu (lower edge left to right, then upper edge back)",
            "ambiguity": "parts where the equations of motion admit several modes; the map shows "
                         "the mode Section 4.7 of the report keeps ('chosen')",
        },
    }
    if loaded:
        geom["lift_off"] = {"k_L": p.k_L, "range": list(p.lift_off) if p.lift_off else None}
        geom["notes"]["ambiguity"] = (  # type: ignore[index]
            "parts where the equations of motion admit several modes; the map shows the mode "
            "Gauss's least constraint chooses ('chosen'), a convention of rigid contact")
        geom["notes"]["loads"] = (  # type: ignore[index]
            "buoyancy beta m g up through C; uplift (u + nu k) m g up at uplift_arm B from C "
            "towards O'; gyration i: I = m B^2 i^2 (null: the uniform block); crest: the top "
            "of the block above C over H")
    return rounded(geom)


def write_json(path: str | os.PathLike[str], geometry: dict[str, Any]) -> None:
    """Write the geometry as JSON (non-finite numbers as null), atomically."""
    write_json_file(path, rounded(geometry))


def export_map(path: str | os.PathLike[str], p: Parameters, *, k_max: float | None = None,
               mu_max: float | None = None, resolution: int | tuple[int, int] = DEFAULT_RESOLUTION,
               fmt: str | None = None, view: str = "designer") -> str:
    """Export the map of ``p`` to ``path`` in the format of its suffix (or ``fmt``).

    Parameters
    ----------
    path : path-like
        ``.npz``, ``.csv`` or ``.json``.
    p : Parameters
    k_max, mu_max : float, optional
        The view (default: the view named ``view``, ``designer`` or ``report``;
        :func:`regimemap.maps.designer_view.view_extent`).
    resolution : int or (int, int)
        Grid samples per axis for ``.npz``/``.csv`` (ignored for ``.json``),
        at most :data:`~regimemap.validation.MAX_RESOLUTION` each and
        :data:`~regimemap.validation.MAX_GRID_POINTS` in all; checked before
        anything is allocated.
    fmt : {"npz", "csv", "json"}, optional
        Overrides the suffix.

    Returns
    -------
    str
        The format written.

    Raises
    ------
    ValueError
        Unknown format, resolution out of range, or a view that is not > 0.
    """
    fmt = format_of(path, fmt)
    if fmt == "json":
        write_json(path, map_geometry(p, k_max, mu_max, view=view))
        return fmt
    _resolution(resolution)
    k_max, mu_max = _extent(p, k_max, mu_max, view)
    k, mu, mode = map_grid(p, k_max, mu_max, resolution)
    if fmt == "npz":
        write_npz(path, p, k, mu, mode, k_max, mu_max)
    else:
        # text for people: the grid values and loads as written (12 digits), classified as written
        k = np.array([round_sig(v) for v in k])
        mu = np.array([round_sig(v) for v in mu])
        loads: dict[str, Any] = {key: (None if v is None else round_sig(v))
                                 for key, v in _loads_of(p).items()}
        gamma, kprime = (round_sig(p.gamma), round_sig(p.kprime)) if loads else (p.gamma, p.kprime)
        write_csv(path, k, mu, label_grid(k, mu, gamma, kprime, **loads), p)
    return fmt
