"""Goda's wave pressures on an upright section, with Takahashi's impulsive coefficient.

Sources
-------
* Goda, Y. (1974). New wave pressure formulae for composite breakwaters.
  *Proc. 14th ICCE*, ASCE, 1702-1720 -- ``eta*``, ``p1``, ``p3``, ``p4``,
  ``pu``, ``alpha1``, ``alpha2``, ``alpha3``.
* Goda, Y. (2000). *Random Seas and Design of Maritime Structures*, 2nd ed.,
  World Scientific, Sect. 4.2 -- the same formulas for design, the wave
  direction ``beta`` "rotated by an amount of up to 15 degrees toward the
  normal of the breakwater", and the force/moment integrals.
* Takahashi, S., Tanimoto, K. & Shimosako, K. (1994). A proposal of impulsive
  pressure coefficient for the design of composite breakwaters. *Proc. Int.
  Conf. on Hydro-Technical Engineering for Port and Harbor Construction*
  (Hydro-Port '94), PHRI, 489-504 -- ``alpha_I = alpha_I0 alpha_I1`` and
  ``alpha* = max(alpha2, alpha_I)``; the modification factors ``lambda1..3``
  for other wall types are those of Takahashi (2002), *Design of vertical
  breakwaters*, PHRI Reference Document 34 (``lambda = 1`` for a plain
  upright wall).

The pressure diagram: ``p1`` at the still-water level, decreasing linearly to
zero at ``eta*`` above it (``p4`` at the crest ``hc`` when :math:`\\eta^* > h_c`) and
to ``p3`` at the base of the upright section (``h'`` below still water);
the uplift is triangular, ``pu`` at the seaward toe and zero at the leeward
heel.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._types import RHO_SEAWATER, FloatArray, G, as_float
from .dispersion import wavelength

__all__ = ["GodaPressures", "GodaSeaState", "effective_angle", "goda_pressures", "goda_pressures_for",
           "goda_sea_state", "impulsive_coefficient"]

GODA_ROTATION_DEG = 15.0
"""Goda's (2000, Sect. 4.2) largest recommended rotation of the wave direction."""


def effective_angle(angle_deg: npt.ArrayLike, rotation_deg: npt.ArrayLike = 0.0) -> FloatArray:
    """Wave angle used in the pressure formulas, after the optional rotation.

    Parameters
    ----------
    angle_deg : array_like
        Angle ``beta`` between the wave direction and the normal to the wall
        [degrees].
    rotation_deg : array_like, optional
        Rotation toward the normal [degrees]. Goda (2000, Sect. 4.2)
        recommends rotating the principal wave direction "by an amount of up
        to 15 degrees" toward the normal, for the uncertainty of the
        estimated direction; ``0`` (the default) applies no rotation and
        ``15`` is the full recommended rotation (what the Deltares
        coastal-structures-toolbox always does).

    Returns
    -------
    ndarray
        ``max(|beta| - rotation, 0)`` [degrees].
    """
    return np.asarray(np.maximum(np.abs(as_float(angle_deg)) - as_float(rotation_deg), 0.0),
                      dtype=np.float64)


def impulsive_coefficient(Hmax: npt.ArrayLike, depth: npt.ArrayLike, armour_depth: npt.ArrayLike,
                          berm_width: npt.ArrayLike, L: npt.ArrayLike
                          ) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Takahashi's impulsive pressure coefficient ``alpha_I = alpha_I0 alpha_I1``.

    Parameters
    ----------
    Hmax : array_like
        Design wave height [m].
    depth : array_like
        Water depth at the wall ``h`` [m].
    armour_depth : array_like
        Depth ``d`` above the armour layer of the mound [m].
    berm_width : array_like
        Berm width ``BM`` [m].
    L : array_like
        Wave length at depth ``h`` [m].

    Returns
    -------
    alpha_I, alpha_I0, alpha_I1 : ndarray

    Notes
    -----
    Takahashi et al. (1994); Takahashi (2002):

    * ``alpha_I0 = H/d`` for ``H <= 2d``, else ``2``;
    * ``delta11 = 0.93 (BM/L - 0.12) + 0.36 ((h - d)/h - 0.6)``,
      ``delta22 = -0.36 (BM/L - 0.12) + 0.93 ((h - d)/h - 0.6)``;
    * ``delta1 = 20 delta11`` if ``delta11 <= 0``, else ``15 delta11``;
      ``delta2 = 4.9 delta22`` if ``delta22 <= 0``, else ``3 delta22``;
    * ``alpha_I1 = cos(delta2) / cosh(delta1)`` if ``delta22 <= 0``, else
      ``1 / (cosh(delta1) cosh(delta2)^(1/2))``.
    """
    H, h, d, bm, ll = np.broadcast_arrays(as_float(Hmax), as_float(depth), as_float(armour_depth),
                                          as_float(berm_width), as_float(L))
    a_i0 = np.where(H <= 2.0 * d, H / d, 2.0)
    a_i1 = _impulsive_section_factor(h, d, bm, ll)
    return (np.asarray(a_i0 * a_i1, dtype=np.float64), np.asarray(a_i0, dtype=np.float64),
            np.asarray(a_i1, dtype=np.float64))


def _impulsive_section_factor(h: FloatArray, d: FloatArray, bm: FloatArray, ll: FloatArray) -> FloatArray:
    """Takahashi's ``alpha_I1`` (the factor of :func:`impulsive_coefficient` without the height)."""
    x = bm / ll - 0.12
    z = (h - d) / h - 0.6
    d11 = 0.93 * x + 0.36 * z
    d22 = -0.36 * x + 0.93 * z
    d1 = np.where(d11 <= 0.0, 20.0 * d11, 15.0 * d11)
    d2 = np.where(d22 <= 0.0, 4.9 * d22, 3.0 * d22)
    with np.errstate(over="ignore"):
        a_i1 = np.where(d22 <= 0.0, np.cos(d2) / np.cosh(d1),
                        1.0 / (np.cosh(d1) * np.sqrt(np.cosh(d2))))
    return np.asarray(a_i1, dtype=np.float64)


@dataclass(frozen=True)
class GodaPressures:
    """Goda-Takahashi pressures and their coefficients (SI: m, Pa).

    Attributes
    ----------
    L : ndarray
        Wave length of ``T1/3`` at depth ``h`` [m].
    beta : ndarray
        Wave angle used, after rotation [degrees].
    eta_star : ndarray
        Elevation ``eta*`` above still water at which the pressure vanishes [m].
    alpha1, alpha2, alpha3 : ndarray
        Goda's coefficients.
    alpha_I, alpha_I0, alpha_I1 : ndarray
        Takahashi's impulsive coefficient and its factors.
    alpha_star : ndarray
        ``max(alpha2, alpha_I)`` (``alpha2`` when the impulsive term is off).
    p1, p2, p3, p4, pu : ndarray
        Pressures at still water, at the sea bed, at the base of the upright
        section, at the crest, and uplift at the seaward toe [Pa].
    hc_star : ndarray
        ``min(eta*, hc)``: the height of the wall loaded above still water [m].
    """

    L: FloatArray
    beta: FloatArray
    eta_star: FloatArray
    alpha1: FloatArray
    alpha2: FloatArray
    alpha3: FloatArray
    alpha_I: FloatArray
    alpha_I0: FloatArray
    alpha_I1: FloatArray
    alpha_star: FloatArray
    p1: FloatArray
    p2: FloatArray
    p3: FloatArray
    p4: FloatArray
    pu: FloatArray
    hc_star: FloatArray


# Goda's (2000) method takes one keyword-only argument per quantity of its formulas (Hmax, T,
# h, hb, d, h', hc, BM, beta ...), named as in the book (PLR0913 accepted here).
def goda_pressures(*, Hmax: npt.ArrayLike, period: npt.ArrayLike, depth: npt.ArrayLike,  # noqa: PLR0913
                   hb: npt.ArrayLike, armour_depth: npt.ArrayLike, base_depth: npt.ArrayLike,
                   crest: npt.ArrayLike, berm_width: npt.ArrayLike = 0.0,
                   angle_deg: npt.ArrayLike = 0.0, rotation_deg: npt.ArrayLike = 0.0,
                   impulsive: bool = True, lambdas: tuple[float, float, float] = (1.0, 1.0, 1.0),
                   rho_w: float = RHO_SEAWATER, g: float = G,
                   L: npt.ArrayLike | None = None) -> GodaPressures:
    """Goda's (2000) pressures with Takahashi's (1994) impulsive coefficient.

    Parameters
    ----------
    Hmax : array_like
        Design wave height ``Hmax`` [m].
    period : array_like
        Wave period (Goda: ``Tmax = T1/3``) [s].
    depth : array_like
        Water depth at the wall ``h`` [m].
    hb : array_like
        Water depth ``5 H1/3`` seaward of the wall [m] (``alpha2``).
    armour_depth : array_like
        Depth ``d`` above the armour layer of the mound [m].
    base_depth : array_like
        Depth ``h'`` of the base of the upright section below still water [m].
    crest : array_like
        Crest height ``hc`` above still water [m].
    berm_width : array_like, optional
        Berm width ``BM`` [m] (impulsive coefficient only).
    angle_deg : array_like, optional
        Wave angle ``beta`` from the normal to the wall [degrees].
    rotation_deg : array_like, optional
        Rotation of the wave direction toward the normal, see
        :func:`effective_angle` (Goda 2000, Sect. 4.2: up to 15 degrees).
    impulsive : bool, optional
        Use ``alpha* = max(alpha2, alpha_I)`` (Takahashi et al. 1994); False
        gives Goda's original formula (``alpha2``).
    lambdas : tuple of float, optional
        Modification factors ``(lambda1, lambda2, lambda3)`` (Takahashi 2002;
        all 1 for a plain upright wall).
    rho_w : float, optional
        Sea-water density [kg/m^3]; :math:`w_0 = \\rho_w g`.
    g : float, optional
        Gravitational acceleration [m/s^2].
    L : array_like, optional
        The wave length of ``period`` at ``depth`` when the caller has it
        already (:func:`regimemap.waves.wavelength`): the pressures of many
        wave heights in one sea state then skip the dispersion solve.

    Returns
    -------
    GodaPressures

    Notes
    -----
    Goda (1974; 2000, Sect. 4.2), with :math:`w_0 = \\rho_w g`:

    * :math:`\\eta^* = 0.75 (1 + \\cos\\beta) \\lambda_1 H_\\mathrm{max}`;
    * :math:`p_1 = 0.5 (1 + \\cos\\beta) (\\lambda_1 \\alpha_1 + \\lambda_2 \\alpha^* \\cos^2\\beta)
      w_0 H_\\mathrm{max}`;
    * :math:`p_2 = p_1 / \\cosh(2 \\pi h / L)`, :math:`p_3 = \\alpha_3 p_1`;
    * :math:`p_4 = p_1 (1 - h_c/\\eta^*)` for :math:`\\eta^* > h_c`, else 0;
    * :math:`p_u = 0.5 (1 + \\cos\\beta) \\lambda_3 \\alpha_1 \\alpha_3 w_0 H_\\mathrm{max}`;
    * :math:`\\alpha_1 = 0.6 + 0.5 [(4 \\pi h/L) / \\sinh(4 \\pi h/L)]^2`;
    * :math:`\\alpha_2 = \\min((h_b - d)/(3 h_b) (H_\\mathrm{max}/d)^2, 2d/H_\\mathrm{max})`;
    * :math:`\\alpha_3 = 1 - (h'/h) [1 - 1/\\cosh(2 \\pi h/L)]`.
    """
    H, t, h, hb_, d, hp, hc, bm, ang, rot = np.broadcast_arrays(
        as_float(Hmax), as_float(period), as_float(depth), as_float(hb), as_float(armour_depth),
        as_float(base_depth), as_float(crest), as_float(berm_width), as_float(angle_deg),
        as_float(rotation_deg))
    state = goda_sea_state(period=t, depth=h, hb=hb_, armour_depth=d, base_depth=hp, crest=hc,
                           berm_width=bm, angle_deg=ang, rotation_deg=rot, lambdas=lambdas, rho_w=rho_w,
                           g=g, L=L)
    return goda_pressures_for(state, H, impulsive=impulsive)


@dataclass(frozen=True)
class GodaSeaState:
    """The part of Goda's pressures that does not depend on the wave height (arrays over sea states).

    :func:`goda_sea_state` computes it once; :func:`goda_pressures_for` then
    gives the pressures of any wave heights in those sea states (many waves
    of one storm, or the steps of a bisection on the height) without the
    dispersion relation and the hyperbolic functions again.  The two together
    are :func:`goda_pressures`, operation for operation.

    Attributes
    ----------
    L, beta : ndarray
        Wave length [m] and the wave angle used [degrees].
    depth, armour_depth, crest : ndarray
        ``h``, ``d`` and ``hc`` [m].
    alpha1, alpha3 : ndarray
        Goda's coefficients.
    alpha_I1 : ndarray
        Takahashi's factor of the section (:func:`impulsive_coefficient`).
    cosh2 : ndarray
        ``cosh(2 pi h / L)``.
    two_d : ndarray
        ``2 d`` (the bounds of ``alpha2`` and ``alpha_I0``).
    alpha2_factor : ndarray
        ``(h_b - d) / (3 h_b)``.
    half : ndarray
        ``0.5 (1 + cos beta)``.
    cos2 : ndarray
        :math:`\\cos^2\\beta`.
    lam1_alpha1 : ndarray
        ``lambda1 alpha1``.
    eta_factor : ndarray
        ``eta* / Hmax = 0.75 (1 + cos beta) lambda1``.
    pu_factor : ndarray
        ``pu / Hmax = 0.5 (1 + cos beta) lambda3 alpha1 alpha3 w0``.
    lam2, w0 : float
        ``lambda2`` and :math:`\\rho_w g`.
    """

    L: FloatArray
    beta: FloatArray
    depth: FloatArray
    armour_depth: FloatArray
    crest: FloatArray
    alpha1: FloatArray
    alpha3: FloatArray
    alpha_I1: FloatArray
    cosh2: FloatArray
    two_d: FloatArray
    alpha2_factor: FloatArray
    half: FloatArray
    cos2: FloatArray
    lam1_alpha1: FloatArray
    eta_factor: FloatArray
    pu_factor: FloatArray
    lam2: float
    w0: float


# The sea-state half of goda_pressures: the same keyword-only arguments but the height (PLR0913).
def goda_sea_state(*, period: npt.ArrayLike, depth: npt.ArrayLike, hb: npt.ArrayLike,  # noqa: PLR0913
                   armour_depth: npt.ArrayLike, base_depth: npt.ArrayLike, crest: npt.ArrayLike,
                   berm_width: npt.ArrayLike = 0.0, angle_deg: npt.ArrayLike = 0.0,
                   rotation_deg: npt.ArrayLike = 0.0,
                   lambdas: tuple[float, float, float] = (1.0, 1.0, 1.0), rho_w: float = RHO_SEAWATER,
                   g: float = G, L: npt.ArrayLike | None = None) -> GodaSeaState:
    """What Goda's pressures need of a sea state before the wave height is known.

    Parameters
    ----------
    period, depth, hb, armour_depth, base_depth, crest, berm_width, angle_deg, rotation_deg
        As :func:`goda_pressures`, broadcast together.
    lambdas, rho_w, g, L
        As :func:`goda_pressures`.

    Returns
    -------
    GodaSeaState
        For :func:`goda_pressures_for`.

    Examples
    --------
    The pressures of two heights in Goda's worked sea state, as
    :func:`goda_pressures` gives them:

    >>> sea = dict(period=11.4, depth=10.1, hb=10.39, armour_depth=5.6, base_depth=7.1, crest=3.4,
    ...            berm_width=8.0, angle_deg=15.0)
    >>> p = goda_pressures_for(goda_sea_state(**sea), [6.0, 8.05])
    >>> bool(np.all(p.p1 == goda_pressures(Hmax=[6.0, 8.05], **sea).p1))
    True
    """
    t, h, hb_, d, hp, hc, bm, ang, rot = np.broadcast_arrays(
        as_float(period), as_float(depth), as_float(hb), as_float(armour_depth), as_float(base_depth),
        as_float(crest), as_float(berm_width), as_float(angle_deg), as_float(rotation_deg))
    lam1, lam2, lam3 = lambdas
    beta = effective_angle(ang, rot)
    cb = np.cos(np.radians(beta))
    w0 = rho_w * g
    L = wavelength(t, h, g) if L is None else np.broadcast_to(as_float(L), h.shape)
    x4 = 4.0 * np.pi * h / L
    with np.errstate(over="ignore"):
        alpha1 = 0.6 + 0.5 * np.where(x4 < 700.0, x4 / np.sinh(np.minimum(x4, 700.0)), 0.0) ** 2
        cosh2 = np.cosh(np.minimum(2.0 * np.pi * h / L, 700.0))
    alpha3 = 1.0 - hp / h * (1.0 - 1.0 / cosh2)
    half = 0.5 * (1.0 + cb)

    def f(a: npt.NDArray[np.float64]) -> FloatArray:
        return np.asarray(a, dtype=np.float64)

    # each factor is the leading part of its formula in goda_pressures_for, evaluated left to
    # right as there: the pressures come out the same to the last bit
    return GodaSeaState(L=f(L), beta=f(beta), depth=h, armour_depth=d, crest=hc, alpha1=f(alpha1),
                        alpha3=f(alpha3), alpha_I1=_impulsive_section_factor(h, d, bm, L),
                        cosh2=f(cosh2), two_d=f(2.0 * d), alpha2_factor=f((hb_ - d) / (3.0 * hb_)),
                        half=f(half), cos2=f(cb**2), lam1_alpha1=f(lam1 * alpha1),
                        eta_factor=f(0.75 * (1.0 + cb) * lam1),
                        pu_factor=f(half * lam3 * alpha1 * alpha3 * w0), lam2=lam2, w0=w0)


def goda_pressures_for(state: GodaSeaState, Hmax: npt.ArrayLike, impulsive: bool = True) -> GodaPressures:
    """Goda's pressures of waves of height ``Hmax`` in sea states prepared by :func:`goda_sea_state`.

    Parameters
    ----------
    state : GodaSeaState
        The sea states.
    Hmax : array_like
        Wave heights [m], broadcast with the sea states.
    impulsive : bool, optional
        As :func:`goda_pressures`.

    Returns
    -------
    GodaPressures
        The same numbers as :func:`goda_pressures` with the same arguments.

    Notes
    -----
    The formulas are those of :func:`goda_pressures`; only the factors that
    do not depend on ``Hmax`` come from ``state``.
    """
    H = as_float(Hmax)
    shape = np.broadcast_shapes(H.shape, state.depth.shape)
    H = np.broadcast_to(H, shape)
    d, hc = state.armour_depth, state.crest
    alpha2 = np.minimum(state.alpha2_factor * (H / d) ** 2, state.two_d / H)
    a_i0 = np.where(H <= state.two_d, H / d, 2.0)
    a_i = a_i0 * state.alpha_I1
    alpha_star = np.maximum(alpha2, a_i) if impulsive else alpha2
    eta = state.eta_factor * H
    p1 = state.half * (state.lam1_alpha1 + state.lam2 * alpha_star * state.cos2) * state.w0 * H
    p2 = p1 / state.cosh2
    p3 = state.alpha3 * p1
    p4 = np.where(eta > hc, p1 * (1.0 - hc / eta), 0.0)
    pu = state.pu_factor * H

    def f(a: npt.NDArray[np.float64]) -> FloatArray:
        a = np.asarray(a, dtype=np.float64)
        return a if a.shape == shape else np.asarray(np.broadcast_to(a, shape), dtype=np.float64)

    return GodaPressures(L=f(state.L), beta=f(state.beta), eta_star=f(eta), alpha1=f(state.alpha1),
                         alpha2=f(alpha2), alpha3=f(state.alpha3), alpha_I=f(a_i), alpha_I0=f(a_i0),
                         alpha_I1=f(state.alpha_I1), alpha_star=f(alpha_star), p1=f(p1), p2=f(p2),
                         p3=f(p3), p4=f(p4), pu=f(pu), hc_star=f(np.minimum(eta, hc)))
