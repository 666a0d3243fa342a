"""How long a wave pushes on the wall: the duration of the half-sine force profile.

Shimosako & Takahashi (1999) give the horizontal force and the uplift of a
wave of height ``H`` on an upright caisson the time profile

    P(t) = P(H) sin(pi t / tau0),   U(t) = U(H) sin(pi t / tau0),   0 <= t <= tau0,

with ``tau0 = (0.5 - H/(8h)) T1/3``.  The formula lives here, beside the
loads it times, so that both users of the profile -- the expected sliding
distance over a lifetime (:mod:`regimemap.lifetime`) and the rigid-block run
under the design wave (:mod:`regimemap.dynamics.design_wave`) -- use the same
one (:doc:`/lifetime`, Sect. 5.2).

Reference
---------
Shimosako, K. & Takahashi, S. (1999). Application of deformation-based
reliability design for coastal structures. Proc. Coastal Structures '99.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ._types import FloatArray

__all__ = ["wave_duration"]


def wave_duration(H: npt.ArrayLike, depth: npt.ArrayLike, period: npt.ArrayLike) -> FloatArray:
    """Duration of a wave's push ``tau0 = (0.5 - H/(8h)) T1/3`` [s] (Shimosako & Takahashi 1999).

    Parameters
    ----------
    H : array_like
        Wave height [m].
    depth : array_like
        Water depth ``h`` at the wall [m].
    period : array_like
        Significant period ``T1/3`` [s].

    Returns
    -------
    ndarray
        ``tau0``, broadcast over the inputs (0-d for scalars).  It is positive
        only for ``H < 4h``; callers that need a pulse check it.

    Examples
    --------
    Goda's worked caisson (``Hmax = 8.05 m``, ``h = 10.1 m``, ``T1/3 = 11.4 s``):

    >>> round(float(wave_duration(8.05, 10.1, 11.4)), 4)
    4.5642
    """
    return np.asarray((0.5 - np.asarray(H, dtype=np.float64) / (8.0 * np.asarray(depth, dtype=np.float64)))
                      * np.asarray(period, dtype=np.float64), dtype=np.float64)
