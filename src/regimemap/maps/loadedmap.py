"""The one door to the loaded map (buoyancy, uplift, inertia) for the caisson tools.

Everything the caisson command and its design sheet need from the map of the
*loaded* block -- the mode at a point, the mode on a grid, the named points,
the margins -- goes through this module, so that the rest of the caisson code
does not depend on where the loaded map lives.  It calls the public API with
the load keywords: :func:`regimemap.classify`, :func:`regimemap.label_grid`,
:func:`regimemap.margin` (exact margins) and the named points of
:class:`regimemap.Parameters`; lift-off is :attr:`regimemap.Mode.LO`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mechanics.block import Parameters
from ..mechanics.curves import named_points as _named_points
from ..mechanics.modes import Mode
from .classify import classify, label_grid
from .margins import Crossing, Margin, margin

__all__ = [
    "LO",
    "Crossing",
    "LoadedMap",
    "Margin",
    "classify_at",
    "margins",
    "mode_description",
    "mode_grid",
    "mode_label",
    "named_points",
]

#: Mode code of lift-off.
LO: int = int(Mode.LO)


@dataclass(frozen=True)
class LoadedMap:
    """The parameters of one loaded map (the keywords of ``classify`` for the loaded block).

    Attributes
    ----------
    gamma : float
        ``H_C / B``.
    kprime : float
        Height of the push above C over ``H_C``, in ``[-1, crest]``.
    buoyancy : float
        Buoyancy as a fraction of ``m g``, upward through C.
    uplift_ratio : float
        Uplift ``U = uplift_ratio * F``.
    uplift_arm : float
        Where the uplift acts: ``uplift_arm * B`` from C toward the seaward corner O'.
    gyration : float or None
        Radius of gyration over ``B`` (None: uniform block).
    crest : float
        Height of the crest above C over ``H_C``.
    """

    gamma: float
    kprime: float
    buoyancy: float = 0.0
    uplift_ratio: float = 0.0
    uplift_arm: float = 1.0 / 3.0
    gyration: float | None = None
    crest: float = 1.0

    def keywords(self) -> dict[str, Any]:
        """The keyword arguments of the loaded ``classify`` (all but gamma and kprime)."""
        return {"buoyancy": self.buoyancy, "uplift_ratio": self.uplift_ratio,
                "uplift_arm": self.uplift_arm, "gyration": self.gyration, "crest": self.crest}

    def check(self) -> None:
        """Raise ValueError if the parameters are outside the loaded map's ranges."""
        self.parameters()

    def parameters(self) -> Parameters:
        """The map's :class:`~regimemap.Parameters` (validated)."""
        return Parameters(self.gamma, self.kprime, **self.keywords())


def mode_label(code: int) -> str:
    """The symbol of a mode code: ``RE``, ``SL``, ... ``LO`` (lift-off)."""
    return Mode(int(code)).label


def mode_description(code: int) -> str:
    """A short description of a mode code."""
    return Mode(int(code)).description


def classify_at(k: ArrayLike, mu: ArrayLike, m: LoadedMap) -> NDArray[np.uint8]:
    """Mode codes at the points (k, mu) of the loaded map ``m`` (broadcast)."""
    return np.asarray(classify(k, mu, m.gamma, m.kprime, **m.keywords()), dtype=np.uint8)


def mode_grid(k_axis: ArrayLike, mu_axis: ArrayLike, m: LoadedMap) -> NDArray[np.uint8]:
    """Mode codes on the grid ``k_axis x mu_axis``, shape ``(len(mu_axis), len(k_axis))``."""
    return np.asarray(label_grid(k_axis, mu_axis, m.gamma, m.kprime, **m.keywords()),
                      dtype=np.uint8)


def named_points(m: LoadedMap) -> dict[str, tuple[float, float]]:
    """The named points (A, C, D, ...) of the loaded map that exist: ``{name: (k, mu)}``."""
    return {n: (p.k, p.mu) for n, p in _named_points(m.parameters()).items()}


def margins(k: float, mu: float, m: LoadedMap) -> tuple[Margin, Margin]:
    """The exact margins of the point (k, mu) on the loaded map ``m``: along k and along mu.

    :func:`regimemap.margin` with the map's loads: the smallest change of k
    (mu fixed) and of mu (k fixed), up or down, that changes the mode.
    """
    return margin(k, mu, m.gamma, m.kprime, **m.keywords())
