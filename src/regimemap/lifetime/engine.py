"""Monte Carlo of lifetimes in blocks: each block of lifetimes draws from its own random stream.

numpy only.  A run of ``trials`` lifetimes is cut into blocks of
:data:`BLOCK` lifetimes; block ``j`` draws every random number it needs from
the stream ``SeedSequence(seed).spawn(...)[j]``, in a fixed order, and a last,
partial block is simulated whole and cut.  So lifetime ``i`` depends only on
``seed`` and ``i``: the results are bit-identical whatever the chunks, the
processes or the machines the blocks run on (:mod:`regimemap.lifetime.parallel`).

Inside a block the work follows the sliding waves, not all waves: a wave
slides only above the storm's sliding height ``H_s``, so the number of
sliding waves of a storm of ``N`` waves is ``Binomial(N, exp(-2 (H_s/H1/3)^2))``
and their heights are the Rayleigh tail ``sqrt(H_s^2 + H1/3^2 E/2)``, ``E``
standard exponential, each capped at the breaker limit -- the same
distribution as drawing all ``N`` heights (docs/lifetime.md, Sect. 8).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .model import Caisson, ErrorFactor, LifetimeModel
from .normal import truncated_normal
from .sliding import half_sine_slide, wave_duration
from .storms import SeaStates, sea_states, sliding_threshold, wave_forces

__all__ = ["BLOCK", "BlockResult", "simulate_block"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: Lifetimes per random stream.
BLOCK = 100

#: Most sliding waves computed at once (bounds the memory of a block).
_WAVE_SLICE = 1 << 20


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
    """

    sliding: FloatArray
    max_storm: FloatArray
    storms: IntArray
    sliding_waves: int


def _factor(f: ErrorFactor, u: FloatArray, truncate: float | None) -> FloatArray:
    """``ratio max(1 + cov z, 0)``: a factor never turns a load or a height negative."""
    if f.cov == 0.0:
        return np.full(u.shape, f.ratio)
    return np.asarray(f.ratio * np.maximum(1.0 + f.cov * truncated_normal(u, truncate), 0.0),
                      dtype=np.float64)


def simulate_block(caissons: tuple[Caisson, ...], model: LifetimeModel, stream: np.random.SeedSequence,
                   n: int = BLOCK) -> BlockResult:
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

    Returns
    -------
    BlockResult

    Notes
    -----
    The draws, in order: ``n`` uniforms for the deep-water factors; the
    number of storms of each year (Poisson, when ``storms_per_year`` is set);
    five uniforms per storm (peak, tide phase, transformation, force and
    friction factors), drawn even for a factor whose ``cov`` is 0 so that no
    option shifts the others' random numbers; the binomial number of sliding
    waves of each storm; one standard exponential per sliding wave.
    """
    rng = np.random.Generator(np.random.PCG64(stream))
    err = model.errors
    f_deep = _factor(err.deepwater, rng.random(n), model.truncate)
    lam = model.climate.storms_per_year
    if lam is None:
        counts = np.full(n, model.years, dtype=np.int64)
    else:
        counts = rng.poisson(lam, size=(n, model.years)).sum(axis=1).astype(np.int64)
    n_storms = int(counts.sum())
    life = np.repeat(np.arange(n), counts)
    u = rng.random((5, n_storms))
    H0 = model.climate.quantile(u[0]) * f_deep[life]
    tide = 0.5 * model.tide_range * np.sin(2.0 * np.pi * u[1])
    seas = sea_states(caissons, model, H0, tide, _factor(err.transformation, u[2], model.truncate),
                      _factor(err.force, u[3], model.truncate), _factor(err.friction, u[4], model.truncate))
    H_s = sliding_threshold(caissons[0], model, seas)
    can = np.isfinite(H_s)
    p = np.zeros(n_storms)
    with np.errstate(divide="ignore", invalid="ignore"):
        p[can] = np.exp(-2.0 * (H_s[can] / seas.H13[can]) ** 2)
    n_sliding = rng.binomial(np.where(can, seas.n_waves, 0), p).astype(np.int64)

    n_w = len(caissons)
    storm_slide = np.zeros((n_w, n_storms))
    first = 0
    total = int(n_sliding.sum())
    ends = np.cumsum(n_sliding)
    while first < n_storms:  # slices of whole storms, at most _WAVE_SLICE waves (or one storm)
        start_wave = 0 if first == 0 else int(ends[first - 1])
        last = int(np.searchsorted(ends, start_wave + _WAVE_SLICE, side="right"))
        last = max(last, first + 1)
        _slide_storms(caissons, model, seas, H_s, n_sliding, rng, first, min(last, n_storms),
                      storm_slide)
        first = last
    sliding = np.stack([np.bincount(life, weights=storm_slide[j], minlength=n) for j in range(n_w)]
                       ).astype(np.float64)
    max_storm = np.zeros((n_w, n))
    for j in range(n_w):
        np.maximum.at(max_storm[j], life, storm_slide[j])
    return BlockResult(sliding=sliding, max_storm=max_storm, storms=counts, sliding_waves=total)


def _slide_storms(caissons: tuple[Caisson, ...], model: LifetimeModel, seas: SeaStates, H_s: FloatArray,
                  n_sliding: IntArray, rng: np.random.Generator, first: int, last: int,
                  storm_slide: FloatArray) -> None:
    """Draw the sliding waves of storms ``first..last-1`` and add up their slides per storm."""
    counts = n_sliding[first:last]
    m = int(counts.sum())
    if m == 0:
        return
    storm = np.repeat(np.arange(first, last), counts)
    E = rng.standard_exponential(m)
    H13 = seas.H13[storm]
    H = np.minimum(np.sqrt(H_s[storm] ** 2 + 0.5 * H13 * H13 * E), seas.H_cap[storm])
    P, u = wave_forces(caissons[0], model, seas, storm, H)
    tau = wave_duration(H, seas.depth[storm], seas.period[storm])
    mu = seas.friction[storm]
    for j, b in enumerate(seas.widths):
        x = half_sine_slide(P + mu * u * b, seas.resistance[j, storm], seas.mass[j, storm], tau)
        storm_slide[j, first:last] += np.bincount(storm - first, weights=x, minlength=last - first)
