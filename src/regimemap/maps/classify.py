"""One mode per point: :func:`classify` (scattered points) and :func:`label_grid`.

The final map (Figs 3.9a-3.11 above C, 4.7a-b below C) in one rule valid for
every k' in [-1, 1] (k' signed, ``upper = 1/gamma - k k'`` is CD above C and AB
below C, ``lower = -1/gamma - k k'`` is DC, ``mu*`` is (3.24)/(4.40))::

    RE     if mu >= k and k <= k_A                       (3.4)-(3.5), (4.7), (4.10)
    SL     elif lower <= mu <= upper                     Section III.2, (4.18)-(4.19)
    SRO'-  elif mu < lower                               (4.92); Section 4.7
    RO     elif mu >= mu*(k)                             (3.17), (3.24), (4.37), (4.40)
    SRO-   elif ak + b >= 0                              (3.42), (4.67)-(4.79)
    SRO+   else                                          (3.44)-(3.45)

It equals the report's regions resolved by :data:`PRIORITY`, which is Section
4.7's rule: inside the slide region neither corner can pivot (SL wins over RO
and SRO-); below DC the body pivots about O', not O (SRO'- wins over RO and
SRO-); slide-rock about O for mu >= mu_B' "simply can not happen" (it loses to
RE, SL and RO, which the solver finds admissible at each of its points).

Loads.  With buoyancy, uplift or another inertia (keyword-only
arguments, as in :class:`~regimemap.mechanics.block.Parameters`) the same rule
holds in every *regular* column (W > 0, f_y of rocking about O > 0, rest not
failing about O'; every column of the report's block) with the generalised
thresholds of :func:`regimemap.mechanics.constants.thresholds`: OA is mu = k/W,
the lines are 1/gamma - s/W and -1/gamma - s/W, mu* has the constants a_O...d_O.
At zero loads these are the report's thresholds bit for bit.  Other columns
(lift-off, W <= 0, rest failing about O' ...) are cut at the ends of every
hypothesis's interval of mu (:func:`regimemap.mechanics.regions.column_intervals`)
and each piece takes the first admissible mode in
:data:`~regimemap.mechanics.modes.SELECTION_ORDER`, which is Gauss's least
constraint (measured); lift-off is a whole column.  ``docs/derivation.md``
Section 5 derives the rule.

Boundaries.  A point exactly on a boundary gets the label of the first rule
above that it satisfies: rest on OA and on AB/AE (limiting equilibrium does
not move), slide on CD/AB and on DC (the reaction just reaches a corner), rock
on mu*(k) (friction just sufficient).  The tests check that the solver admits
this label at boundary points too.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..mechanics.constants import thresholds
from ..mechanics.loads import BlockConstants, block_constants, subset
from ..mechanics.modes import PRIORITY, Mode
from ..mechanics.regions import column_intervals
from ..mechanics.validation import (
    MAX_GRID_POINTS,
    check_axis,
    check_gamma,
    check_kprime,
    check_loads,
    check_nonnegative_array,
)

__all__ = ["classify", "classify_constants", "label_grid", "PRIORITY", "column_segments",
           "block_of"]

_RE, _SL, _RO, _SM, _SP, _SPM = (np.uint8(m) for m in (
    Mode.RE, Mode.SL, Mode.RO, Mode.SRO_MINUS, Mode.SRO_PLUS, Mode.SRO_PRIME_MINUS))

def _check_param_arrays(gamma: ArrayLike, kprime: ArrayLike, crest: float = 1.0) -> tuple[Any, Any]:
    """gamma and kprime as floats (scalars) or float arrays, each value checked."""
    out: list[Any] = []
    checks = (("gamma", gamma, check_gamma), ("kprime", kprime, lambda v: check_kprime(v, crest)))
    for name, value, check in checks:
        if np.ndim(value) == 0:
            out.append(check(value.item() if isinstance(value, np.ndarray) else value))
            continue
        try:
            arr = np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be an array of numbers, got {value!r}") from None
        # the allowed sets are intervals: checking NaN, the minimum and the
        # maximum with the scalar check gives the same messages and ranges
        if arr.size:
            if np.isnan(arr).any():
                check(float("nan"))
            check(float(arr.min()))
            check(float(arr.max()))
        out.append(arr + 0.0 if name == "kprime" else arr)  # fold -0.0
    return out[0], out[1]


def block_of(gamma: ArrayLike, kprime: ArrayLike, buoyancy: Any = 0.0, uplift: Any = 0.0,
             uplift_ratio: Any = 0.0, uplift_arm: Any = 1.0 / 3.0, gyration: Any = None,
             crest: Any = 1.0) -> BlockConstants:
    """The checked constants of a block (gamma, kprime may be arrays; the loads are numbers)."""
    beta, u, nu, eu, gy, cr = check_loads(buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest)
    g, kp = _check_param_arrays(gamma, kprime, cr)
    return block_constants(g, kp, beta, u, nu, eu, gy)


def _broadcast(*arrays: Any) -> list[np.ndarray]:
    try:
        return list(np.broadcast_arrays(*arrays))
    except ValueError:
        shapes = ", ".join(f"{n} {np.shape(a)}" for n, a in zip(("k", "mu", "gamma", "kprime"), arrays))
        raise ValueError(f"k, mu, gamma and kprime must broadcast to one shape, got {shapes}") from None


def classify(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *,
             buoyancy: float = 0.0, uplift: float = 0.0, uplift_ratio: float = 0.0,
             uplift_arm: float = 1.0 / 3.0, gyration: float | None = None, crest: float = 1.0
             ) -> np.ndarray:
    """Mode code at each point (k, mu) for aspect ratio gamma and force height kprime.

    Parameters
    ----------
    k : array_like
        Force F/(mg) >= 0.
    mu : array_like
        Coefficient of friction >= 0.
    gamma : array_like
        Aspect ratio H/B > 0.
    kprime : array_like
        Force height h/H in [-1, crest] (negative below the centre of mass).
        All four broadcast together like the arguments of a numpy ufunc.
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest : float, keyword-only
        The loads of the block (see :class:`~regimemap.mechanics.block.Parameters`);
        the defaults are the report's block.

    Returns
    -------
    numpy.ndarray of uint8
        :class:`~regimemap.mechanics.modes.Mode` codes, of the broadcast shape (0-d for
        scalars).  ``Mode(out[i])`` gives the mode.

    Raises
    ------
    ValueError
        If any k or mu is negative, NaN or infinite, gamma is not > 0, kprime
        is outside [-1, crest] or a load is outside its range (the message names
        the parameter and the range).

    Notes
    -----
    The rule and its boundary convention are in the module docstring; the
    equations are (3.4)-(3.5), (3.24), (3.42), (3.44)-(3.45) above C and
    (4.7)-(4.21), (4.40), (4.92) with Section 4.7 below C.

    Examples
    --------
    >>> from regimemap import Mode, classify
    >>> Mode(classify(0.1, 0.5, 3.0, 0.4)).label
    'RE'
    >>> [Mode(c).label for c in classify([0.3, 0.5], [0.2, 0.8], 3.0, 0.4)]
    ['SL', 'RO']
    >>> Mode(classify(1.0, 0.5, 3.0, 0.0, buoyancy=0.5, uplift=0.3, uplift_ratio=0.5, uplift_arm=0.0)).label
    'LO'
    """
    k = check_nonnegative_array("k", k)
    mu = check_nonnegative_array("mu", mu)
    beta, u, nu, eu, gy, cr = check_loads(buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest)
    g, kp = _check_param_arrays(gamma, kprime, cr)
    if np.ndim(g) or np.ndim(kp):
        k, mu, g, kp = _broadcast(k, mu, g, kp)
    else:
        k, mu = _broadcast(k, mu)
    return classify_constants(k, mu, block_constants(g, kp, beta, u, nu, eu, gy))


def classify_constants(k: np.ndarray, mu: np.ndarray, cst: BlockConstants) -> np.ndarray:
    """The rule of :func:`classify` on checked arrays of one shape and a block's constants."""
    t = thresholds(k, cst)
    out = np.where(t.f_pos, _SM, _SP)
    np.copyto(out, _RO, where=mu >= t.mu_star)
    np.copyto(out, _SL, where=mu <= t.upper)
    np.copyto(out, _SPM, where=mu < t.lower)
    np.copyto(out, _RE, where=(mu >= t.mu_rest) & t.rest_ok)
    odd = ~t.regular
    if odd.any():
        kk, mm = k[odd], mu[odd]
        gen = np.full(kk.shape, 255, dtype=np.uint8)
        for mode, lo, hi in reversed(column_intervals(kk, subset(cst, k.shape, odd))):
            np.copyto(gen, np.uint8(mode), where=(mm >= lo) & (mm <= hi))
        out[odd] = gen
    return np.asarray(out)


def column_segments(k: np.ndarray, mu_sorted: np.ndarray, gamma: float, kprime: float,
                    **loads: Any) -> tuple[np.ndarray, np.ndarray]:
    """Labels and run lengths along each column of a grid whose mu axis is sorted.

    Along a regular column (fixed k) the rule of :func:`classify` gives, from
    mu = 0 up, at most five runs: SRO'-, SL, SRO-/SRO+, RO, RE.  The run ends are
    counted with ``searchsorted`` against the very thresholds ``classify``
    compares with, so the two agree exactly.  Other columns (loads only) are
    cut at the ends of every interval of
    :func:`~regimemap.mechanics.regions.column_intervals` and each piece takes
    the first interval holding it.  ``loads`` are the keywords of :func:`classify`.

    Returns
    -------
    labels, counts : ndarray, shape (len(k), m), m >= 5
        Mode codes and run lengths (sum of each row = len(mu_sorted)).
    """
    return _segments(np.asarray(k, dtype=np.float64), np.asarray(mu_sorted, dtype=np.float64),
                     block_of(gamma, kprime, **loads))


def _segments(k: np.ndarray, mu_sorted: np.ndarray, cst: BlockConstants
              ) -> tuple[np.ndarray, np.ndarray]:
    n = mu_sorted.size
    t = thresholds(k, cst)
    n_k = np.where(t.rest_ok, np.searchsorted(mu_sorted, t.mu_rest, side="left"), n)
    c1 = np.minimum(np.searchsorted(mu_sorted, t.lower, side="left"), n_k)
    c2 = np.minimum(np.searchsorted(mu_sorted, t.upper, side="right"), n_k)
    c3 = np.minimum(np.maximum(np.searchsorted(mu_sorted, t.mu_star, side="left"), c2), n_k)
    counts5 = np.stack([c1, c2 - c1, c3 - c2, n_k - c3, n - n_k], axis=1)
    labels5 = np.empty((k.size, 5), dtype=np.uint8)
    labels5[:, 0] = _SPM
    labels5[:, 1] = _SL
    labels5[:, 2] = np.where(t.f_pos, _SM, _SP)
    labels5[:, 3] = _RO
    labels5[:, 4] = _RE
    odd = np.flatnonzero(~t.regular)
    if odd.size == 0:
        return labels5, counts5
    ivs = column_intervals(k[odd], subset(cst, k.shape, odd))
    starts = np.stack([np.searchsorted(mu_sorted, lo, side="left") for _, lo, _ in ivs], axis=1)
    ends = np.stack([np.searchsorted(mu_sorted, hi, side="right") for _, _, hi in ivs], axis=1)
    ends = np.maximum(ends, starts)
    codes = np.array([int(m) for m, _, _ in ivs], dtype=np.uint8)
    cuts = np.sort(np.concatenate([starts, ends, np.zeros((odd.size, 1), np.intp),
                                   np.full((odd.size, 1), n, np.intp)], axis=1), axis=1)
    left = cuts[:, :-1]
    cnt = np.diff(cuts, axis=1)
    # piece [left, left + cnt) lies in interval j iff starts_j <= left < ends_j (cuts hold every end)
    inside = (starts[:, None, :] <= left[:, :, None]) & (left[:, :, None] < ends[:, None, :])
    first = np.argmax(inside, axis=2)
    lab = np.where(inside.any(axis=2), codes[first], np.uint8(255)).astype(np.uint8)
    m = max(5, cnt.shape[1])
    labels = np.zeros((k.size, m), dtype=np.uint8)
    counts = np.zeros((k.size, m), dtype=np.intp)
    labels[:, :5] = labels5
    counts[:, :5] = counts5
    labels[odd] = 0
    counts[odd] = 0
    labels[odd, : cnt.shape[1]] = lab
    counts[odd, : cnt.shape[1]] = cnt
    return labels, counts


def label_grid(k_axis: ArrayLike, mu_axis: ArrayLike, gamma: float, kprime: float, *,
               buoyancy: float = 0.0, uplift: float = 0.0, uplift_ratio: float = 0.0,
               uplift_arm: float = 1.0 / 3.0, gyration: float | None = None, crest: float = 1.0
               ) -> np.ndarray:
    """Mode codes on the rectilinear grid ``k_axis x mu_axis``.

    Parameters
    ----------
    k_axis, mu_axis : array_like, 1-D
        Values of k and of mu (finite, >= 0; any order).
    gamma : float
        Aspect ratio H/B > 0.
    kprime : float
        Force height h/H in [-1, crest].
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest : float, keyword-only
        The loads, as in :func:`classify`.

    Returns
    -------
    numpy.ndarray of uint8, shape (len(mu_axis), len(k_axis))
        ``out[i, j] == classify(k_axis[j], mu_axis[i], gamma, kprime, **loads)``
        exactly (rows mu, columns k, as an image with origin lower left when
        mu_axis increases), C-contiguous.

    Raises
    ------
    ValueError
        For invalid parameters, axes that are not 1-D finite numbers >= 0, or
        a grid of more than :data:`~regimemap.mechanics.validation.MAX_GRID_POINTS` points.

    Notes
    -----
    Each column is cut into runs by ``searchsorted`` against the thresholds of
    :func:`classify` and filled with ``numpy.repeat``: the cost is that of
    writing the labels, not of evaluating every hypothesis.
    """
    beta, u, nu, eu, gy, cr = check_loads(buoyancy, uplift, uplift_ratio, uplift_arm, gyration, crest)
    g = check_gamma(gamma)
    kp = check_kprime(kprime, cr)
    k_axis = check_axis("k_axis", k_axis)
    mu_axis = check_axis("mu_axis", mu_axis)
    if k_axis.size * mu_axis.size > MAX_GRID_POINTS:
        raise ValueError(
            f"grid of {mu_axis.size} x {k_axis.size} points exceeds the limit of "
            f"{MAX_GRID_POINTS} points"
        )
    if mu_axis.size == 0 or k_axis.size == 0:
        return np.empty((mu_axis.size, k_axis.size), dtype=np.uint8)
    diffs = np.diff(mu_axis)
    order: str | np.ndarray | None
    if np.all(diffs >= 0):
        order = None
        mu_sorted = mu_axis
    elif np.all(diffs <= 0):
        order = "reversed"
        mu_sorted = mu_axis[::-1]
    else:
        order = np.argsort(mu_axis, kind="stable")
        mu_sorted = mu_axis[order]
    labels, counts = _segments(k_axis, mu_sorted, block_constants(g, kp, beta, u, nu, eu, gy))
    cols = np.repeat(labels.ravel(), counts.ravel()).reshape(k_axis.size, mu_sorted.size)
    grid = np.ascontiguousarray(cols.T)
    if order is None:
        return grid
    if isinstance(order, str):
        return np.ascontiguousarray(grid[::-1])
    out = np.empty_like(grid)
    out[order] = grid
    return out
