"""The design chart: expected sliding distance against caisson width.

numpy only.  Every width sees the same storms and the same waves (one joint
simulation, common random numbers), so the curve is smooth and, for a
section whose weight grows with its width, does not rise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from regimemap.records.checks import Check
from regimemap.waves import analyse_caisson

from .model import Caisson, LifetimeModel
from .parallel import DEFAULT_CHUNK, make_chunks, root_seed, run_chunks

__all__ = ["BOOTSTRAP_RESAMPLES", "BOOTSTRAP_STREAM", "DEFAULT_TOLERANCE", "INTERVAL_LEVEL", "DesignChart",
           "crossing_width",
           "WidthInterval", "bisection_steps", "design_chart", "sf_width", "target_bracket_problem",
           "width_interval"]

FloatArray = NDArray[np.float64]

#: Default tolerance of the width for a target ESD [m]: the bisection stops when the bracket is
#: this narrow, and the width reported (its upper end, which meets the target) is within it.
DEFAULT_TOLERANCE = 0.05
#: Level of the Monte Carlo interval of the width for the target.
INTERVAL_LEVEL = 0.95
#: Bootstrap resamples of that interval.
BOOTSTRAP_RESAMPLES = 1000
#: The child of the root seed the bootstrap draws from (``SeedSequence(seed).spawn``'s child of
#: this index: the lifetimes' blocks use children 0, 1, ... far below it).
BOOTSTRAP_STREAM = 2**32 - 1
#: Most groups of lifetimes the bootstrap resamples (beyond, consecutive lifetimes are summed in
#: groups: independent groups resample the mean as the lifetimes do, at a bounded cost).
_GROUPS = 4000


@dataclass(frozen=True)
class WidthInterval:
    """The Monte Carlo uncertainty of the width for the target: a bootstrap percentile interval.

    Attributes
    ----------
    level : float
        Its confidence level (0.95).
    lower, upper : float
        Its ends [m].
    resamples : int
        Bootstrap resamples.
    """

    level: float
    lower: float
    upper: float
    resamples: int = BOOTSTRAP_RESAMPLES


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
        same random numbers, to within ``tolerance``; the narrowest width when
        every width meets it); None when no width of the chart meets it.
    required_sf : float
        Required sliding safety factor under the 50-year wave.
    sf_width : float
        The width with that safety factor [m] (Goda's deterministic design).
    trials, seed : int
        Lifetimes per width and the root seed.
    tolerance : float
        The bisection's tolerance [m].
    width_interval : WidthInterval or None
        The Monte Carlo interval of ``width_for_target``.
    thresholds : tuple of float
        Lifetime slides [m] whose exceedance ``exceedance`` holds.
    exceedance : ndarray, shape (widths, thresholds)
        ``P(S > x)`` at each width.
    failure_sliding : float or None
        The sliding at which the caisson is off its mound [m].
    failure_probability : ndarray or None
        ``P(S > failure_sliding)`` at each width.
    probes : tuple of (float, float)
        The bisection's widths and their ESD [m], in order.
    checks : tuple of Check
        The design's requirements (:func:`regimemap.lifetime.requirements.judge_chart`).
    design_width : float or None
        The design's own width [m], when judged.
    impulsive : bool
        Takahashi's impulsive coefficient in the waves' forces (the model's).
    by_year, by_year_error : ndarray, shape (widths, years)
        Expected cumulative sliding at the end of each service year at each
        width, and its standard error [m]; empty when not recorded.
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
    tolerance: float = DEFAULT_TOLERANCE
    width_interval: WidthInterval | None = None
    thresholds: tuple[float, ...] = ()
    exceedance: FloatArray | None = None
    failure_sliding: float | None = None
    failure_probability: FloatArray | None = None
    probes: tuple[tuple[float, float], ...] = ()
    checks: tuple[Check, ...] = ()
    design_width: float | None = None
    impulsive: bool = False
    by_year: FloatArray = field(default_factory=lambda: np.zeros((0, 0)))
    by_year_error: FloatArray = field(default_factory=lambda: np.zeros((0, 0)))

    def bracket_problem(self) -> str | None:
        """Why the chart's widths do not bracket the target (its ESD at both ends); None when they do."""
        return target_bracket_problem(self.widths, self.expected_sliding, self.target)

    def rows(self) -> list[dict[str, float]]:
        """One dict per width: ``width``, ``expected_sliding``, ``std_error``."""
        return [{"width": float(w), "expected_sliding": float(e), "std_error": float(s)}
                for w, e, s in zip(self.widths, self.expected_sliding, self.std_error)]


def target_bracket_problem(widths: FloatArray, esd: FloatArray, target: float,
                           curve: str = "the ESD") -> str | None:
    """Why the ESD ``esd`` at the increasing ``widths`` (``curve`` says which ESD) does not bracket
    ``target`` at the ends of the widths; None when it does."""
    e0, e1 = float(esd[0]), float(esd[-1])
    w0, w1 = float(widths[0]), float(widths[-1])
    if e0 > target >= e1:
        return None
    where = ("every width meets it: give narrower widths" if e0 <= target
             else "no width meets it: give wider widths")
    return (f"the target ESD {target:g} m is not between {curve} at the ends of the widths, "
            f"{e0:.4g} m at {w0:g} m and {e1:.4g} m at {w1:g} m ({where})")


def bisection_steps(step: float, tolerance: float) -> int:
    """Bisection steps that narrow a bracket ``step`` metres wide to ``tolerance`` metres."""
    if not tolerance > 0.0:
        raise ValueError(f"tolerance must be > 0 m, got {tolerance!r}")
    return max(0, math.ceil(math.log2(step / tolerance))) if step > tolerance else 0


def crossing_width(widths: FloatArray, esd: FloatArray, target: float) -> float:
    """Where ``esd`` (at increasing ``widths``) first falls to ``target``: linear in log ESD between
    the two widths around it (linear in ESD when one is 0); clamped to the ends.

    Examples
    --------
    >>> crossing_width(np.array([10.0, 12.0]), np.array([1.0, 0.01]), 0.1)
    11.0
    """
    ok = np.flatnonzero(esd <= target)
    if ok.size == 0:
        return float(widths[-1])
    i = int(ok[0])
    if i == 0:
        return float(widths[0])
    e0, e1 = float(esd[i - 1]), float(esd[i])
    if e1 > 0.0:
        t = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
    else:
        t = (e0 - target) / (e0 - e1)
    return float(widths[i - 1] + t * (widths[i] - widths[i - 1]))


def width_interval(widths: ArrayLike, sliding: ArrayLike, target: float, seed: int,
                   level: float = INTERVAL_LEVEL, resamples: int = BOOTSTRAP_RESAMPLES) -> WidthInterval:
    """The bootstrap percentile interval of the width where the ESD falls to ``target``.

    Parameters
    ----------
    widths : array_like, shape (k,)
        The widths simulated [m] (the chart's and the bisection's), any order.
    sliding : array_like, shape (k, n)
        The lifetime sliding of the same ``n`` lifetimes at each width (common
        random numbers) [m].
    target : float
        The tolerable ESD [m].
    seed : int
        The root seed: the resamples draw from its child :data:`BOOTSTRAP_STREAM`.
    level : float, optional
        Confidence level.
    resamples : int, optional
        Bootstrap resamples.

    Returns
    -------
    WidthInterval

    Notes
    -----
    Each resample draws ``n`` lifetimes with replacement -- the same lifetimes at
    every width, as the simulation used the same random numbers -- and
    recomputes the ESD at every stored width; its width for the target is the
    crossing of that curve, interpolated linearly in log ESD between the
    stored widths around it.  The interval is the ``(1 - level)/2`` and
    ``(1 + level)/2`` quantiles of those widths (Efron & Tibshirani 1993,
    ch. 13).  Above :data:`_GROUPS` lifetimes, consecutive lifetimes are summed
    in groups (independent, so the groups resample the mean as the lifetimes
    do).
    """
    w = np.asarray(widths, dtype=np.float64)
    x = np.asarray(sliding, dtype=np.float64)
    order = np.argsort(w)
    w, x = w[order], x[order]
    n = x.shape[1]
    groups = min(n, _GROUPS)
    starts = (np.arange(groups) * n) // groups
    sums = np.add.reduceat(x, starts, axis=1)                       # (k, groups)
    sizes = np.diff(np.append(starts, n)).astype(np.float64)        # (groups,)
    rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(seed, spawn_key=(BOOTSTRAP_STREAM,))))
    found = np.empty(resamples)
    batch = max(1, 200_000 // groups)
    for first in range(0, resamples, batch):
        b = min(batch, resamples - first)
        pick = rng.integers(0, groups, size=(b, groups))
        counts = np.zeros((b, groups))
        np.add.at(counts, (np.repeat(np.arange(b), groups), pick.ravel()), 1.0)
        esd = (counts @ sums.T) / (counts @ sizes)[:, None]         # (b, k)
        for j in range(b):
            found[first + j] = crossing_width(w, esd[j], target)
    tail = 0.5 * (1.0 - level)
    lower, upper = np.quantile(found, [tail, 1.0 - tail])
    return WidthInterval(level=level, lower=float(lower), upper=float(upper), resamples=resamples)


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
    T = float(model.storm_period(H0, caisson.g))

    def sf(width: float) -> float:
        c = caisson.with_width(width)
        a = analyse_caisson(depth=c.depth, armour_depth=c.armour_depth, seabed_slope=c.seabed_slope, period=T,
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
                 sf_impulsive: bool = True, tolerance: float = DEFAULT_TOLERANCE,
                 failure_sliding: float | None = None, chunk: int = DEFAULT_CHUNK, **run: Any
                 ) -> DesignChart:
    """ESD of the same section at several widths, on the same random numbers, and the width for a target.

    Parameters
    ----------
    caisson : Caisson
        The section (its own width is not used unless listed).
    model : LifetimeModel
        Climate and options.
    widths : array_like
        Full widths [m], increasing.
    trials, seed, chunk
        As :func:`regimemap.lifetime.lifetime_sliding`.
    **run
        ``jobs``, ``scheduler`` and ``progress`` as
        :func:`regimemap.lifetime.lifetime_sliding` (``progress`` counts
        lifetimes of the chart, then of each bisection step).
    target : float, optional
        Tolerable ESD [m] (0.1, Goda & Takagi 2000).
    required_sf : float, optional
        Required safety factor for the deterministic width (1.2).
    sf_impulsive : bool, optional
        Takahashi's impulsive coefficient in the deterministic design (see
        :func:`sf_width`).
    tolerance : float, optional
        The bisection stops when its bracket is this narrow [m].
    failure_sliding : float, optional
        The sliding at which the caisson is off its mound [m]: the chart then
        holds ``P(S > failure_sliding)`` at each width.

    Returns
    -------
    DesignChart

    Notes
    -----
    The waves of every storm are drawn once, above the lowest sliding height
    of all widths, and each width slides under the same waves.  The width for
    the target is bisected between the two chart widths that bracket it until
    the bracket is at most ``tolerance`` wide; the width reported is its upper
    end (whose ESD meets the target).  Each step simulates the trial width
    together with the narrowest chart width, so its waves -- and so its ESD --
    are those of the chart's own curve.  The width's Monte Carlo interval is
    :func:`width_interval` over the chart's and the bisection's widths.
    """
    w = np.sort(np.asarray(widths, dtype=np.float64).ravel())
    if w.size < 2 or np.any(w <= 0.0):
        raise ValueError("need at least two widths > 0")
    if not tolerance > 0.0:
        raise ValueError(f"tolerance must be > 0 m, got {tolerance!r}")
    if model.trend is not None:
        model.trend.check_site(caisson)
    seed_ = root_seed(seed)
    chunks = make_chunks(trials, seed_, chunk)
    caissons = tuple(caisson.with_width(float(x)) for x in w)
    out = run_chunks(caissons, model, chunks, **run)
    esd = out.sliding.mean(axis=1)
    se = out.sliding.std(axis=1, ddof=1) / math.sqrt(trials) if trials > 1 else np.full(w.size, math.nan)

    found: float | None = None
    interval: WidthInterval | None = None
    probe_widths: list[float] = []
    probe_rows: list[FloatArray] = []
    ok = np.flatnonzero(esd <= target)
    if ok.size and int(ok[0]) == 0:
        found = float(w[0])
    elif ok.size:
        i = int(ok[0])
        lo, hi = float(w[i - 1]), float(w[i])
        for _ in range(bisection_steps(hi - lo, tolerance)):
            mid = 0.5 * (lo + hi)
            # the narrowest chart width guides the sampling (the chart's waves), unslid
            pair = (caissons[0], caisson.with_width(mid))
            r = run_chunks(pair, model, chunks, guides=1, **run)
            probe_widths.append(mid)
            probe_rows.append(r.sliding[0])
            if float(r.sliding[0].mean()) <= target:
                hi = mid
            else:
                lo = mid
        found = hi
        if trials > 1:
            every_s = np.vstack([out.sliding, *probe_rows]) if probe_rows else out.sliding
            interval = width_interval(np.concatenate([w, probe_widths]), every_s, target, seed_)
    thresholds = tuple(model.thresholds)
    exceed = np.array([[float(np.mean(row > x)) for x in thresholds] for row in out.sliding])
    fail = None if failure_sliding is None else np.mean(out.sliding > failure_sliding, axis=1)
    return DesignChart(widths=w, expected_sliding=esd, std_error=np.asarray(se, dtype=np.float64),
                       target=target, width_for_target=found, required_sf=required_sf,
                       sf_width=sf_width(caisson, model, required_sf, impulsive=sf_impulsive),
                       trials=trials, seed=seed_, tolerance=tolerance, width_interval=interval,
                       thresholds=thresholds, exceedance=exceed.reshape(w.size, len(thresholds)),
                       failure_sliding=failure_sliding,
                       failure_probability=None if fail is None else np.asarray(fail, dtype=np.float64),
                       probes=tuple((float(a), float(b.mean())) for a, b in zip(probe_widths, probe_rows)),
                       impulsive=model.impulsive, by_year=out.years.mean(),
                       by_year_error=out.years.std_error())
