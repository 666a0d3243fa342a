"""Wave records to extreme sea states: readers' records, storms, annual maxima, extreme-value fits
with their intervals (numpy and scipy; layer 2, beside :mod:`regimemap.lifetime`).  Names are
imported on first use (:func:`regimemap._lazy.attach`): reading a record does not import scipy.

* :class:`Record`, :func:`make_record` -- a record and its quality control (the files are read by
  :func:`regimemap.climate.file.read_record`);
* :func:`storms`, :func:`annual_maxima` -- peaks over a threshold (runs declustering) and the
  maxima of well-observed years;
* :func:`fit` -- GPD, Weibull, Gumbel and GEV by maximum likelihood; :mod:`regimemap.climate.intervals`
  -- their return values' intervals: the grid posterior (the default), the profile likelihood and
  the non-parametric :func:`bootstrap`; :mod:`regimemap.climate.guards` -- the
  warnings of a fit that breaks;
* :func:`analyse` -- all of it, with :class:`ClimateOptions`, to a :class:`ClimateResult`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .analysis import METHODS, ClimateOptions, ClimateResult, analyse
    from .fits import AM_DISTRIBUTIONS, POT_DISTRIBUTIONS, Fit, fit
    from .intervals import Band, bootstrap
    from .peaks import AnnualMaxima, Storms, annual_maxima, parse_threshold, storms
    from .wave_record import Quality, Record, make_record

__all__ = [
    "AM_DISTRIBUTIONS", "METHODS", "POT_DISTRIBUTIONS", "AnnualMaxima", "Band", "ClimateOptions",
    "ClimateResult", "Fit", "Quality", "Record", "Storms", "analyse", "annual_maxima", "bootstrap", "fit",
    "make_record", "parse_threshold", "storms",
]

if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
