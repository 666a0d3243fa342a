"""Loads on, and stability of, an upright caisson per metre of breakwater.

Sources
-------
* Goda, Y. (2000). *Random Seas and Design of Maritime Structures*, 2nd ed.,
  World Scientific, Sect. 4.2 (horizontal force ``P``, its moment ``Mp``
  about the heel, uplift ``U`` and its moment ``Mu``; safety factors against
  sliding and overturning; heel (bearing) pressure by the eccentric-load
  formula) and Sect. 4.3 (weight of the caisson: the buoyant weight ``W'``,
  i.e. the weight in still water).

Conventions: SI units, forces in N per metre of breakwater, moments in N m
per metre. ``width`` is the FULL width ``2B`` of the upright section; the
heel is the leeward bottom corner.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._types import RHO_SEAWATER, FloatArray, G, as_float
from .pressure import GodaPressures

__all__ = ["CaissonLoads", "CaissonSection", "Stability", "caisson_loads", "heel_pressure",
           "section_from_densities", "section_from_weight", "stability"]


@dataclass(frozen=True)
class CaissonLoads:
    """Wave loads per metre of breakwater (Goda 2000, Sect. 4.2).

    Attributes
    ----------
    P : ndarray
        Horizontal wave force [N/m].
    Mp : ndarray
        Moment of ``P`` about the base of the upright section [N m/m].
    U : ndarray
        Uplift force [N/m].
    Mu : ndarray
        Moment of ``U`` about the leeward heel [N m/m].
    """

    P: FloatArray
    Mp: FloatArray
    U: FloatArray
    Mu: FloatArray


def caisson_loads(pressures: GodaPressures, base_depth: npt.ArrayLike,
                  width: npt.ArrayLike) -> CaissonLoads:
    """Integrate Goda's pressure diagram into forces and moments.

    Parameters
    ----------
    pressures : GodaPressures
        From :func:`regimemap.waves.goda_pressures`.
    base_depth : array_like
        ``h'``, depth of the base of the upright section below still water [m].
    width : array_like
        Full width ``2B`` of the upright section [m].

    Returns
    -------
    CaissonLoads

    Notes
    -----
    Goda (2000, Sect. 4.2), with :math:`h_c^* = \\min(\\eta^*, h_c)`:

    * :math:`P = (p_1 + p_3) h'/2 + (p_1 + p_4) h_c^*/2`;
    * :math:`M_P = (2 p_1 + p_3) h'^2/6 + (p_1 + p_4) h' h_c^*/2 + (p_1 + 2 p_4) h_c^{*2}/6`;
    * :math:`U = p_u\\,\\mathrm{width} / 2` (triangle, ``pu`` at the seaward toe);
    * :math:`M_U = (2/3)\\, U\\,\\mathrm{width}`.
    """
    hp = as_float(base_depth)
    w = as_float(width)
    p1, p3, p4, hcs = pressures.p1, pressures.p3, pressures.p4, pressures.hc_star
    P = 0.5 * (p1 + p3) * hp + 0.5 * (p1 + p4) * hcs
    Mp = (2.0 * p1 + p3) * hp**2 / 6.0 + 0.5 * (p1 + p4) * hp * hcs + (p1 + 2.0 * p4) * hcs**2 / 6.0
    U = 0.5 * pressures.pu * w
    Mu = 2.0 / 3.0 * U * w
    return CaissonLoads(P=np.asarray(P, dtype=np.float64), Mp=np.asarray(Mp, dtype=np.float64),
                        U=np.asarray(U, dtype=np.float64), Mu=np.asarray(Mu, dtype=np.float64))


@dataclass(frozen=True)
class CaissonSection:
    """Mass properties of the upright section per metre of breakwater.

    Attributes
    ----------
    width : ndarray
        Full width ``2B`` [m].
    base_depth : ndarray
        ``h'`` [m].
    crest : ndarray
        ``hc`` [m].
    mass : ndarray
        Dry mass ``m`` per metre [kg/m].
    buoyancy : ndarray
        :math:`\\rho_w g\\,\\mathrm{width}\\, h'` [N/m], the weight of the displaced water.
    buoyant_weight : ndarray
        ``W' = m g - buoyancy`` [N/m].
    height_cg : ndarray
        Height ``H_C`` of the centre of mass above the base [m].
    inertia : ndarray
        Moment of inertia about the centre of mass per metre [kg m^2/m].
    t : ndarray
        Horizontal distance from the leeward heel to the centre of mass [m]
        (``width/2``: both constructors are symmetric about the vertical axis).
    """

    width: FloatArray
    base_depth: FloatArray
    crest: FloatArray
    mass: FloatArray
    buoyancy: FloatArray
    buoyant_weight: FloatArray
    height_cg: FloatArray
    inertia: FloatArray
    t: FloatArray


def section_from_weight(buoyant_weight: npt.ArrayLike, width: npt.ArrayLike,
                        base_depth: npt.ArrayLike, crest: npt.ArrayLike,
                        rho_w: float = RHO_SEAWATER, g: float = G) -> CaissonSection:
    """A uniform caisson of given buoyant weight ``W'`` (Goda 2000, Sect. 4.3).

    Parameters
    ----------
    buoyant_weight : array_like
        ``W'``, weight in still water per metre [N/m].
    width, base_depth, crest : array_like
        ``2B``, ``h'``, ``hc`` [m].
    rho_w, g : float, optional
        Sea-water density [kg/m^3], gravity [m/s^2].

    Returns
    -------
    CaissonSection
        Dry weight :math:`m g = W' + \\rho_w g\\, 2B h'`; the mass is taken as uniform
        over the rectangle ``2B x (h' + hc)``, so ``H_C = (h' + hc)/2`` and
        :math:`I = m (4B^2 + (h' + h_c)^2)/12` (:math:`i^2 = (1 + \\gamma^2)/3`).
    """
    wp, w, hp, hc = np.broadcast_arrays(as_float(buoyant_weight), as_float(width),
                                        as_float(base_depth), as_float(crest))
    buoy = rho_w * g * w * hp
    mass = (wp + buoy) / g
    height = hp + hc
    return CaissonSection(width=w.copy(), base_depth=hp.copy(), crest=hc.copy(),
                          mass=np.asarray(mass, dtype=np.float64),
                          buoyancy=np.asarray(buoy, dtype=np.float64), buoyant_weight=wp.copy(),
                          height_cg=np.asarray(0.5 * height, dtype=np.float64),
                          inertia=np.asarray(mass * (w**2 + height**2) / 12.0, dtype=np.float64),
                          t=np.asarray(0.5 * w, dtype=np.float64))


def section_from_densities(width: npt.ArrayLike, base_depth: npt.ArrayLike, crest: npt.ArrayLike,
                           *, concrete_fraction: npt.ArrayLike, concrete_density: npt.ArrayLike,
                           fill_density: npt.ArrayLike,
                           fill_density_above: npt.ArrayLike | None = None,
                           rho_w: float = RHO_SEAWATER, g: float = G) -> CaissonSection:
    """A filled caisson from the densities of its concrete and of its fill.

    Parameters
    ----------
    width, base_depth, crest : array_like
        ``2B``, ``h'``, ``hc`` [m].
    concrete_fraction : array_like
        Fraction ``phi`` of the section's area that is concrete (walls, slabs,
        cap), ``0 <= phi <= 1``; the rest is fill.
    concrete_density : array_like
        :math:`\\rho_c` [kg/m^3] (reinforced concrete about 2400).
    fill_density : array_like
        Density of the fill BELOW still water [kg/m^3]: saturated sand or
        gravel, pores full of water (about 2000).
    fill_density_above : array_like, optional
        Density of the fill ABOVE still water [kg/m^3] (moist sand, about
        1800); defaults to ``fill_density``.
    rho_w, g : float, optional
        Sea-water density [kg/m^3], gravity [m/s^2].

    Returns
    -------
    CaissonSection

    Notes
    -----
    The section is modelled as two horizontal layers, each homogenised over
    the full width ``2B`` (concrete and fill smeared in the ratio
    ``phi : 1 - phi``): the submerged layer ``0 <= z <= h'`` of density
    :math:`\\rho_b = \\phi \\rho_c + (1 - \\phi) \\rho_\\mathrm{fill}` and the emerged layer
    ``h' <= z <= h' + hc`` of density
    :math:`\\rho_a = \\phi \\rho_c + (1 - \\phi) \\rho_\\mathrm{fill,above}`. Per metre:
    :math:`m = 2B (\\rho_b h' + \\rho_a h_c)`, buoyancy :math:`\\rho_w g\\, 2B h'` (the
    caisson displaces its whole submerged volume; water in the pores of the
    fill is part of :math:`\\rho_b`), :math:`W' = m g - \\rho_w g\\, 2B h'` (Goda 2000,
    Sect. 4.3), :math:`H_C = (m_b h'/2 + m_a (h' + h_c/2)) / m` and
    :math:`I = \\sum_j m_j ((2B)^2 + t_j^2)/12 + m_j (z_j - H_C)^2` (rectangles and
    parallel axes). Horizontally symmetric, so ``t = B``.
    """
    w, hp, hc, phi, rc, rf = np.broadcast_arrays(
        as_float(width), as_float(base_depth), as_float(crest), as_float(concrete_fraction),
        as_float(concrete_density), as_float(fill_density))
    rfa = rf if fill_density_above is None else np.broadcast_to(as_float(fill_density_above),
                                                                w.shape)
    rho_b = phi * rc + (1.0 - phi) * rf
    rho_a = phi * rc + (1.0 - phi) * rfa
    m_b = rho_b * w * hp
    m_a = rho_a * w * hc
    mass = m_b + m_a
    zc = (m_b * 0.5 * hp + m_a * (hp + 0.5 * hc)) / mass
    inertia = (m_b * (w**2 + hp**2) / 12.0 + m_b * (0.5 * hp - zc) ** 2
               + m_a * (w**2 + hc**2) / 12.0 + m_a * (hp + 0.5 * hc - zc) ** 2)
    buoy = rho_w * g * w * hp
    return CaissonSection(width=w.copy(), base_depth=hp.copy(), crest=hc.copy(),
                          mass=np.asarray(mass, dtype=np.float64),
                          buoyancy=np.asarray(buoy, dtype=np.float64),
                          buoyant_weight=np.asarray(mass * g - buoy, dtype=np.float64),
                          height_cg=np.asarray(zc, dtype=np.float64),
                          inertia=np.asarray(inertia, dtype=np.float64),
                          t=np.asarray(0.5 * w, dtype=np.float64))


def heel_pressure(buoyant_weight: npt.ArrayLike, loads: CaissonLoads, t: npt.ArrayLike,
                  width: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Bearing pressure at the leeward heel by the eccentric-load formula.

    Parameters
    ----------
    buoyant_weight : array_like
        ``W'`` [N/m].
    loads : CaissonLoads
        Wave loads.
    t : array_like
        Distance from the heel to the centre of gravity [m].
    width : array_like
        Full width ``2B`` [m].

    Returns
    -------
    pe : ndarray
        Heel pressure [Pa]; ``inf`` when ``Me <= 0`` (the resultant falls
        outside the base: no equilibrium on the heel).
    te : ndarray
        Distance of the resultant from the heel [m].

    Notes
    -----
    Goda (2000, Sect. 4.2), with ``We = W' - U``, ``Me = W' t - Mu - Mp``,
    ``te = Me / We``:
    ``pe = 2 We / (3 te)`` for ``te <= width/3`` (triangular distribution)
    and ``pe = (2 We / width)(2 - 3 te / width)`` for ``te > width/3``
    (trapezoidal distribution).
    """
    wp, tt, w = np.broadcast_arrays(as_float(buoyant_weight), as_float(t), as_float(width))
    we = wp - loads.U
    me = wp * tt - loads.Mu - loads.Mp
    with np.errstate(divide="ignore", invalid="ignore"):
        te = me / we
        pe = np.where(te <= w / 3.0, 2.0 * we / (3.0 * te), 2.0 * we / w * (2.0 - 3.0 * te / w))
    pe = np.where((me <= 0.0) | (we <= 0.0), np.inf, pe)
    return np.asarray(pe, dtype=np.float64), np.asarray(te, dtype=np.float64)


@dataclass(frozen=True)
class Stability:
    """Safety factors and heel pressure (Goda 2000, Sect. 4.2).

    Attributes
    ----------
    sliding : ndarray
        ``SF_s = mu (W' - U) / P``.
    overturning : ndarray
        ``SF_o = (W' t - Mu) / Mp``.
    heel_pressure : ndarray
        ``pe`` [Pa], see :func:`heel_pressure`.
    te : ndarray
        Distance of the resultant from the heel [m].
    """

    sliding: FloatArray
    overturning: FloatArray
    heel_pressure: FloatArray
    te: FloatArray


def stability(section: CaissonSection, loads: CaissonLoads, friction: npt.ArrayLike) -> Stability:
    """Safety factors against sliding and overturning, and the heel pressure.

    Parameters
    ----------
    section : CaissonSection
        From :func:`section_from_weight` or :func:`section_from_densities`.
    loads : CaissonLoads
        From :func:`caisson_loads`.
    friction : array_like
        Friction coefficient ``mu`` between caisson and mound (Goda: 0.6).

    Returns
    -------
    Stability

    Notes
    -----
    Goda (2000, Sect. 4.2): ``SF_s = mu (W' - U) / P`` and
    ``SF_o = (W' t - Mu) / Mp``; Goda recommends ``SF >= 1.2`` for both.
    """
    mu = as_float(friction)
    wp = section.buoyant_weight
    sf_s = mu * (wp - loads.U) / loads.P
    sf_o = (wp * section.t - loads.Mu) / loads.Mp
    pe, te = heel_pressure(wp, loads, section.t, section.width)
    return Stability(sliding=np.asarray(sf_s, dtype=np.float64),
                     overturning=np.asarray(sf_o, dtype=np.float64), heel_pressure=pe, te=te)
