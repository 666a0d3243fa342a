"""The one door to the loaded map (issue 10) for the caisson tools.

Everything the caisson command and its design sheet need from the map of the
*loaded* block -- the mode at a point, the mode on a grid, the named points,
the margins -- goes through this module, so the rest of the code does not
depend on where the loaded map lives.  It currently calls the closed forms of
:mod:`regimemap.mechanics.loaded` (``classify_loaded``, ``label_grid_loaded``,
``named_points_loaded``); once the loaded block is wired into the core
(``regimemap.classify(..., buoyancy=..., uplift_ratio=...)``, ``query_point``)
only this module changes.

Margins here are found by a scan and a bisection on the classification
(see :func:`margins`), not from the list of the boundaries' roots as in
:mod:`regimemap.maps.margins`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..mechanics.loaded import LO, classify_loaded, label_grid_loaded, loaded_constants, named_points_loaded
from ..mechanics.modes import Mode

__all__ = [
    "LO",
    "LoadedCrossing",
    "LoadedMap",
    "LoadedMargin",
    "classify_at",
    "margins",
    "mode_description",
    "mode_grid",
    "mode_label",
    "named_points",
]

#: Samples of the scan that looks for the nearest change of mode (then bisection).
_SCAN = 4000
#: Bisection steps (enough to reach adjacent doubles from any bracket).
_BISECT = 200
#: The scan upward goes as far as this multiple of the value (plus one).
_UP_REACH = 1e4


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
        loaded_constants(self.gamma, self.kprime, **self.keywords())


def mode_label(code: int) -> str:
    """The symbol of a mode code: ``RE``, ``SL``, ... or ``LO`` (lift-off)."""
    return "LO" if int(code) == LO else Mode(int(code)).label


def mode_description(code: int) -> str:
    """A short description of a mode code."""
    return "lift-off: no contact force" if int(code) == LO else Mode(int(code)).description


def classify_at(k: ArrayLike, mu: ArrayLike, m: LoadedMap) -> NDArray[np.uint8]:
    """Mode codes at the points (k, mu) of the loaded map ``m`` (broadcast)."""
    return np.asarray(classify_loaded(k, mu, m.gamma, m.kprime, **m.keywords()), dtype=np.uint8)


def mode_grid(k_axis: ArrayLike, mu_axis: ArrayLike, m: LoadedMap) -> NDArray[np.uint8]:
    """Mode codes on the grid ``k_axis x mu_axis``, shape ``(len(mu_axis), len(k_axis))``."""
    return np.asarray(label_grid_loaded(k_axis, mu_axis, m.gamma, m.kprime, **m.keywords()),
                      dtype=np.uint8)


def named_points(m: LoadedMap) -> dict[str, tuple[float, float]]:
    """The named points (A, C, D, ...) of the loaded map that exist: ``{name: (k, mu)}``."""
    cst = loaded_constants(m.gamma, m.kprime, **m.keywords())
    return {n: (p.k, p.mu) for n, p in named_points_loaded(cst).items()}


@dataclass(frozen=True)
class LoadedCrossing:
    """The nearest change of mode in one direction.

    Attributes
    ----------
    direction : {"up", "down"}
    at : float
        The first value found with another mode.
    delta : float
        ``|at - value|``.
    relative : float or None
        ``delta / value`` (None when the value is 0).
    to : int
        Mode code just beyond (:func:`mode_label` names it).
    """

    direction: str
    at: float
    delta: float
    relative: float | None
    to: int


@dataclass(frozen=True)
class LoadedMargin:
    """Smallest change of k (mu fixed) or of mu (k fixed) that changes the mode.

    ``up`` / ``down`` are None when no change was found in that direction
    (down from 0, or up to :data:`_UP_REACH` times the value).
    """

    variable: str
    value: float
    up: LoadedCrossing | None
    down: LoadedCrossing | None

    @property
    def nearest(self) -> LoadedCrossing | None:
        options = [c for c in (self.down, self.up) if c is not None]
        return min(options, key=lambda c: c.delta) if options else None


def _codes(var: str, x: NDArray[np.float64], other: float, m: LoadedMap) -> NDArray[np.uint8]:
    return classify_at(x, other, m) if var == "k" else classify_at(other, x, m)


def _crossing(var: str, x0: float, other: float, m: LoadedMap, m0: int, up: bool
              ) -> LoadedCrossing | None:
    if up:
        reach = _UP_REACH * (abs(x0) + 1.0)
        near = x0 + np.linspace(0.0, 2.0 * x0 + 1.0, _SCAN + 1)[1:]
        far = np.geomspace(near[-1], x0 + reach, _SCAN // 4 + 1)[1:]
        probes = np.concatenate([near, far])
    else:
        if x0 <= 0.0:
            return None
        probes = np.linspace(x0, 0.0, _SCAN + 1)[1:]
    codes = _codes(var, probes, other, m)
    differs = np.flatnonzero(codes != m0)
    if differs.size == 0:
        return None
    j = int(differs[0])
    lo = x0 if j == 0 else float(probes[j - 1])
    hi = float(probes[j])
    for _ in range(_BISECT):
        mid = lo + 0.5 * (hi - lo)
        if mid in (lo, hi):
            break
        if int(_codes(var, np.array([mid]), other, m)[0]) == m0:
            lo = mid
        else:
            hi = mid
    to = int(_codes(var, np.array([hi]), other, m)[0])
    delta = abs(hi - x0)
    return LoadedCrossing("up" if up else "down", hi, delta, delta / x0 if x0 > 0.0 else None, to)


def margins(k: float, mu: float, m: LoadedMap) -> tuple[LoadedMargin, LoadedMargin]:
    """The margins of the point (k, mu) on the loaded map ``m``: along k and along mu.

    A scan of :data:`_SCAN` samples in each direction (down to 0; up to
    twice the value plus one, then geometrically to :data:`_UP_REACH` times
    it) finds the first sample with another mode, and a bisection on the
    classification pins the boundary down to adjacent doubles.  A region
    thinner than the scan's step can be missed.
    """
    m0 = int(classify_at(k, mu, m))
    out = []
    for var, x, other in (("k", float(k), float(mu)), ("mu", float(mu), float(k))):
        out.append(LoadedMargin(var, x, _crossing(var, x, other, m, m0, up=True),
                                _crossing(var, x, other, m, m0, up=False)))
    return out[0], out[1]
