"""Point queries: the mode at a design point, the physics at initiation and the margin.

A designer asks "what happens to *my* caisson?": :func:`query_point` answers
for one point (k, mu) of the map, :func:`query_points` for many.  After the
regime functions of ``fluids.two_phase`` (which return the regime together with
the dimensionless groups that decided it), the answer is a
:class:`PointResult` holding

* the mode of the final map (:func:`regimemap.classify`, Section 4.7 below C);
* the reactions and accelerations at initiation of that mode, from the
  independent equations-of-motion solver (:func:`regimemap.mechanics.solver.solve`) for
  the mode's contact hypothesis: ``fx``, ``fy`` (divided by m g), ``xi`` (the
  point of action of f_y from C, divided by B; -1 is the corner O, +1 is O'),
  ``xdd``, ``ydd`` (accelerations of C divided by g), ``thdd`` (theta'' B/g,
  positive counter-clockwise), ``slip`` (horizontal acceleration of the
  slipping contact divided by g; ``None`` when the contact sticks) and ``lift``
  (upward acceleration of the lifting corner divided by g; ``None`` for full
  base contact);
* every mode the equations of motion admit at the point (several on a
  boundary, and below C for mu > mu_B' = (4+g^2)/(3g), (4.49), where rigid
  contact with friction is not unique - Painleve's paradox - and Section 4.7
  of the report picks one);
* the **margin**: the smallest change of k (mu held fixed) and of mu (k held
  fixed), up or down, that changes the mode, and the mode it changes to;
* the thresholds at the point's k (mu*(k), the lines CD/AB and DC, k_A, mu_B').

With loads (keyword-only ``buoyancy``, ``uplift``, ``uplift_ratio``,
``uplift_arm``, ``gyration``, ``crest``, as in :func:`regimemap.classify`) the
solver carries them, lift-off (LO) is one more mode, and where several modes are
admissible Gauss's least constraint chooses (:attr:`PointResult.chosen_by`).

The margin is computed by :mod:`regimemap.maps.margins`, the result and its display
are :mod:`regimemap.maps.point_result`; flat rows and text for people are
:mod:`regimemap.maps.record_tables`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from ..mechanics import constants as C
from ..mechanics.block import Case, Parameters
from ..mechanics.modes import SELECTION_ORDER, Mode
from ..mechanics.solver import Hypothesis, solve
from ..mechanics.validation import check_gamma, check_kprime, check_nonnegative_array
from .classify import classify
from .margins import (
    Crossing,
    Margin,
    carries_loads,
    checked_loads,
    loads_constants,
    margin,
    margin_arrays,
    margin_at,
)
from .point_result import PointResult
from .points import DesignPoint

__all__ = [
    "Crossing",
    "HYPOTHESES_OF_MODE",
    "Margin",
    "PointResult",
    "classify_point",
    "margin",
    "query_point",
    "query_points",
]

#: The contact hypotheses of each mode, in the order tried (the first admissible one is used).
HYPOTHESES_OF_MODE: dict[Mode, tuple[Hypothesis, ...]] = {}
for _h in Hypothesis:
    HYPOTHESES_OF_MODE.setdefault(_h.mode, ())
    HYPOTHESES_OF_MODE[_h.mode] += (_h,)

#: Points are processed in blocks of this many (the solver builds 6x6 systems per point).
_BLOCK = 20_000


# --------------------------------------------------------------------------------------
# queries
# --------------------------------------------------------------------------------------
def _query_block(k: np.ndarray, mu: np.ndarray, g: np.ndarray, kp: np.ndarray,
                 names: Sequence[str], cases: Sequence[Case], loads: dict[str, Any]
                 ) -> list[PointResult]:
    m0 = classify(k, mu, g, kp, **loads)
    solver_loads = {key: v for key, v in loads.items() if key != "crest"}
    responses = {h: solve(h, k, mu, g, kp, **solver_loads) for h in Hypothesis}
    adm_mode: dict[Mode, np.ndarray] = {}
    for h, r in responses.items():
        adm_mode[h.mode] = adm_mode[h.mode] | r.ok if h.mode in adm_mode else r.ok
    margins = {var: margin_arrays(var, k, mu, g, kp, m0, loads) for var in ("k", "mu")}
    t = C.thresholds(k, loads_constants(g, kp, loads))
    lower, upper, mu_s = t.lower, t.upper, t.mu_star
    shown = dict(loads) if carries_loads(loads) else {}
    out: list[PointResult] = []
    for i in range(k.size):
        mode = Mode(int(m0[i]))
        hyps = HYPOTHESES_OF_MODE[mode]
        hyp = next((h for h in hyps if responses[h].ok[i]), hyps[0])
        r = responses[hyp]
        solvable = bool(r.solvable[i])

        def val(arr: np.ndarray, i: int = i, solvable: bool = solvable) -> float:
            return float(arr[i]) if solvable else math.nan

        slip = None if hyp.sigma == 0 or not solvable else float(r.slip[i])
        lift = None if hyp.contact == "full" or not solvable else float(r.lift[i])
        adm = tuple(m for m in SELECTION_ORDER if m in adm_mode and adm_mode[m][i])
        point = loads_constants(float(g[i]), float(kp[i]), loads)
        out.append(PointResult(
            k=float(k[i]), mu=float(mu[i]), gamma=float(g[i]), kprime=float(kp[i]),
            mode=mode, hypothesis=hyp,
            fx=val(r.fx), fy=val(r.fy), xi=val(r.xi),
            xdd=val(r.xdd), ydd=val(r.ydd), thdd=val(r.thdd),
            slip=slip, lift=lift, case=cases[i], admissible=adm,
            hypothesis_admissible=bool(r.ok[i]), solvable=solvable,
            margin_k=margin_at("k", float(k[i]), margins["k"], i),
            margin_mu=margin_at("mu", float(mu[i]), margins["mu"], i),
            thresholds={
                "mu_star": float(mu_s[i]),
                "upper_line": float(upper[i]),
                "lower_line": float(lower[i]),
                "k_A": C.k_A(point),
                "mu_Bprime": C.mu_Bprime(point),
            },
            name=names[i], loads=shown,
        ))
    return out


def query_point(k: float, mu: float, gamma: float, kprime: float, name: str = "", *,
                buoyancy: float = 0.0, uplift: float = 0.0, uplift_ratio: float = 0.0,
                uplift_arm: float = 1.0 / 3.0, gyration: float | None = None,
                crest: float = 1.0) -> PointResult:
    """The mode at (k, mu), the physics at its initiation and its margin.

    Parameters
    ----------
    k : float
        Force F/(mg) >= 0.
    mu : float
        Coefficient of friction >= 0.
    gamma : float
        Aspect ratio H/B > 0.
    kprime : float
        Force height h/H in [-1, crest] (negative below the centre of mass).
    name : str, optional
        A label carried into the result.
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest : float, keyword-only
        The loads of the block, as in :func:`regimemap.classify`.

    Returns
    -------
    PointResult

    Raises
    ------
    ValueError
        For a negative or non-finite k or mu, gamma <= 0 or kprime outside
        [-1, 1]; the message names the parameter and the allowed range.

    Examples
    --------
    >>> r = query_point(0.5, 0.8, gamma=3.0, kprime=0.4)
    >>> r.mode.label, r.hypothesis.name, round(r.thdd, 4) > 0
    ('RO', 'ROCK_O', True)
    """
    return query_points([DesignPoint(_scalar("k", k), _scalar("mu", mu), name)],
                        gamma=gamma, kprime=kprime, buoyancy=buoyancy, uplift=uplift,
                        uplift_ratio=uplift_ratio, uplift_arm=uplift_arm, gyration=gyration,
                        crest=crest)[0]


def _scalar(name: str, v: Any) -> float:
    arr = check_nonnegative_array(name, v)
    if arr.size != 1:
        raise ValueError(f"{name} must be one number, got an array of shape {arr.shape}")
    return float(arr.reshape(-1)[0])


def query_points(points: Iterable[DesignPoint | tuple[float, float]],
                 gamma: float | None = None, kprime: float | None = None, *,
                 buoyancy: float = 0.0, uplift: float = 0.0, uplift_ratio: float = 0.0,
                 uplift_arm: float = 1.0 / 3.0, gyration: float | None = None,
                 crest: float = 1.0) -> list[PointResult]:
    """:func:`query_point` for many points (vectorised in blocks).

    Parameters
    ----------
    points : iterable of DesignPoint or (k, mu) pairs
        A point's own ``gamma``/``kprime`` and loads (see
        :class:`~regimemap.maps.points.DesignPoint`) take precedence over the
        defaults below.
    gamma, kprime : float, optional
        Defaults for points that do not carry their own.
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest : float, keyword-only
        The loads of the block (the default of every point), as in :func:`regimemap.classify`.

    Returns
    -------
    list of PointResult, in the order of ``points``.

    Raises
    ------
    ValueError
        If a point lacks gamma or kprime and no default is given (the message
        names the point by position and name), or any value is invalid.
    """
    defaults = {"buoyancy": buoyancy, "uplift": uplift, "uplift_ratio": uplift_ratio,
                "uplift_arm": uplift_arm, "gyration": gyration, "crest": crest}
    pts = list(points)
    if any(isinstance(pt, DesignPoint) and pt.loads for pt in pts):
        # points with loads of their own: one shared-loads query per set of loads
        groups: dict[tuple[Any, ...], list[int]] = {}
        for i, pt in enumerate(pts):
            own = pt.loads if isinstance(pt, DesignPoint) else {}
            key = tuple(own.get(name, default) for name, default in defaults.items())
            groups.setdefault(key, []).append(i)
        out_all: list[PointResult | None] = [None] * len(pts)
        for key, idx in groups.items():
            res = _query_shared([pts[i] for i in idx], gamma, kprime, dict(zip(defaults, key)),
                                [i + 1 for i in idx])
            for i, r in zip(idx, res):
                out_all[i] = r
        return [r for r in out_all if r is not None]
    return _query_shared(pts, gamma, kprime, defaults, range(1, len(pts) + 1))


def _query_shared(points: Sequence[DesignPoint | tuple[float, float]], gamma: float | None,
                  kprime: float | None, load_kw: dict[str, Any], positions: Iterable[int]
                  ) -> list[PointResult]:
    """:func:`query_points` of points that share their loads (``positions``: their numbers)."""
    try:
        loads = checked_loads(**load_kw)
    except ValueError as exc:
        first = next(iter(positions), 1)
        pt0 = points[0] if points else None
        if pt0 is not None and isinstance(pt0, DesignPoint) and pt0.loads:
            label = f"point {first}" + (f" ({pt0.name!r})" if pt0.name else "")
            raise ValueError(f"{label}: {exc}") from None
        raise
    g_def = None if gamma is None else check_gamma(gamma)
    kp_def = None if kprime is None else check_kprime(kprime, loads["crest"])
    ks: list[float] = []
    mus: list[float] = []
    gs: list[float] = []
    kps: list[float] = []
    names: list[str] = []
    for i, pt in zip(positions, points):
        if not isinstance(pt, DesignPoint):
            try:
                kk, mm = pt
            except (TypeError, ValueError):
                raise ValueError(f"point {i}: expected a DesignPoint or a (k, mu) pair, "
                                 f"got {pt!r}") from None
            pt = DesignPoint(_scalar("k", kk), _scalar("mu", mm))
        label = f"point {i}" + (f" ({pt.name!r})" if pt.name else "")
        g = pt.gamma if pt.gamma is not None else g_def
        kp = pt.kprime if pt.kprime is not None else kp_def
        if g is None:
            raise ValueError(f"{label} has no gamma and no default gamma was given")
        if kp is None:
            raise ValueError(f"{label} has no kprime and no default kprime was given")
        try:
            ks.append(_scalar("k", pt.k))
            mus.append(_scalar("mu", pt.mu))
            gs.append(check_gamma(g))
            kps.append(check_kprime(kp, loads["crest"]))
        except ValueError as exc:
            raise ValueError(f"{label}: {exc}") from None
        names.append(pt.name)
    k = np.asarray(ks, dtype=np.float64)
    mu = np.asarray(mus, dtype=np.float64)
    g_arr = np.asarray(gs, dtype=np.float64)
    kp_arr = np.asarray(kps, dtype=np.float64)
    # the case of each distinct (gamma, k') once, in the order the points first give it
    case_of = {key: Parameters(*key, crest=loads["crest"]).case for key in dict.fromkeys(zip(gs, kps))}
    cases = [case_of[key] for key in zip(gs, kps)]
    out: list[PointResult] = []
    for s in range(0, k.size, _BLOCK):
        sl = slice(s, s + _BLOCK)
        out.extend(_query_block(k[sl], mu[sl], g_arr[sl], kp_arr[sl], names[sl], cases[sl], loads))
    return out


def classify_point(point: DesignPoint, params: Parameters) -> PointResult:
    """:func:`query_points` of one point for the block ``params`` (its gamma, k' and loads).

    The answer ``regimemap explore`` shows for a click, as ``regimemap classify`` computes it.
    """
    return query_points([point], gamma=params.gamma, kprime=params.kprime, **params.loads)[0]
