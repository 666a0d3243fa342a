"""Monte Carlo of lifetimes in blocks: each block of lifetimes draws from its own random stream.

numpy only.  A run of ``trials`` lifetimes is cut into blocks of
:data:`BLOCK` lifetimes; block ``j`` draws every random number it needs from
the stream ``SeedSequence(seed).spawn(...)[j]``, in a fixed order, and a last,
partial block is simulated whole and cut.  So lifetime ``i`` depends only on
``seed`` and ``i``: on one machine the results are bit-identical whatever the
chunks or the processes the blocks run on (:mod:`regimemap.lifetime.parallel`).
Across machines they agree to a relative 1e-12 or better, not bit for bit: numpy's
exp, log, sin and power differ in the last bits between CPU feature levels
(docs/guide/development.md, "Reproducibility").

Inside a block the work follows the sliding waves, not all waves: a wave
slides only above the storm's sliding height ``H_s``, so the number of
sliding waves of a storm of :math:`N` waves is
:math:`\\mathrm{Binomial}(N, e^{-2 (H_s/H_{1/3})^2})` and their heights are the
Rayleigh tail :math:`\\sqrt{H_s^2 + H_{1/3}^2 E/2}`, :math:`E` standard exponential,
each capped at the breaker limit -- the same distribution as drawing all :math:`N` heights
(docs/lifetime.md, Sect. 8).

Each storm has a service year, whose :class:`~regimemap.lifetime.model.YearTrend`
values set its sea level, peak factor and rate; a block keeps per width and year only the
sums of its lifetimes' cumulative sliding (:class:`YearStats`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .model import Caisson, ErrorFactor, LifetimeModel
from .normal import truncated_normal
from .sliding import half_sine_slide, wave_duration
from .storms import SeaStates, sea_states, sliding_threshold, wave_forces

__all__ = ["BLOCK", "BlockResult", "YearStats", "simulate_block", "simulate_blocks"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: Lifetimes per random stream.
BLOCK = 100

#: Most exponentials drawn at once (the slices of whole storms the draws come in).
_WAVE_SLICE = 1 << 20

#: Most sliding waves whose loads are computed at once (bounds the memory of a chunk).
_PIECE = 1 << 18

#: Most slides (widths x waves) computed at once.
_SLIDE_ELEMENTS = 1 << 21


@dataclass(frozen=True)
class YearStats:
    """The cumulative sliding by service year of blocks of lifetimes, block by block.

    Attributes
    ----------
    count : ndarray of int, shape (n_blocks,)
        Lifetimes of each block.
    sums : ndarray, shape (n_blocks, n_widths, years)
        Sum over the block's lifetimes of the sliding up to the end of each year [m].
    m2 : ndarray, shape (n_blocks, n_widths, years)
        Sum of the squared deviations from the block's mean [m^2].

    Notes
    -----
    Joined in block order, ``M2 = sum_b M2_b + sum_b n_b (mean_b - mean)^2`` (Chan, Golub &
    LeVeque 1983): the same bits for any chunks.
    """

    count: IntArray
    sums: FloatArray
    m2: FloatArray

    @classmethod
    def of(cls, cumulative: FloatArray) -> YearStats:
        """One block's statistics from its lifetimes' cumulative sliding ``(n_widths, n, years)``."""
        n = cumulative.shape[1]
        sums = cumulative.sum(axis=1)
        mean = sums / n if n else sums
        m2 = ((cumulative - mean[:, None, :]) ** 2).sum(axis=1)
        return cls(np.array([n], dtype=np.int64), sums[None], m2[None])

    @classmethod
    def join(cls, parts: Sequence[YearStats]) -> YearStats:
        """The blocks of ``parts``, in order."""
        return cls(np.concatenate([p.count for p in parts]), np.concatenate([p.sums for p in parts]),
                   np.concatenate([p.m2 for p in parts]))

    def mean(self) -> FloatArray:
        """Expected cumulative sliding at the end of each service year, ``(n_widths, years)`` [m]."""
        return np.asarray(self.sums.sum(axis=0) / self.count.sum(), dtype=np.float64)

    def std_error(self) -> FloatArray:
        """Standard error of :meth:`mean`: sample standard deviation over sqrt(lifetimes) [m]."""
        n = int(self.count.sum())
        if n < 2:
            return np.full(self.sums.shape[1:], np.nan)
        mean = self.mean()
        c = self.count[:, None, None].astype(np.float64)
        block_mean = self.sums / c
        m2 = self.m2.sum(axis=0) + (c * (block_mean - mean[None]) ** 2).sum(axis=0)
        return np.asarray(np.sqrt(m2 / (n - 1) / n), dtype=np.float64)


@dataclass(frozen=True)
class BlockResult:
    """What a block of lifetimes gives (plain arrays).

    Attributes
    ----------
    sliding : ndarray, shape (n_widths, n)
        Total sliding of each lifetime [m].
    max_storm : ndarray, shape (n_widths, n)
        The largest sliding of one storm in each lifetime [m].
    storms : ndarray of int, shape (n,)
        Number of storms in each lifetime.
    sliding_waves : int
        Waves that were computed (above the sampling threshold).
    years : YearStats
        The cumulative sliding by service year, per block.
    """

    sliding: FloatArray
    max_storm: FloatArray
    storms: IntArray
    sliding_waves: int
    years: YearStats

    @classmethod
    def join(cls, parts: Sequence[BlockResult], keep: int | None = None) -> BlockResult:
        """The lifetimes of ``parts``, in order: the first ``keep`` of them (None: all)."""
        cut = slice(None, keep)
        return cls(sliding=np.concatenate([p.sliding for p in parts], axis=1)[:, cut],
                   max_storm=np.concatenate([p.max_storm for p in parts], axis=1)[:, cut],
                   storms=np.concatenate([p.storms for p in parts])[cut],
                   sliding_waves=sum(p.sliding_waves for p in parts),
                   years=YearStats.join([p.years for p in parts]))


def _factor(f: ErrorFactor, u: FloatArray, truncate: float | None) -> FloatArray:
    """``ratio max(1 + cov z, 0)``: a factor never turns a load or a height negative."""
    if f.cov == 0.0:
        return np.full(u.shape, f.ratio)
    return np.asarray(f.ratio * np.maximum(1.0 + f.cov * truncated_normal(u, truncate), 0.0),
                      dtype=np.float64)


@dataclass
class _Draws:
    """One block's uniforms and storm counts, and the generator that drew them."""

    rng: np.random.Generator
    n: int
    counts: IntArray          # storms of each lifetime
    life: IntArray            # the lifetime of each storm
    year: IntArray            # the service year of each storm, from 0
    first: int                # its first storm among the blocks simulated together
    u_deep: FloatArray        # (n,) for the deep-water factors
    u: FloatArray             # (5, storms): peak, tide phase, transformation, force, friction


def _draw_storms(model: LifetimeModel, stream: np.random.SeedSequence, n: int, first: int) -> _Draws:
    """The block's draws up to the storms' factors, in the order of :func:`simulate_block`."""
    rng = np.random.Generator(np.random.PCG64(stream))
    u_deep = rng.random(n)
    lam = model.climate.storms_per_year
    years = np.arange(model.years, dtype=np.int64)
    if lam is None:
        counts = np.full(n, model.years, dtype=np.int64)
        year = np.tile(years, n)
    else:
        rate = lam if model.trend is None else lam * np.asarray(model.trend.storm_rate)
        per_year = rng.poisson(rate, size=(n, model.years)).astype(np.int64)
        counts = per_year.sum(axis=1)
        year = np.repeat(np.tile(years, n), per_year.ravel())
    life = np.repeat(np.arange(n), counts)
    return _Draws(rng, n, counts, life, year, first, u_deep, rng.random((5, life.size)))


def _peaks(model: LifetimeModel, u: FloatArray, year: IntArray) -> FloatArray:
    """The storms' peaks ``H0'`` before the deep-water factor, from their uniforms and years.

    An annual-maximum climate's year with storm-rate factor ``f`` has the peak
    distribution ``F^f``, so its peak is ``F^-1(u^(1/f))`` (docs/lifetime.md,
    "A changing climate"); a Poisson climate's storms keep ``F`` (the factor
    is on their number).  A factor of exactly 1 leaves ``u`` untouched.
    """
    trend = model.trend
    if trend is None or model.climate.storms_per_year is not None:
        return model.climate.quantile(u)
    f = np.asarray(trend.storm_rate)[year]
    return model.climate.quantile(np.where(f == 1.0, u, u ** (1.0 / f)))


def _storm_seas(caissons: tuple[Caisson, ...], model: LifetimeModel, blocks: Sequence[_Draws]) -> SeaStates:
    """The sea states of the storms of all the blocks (element by element: as block by block)."""
    err, cut = model.errors, model.truncate
    f_deep = _factor(err.deepwater, np.concatenate([b.u_deep for b in blocks]), cut)
    life = np.concatenate([b.life + k * b.n for k, b in enumerate(blocks)])
    year = np.concatenate([b.year for b in blocks])
    u = np.concatenate([b.u for b in blocks], axis=1)
    H0 = _peaks(model, u[0], year) * f_deep[life]
    tide = 0.5 * model.tide_range * np.sin(2.0 * np.pi * u[1])
    if model.trend is not None:  # the year's peak factor and mean sea level (docs/lifetime.md)
        H0 = H0 * np.asarray(model.trend.wave_height)[year]
        tide = tide + np.asarray(model.trend.sea_level)[year]
    return sea_states(caissons, model, H0, tide, _factor(err.transformation, u[2], cut),
                      _factor(err.force, u[3], cut), _factor(err.friction, u[4], cut))


def _draw_waves(d: _Draws, seas: SeaStates, H_s: FloatArray) -> tuple[IntArray, IntArray, FloatArray]:
    """The block's sliding waves: their number per storm, their storms (global) and exponentials.

    The exponentials are drawn in slices of whole storms of at most
    :data:`_WAVE_SLICE` waves (or one storm), which bounds the memory; the slices
    depend on the stream's storms only, so a seed gives the same waves every run.
    """
    k = slice(d.first, d.first + d.life.size)
    can = np.isfinite(H_s[k])
    p = np.zeros(d.life.size)
    with np.errstate(divide="ignore", invalid="ignore"):
        p[can] = np.exp(-2.0 * (H_s[k][can] / seas.H13[k][can]) ** 2)
    n_sliding = d.rng.binomial(np.where(can, seas.n_waves[k], 0), p).astype(np.int64)
    ends = np.cumsum(n_sliding)
    draws = []
    first = 0
    while first < n_sliding.size:  # slices of whole storms, at most _WAVE_SLICE waves (or one storm)
        start_wave = 0 if first == 0 else int(ends[first - 1])
        last = max(int(np.searchsorted(ends, start_wave + _WAVE_SLICE, side="right")), first + 1)
        last = min(last, n_sliding.size)
        m = int(ends[last - 1]) - start_wave
        if m:
            draws.append(d.rng.standard_exponential(m))
        first = last
    storm = np.repeat(np.arange(d.first, d.first + n_sliding.size, dtype=np.int64), n_sliding)
    E = np.concatenate(draws) if draws else np.zeros(0)
    return n_sliding, storm, E


def simulate_block(caissons: tuple[Caisson, ...], model: LifetimeModel, stream: np.random.SeedSequence,
                   n: int = BLOCK, keep: int | None = None) -> BlockResult:
    """Simulate ``n`` lifetimes of the same caisson at several widths, from one random stream.

    Parameters
    ----------
    caissons : tuple of Caisson
        One section at one site, of one or more widths (every width sees the
        same storms and the same waves: common random numbers).
    model : LifetimeModel
        Climate and options.
    stream : numpy.random.SeedSequence
        This block's seed.
    n : int, optional
        Lifetimes in the block (:data:`BLOCK`).
    keep : int, optional
        The year statistics count the first ``keep`` lifetimes only (all: None).

    Returns
    -------
    BlockResult

    Notes
    -----
    The draws, in order: ``n`` uniforms for the deep-water factors; the
    number of storms of each year (Poisson, when ``storms_per_year`` is set,
    with the rate times the year's ``storm_rate`` factor of a trend);
    five uniforms per storm (peak, tide phase, transformation, force and
    friction factors), drawn even for a factor whose ``cov`` is 0 so that no
    option shifts the others' random numbers; the binomial number of sliding
    waves of each storm; one standard exponential per sliding wave.
    """
    return simulate_blocks(caissons, model, (stream,), n, keep=keep)[0]


def simulate_blocks(caissons: tuple[Caisson, ...], model: LifetimeModel,
                    streams: Sequence[np.random.SeedSequence], n: int = BLOCK,
                    guides: int = 0, keep: int | None = None) -> list[BlockResult]:
    """Simulate several blocks together: each as :func:`simulate_block`, to the last bit.

    Parameters
    ----------
    caissons : tuple of Caisson
        One section at one site, of one or more widths.
    model : LifetimeModel
        Climate and options.
    streams : sequence of numpy.random.SeedSequence
        One seed per block; each block draws from its own generator, in the
        order of :func:`simulate_block`.
    n : int, optional
        Lifetimes in each block (:data:`BLOCK`).
    guides : int, optional
        The first ``guides`` caissons only guide the sampling -- their
        sliding heights choose the waves drawn, as in a run of all the
        caissons -- and are not slid: the results have the rows of
        ``caissons[guides:]`` only (the bisection of the design chart keeps
        the chart's waves without sliding its narrowest width again).
    keep : int, optional
        The year statistics count the first ``keep`` lifetimes of the blocks
        together (the rest of the last block is simulated and not counted);
        None: all.

    Returns
    -------
    list of BlockResult
        One per stream, the same as :func:`simulate_block` of that stream
        (its rows ``guides:``).

    Notes
    -----
    Every formula is element by element over storms or waves, and every sum
    is over the waves of one storm or the storms of one lifetime, in order:
    so the storms of all the blocks share one computation of the sea states
    and the sliding thresholds, and their waves one computation of the loads
    and the slides (all widths at once), and each block's numbers are those
    it would have alone.
    """
    blocks: list[_Draws] = []
    first = 0
    for stream in streams:
        blocks.append(_draw_storms(model, stream, n, first))
        first += blocks[-1].life.size
    seas = _storm_seas(caissons, model, blocks)
    H_s = sliding_threshold(caissons[0], model, seas)
    waves = [_draw_waves(b, seas, H_s) for b in blocks]
    n_sliding = np.concatenate([w[0] for w in waves])
    storm = np.concatenate([w[1] for w in waves])
    E = np.concatenate([w[2] for w in waves])
    if not 0 <= guides < len(caissons):
        raise ValueError(f"guides must be in [0, {len(caissons)}), got {guides!r}")
    storm_slide = _slide_waves(caissons[0], model, seas, H_s, n_sliding, storm, E, guides)

    n_w = len(caissons) - guides
    left = n * len(blocks) if keep is None else keep
    out = []
    for b in blocks:
        k = storm_slide[:, b.first:b.first + b.life.size]
        index = (np.arange(n_w)[:, None] * b.n + b.life[None, :]).ravel()
        sliding = np.bincount(index, weights=k.ravel(), minlength=n_w * b.n).reshape(n_w, b.n)
        max_storm = np.zeros((n_w, b.n))
        np.maximum.at(max_storm.reshape(-1), index, k.ravel())
        total = int(n_sliding[b.first:b.first + b.life.size].sum())
        counted = max(0, min(b.n, left))
        left -= counted
        out.append(BlockResult(sliding=sliding.astype(np.float64), max_storm=max_storm, storms=b.counts,
                               sliding_waves=total, years=_year_stats(b, k, model.years, counted)))
    return out


def _year_stats(b: _Draws, storm_slide: FloatArray, years: int, keep: int) -> YearStats:
    """The block's cumulative sliding by service year over its first ``keep`` lifetimes.

    ``storm_slide`` is ``(n_widths, storms)`` of the block's storms; each
    lifetime-year's sliding is the sum of its storms' in order, then summed
    over the years.
    """
    n_w = storm_slide.shape[0]
    index = ((np.arange(n_w)[:, None] * b.n + b.life[None, :]) * years + b.year[None, :]).ravel()
    per_year = np.bincount(index, weights=storm_slide.ravel(), minlength=n_w * b.n * years)
    cumulative = np.cumsum(per_year.reshape(n_w, b.n, years)[:, :keep, :], axis=2)
    return YearStats.of(np.asarray(cumulative, dtype=np.float64))


def _slide_waves(caisson: Caisson, model: LifetimeModel, seas: SeaStates, H_s: FloatArray,
                 n_sliding: IntArray, storm: IntArray, E: FloatArray, guides: int) -> FloatArray:
    """Each storm's total slide at widths ``guides:``, ``(n_widths - guides, n_storms)``.

    The waves go in pieces of whole storms (at most :data:`_PIECE` waves, or
    one storm), and the widths of a piece in groups of at most
    :data:`_SLIDE_ELEMENTS` slides: one numpy call for all the waves of a
    piece, one for a group's slides, one sum per storm in wave order.
    """
    n_storms = n_sliding.size
    storm_slide = np.zeros((seas.widths.size - guides, n_storms))
    ends = np.cumsum(n_sliding)
    first = 0
    while first < n_storms:
        start_wave = 0 if first == 0 else int(ends[first - 1])
        last = max(int(np.searchsorted(ends, start_wave + _PIECE, side="right")), first + 1)
        last = min(last, n_storms)
        waves = slice(start_wave, int(ends[last - 1]))
        if waves.stop > waves.start:
            _slide_piece(caisson, model, seas, H_s, storm[waves], E[waves], first, last, guides, storm_slide)
        first = last
    return storm_slide


def _slide_piece(caisson: Caisson, model: LifetimeModel, seas: SeaStates, H_s: FloatArray, storm: IntArray,
                 E: FloatArray, first: int, last: int, guides: int, storm_slide: FloatArray) -> None:
    """The slides of the waves of storms ``first..last-1`` at widths ``guides:``, summed per storm."""
    H13 = seas.H13[storm]
    H = np.minimum(np.sqrt(H_s[storm] ** 2 + 0.5 * H13 * H13 * E), seas.H_cap[storm])
    P, u = wave_forces(caisson, model, seas, storm, H)
    tau = wave_duration(H, seas.depth[storm], seas.period[storm])
    mu_u = seas.friction[storm] * u
    m, n_storms = storm.size, last - first
    n_w = seas.widths.size
    rows = max(1, _SLIDE_ELEMENTS // m)
    for j in range(guides, n_w, rows):
        group = slice(j, min(j + rows, n_w))
        F = P[None, :] + mu_u[None, :] * seas.widths[group, None]
        x = half_sine_slide(F, seas.resistance[group, storm], seas.mass[group, storm], tau[None, :])
        k = group.stop - group.start
        index = (np.arange(k)[:, None] * n_storms + (storm - first)[None, :]).ravel()
        sums = np.bincount(index, weights=x.ravel(), minlength=k * n_storms).reshape(k, n_storms)
        storm_slide[group.start - guides:group.stop - guides, first:last] += sums
