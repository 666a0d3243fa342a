"""Sliding of a caisson over its design life: the expected sliding distance (ESD).

numpy only; it consumes :mod:`regimemap.waves` (Goda's heights, pressures and
loads).  A vectorised Monte Carlo of lifetimes after Shimosako & Takahashi
(1999), Goda & Takagi (2000) and Kim & Takayama (2003): storms from the
site's climate, waves from each storm, the slide of each wave in closed form,
added up over the design life.  See docs/lifetime.md for every formula and
the source of every default.

* :class:`Climate` -- storm peaks ``H0'`` (Weibull or Gumbel; two return
  values, or a maximum-likelihood fit of annual maxima);
* :class:`Caisson`, :class:`LifetimeModel`, :class:`Errors`,
  :class:`ErrorFactor`, :class:`YearTrend` -- the inputs (a trend: the climate's
  change year by year over the life);
* :func:`lifetime_sliding` -> :class:`LifetimeResult` -- the ESD with its
  standard error, quantiles and exceedance probabilities;
* :func:`design_chart` -> :class:`DesignChart` -- ESD against width, the
  width for a target ESD (to a tolerance, with its bootstrap interval), the
  width of a required safety factor;
* :class:`Requirements`, :func:`judge_lifetime`, :func:`judge_chart` -- the
  requirements (target ESD, allowed exceedance probabilities, the sliding
  limit off the mound) as :class:`~regimemap.records.checks.Check` lists and
  the probability of failure (:class:`Failure`);
* :func:`half_sine_slide`, :func:`added_mass` -- the sliding of one wave.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from ..workers import available_cores
    from .chart import DesignChart, design_chart, sf_width
    from .climate import DISTRIBUTIONS, Climate
    from .model import (
        DEFAULT_ERRORS,
        DEFAULT_THRESHOLDS,
        Caisson,
        ErrorFactor,
        Errors,
        LifetimeModel,
        YearTrend,
    )
    from .parallel import ClusterUnavailable
    from .requirements import Requirements, judge_chart, judge_lifetime
    from .results import Failure, LifetimeResult
    from .simulate import lifetime_sliding
    from .sliding import ADDED_MASS_COEFFICIENT, added_mass, half_sine_slide, wave_duration

__all__ = [
    "ADDED_MASS_COEFFICIENT", "DEFAULT_ERRORS", "DEFAULT_THRESHOLDS", "DISTRIBUTIONS", "Caisson",
    "Climate", "ClusterUnavailable", "DesignChart", "ErrorFactor", "Errors", "Failure", "LifetimeModel",
    "LifetimeResult", "Requirements", "YearTrend", "added_mass", "available_cores", "design_chart",
    "half_sine_slide", "judge_chart", "judge_lifetime", "lifetime_sliding", "sf_width", "wave_duration",
]


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
