"""The planar rigid block (bare or loaded) of :mod:`regimemap.dynamics`.

Geometry (the report's, see :mod:`regimemap.solver`): the centre of mass C is at
the origin at rest, the base corners are O = (-B, -H_C) (left, leeward) and
O' = (B, -H_C) (right, seaward), theta is positive counter-clockwise (rocking
about O is theta > 0).  The push F = k m g acts to the *left* (towards O) at
the body point on the vertical centre line k' H_C above C (it turns with the
block; for k' = 0 it acts at C and is exactly a ground acceleration a_g = k g).

Loads (all optional, in units of m g): a buoyancy ``beta`` (``buoyancy``) upward through C;
an uplift ``U = u m g + nu F`` (``uplift`` u, ``uplift_ratio`` nu) upward on the base at
``e_u B`` (``uplift_arm`` e_u) from C towards O' (default e_u = 1/3, a triangular uplift
pressure, after Goda's caisson design practice as used by Tanimoto et al. 1996 and Shimosako &
Takahashi 1999).

References
----------
Housner, G. W. (1963). The behavior of inverted pendulum structures during
earthquakes. Bull. Seismol. Soc. Am. 53(2), 403-417.

Makris, N. & Roussos, Y. (2000). Rocking response of rigid blocks under
near-source ground motions. Geotechnique 50(3), 243-262.

Zhang, J. & Makris, N. (2001). Rocking response of free-standing blocks under
cycloidal pulses. J. Eng. Mech. 127(5), 473-483.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Block", "G", "slenderness", "frequency_parameter", "size_R"]

#: Default gravity (m/s^2).
G = 9.81

FloatArray = NDArray[np.float64]


def slenderness(gamma: ArrayLike) -> FloatArray:
    """Slenderness angle alpha = atan(1/gamma) (rad) of Housner (1963)."""
    return np.arctan2(1.0, np.asarray(gamma, dtype=np.float64))


def size_R(B: ArrayLike, gamma: ArrayLike) -> FloatArray:
    """Half-diagonal R = B sqrt(1 + gamma^2) (m): distance from C to a base corner."""
    B_ = np.asarray(B, dtype=np.float64)
    return B_ * np.hypot(1.0, np.asarray(gamma, dtype=np.float64))


def frequency_parameter(B: ArrayLike, gamma: ArrayLike, g: float = G) -> FloatArray:
    """Housner's frequency parameter p = sqrt(3 g / (4 R)) (rad/s) of a uniform block."""
    return np.sqrt(3.0 * g / (4.0 * size_R(B, gamma)))


@dataclass(frozen=True)
class Block:
    """A rigid block on a rigid base with Coulomb friction, and its loads.

    Every field may be a scalar or an array (one value per run); they broadcast
    together with the pulse parameters in :func:`regimemap.dynamics.simulate`.

    Parameters
    ----------
    B : array_like
        Half width (m).  Size matters: p = sqrt(3 g / (4 R)) depends on it.
    gamma : array_like
        H_C / B, with H_C the height of C above the base (the half height of
        a uniform block).
    mu : array_like
        Coulomb friction coefficient (static = kinetic).
    kprime : array_like
        Height of the push above C in units of H_C (the pulse may override it
        with a history, see :meth:`Pulse.from_arrays`).
    i2 : array_like or None
        Squared radius of gyration about C in units of B^2 (I = m B^2 i2);
        None is the uniform block, i2 = (1 + gamma^2)/3.
    buoyancy : array_like
        ``beta``: buoyancy, upward through C, in units of m g.
    uplift, uplift_ratio : array_like
        ``u`` and ``nu`` of the uplift U = u m g + nu F, upward on the base.
    uplift_arm : array_like
        ``e_u``: point of application of the uplift, e_u B from C towards O'.
    g : float
        Gravity (m/s^2).
    """

    B: ArrayLike
    gamma: ArrayLike
    mu: ArrayLike
    kprime: ArrayLike = 0.0
    i2: ArrayLike | None = None
    buoyancy: ArrayLike = 0.0
    uplift: ArrayLike = 0.0
    uplift_ratio: ArrayLike = 0.0
    uplift_arm: ArrayLike = field(default=1.0 / 3.0)
    g: float = G

    @classmethod
    def from_frequency(cls, p: float, alpha: float, mu: ArrayLike = 100.0, g: float = G,
                       **loads: Any) -> Block:
        """The uniform block of given Housner parameters p (rad/s) and alpha (rad).

        R = 3 g / (4 p^2), B = R sin(alpha), gamma = 1/tan(alpha).
        """
        R = 3.0 * g / (4.0 * p * p)
        return cls(B=R * np.sin(alpha), gamma=1.0 / np.tan(alpha), mu=mu, g=g, **loads)

    @property
    def H(self) -> FloatArray:
        """Height H_C of C above the base (m)."""
        return np.asarray(self.B, dtype=np.float64) * np.asarray(self.gamma, dtype=np.float64)

    @property
    def R(self) -> FloatArray:
        """Distance from C to a base corner (m)."""
        return size_R(self.B, self.gamma)

    @property
    def alpha(self) -> FloatArray:
        """Slenderness angle atan(1/gamma) (rad)."""
        return slenderness(self.gamma)

    @property
    def gyration2(self) -> FloatArray:
        """Squared radius of gyration about C in units of B^2."""
        if self.i2 is None:
            return (1.0 + np.asarray(self.gamma, dtype=np.float64) ** 2) / 3.0
        return np.asarray(self.i2, dtype=np.float64)

    @property
    def p(self) -> FloatArray:
        """Frequency parameter p = sqrt(m g R / I_O) (rad/s); sqrt(3g/(4R)) when uniform."""
        B = np.asarray(self.B, dtype=np.float64)
        R = self.R
        return np.sqrt(self.g * R / (self.gyration2 * B * B + R * R))

    @property
    def housner_ratio(self) -> FloatArray:
        """Housner's plastic rocking ratio theta_dot+/theta_dot- (angular momentum about the new pivot).

        (I + m (H^2 - B^2)) / (I + m (H^2 + B^2)); 1 - (3/2) sin^2(alpha) when uniform.
        The formula assumes that the block rocks on about the other corner; for a squat block
        (I + m H^2 <= m B^2; uniform: gamma <= 1/sqrt(2)) it is <= 0 and does not apply: the
        impact ends the rocking and the block lands flat (the stepper's plastic impact gives
        this; ``regimemap simulate`` says "not applicable").
        """
        B = np.asarray(self.B, dtype=np.float64)
        H = self.H
        J = self.gyration2 * B * B
        return (J + H * H - B * B) / (J + H * H + B * B)

    @property
    def loaded(self) -> bool:
        """Whether any buoyancy or uplift is present."""
        return bool(np.any(np.asarray(self.buoyancy) != 0) or np.any(np.asarray(self.uplift) != 0)
                    or np.any(np.asarray(self.uplift_ratio) != 0))

    def with_(self, **changes: Any) -> Block:
        """A copy with some fields changed."""
        return replace(self, **changes)

    def arrays(self, n: int) -> dict[str, FloatArray]:
        """Every field broadcast to ``n`` runs (float arrays, ``i2`` resolved)."""
        out: dict[str, FloatArray] = {}
        for f in fields(self):
            if f.name == "g":
                continue
            value = self.gyration2 if f.name == "i2" else getattr(self, f.name)
            out[f.name] = np.broadcast_to(np.asarray(value, dtype=np.float64), (n,)).copy()
        return out
