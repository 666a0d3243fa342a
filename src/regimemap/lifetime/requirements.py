"""The requirements of a lifetime design and their verdicts.

numpy only.  The design file's ``[lifetime]`` table states what the caisson
must achieve over its life: a tolerable expected sliding distance (``target``,
0.1 m after Goda & Takagi 2000), the largest allowed probabilities of
exceeding given slides (``allowed``, after Kim & Suh 2013) and the sliding at
which the caisson is off its mound (``failure_sliding``).  From a
:class:`~regimemap.lifetime.LifetimeResult` they give a list of
:class:`~regimemap.records.checks.Check` -- read by the text, the JSON, the
figures and the exit status of ``--check`` -- and the probability of failure
with its standard error.  The verdict compares the Monte Carlo estimate with
the limit; the estimate's standard error is reported beside it.

With a wave record's climate the requirements are judged on the results *with the climate's
uncertainty* -- a :class:`~regimemap.lifetime.replicates.ClimateBand`: the ESD and each
``P(S > x)`` are the means over the replicate climates (the expectation over the fit's
uncertainty as well as over the lifetimes), and each check's name says so.  The design
chart's width is judged at the band's upper level
(:attr:`~regimemap.lifetime.replicates.ChartBand.width_for_target`): the narrowest width
whose ESD at the upper end of the band meets the target.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ..records.checks import Check
from .chart import DesignChart
from .results import Failure, LifetimeResult

if TYPE_CHECKING:
    from .replicates import ChartBand, ClimateBand

__all__ = ["DEFAULT_TARGET", "WITH_CLIMATE", "Requirements", "band_thresholds", "chart_checks",
           "judge_chart", "judge_lifetime", "lifetime_checks"]

#: The tolerable expected sliding distance of Goda & Takagi (2000) [m].
DEFAULT_TARGET = 0.1
#: How a check judged with the climate's uncertainty says so.
WITH_CLIMATE = "including the climate's uncertainty"


@dataclass(frozen=True)
class Requirements:
    """What the caisson must achieve over its design life.

    Attributes
    ----------
    target : float
        The largest tolerable expected sliding distance [m].
    allowed : mapping of float to float
        Lifetime sliding ``x`` [m] -> the largest allowed ``P(S > x)``.
    failure_sliding : float or None
        The sliding at which the caisson is off its mound [m]; None: not given.
    """

    target: float = DEFAULT_TARGET
    allowed: Mapping[float, float] = field(default_factory=dict)
    failure_sliding: float | None = None


def exceedance_name(x: float) -> str:
    """The name of an exceedance requirement: ``P(S > 0.1 m)``."""
    return f"P(S > {x:g} m)"


def band_thresholds(req: Requirements) -> tuple[float, ...]:
    """The slides [m] whose ``P(S > x)`` a climate band must keep to judge ``req``: the allowed
    exceedances' and the failure's sliding."""
    xs = set(float(x) for x in req.allowed)
    if req.failure_sliding is not None:
        xs.add(float(req.failure_sliding))
    return tuple(sorted(xs))


def lifetime_checks(result: LifetimeResult, req: Requirements,
                    band: ClimateBand | None = None) -> tuple[Check, ...]:
    """The requirements of ``req``: ESD <= target, then each ``P(S > x) <= p``.

    Judged on ``result`` (``expected sliding distance``, ``P(S > x m)``), or, given the climate
    band of a record, on the results with the climate's uncertainty (``ESD including the climate's
    uncertainty``, ``P(S > x m) including ...``: the means over the replicate climates).
    """
    judged: LifetimeResult | ClimateBand = result if band is None else band
    esd_name = "expected sliding distance" if band is None else f"ESD {WITH_CLIMATE}"
    suffix = "" if band is None else f" {WITH_CLIMATE}"
    checks = [Check.at_most(esd_name, judged.expected_sliding, req.target, "m")]
    checks += [Check.at_most(exceedance_name(x) + suffix, judged.exceedance(x), p)
               for x, p in sorted(req.allowed.items())]
    return tuple(checks)


def judge_lifetime(result: LifetimeResult, req: Requirements,
                   band: ClimateBand | None = None) -> LifetimeResult:
    """``result`` with its checks (:func:`lifetime_checks`) and, given a sliding limit, its
    probability of failure -- of ``result``'s lifetimes, or with ``band`` the climate's
    uncertainty included (the replicates' mean)."""
    failure = None
    if req.failure_sliding is not None:
        failure = (Failure.of(result.sliding, req.failure_sliding) if band is None
                   else band.failure(req.failure_sliding))
    return replace(result, checks=lifetime_checks(result, req, band), failure=failure)


def chart_checks(chart: DesignChart, design_width: float, band: ChartBand | None = None) -> tuple[Check, ...]:
    """The design's width against the chart's width for the target: ``design_width >= width_for_target``.

    With the chart's climate band the width is the band's at its upper level
    (:attr:`ChartBand.width_for_target`).  None when the chart (or band) found no width (it has no
    check then).
    """
    if band is None:
        width, name = chart.width_for_target, f"width for ESD <= {chart.target:g} m"
    else:
        top = f"{100 * (0.5 + 0.5 * band.level):g} %"
        width, name = band.width_for_target, (f"width for ESD <= {band.target:g} m at the upper end of the "
                                              f"climate band ({top} quantile of {band.replicates} climates)")
    return () if width is None else (Check.at_least(name, design_width, width, "m"),)


def judge_chart(chart: DesignChart, design_width: float, band: ChartBand | None = None) -> DesignChart:
    """``chart`` with the check of the design's width (:func:`chart_checks`)."""
    return replace(chart, checks=chart_checks(chart, design_width, band), design_width=float(design_width))
