"""The design chart: expected sliding distance against caisson width.

numpy only.  Every width sees the same storms and the same waves (one joint
simulation, common random numbers), so the curve is smooth and, for a
section whose weight grows with its width, does not rise.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from regimemap.waves import analyse_caisson

from .model import PERIOD_COEFFICIENT, PERIOD_EXPONENT, Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, make_chunks, root_seed, run_chunks

__all__ = ["WIDTH_STEPS", "DesignChart", "design_chart", "sf_width"]

FloatArray = NDArray[np.float64]

#: Bisection steps for the width of a target ESD (the bracket is one chart step wide, so the
#: width is found to 1/256 of a chart step); each step is one simulation of ``trials`` lifetimes.
WIDTH_STEPS = 8


@dataclass(frozen=True)
class DesignChart:
    """ESD against width, with the width for a target and the width of a required safety factor.

    Attributes
    ----------
    widths : ndarray
        Full widths [m].
    expected_sliding, std_error : ndarray
        ESD and its standard error at each width [m].
    target : float
        The tolerable ESD [m].
    width_for_target : float or None
        The narrowest width whose ESD is at most ``target`` (bisection on the
        same random numbers); None when no width of the chart meets it.
    required_sf : float
        Required sliding safety factor under the 50-year wave.
    sf_width : float
        The width with that safety factor [m] (Goda's deterministic design).
    trials, seed : int
        Lifetimes per width and the root seed.
    """

    widths: FloatArray
    expected_sliding: FloatArray
    std_error: FloatArray
    target: float
    width_for_target: float | None
    required_sf: float
    sf_width: float
    trials: int
    seed: int

    def rows(self) -> list[dict[str, float]]:
        """One dict per width: ``width``, ``expected_sliding``, ``std_error``."""
        return [{"width": float(w), "expected_sliding": float(e), "std_error": float(s)}
                for w, e, s in zip(self.widths, self.expected_sliding, self.std_error)]


def sf_width(caisson: Caisson, model: LifetimeModel, required_sf: float = 1.2,
             return_period: float = 50.0, impulsive: bool = True) -> float:
    """The width whose sliding safety factor under the ``return_period`` wave is ``required_sf``.

    The conventional (deterministic) design of Goda (2000, Sect. 4.2),
    ``SF = mu (W' - U)/P``, as ``regimemap caisson`` computes it: the design
    wave ``H0'`` is the climate's return value, its period the model's storm
    relation, ``Hmax`` from Goda's formulas, the pressures Goda's with
    Takahashi's impulsive coefficient ``alpha* = max(alpha2, alpha_I)`` when
    ``impulsive`` (the default, as in the Japanese standards and the design
    file's ``[caisson] impulsive``); ``W'`` scales with the width as in
    :meth:`Caisson.with_width`.  The safety factor is linear in the width for
    such sections; it is solved by bisection anyway.
    """
    H0 = model.climate.return_value(return_period)
    if model.period is not None:
        T = model.period
    elif model.steepness is not None:
        T = math.sqrt(2.0 * math.pi * H0 / (caisson.g * model.steepness))
    else:
        a, b = model.period_law or (PERIOD_COEFFICIENT, PERIOD_EXPONENT)
        T = a * H0**b

    def sf(width: float) -> float:
        c = caisson.with_width(width)
        a = analyse_caisson(depth=c.depth, armour_depth=c.armour_depth, slope=c.slope, period=T,
                            width=c.width, base_depth=c.base_depth, crest=c.crest, friction=c.friction,
                            H0=H0, angle_deg=c.angle_deg, rotation_deg=c.rotation_deg,
                            berm_width=c.berm_width, buoyant_weight=c.buoyant_weight,
                            densities=c.densities, impulsive=impulsive, rho_w=c.rho_w, g=c.g)
        return float(a.stability.sliding)

    lo, hi = 1e-3 * caisson.width, caisson.width
    while sf(hi) < required_sf:
        hi *= 2.0
        if hi > 1e4:
            return math.inf
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if sf(mid) < required_sf:
            lo = mid
        else:
            hi = mid
    return hi


def design_chart(caisson: Caisson, model: LifetimeModel, widths: ArrayLike, trials: int = 5000,
                 seed: int | None = None, *, target: float = 0.1, required_sf: float = 1.2,
                 sf_impulsive: bool = True, chunk: int = DEFAULT_CHUNK, jobs: int = 1,
                 scheduler: str | None = None,
                 progress: Callable[[int], None] | None = None) -> DesignChart:
    """ESD of the same section at several widths, on the same random numbers.

    Parameters
    ----------
    caisson : Caisson
        The section (its own width is not used unless listed).
    model : LifetimeModel
        Climate and options.
    widths : array_like
        Full widths [m], increasing.
    trials, seed, chunk, jobs, scheduler, progress
        As :func:`regimemap.lifetime.lifetime_sliding` (``progress`` counts
        lifetimes of the chart, then of each bisection step).
    target : float, optional
        Tolerable ESD [m] (0.1, Goda & Takagi 2000).
    required_sf : float, optional
        Required safety factor for the deterministic width (1.2).
    sf_impulsive : bool, optional
        Takahashi's impulsive coefficient in the deterministic design (see
        :func:`sf_width`).

    Returns
    -------
    DesignChart

    Notes
    -----
    The waves of every storm are drawn once, above the lowest sliding height
    of all widths, and each width slides under the same waves.  The width for
    the target is bisected between the two chart widths that bracket it; each
    step simulates the trial width together with the narrowest chart width,
    so its waves -- and so its ESD -- are those of the chart's own curve.
    """
    w = np.sort(np.asarray(widths, dtype=np.float64).ravel())
    if w.size < 2 or np.any(w <= 0.0):
        raise ValueError("need at least two widths > 0")
    seed_ = root_seed(seed)
    chunks = make_chunks(trials, seed_, chunk)
    caissons = tuple(caisson.with_width(float(x)) for x in w)
    out = run_chunks(caissons, model, chunks, jobs=jobs, scheduler=scheduler, progress=progress)
    esd = out.sliding.mean(axis=1)
    se = out.sliding.std(axis=1, ddof=1) / math.sqrt(trials) if trials > 1 else np.full(w.size, math.nan)

    found: float | None = None
    ok = np.flatnonzero(esd <= target)
    if ok.size:
        i = int(ok[0])
        if i == 0:
            found = float(w[0])
        else:
            lo, hi = float(w[i - 1]), float(w[i])
            for _ in range(WIDTH_STEPS):
                mid = 0.5 * (lo + hi)
                # the narrowest chart width guides the sampling (the chart's waves), unslid
                pair = (caissons[0], caisson.with_width(mid))
                r = run_chunks(pair, model, chunks, jobs=jobs, scheduler=scheduler, progress=progress,
                               guides=1)
                if float(r.sliding[0].mean()) <= target:
                    hi = mid
                else:
                    lo = mid
            found = hi
    return DesignChart(widths=w, expected_sliding=esd, std_error=np.asarray(se, dtype=np.float64),
                       target=target, width_for_target=found, required_sf=required_sf,
                       sf_width=sf_width(caisson, model, required_sf, impulsive=sf_impulsive),
                       trials=trials, seed=seed_)
