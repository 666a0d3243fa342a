"""Array type aliases shared by :mod:`regimemap.waves`."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
"""A float64 array; scalars come back as 0-d arrays."""

G: float = 9.81
"""Default gravitational acceleration [m/s^2]."""

RHO_SEAWATER: float = 1030.0
"""Default density of sea water [kg/m^3] (Goda 2000 uses w0 = 1.03 tf/m^3)."""


def as_float(x: npt.ArrayLike) -> FloatArray:
    """Return ``x`` as a float64 array (0-d for a scalar)."""
    return np.asarray(x, dtype=np.float64)
