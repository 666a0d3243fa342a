"""What a lifetime simulation needs: the caisson at its site, the model's options, the errors.

numpy only.  :class:`Caisson` is the section and its site (SI units: m, N/m,
kg/m^3); :class:`LifetimeModel` the climate and every modelling choice, each a
named option with the reference model of docs/lifetime.md as its default;
:class:`ErrorFactor` one normal uncertainty factor ``ratio (1 + cov z)``;
:class:`YearTrend` the change of the climate year by year over the design life.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from regimemap.waves import CaissonSection, Densities, section_from_densities, section_from_weight

from .climate import Climate

__all__ = ["DEFAULT_ERRORS", "DEFAULT_THRESHOLDS", "FRICTION_SIGMAS", "Caisson", "ErrorFactor", "Errors",
           "LifetimeModel", "PERIOD_COEFFICIENT", "PERIOD_EXPONENT", "YearTrend"]

#: Goda's storm relation :math:`T_{1/3} = 3.3 \, {H_0'}^{0.63}` (Goda 2000, Sect. 4.2 and 11;
#: docs/lifetime.md, Sect. 3).
PERIOD_COEFFICIENT = 3.3
PERIOD_EXPONENT = 0.63

#: The friction factor may not reach 0 within this many standard deviations (untruncated): a
#: caisson without friction would slide without end (docs/lifetime.md, Sect. 7).
FRICTION_SIGMAS = 6.0

#: Lifetime slides whose exceedance probability is reported by default [m].
DEFAULT_THRESHOLDS: tuple[float, ...] = (0.03, 0.1, 0.3, 1.0, 3.0)


@dataclass(frozen=True)
class ErrorFactor:
    """A normal uncertainty factor ``ratio (1 + cov z)``, ``z`` standard normal.

    Attributes
    ----------
    ratio : float
        Mean of the factor (the bias of the formula it multiplies), > 0.
    cov : float
        Coefficient of variation, >= 0; 0 makes the factor the constant ``ratio``.
    """

    ratio: float = 1.0
    cov: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.ratio) and self.ratio > 0.0):
            raise ValueError(f"ratio must be a finite number > 0, got {self.ratio!r}")
        if not (math.isfinite(self.cov) and self.cov >= 0.0):
            raise ValueError(f"cov must be a finite number >= 0, got {self.cov!r}")


@dataclass(frozen=True)
class Errors:
    """The four uncertainty factors of the reference model (docs/lifetime.md, Sect. 7).

    Attributes
    ----------
    deepwater : ErrorFactor
        On the storm's deep-water height ``H0'`` (drawn once per lifetime: the
        estimate of the climate is wrong the same way for 50 years).
    transformation : ErrorFactor
        On ``H1/3`` at the wall (Goda's surf-zone formulas), once per storm.
    force : ErrorFactor
        On ``P`` and ``U`` together (Goda's pressure formulas), once per storm.
    friction : ErrorFactor
        On the friction coefficient, once per storm.
    """

    deepwater: ErrorFactor = field(default_factory=lambda: ErrorFactor(1.0, 0.10))
    transformation: ErrorFactor = field(default_factory=lambda: ErrorFactor(0.97, 0.04))
    force: ErrorFactor = field(default_factory=lambda: ErrorFactor(0.91, 0.17))
    friction: ErrorFactor = field(default_factory=lambda: ErrorFactor(1.06, 0.15))

    @classmethod
    def none(cls) -> Errors:
        """No uncertainty: every factor the constant 1."""
        one = ErrorFactor(1.0, 0.0)
        return cls(one, one, one, one)

    def names(self) -> tuple[str, ...]:
        """The factors' names, in the order they are drawn."""
        return ("deepwater", "transformation", "force", "friction")


#: The reference model's factors: Takayama & Ikeda (1992) as used by Shimosako & Takahashi
#: (1999) -- deep water (1.0, 0.10), transformation (0.97, 0.04), force (0.91, 0.17),
#: friction (1.06, 0.15) (docs/lifetime.md, Sect. 7 gives the sources and the other sets in use).
DEFAULT_ERRORS = Errors()


@dataclass(frozen=True)
class Caisson:
    """A caisson section at its site, per metre of breakwater (SI units).

    Attributes
    ----------
    depth, armour_depth : float
        ``h`` at the wall and ``d`` above the armour layer [m].
    seabed_slope : float
        ``tan(theta)`` of the sea bed.
    width, base_depth, crest : float
        Full width ``b`` (twice the map's half width ``B``), ``h'``, ``hc`` [m].
    friction : float
        ``mu`` between caisson and mound.
    buoyant_weight : float or None
        ``W'`` at still water [N/m]; or ``densities``.
    densities : Densities or None
        Concrete fraction and densities of a filled caisson.
    berm_width : float
        ``BM`` [m] (Takahashi's impulsive coefficient only).
    angle_deg, rotation_deg : float
        Wave angle from the normal and its rotation toward the normal [deg].
    rho_w, g : float
        Water density [kg/m^3], gravity [m/s^2].
    """

    depth: float
    armour_depth: float
    seabed_slope: float
    width: float
    base_depth: float
    crest: float
    friction: float
    buoyant_weight: float | None = None
    densities: Densities | None = None
    berm_width: float = 0.0
    angle_deg: float = 0.0
    rotation_deg: float = 0.0
    rho_w: float = 1030.0
    g: float = 9.81

    def __post_init__(self) -> None:
        if (self.buoyant_weight is None) == (self.densities is None):
            raise ValueError("give exactly one of buoyant_weight and densities")

    def section(self) -> CaissonSection:
        """Mass properties at still water (:mod:`regimemap.waves`, Goda 2000, Sect. 4.3)."""
        if self.densities is not None:
            d = self.densities
            return section_from_densities(self.width, self.base_depth, self.crest,
                                          concrete_fraction=d.concrete_fraction,
                                          concrete_density=d.concrete, fill_density=d.fill,
                                          fill_density_above=d.fill_above, rho_w=self.rho_w, g=self.g)
        assert self.buoyant_weight is not None
        return section_from_weight(self.buoyant_weight, self.width, self.base_depth, self.crest,
                                   rho_w=self.rho_w, g=self.g)

    @property
    def mass(self) -> float:
        """Dry mass per metre [kg/m]."""
        return float(self.section().mass)

    def with_width(self, width: float) -> Caisson:
        """The same section ``width`` wide: ``W'`` in proportion to the width, or from the densities."""
        if self.buoyant_weight is not None:
            return replace(self, width=width, buoyant_weight=self.buoyant_weight * width / self.width)
        return replace(self, width=width)


@dataclass(frozen=True)
class YearTrend:
    """Year-by-year change of the climate over the design life; element ``y - 1`` is service year ``y``.

    Attributes
    ----------
    sea_level : tuple of float
        Mean sea level of each service year above today's [m] (finite, any
        sign); it adds to the depth terms exactly like the tide: ``h``,
        ``h'`` and ``d`` rise by it and ``hc`` falls by it.
    wave_height : tuple of float
        Factor (> 0) on the storm peak ``H0'`` of each year's storms.
    storm_rate : tuple of float
        Factor ``f`` (> 0) on the number of storms of each year: a Poisson
        climate's rate ``lambda f``; an annual-maximum climate's yearly peak
        with the distribution ``F^f`` (the maximum of ``f`` independent annual
        maxima for a whole ``f``; docs/lifetime.md, "A changing climate").

    Examples
    --------
    >>> YearTrend.stationary(3)
    YearTrend(sea_level=(0.0, 0.0, 0.0), wave_height=(1.0, 1.0, 1.0), storm_rate=(1.0, 1.0, 1.0))
    """

    sea_level: tuple[float, ...]
    wave_height: tuple[float, ...]
    storm_rate: tuple[float, ...]

    def __post_init__(self) -> None:
        n = len(self.sea_level)
        if n < 1:
            raise ValueError("a year trend needs at least one service year, got none")
        for name in ("sea_level", "wave_height", "storm_rate"):
            values = tuple(float(x) for x in getattr(self, name))
            if len(values) != n:
                raise ValueError(f"{name} has {len(values)} service years, sea_level {n}: "
                                 "give every field one value per service year")
            positive = name != "sea_level"
            for year, x in enumerate(values, start=1):
                if not math.isfinite(x) or (positive and not x > 0.0):
                    need = "a finite factor > 0" if positive else "a finite level [m]"
                    raise ValueError(f"{name} of service year {year} (of 1..{n}) must be {need}, got {x!r}")
            object.__setattr__(self, name, values)

    @classmethod
    def stationary(cls, years: int) -> YearTrend:
        """Today's climate for ``years`` years: no rise, every factor 1."""
        whole: object = years  # a float or a string from an untyped caller is refused
        if not (isinstance(whole, int) and years >= 1):
            raise ValueError(f"years must be a whole number >= 1, got {years!r}")
        return cls((0.0,) * years, (1.0,) * years, (1.0,) * years)

    @property
    def years(self) -> int:
        """Service years covered."""
        return len(self.sea_level)

    def check_site(self, caisson: Caisson) -> None:
        """Refuse a mean sea level that leaves the mound dry or puts the crest under still water.

        Goda's formulas need water above the armour, ``d + eta > 0``, and a
        crest above the still water, ``hc - eta > 0``; a year at today's level
        (``eta = 0``) is today's site and is not checked, so a stationary
        trend runs wherever no trend does.  The tide is not part of the check
        (today's climate does not check it either).

        Raises
        ------
        ValueError
            Naming the service year, its sea level and the range allowed.
        """
        low, high = -caisson.armour_depth, caisson.crest
        for year, eta in enumerate(self.sea_level, start=1):
            if eta != 0.0 and not low < eta < high:
                raise ValueError(
                    f"sea_level of service year {year} = {eta:g} m "
                    f"{'leaves the mound dry' if eta <= low else 'puts the crest under water'}: "
                    f"the sea level must be in ({low:g}, {high:g}) m "
                    f"(armour depth d = {caisson.armour_depth:g} m, crest hc = {caisson.crest:g} m)")


@dataclass(frozen=True)
class LifetimeModel:
    """The climate and the modelling choices of a lifetime simulation.

    Attributes
    ----------
    climate : Climate
        Storm peaks ``H0'``.
    years : int
        Design life (50).
    storm_hours : float
        Duration of a storm's peak sea state [h] (2).
    period : float or None
        A fixed ``T1/3`` [s] for every storm; None: Goda's ``3.3 H0'^0.63``.
    steepness : float or None
        A fixed ``H0'/L0`` for every storm (``T1/3 = sqrt(2 pi H0'/(g s))``);
        None: Goda's relation.  Not with ``period``.
    period_law : (float, float) or None
        ``(a, b)``: ``T1/3 = a H0'^b`` (fitted on a record's storm peaks,
        :func:`regimemap.climate.life.period_law`); None: Goda's ``(3.3, 0.63)``.
        Not with ``period`` or ``steepness``.
    tide_range : float
        Range of the tide [m]; each storm's level is ``(range/2) sin 2 pi phi``,
        ``phi`` uniform (0: no tide).
    impulsive : bool
        Takahashi's impulsive coefficient ``alpha* = max(alpha2, alpha_I)`` in
        each wave's pressure (False, the reference model: ``alpha* = alpha2``).
    truncate : float or None
        Cut every normal factor's ``z`` at ``±truncate`` (a truncated
        distribution, Kim & Takayama 2003); None: no cut.  A factor is
        ``ratio max(1 + cov z, 0)`` (never negative); the friction factor
        must stay above 0 within the cut (or within :data:`FRICTION_SIGMAS`
        standard deviations when uncut).
    errors : Errors
        The uncertainty factors.
    thresholds : tuple of float
        Lifetime slides [m] whose exceedance probability is reported.
    trend : YearTrend or None
        The climate's change over the service years (``years`` long); None:
        today's climate every year.
    """

    climate: Climate
    years: int = 50
    storm_hours: float = 2.0
    period: float | None = None
    steepness: float | None = None
    tide_range: float = 0.0
    period_law: tuple[float, float] | None = None
    impulsive: bool = False
    truncate: float | None = None
    errors: Errors = field(default_factory=Errors)
    thresholds: tuple[float, ...] = DEFAULT_THRESHOLDS
    trend: YearTrend | None = None

    def __post_init__(self) -> None:
        years: object = self.years  # a float or a string from an untyped caller is refused
        if not (isinstance(years, int) and years >= 1):
            raise ValueError(f"years must be a whole number >= 1, got {self.years!r}")
        if not self.storm_hours > 0.0:
            raise ValueError(f"storm_hours must be > 0, got {self.storm_hours!r}")
        if self.period is not None and self.steepness is not None:
            raise ValueError("give period or steepness, not both")
        if self.period is not None and not self.period > 0.0:
            raise ValueError(f"period must be > 0, got {self.period!r}")
        if self.period_law is not None and (self.period is not None or self.steepness is not None
                                            or not self.period_law[0] > 0.0
                                            or not math.isfinite(self.period_law[1])):
            raise ValueError(f"period_law (a, b) needs a > 0 and a finite b, without period or steepness, "
                             f"got {self.period_law!r}")
        if self.steepness is not None and not 0.0 < self.steepness <= 0.142:
            raise ValueError(f"steepness must be in (0, 0.142], got {self.steepness!r}")
        if not self.tide_range >= 0.0:
            raise ValueError(f"tide_range must be >= 0, got {self.tide_range!r}")
        if self.truncate is not None and not self.truncate > 0.0:
            raise ValueError(f"truncate must be > 0, got {self.truncate!r}")
        if any(not (x > 0.0 and math.isfinite(x)) for x in self.thresholds):
            raise ValueError("thresholds must be finite numbers > 0")
        if self.trend is not None and self.trend.years != self.years:
            raise ValueError(f"trend covers {self.trend.years} service years, the design life is "
                             f"{self.years} years: give one value per service year 1..{self.years}")
        reach = FRICTION_SIGMAS if self.truncate is None else self.truncate
        cov = self.errors.friction.cov
        if cov * reach >= 1.0:
            where = (f"within {FRICTION_SIGMAS:g} standard deviations" if self.truncate is None
                     else f"within the truncation at {self.truncate:g}")
            raise ValueError(
                f"the friction factor's cov = {cov:g} lets friction reach 0 {where} "
                f"(z = -{1.0 / cov:.3g}), and a caisson without friction slides without end; "
                f"accepted: cov * n < 1 with n = truncate, or n = {FRICTION_SIGMAS:g} untruncated "
                f"(cov < {1.0 / reach:.4g})")

    def storm_period(self, H0: float | NDArray[np.float64], g: float) -> float | NDArray[np.float64]:
        """``T1/3`` [s] of storms of peak ``H0'`` [m] (a number or an array): the fixed ``period``,
        ``sqrt(2 pi H0'/(g s))`` of the ``steepness``, or ``a H0'^b`` of the period law (Goda's)."""
        if self.period is not None:
            return self.period
        if self.steepness is not None:
            return np.sqrt(2.0 * np.pi * H0 / (g * self.steepness))
        a, b = self.period_law or (PERIOD_COEFFICIENT, PERIOD_EXPONENT)
        return a * H0**b

    def with_(self, **changes: object) -> LifetimeModel:
        """A copy with some options changed."""
        return replace(self, **changes)  # type: ignore[arg-type]
