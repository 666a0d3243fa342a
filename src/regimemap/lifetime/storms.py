"""The sea state of each storm at the wall, the force of each wave, and the sliding threshold.

numpy only, vectorised over storms (and over waves, indexed by their storm).
Every formula is :mod:`regimemap.waves`' (Goda's heights, pressures and loads)
or :mod:`regimemap.lifetime.sliding`'s; this module only assembles them for
many storms and many caisson widths at once (docs/lifetime.md, Sects. 3-5).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from regimemap.waves import breaker_height, caisson_loads, design_heights, wavelength
from regimemap.waves.pressure import GodaSeaState, goda_pressures_for, goda_sea_state

from .model import Caisson, LifetimeModel
from .sliding import added_mass

__all__ = ["SeaStates", "StormLoads", "sea_states", "sliding_threshold", "storm_loads", "wave_forces"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

#: Bisection steps for the sliding threshold: the bracket shrinks to 2^-48 of
#: the breaker height (the lower end is used, so the sampling stays exact).
_THRESHOLD_STEPS = 48


@dataclass(frozen=True)
class SeaStates:
    """The storms' conditions at the wall, and what the caissons oppose (arrays over storms).

    Width-dependent arrays have shape ``(n_widths, n_storms)``.
    """

    H0: FloatArray            # storm peak H0' after the deep-water factor [m]
    period: FloatArray        # T1/3 [s]
    depth: FloatArray         # h + tide [m]
    base_depth: FloatArray    # h' + tide [m]
    armour_depth: FloatArray  # d + tide [m]
    crest: FloatArray         # hc - tide [m]
    H13: FloatArray           # H1/3 at the wall, after the transformation factor [m]
    hb: FloatArray            # h + 5 H1/3 tan(theta) [m]
    L: FloatArray             # wave length of T1/3 at h [m]
    H_cap: FloatArray         # breaker limit of an individual wave [m]
    n_waves: IntArray         # waves in the storm
    force_factor: FloatArray  # on P and U
    friction: FloatArray      # mu times the friction factor
    widths: FloatArray        # (n_widths,) full widths b [m]
    resistance: FloatArray    # (n_widths, n_storms) R = mu W' [N/m]
    mass: FloatArray          # (n_widths, n_storms) W/g + M_a [kg/m]


def sea_states(caissons: tuple[Caisson, ...], model: LifetimeModel, H0: FloatArray, tide: FloatArray,
               transformation: FloatArray, force: FloatArray, friction: FloatArray) -> SeaStates:
    """The storms' sea states at the wall for one site and several caisson widths.

    Parameters
    ----------
    caissons : tuple of Caisson
        The same section at the same site, of different widths.
    model : LifetimeModel
        Storm period, duration.
    H0 : ndarray
        Storm peaks ``H0'`` after the deep-water factor [m] (<= 0: a calm).
    tide : ndarray
        Water level of each storm above the design level [m].
    transformation, force, friction : ndarray
        The storms' uncertainty factors.

    Returns
    -------
    SeaStates
    """
    c = caissons[0]
    calm = ~(H0 > 0.0)
    h0 = np.where(calm, 1.0, H0)  # placeholder height for calm storms (no waves below)
    T = np.full_like(h0, model.storm_period(h0, c.g))
    h = c.depth + tide
    hp = c.base_depth + tide
    d = c.armour_depth + tide
    hc = c.crest - tide
    heights = design_heights(h0, T, h, c.seabed_slope, g=c.g)
    H13 = np.where(calm, 0.0, heights.H13 * transformation)
    hb = h + 5.0 * H13 * c.seabed_slope
    n_waves = np.where(calm, 0, np.rint(model.storm_hours * 3600.0 / T)).astype(np.int64)
    mu = c.friction * friction
    widths = np.array([ci.width for ci in caissons], dtype=np.float64)
    dry = np.array([ci.mass for ci in caissons], dtype=np.float64)[:, None]
    weight = dry * c.g - c.rho_w * c.g * widths[:, None] * hp[None, :]
    return SeaStates(H0=np.where(calm, 0.0, h0), period=T, depth=h, base_depth=hp, armour_depth=d,
                     crest=hc, H13=H13, hb=hb, L=wavelength(T, h, c.g),
                     H_cap=breaker_height(heights.L0, hb, c.seabed_slope), n_waves=n_waves,
                     force_factor=np.asarray(force, dtype=np.float64), friction=mu, widths=widths,
                     resistance=mu[None, :] * weight,
                     mass=dry + added_mass(hp, c.rho_w)[None, :])


@dataclass(frozen=True)
class StormLoads:
    """The wave loads of given storms, prepared once for any wave heights (:func:`storm_loads`).

    Calling it with the heights ``H`` (one per storm of ``storm``, or
    broadcast) gives ``(P, U_per_width)`` as :func:`wave_forces` does.
    """

    sea: GodaSeaState        # the storms' sea states (Goda's height-free factors)
    base_depth: FloatArray   # h' + tide [m]
    force_factor: FloatArray
    impulsive: bool

    def __call__(self, H: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``P`` [N/m] and ``U/b`` [N/m per m of width] of waves of height ``H``, times the force factor."""
        loads = caisson_loads(goda_pressures_for(self.sea, H, self.impulsive), self.base_depth, 1.0)
        f = self.force_factor
        return np.asarray(loads.P * f, dtype=np.float64), np.asarray(loads.U * f, dtype=np.float64)


def storm_loads(caisson: Caisson, model: LifetimeModel, seas: SeaStates, storm: IntArray) -> StormLoads:
    """Goda's loads in the sea states of ``storm``, for waves of heights given later.

    Parameters
    ----------
    caisson : Caisson
        The site (and the wave angle, berm width).
    model : LifetimeModel
        ``impulsive``.
    seas : SeaStates
        The storms.
    storm : ndarray of int
        The storm of each wave (or each storm once, for a bisection on the height).

    Returns
    -------
    StormLoads
        The wave length, Goda's ``alpha1``, ``alpha3`` and Takahashi's
        ``alpha_I1`` of each entry computed once: evaluating it at many heights
        costs only the height-dependent part of the formulas, and gives the
        same numbers, bit for bit, as :func:`wave_forces`.
    """
    c = caisson
    sea = goda_sea_state(period=seas.period[storm], depth=seas.depth[storm], hb=seas.hb[storm],
                         armour_depth=seas.armour_depth[storm], base_depth=seas.base_depth[storm],
                         crest=seas.crest[storm], berm_width=c.berm_width, angle_deg=c.angle_deg,
                         rotation_deg=c.rotation_deg, rho_w=c.rho_w, g=c.g, L=seas.L[storm])
    return StormLoads(sea=sea, base_depth=seas.base_depth[storm], force_factor=seas.force_factor[storm],
                      impulsive=model.impulsive)


def wave_forces(caisson: Caisson, model: LifetimeModel, seas: SeaStates, storm: IntArray,
                H: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Goda's force ``P`` and uplift per metre of width ``U/b`` of waves of height ``H``.

    Parameters
    ----------
    caisson : Caisson
        The site (and the wave angle, berm width).
    model : LifetimeModel
        ``impulsive``.
    seas : SeaStates
        The storms.
    storm : ndarray of int
        The storm of each wave.
    H : ndarray
        The waves' heights [m] (in place of Goda's ``Hmax``; the storm's
        ``H1/3`` sets ``h_b``).

    Returns
    -------
    P, U_per_width : ndarray
        [N/m] and [N/m per m of width], both times the storm's force factor
        (:func:`storm_loads` evaluated once).
    """
    return storm_loads(caisson, model, seas, storm)(H)


def _excess(P: FloatArray, mu_u: FloatArray, widths: FloatArray, resistance: FloatArray) -> FloatArray:
    """``max over widths of F - R``, ``F = P + mu U`` (> 0: some width slides).

    ``mu_u`` is ``mu U/b`` of each wave, ``resistance`` the ``(n_widths, n)``
    friction ``R`` at rest of the waves' storms.
    """
    F = P[None, :] + mu_u[None, :] * widths[:, None]
    return np.asarray(np.max(F - resistance, axis=0), dtype=np.float64)


def sliding_threshold(caisson: Caisson, model: LifetimeModel, seas: SeaStates) -> FloatArray:
    """A lower bound of the height from which a wave slides some caisson width, per storm [m].

    Parameters
    ----------
    caisson : Caisson
        The site.
    model : LifetimeModel
        ``impulsive``.
    seas : SeaStates
        The storms.

    Returns
    -------
    ndarray
        ``inf`` where no wave up to the breaker limit slides any width;
        elsewhere the lower end of a bisection bracket of width ``2^-48 H_cap``
        around the root of ``P(H) + mu U(H) = mu W'`` (the push grows with
        ``H``: Goda's ``p1``, ``eta*`` and ``pu`` all do).  Waves between the
        bound and the true threshold slide exactly 0, so sampling the waves
        above the bound is exact.
    """
    n = seas.H0.size
    out = np.full(n, np.inf)
    live = np.flatnonzero((seas.n_waves > 0) & (seas.H13 > 0.0))
    if live.size == 0:
        return out
    P, u = wave_forces(caisson, model, seas, live, seas.H_cap[live])
    live = live[_excess(P, seas.friction[live] * u, seas.widths, seas.resistance[:, live]) > 0.0]
    if live.size == 0:
        return out
    # the storms' sea states, frictions and resistances once; each step only evaluates the heights
    loads = storm_loads(caisson, model, seas, live)
    mu = seas.friction[live]
    resistance = seas.resistance[:, live]
    lo = np.zeros(live.size)
    hi = seas.H_cap[live].copy()
    for _ in range(_THRESHOLD_STEPS):
        mid = 0.5 * (lo + hi)
        P, u = loads(mid)
        slides = _excess(P, mu * u, seas.widths, resistance) > 0.0
        hi = np.where(slides, mid, hi)
        lo = np.where(slides, lo, mid)
    out[live] = lo
    return out
