"""Parameter sweeps shared by the engine tests: a dense grid of (gamma, kprime)
with every case threshold of the report, k' = 0 and k' = +-1."""

from __future__ import annotations

import math

import numpy as np


def thresholds(gamma: float) -> list[float]:
    g2 = gamma * gamma
    out = [0.0, 1.0, -1.0, (1 + g2) / (4 + g2), -(1 + g2) / (4 + g2), -0.5, 0.5]
    for t in ((1 + g2) / (3 * g2), (4 + g2) / (3 * g2)):
        if t <= 1.0:
            out.append(t)
    return out


GAMMAS = [0.3, 0.5, 0.8, 1.0, 1.2, math.sqrt(2), 1.6, 2.0, 2.5, 3.0, 4.0, 6.0]


def sweep(n_kprime: int = 21) -> list[tuple[float, float]]:
    pairs = []
    for g in GAMMAS:
        kps = set(np.round(np.linspace(-1, 1, n_kprime), 12)) | set(thresholds(g))
        for kp in sorted(kps):
            pairs.append((g, float(kp)))
    return pairs


def sample_points(gamma: float, kprime: float, n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Random points covering every characteristic point of the map (k up to
    about three times the largest characteristic abscissa, mu up to twice
    (4+g^2)/(3g))."""
    from regimemap import Parameters

    p = Parameters(gamma, kprime)
    marks = [p.k_A, p.k_Bprime, p.b_over_abs_a, p.k_D, p.k_pole, 1.0]
    k_hi = 3.0 * max(x for x in marks if math.isfinite(x))
    k_hi = min(k_hi, 60.0)
    mu_hi = 2.0 * max(p.mu_Bprime, 1.0)
    rng = np.random.default_rng(seed)
    return rng.uniform(0, k_hi, n), rng.uniform(0, mu_hi, n)


def tiered(cases: list, every: int = 4, deep: int = 2) -> list:
    """``cases`` as pytest parameters for a long sweep, in three nested samples: every ``every``-th
    case (a spread sample, the first and the last included) in the fast tier; every ``deep``-th
    case of the others marked ``slow`` (``make test`` runs them with the fast sample); the rest
    marked ``deep`` (``make test-deep``, which CI runs).  ``deep=1`` keeps the whole sweep in
    ``make test``.

    Examples
    --------
    >>> marks = [getattr(c, "marks", ()) for c in tiered([(i,) for i in range(9)], every=4, deep=2)]
    >>> ["fast" if not m else m[0].name for m in marks]
    ['fast', 'deep', 'slow', 'deep', 'fast', 'deep', 'slow', 'deep', 'fast']
    """
    import pytest

    last = len(cases) - 1
    out = []
    for i, case in enumerate(cases):
        if i % every == 0 or i == last:
            out.append(case)
        else:
            mark = pytest.mark.slow if i % deep == 0 else pytest.mark.deep
            out.append(pytest.param(*case, marks=mark))
    return out
