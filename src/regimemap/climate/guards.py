"""When a fit breaks: the shape parameter, the upper end point, the search bounds, a physical limit.

numpy only.  Each guard is a :class:`~regimemap.records.notices.Notice` (code ``fit``) with the
quantity and its value; ``regimemap climate --strict`` makes them errors.

* GPD shape :math:`\\xi < -1/2` (:data:`XI_NONREGULAR`): the maximum-likelihood estimator is no
  longer regular -- its variance is not the inverse information and it converges faster than
  :math:`n^{-1/2}` towards a boundary (Smith 1985, Biometrika 72, 67-90) -- and below
  :data:`XI_NEAR_BOUND` the fit approaches :math:`\\xi = -1`, where the likelihood grows without
  bound as the end point reaches the largest storm;
* the fitted upper end point :math:`u - \\sigma/\\xi` (:math:`\\xi < 0`) close to the record's
  largest storm on a short record (:func:`endpoint_close`);
* a fit at a search bound: the GEV shape at either end of :data:`~regimemap.climate.fits.GEV_XI`,
  the GPD search at its lowest :math:`\\theta = \\xi/\\sigma = -1/\\max y` (the end point is the
  largest storm);
* a return value or interval bound above a physical limit (by default the
  :data:`~regimemap.climate.wave_record.HS_MAX` the record reader refuses in a record; a design file
  may give the depth-limited breaker height).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..records.notices import Notice
from ..records.numbers import shortest
from .fits import GEV_XI, Fit

__all__ = ["XI_NEAR_BOUND", "XI_NONREGULAR", "endpoint", "endpoint_close", "fit_notices", "limit_notices"]

#: Below this GPD shape the maximum-likelihood estimator is non-regular (Smith 1985).
XI_NONREGULAR = -0.5
#: Below this GPD shape the fit nears xi = -1, where the likelihood is unbounded.
XI_NEAR_BOUND = -0.8


def endpoint(fit: Fit) -> float | None:
    """The fitted upper end point [m]: ``u - sigma/xi`` (GPD), ``mu - sigma/xi`` (GEV), for
    ``xi < 0``; None for an unbounded tail."""
    p = fit.parameters
    if fit.distribution == "gpd" and p["xi"] < 0.0:
        assert fit.threshold is not None
        return float(fit.threshold - p["sigma"] / p["xi"])
    if fit.distribution == "gev" and p["xi"] < 0.0:
        return float(p["mu"] - p["sigma"] / p["xi"])
    return None


def endpoint_close(top: float, base: float, end: float, years: float, longest: float) -> bool:
    """Whether the end point ``end`` sits close to the largest value ``top`` on a short record.

    *Close*: the gap ``end - top`` is smaller than the range of the values above ``base`` (the
    threshold, or the smallest annual maximum), ``top - base``.  The gap is estimated from the
    spacing of the few largest storms, so one storm larger than any seen would move it by as much.
    *Short*: the record's ``years`` are fewer than the ``longest`` return period asked for -- it has
    not sampled the years the value is for, and cannot tell a bounded tail from an unseen storm.
    """
    return years < longest and end - top < top - base


def fit_notices(fit: Fit, values: ArrayLike, years: float, longest: float) -> list[Notice]:
    """The shape, end-point and search-bound notices of a fit of ``values`` from ``years`` of record
    (``longest``: the longest return period asked for)."""
    x = np.asarray(values, dtype=np.float64)
    top = float(x.max())
    out: list[Notice] = []
    p = fit.parameters
    base = float(fit.threshold) if fit.threshold is not None else float(x.min())
    end = endpoint(fit)
    if fit.distribution == "gpd":
        xi = p["xi"]
        at_bound = end is not None and end - top <= 1e-6 * max(top - base, 1e-12)
        if at_bound:
            out.append(Notice("fit", f"the GPD fit stopped at its search bound: the fitted upper end "
                                     f"point {end:.2f} m is the largest storm (xi = {xi:.3g}), where the "
                                     "likelihood grows without bound (Smith 1985); its return values are "
                                     "the record's maximum, not an extrapolation (raise the number of "
                                     "storms: a lower threshold or a longer record)", "xi", xi))
        elif xi < XI_NEAR_BOUND:
            out.append(Notice("fit", f"GPD shape xi = {xi:.3g} approaches -1, where the likelihood is "
                                     "unbounded: the fit is pinned to the largest storms and its return "
                                     "values cannot exceed them by much (lower the threshold)", "xi", xi))
        elif xi < XI_NONREGULAR:
            out.append(Notice("fit", f"GPD shape xi = {xi:.3g} < -0.5: the maximum-likelihood fit is "
                                     "non-regular there (Smith 1985) and its standard errors do not hold",
                              "xi", xi))
    if fit.distribution == "gev":
        xi = p["xi"]
        for bound in GEV_XI:
            if abs(xi - bound) <= 1e-6:
                why = ("too few or too even annual maxima for three parameters" if bound < 0 else
                       "a tail heavier than the search allows")
                out.append(Notice("fit", f"the GEV shape reached its search bound xi = {bound:g} ({why}): "
                                         "prefer gumbel or peaks over a threshold", "xi", xi))
    if end is not None and endpoint_close(top, base, end, years, longest) and not any(
            n.quantity == "xi" and "search bound" in n.message for n in out):
        out.append(Notice("fit", f"the fitted upper end point {end:.2f} m is only {end - top:.2f} m above "
                                 f"the largest value {top:.2f} m of a {years:.3g}-year record: a bounded "
                                 "tail is what so few storms cannot rule out, not what they show; the "
                                 f"{longest:g}-year value rests on the shape (read its interval)",
                          "endpoint", end))
    return out


def limit_notices(return_values: Sequence[dict[str, float | None]], limit: float,
                  what: str) -> list[Notice]:
    """A notice for each return value or interval bound above ``limit`` [m] (``what`` names it)."""
    out: list[Notice] = []
    for rv in return_values:
        for key in ("value", "upper"):
            v = rv.get(key)
            if v is not None and math.isfinite(v) and v > limit:
                name = "return value" if key == "value" else "interval's upper bound"
                period = rv["period"]
                assert period is not None
                years = shortest(period)
                out.append(Notice("fit", f"the {years}-year {name} {v:.3g} m is above {what} "
                                         f"({limit:g} m): the fit cannot be trusted that far",
                                  f"H{rv['period']:g}", v))
    return out
