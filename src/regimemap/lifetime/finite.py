"""No wrong number written as an answer: a result that is not finite is an error, with its reason.

A lifetime simulation pushed outside the reach of its formulas (a crest under the
water, a depth of a kilometre) may slide a caisson an infinite distance; its mean is
then ``inf``, its standard error ``nan``, and the probabilities counted from it look
like numbers.  :func:`require_finite` refuses such a result before it is printed or
stored -- the lifetimes of ``regimemap lifetime`` and its chart
(:mod:`regimemap.lifetime.run`) and every task of a study
(:mod:`regimemap.study.run_tasks`) -- naming what is not finite and in how many
of its values.  The arithmetic that made them runs under :func:`quiet_arithmetic`, so
numpy's ``RuntimeWarning`` never reaches the terminal: the check that follows says
what went wrong, once, in words.  numpy only.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["NonFiniteResult", "quiet_arithmetic", "require_finite"]


class NonFiniteResult(ValueError):
    """A result holds ``inf`` or ``nan``: the run is refused, nothing of it is printed or stored."""


@contextmanager
def quiet_arithmetic() -> Iterator[None]:
    """numpy's overflow, invalid and divide-by-zero warnings silenced, for a computation whose
    results :func:`require_finite` checks afterwards (underflow stays numpy's default, ignored)."""
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        yield


def require_finite(what: str, values: ArrayLike, context: str = "") -> None:
    """Raise :class:`NonFiniteResult` when ``values`` hold ``inf`` or ``nan``; return otherwise.

    Parameters
    ----------
    what : str
        The quantity, in words (``"the lifetime sliding"``).
    values : array_like
        Its values (any shape; empty passes).
    context : str, optional
        Where it comes from (``"section 'head', scenario 'rise 1 m'"``), put first in the message.

    Raises
    ------
    NonFiniteResult
        ``"<context>: <what> is not finite (inf in 15 of 40 values, nan in 0): the model is outside
        the range of its formulas; nothing is written"``.

    Examples
    --------
    >>> require_finite("the ESD", [0.1, 0.2])
    >>> require_finite("the ESD", [0.1, float("inf")])
    Traceback (most recent call last):
    ...
    regimemap.lifetime.finite.NonFiniteResult: the ESD is not finite (inf in 1 of 2 values, nan in 0): \
the model is outside the range of its formulas; nothing is written
    """
    a = np.asarray(values, dtype=np.float64)
    bad = ~np.isfinite(a)
    if not bad.any():
        return
    n_inf = int(np.isinf(a).sum())
    n_nan = int(np.isnan(a).sum())
    head = f"{context}: " if context else ""
    raise NonFiniteResult(f"{head}{what} is not finite (inf in {n_inf} of {a.size} values, nan in {n_nan}): "
                          "the model is outside the range of its formulas; nothing is written")
