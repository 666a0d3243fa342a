"""The equivalent loaded block of the regime map, and its closed-form rest check.

The regime map (Shenton-type rigid block, half width ``B``, centre of mass
``C`` at height ``H`` above the base) is driven by a horizontal force
``F = m g k`` acting at ``k' H`` above ``C`` with Coulomb friction ``mu``.
A caisson under Goda's wave load maps onto it as follows (this module's own
derivation; the wave loads are Goda's, Sect. 4.2 of Goda 2000):

* ``m g`` is the DRY weight, :math:`W' + \\rho_w g V_\\mathrm{sub}` (``W'`` is Goda's
  buoyant weight, Sect. 4.3);
* ``H = H_C`` (height of the centre of mass above the base), ``gamma = H_C/B``;
* ``k = P / (m g)``; ``k' = (Mp/P - H_C) / H_C`` (``Mp/P`` is the height of
  the resultant of ``P`` above the base);
* buoyancy :math:`\\beta_b m g = \\rho_w g V_\\mathrm{sub}` upward through ``C``;
* uplift ``U = u m g + nu F`` upward at ``x = e_u B`` from ``C`` toward the
  seaward corner ``O'``: here ``u = 0``, ``nu = U/P`` and, from the uplift
  moment about the leeward heel, ``e_u = (Mu/U - B)/B`` (1/3 for Goda's
  triangle);
* ``F`` pushes toward the leeward corner ``O``; radius of gyration ``i`` with
  :math:`I = m B^2 i^2`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._types import FloatArray, as_float
from .caisson import CaissonLoads, CaissonSection

__all__ = ["EquivalentBlock", "RestCheck", "equivalent_block", "static_rest_check"]


@dataclass(frozen=True)
class RestCheck:
    """Closed-form static check of the loaded block (all arrays).

    Attributes
    ----------
    sliding_margin : ndarray
        ``mu (1 - beta_b - u - nu k) - k``; ``>= 0``: no sliding.
    overturning_margin : ndarray
        ``(1 - beta_b) - k (1 + k') gamma - (u + nu k)(1 + e_u)``, restoring
        minus overturning moment about ``O`` divided by ``m g B``; ``>= 0``:
        no overturning.
    no_sliding, no_overturning, at_rest : ndarray of bool
    """

    sliding_margin: FloatArray
    overturning_margin: FloatArray
    no_sliding: npt.NDArray[np.bool_]
    no_overturning: npt.NDArray[np.bool_]
    at_rest: npt.NDArray[np.bool_]


def static_rest_check(*, k: npt.ArrayLike, mu: npt.ArrayLike, gamma: npt.ArrayLike,
                      kprime: npt.ArrayLike, buoyancy: npt.ArrayLike = 0.0, uplift_ratio: npt.ArrayLike = 0.0,
                      uplift_arm: npt.ArrayLike = 0.0, uplift: npt.ArrayLike = 0.0) -> RestCheck:
    """Does the loaded block stay at rest? Closed form, vectorised.

    Parameters
    ----------
    k : array_like
        ``F / (m g)``, ``F`` pushing toward the leeward corner ``O``.
    mu : array_like
        Friction coefficient.
    gamma : array_like
        ``H / B``.
    kprime : array_like
        Height of ``F`` above ``C`` in units of ``H``.
    buoyancy : array_like, optional
        ``beta_b``: buoyancy as a fraction of ``m g``, upward through ``C``.
    uplift_ratio : array_like, optional
        ``nu``: uplift proportional to ``F``, ``nu F``.
    uplift_arm : array_like, optional
        ``e_u``: arm of the uplift from ``C`` toward ``O'``, in units of ``B``.
    uplift : array_like, optional
        ``u``: uplift independent of ``F``, fraction of ``m g`` (0 for a caisson).

    Returns
    -------
    RestCheck

    Notes
    -----
    Statics of the rigid block on its base (derived here). The normal force
    is ``N = m g (1 - beta_b - u - nu k)``, so friction holds while
    ``mu (1 - beta_b - u - nu k) >= k``. About the leeward corner
    ``O = (B, -H)``: the net weight ``(1 - beta_b) m g`` restores with arm
    ``B``; ``F`` overturns with arm ``(1 + k') H``; the uplift overturns with
    arm ``(1 + e_u) B``. Dividing by ``m g B``: no overturning while
    ``1 - beta_b >= k (1 + k') gamma + (u + nu k)(1 + e_u)``. For a caisson
    (``u = 0``) these are exactly Goda's ``SF_s >= 1`` and ``SF_o >= 1``
    (``t = B``): ``SF_s = mu (1 - beta_b - nu k)/k`` and
    ``SF_o = ((1 - beta_b) - nu k (1 + e_u)) / (k (1 + k') gamma)``.
    """
    k_, mu_, g_, kp, bb, nu_, eu, u_ = np.broadcast_arrays(
        as_float(k), as_float(mu), as_float(gamma), as_float(kprime), as_float(buoyancy),
        as_float(uplift_ratio), as_float(uplift_arm), as_float(uplift))
    slide = mu_ * (1.0 - bb - u_ - nu_ * k_) - k_
    over = (1.0 - bb) - k_ * (1.0 + kp) * g_ - (u_ + nu_ * k_) * (1.0 + eu)
    ns = slide >= 0.0
    no = over >= 0.0
    return RestCheck(sliding_margin=np.asarray(slide, dtype=np.float64),
                     overturning_margin=np.asarray(over, dtype=np.float64),
                     no_sliding=np.asarray(ns, dtype=np.bool_),
                     no_overturning=np.asarray(no, dtype=np.bool_),
                     at_rest=np.asarray(ns & no, dtype=np.bool_))


@dataclass(frozen=True)
class EquivalentBlock:
    """The caisson as the loaded block of the regime map (arrays).

    Attributes
    ----------
    B : ndarray
        Half width [m].
    H : ndarray
        ``H_C``, height of the centre of mass above the base [m].
    gamma : ndarray
        ``H_C / B``.
    k : ndarray
        ``P / (m g)``, ``m g`` the dry weight.
    kprime : ndarray
        ``(Mp/P - H_C)/H_C``.
    buoyancy : ndarray
        ``beta_b``, the buoyancy fraction :math:`\\rho_w g V_\\mathrm{sub} / (m g)`.
    uplift_ratio : ndarray
        ``nu = U / P``.
    uplift_arm : ndarray
        ``e_u = (Mu/U - B)/B``, arm of the uplift from ``C`` toward ``O'`` in units
        of ``B``.
    uplift : ndarray
        ``u``, uplift independent of ``F`` (0).
    gyration : ndarray
        ``i``, radius of gyration in units of ``B``: :math:`I = m B^2 i^2`
        (:math:`i^2 = (1 + \\gamma^2)/3` for a uniform block).
    mu : ndarray
        Friction coefficient.
    mass : ndarray
        Dry mass per metre [kg/m].
    """

    B: FloatArray
    H: FloatArray
    gamma: FloatArray
    k: FloatArray
    kprime: FloatArray
    buoyancy: FloatArray
    uplift_ratio: FloatArray
    uplift_arm: FloatArray
    uplift: FloatArray
    gyration: FloatArray
    mu: FloatArray
    mass: FloatArray

    def rest_check(self) -> RestCheck:
        """:func:`static_rest_check` of this block."""
        return static_rest_check(k=self.k, mu=self.mu, gamma=self.gamma, kprime=self.kprime,
                                 buoyancy=self.buoyancy, uplift_ratio=self.uplift_ratio,
                                 uplift_arm=self.uplift_arm, uplift=self.uplift)


def equivalent_block(section: CaissonSection, loads: CaissonLoads, friction: npt.ArrayLike,
                     g: float = 9.81) -> EquivalentBlock:
    """Map a caisson under Goda's wave loads onto the loaded block.

    Parameters
    ----------
    section : CaissonSection
        Mass properties (its ``buoyancy`` is :math:`\\rho_w g V_\\mathrm{sub}`).
    loads : CaissonLoads
        ``P``, ``Mp``, ``U``, ``Mu`` per metre.
    friction : array_like
        ``mu``.
    g : float, optional
        Gravitational acceleration [m/s^2]; must be the one used for
        ``section``.

    Returns
    -------
    EquivalentBlock
        See the module docstring for the definitions.
    """
    B = 0.5 * section.width
    hc_ = section.height_cg
    mg = section.mass * g
    with np.errstate(divide="ignore", invalid="ignore"):
        k = loads.P / mg
        kprime = (loads.Mp / loads.P - hc_) / hc_
        nu = loads.U / loads.P
        e_u = np.where(loads.U > 0.0, (loads.Mu / loads.U - B) / B, 1.0 / 3.0)
    i = np.sqrt(section.inertia / (section.mass * B * B))
    mu = np.broadcast_to(as_float(friction), k.shape)

    def f(a: npt.NDArray[np.float64]) -> FloatArray:
        return np.asarray(a, dtype=np.float64)

    return EquivalentBlock(B=f(B), H=f(hc_), gamma=f(hc_ / B), k=f(k), kprime=f(kprime),
                           buoyancy=f(section.buoyancy / mg), uplift_ratio=f(nu), uplift_arm=f(e_u),
                           uplift=np.zeros(k.shape), gyration=f(i), mu=f(mu), mass=f(section.mass))
