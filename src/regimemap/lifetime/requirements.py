"""The requirements of a lifetime design and their verdicts.

numpy only.  The design file's ``[lifetime]`` table states what the caisson
must achieve over its life: a tolerable expected sliding distance (``target``,
0.1 m after Goda & Takagi 2000), the largest allowed probabilities of
exceeding given slides (``allowed``, after Kim & Suh 2013) and the sliding at
which the caisson is off its mound (``failure_sliding``).  From a
:class:`~regimemap.lifetime.LifetimeResult` they give a list of
:class:`~regimemap.mechanics.checks.Check` -- read by the text, the JSON, the
figures and the exit status of ``--check`` -- and the probability of failure
with its standard error.  The verdict compares the Monte Carlo estimate with
the limit; the estimate's standard error is reported beside it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

from ..mechanics.checks import Check
from .chart import DesignChart
from .results import Failure, LifetimeResult

__all__ = ["DEFAULT_TARGET", "Requirements", "chart_checks", "judge_chart", "judge_lifetime",
           "lifetime_checks"]

#: The tolerable expected sliding distance of Goda & Takagi (2000) [m].
DEFAULT_TARGET = 0.1


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


def lifetime_checks(result: LifetimeResult, req: Requirements) -> tuple[Check, ...]:
    """The requirements of ``req`` against ``result``: ESD <= target, then each ``P(S > x) <= p``."""
    checks = [Check.at_most("expected sliding distance", result.expected_sliding, req.target, "m")]
    checks += [Check.at_most(exceedance_name(x), result.exceedance(x), p)
               for x, p in sorted(req.allowed.items())]
    return tuple(checks)


def judge_lifetime(result: LifetimeResult, req: Requirements) -> LifetimeResult:
    """``result`` with its checks and, given a sliding limit, its probability of failure."""
    failure = None if req.failure_sliding is None else Failure.of(result.sliding, req.failure_sliding)
    return replace(result, checks=lifetime_checks(result, req), failure=failure)


def chart_checks(chart: DesignChart, design_width: float) -> tuple[Check, ...]:
    """The design's width against the chart's width for the target: ``design_width >= width_for_target``.

    None when the chart found no width (it has no check then).
    """
    if chart.width_for_target is None:
        return ()
    return (Check.at_least(f"width for ESD <= {chart.target:g} m", design_width, chart.width_for_target,
                           "m"),)


def judge_chart(chart: DesignChart, design_width: float) -> DesignChart:
    """``chart`` with the check of the design's width (:func:`chart_checks`)."""
    return replace(chart, checks=chart_checks(chart, design_width), design_width=float(design_width))
