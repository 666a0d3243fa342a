"""From site, design wave and caisson section to loads, safety factors and the loaded block."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ..records.htmltable import html_table
from ..records.numbers import number_range
from ._types import RHO_SEAWATER, G, as_float
from .block import EquivalentBlock, equivalent_block
from .caisson import (
    CaissonLoads,
    CaissonSection,
    Stability,
    caisson_loads,
    section_from_densities,
    section_from_weight,
    stability,
)
from .heights import HMAX_FACTOR, DesignHeights, design_heights, given_heights
from .pressure import GodaPressures, goda_pressures

__all__ = ["CaissonAnalysis", "Densities", "analyse_caisson"]


@dataclass(frozen=True)
class Densities:
    """Densities of a filled caisson, see :func:`section_from_densities`.

    Attributes
    ----------
    concrete_fraction : float
        Area fraction of concrete in the section, 0..1.
    concrete : float
        Concrete density [kg/m^3].
    fill : float
        Fill density below still water (saturated) [kg/m^3].
    fill_above : float or None
        Fill density above still water [kg/m^3]; None: same as ``fill``.
    """

    concrete_fraction: float
    concrete: float
    fill: float
    fill_above: float | None = None


@dataclass(frozen=True)
class CaissonAnalysis:
    """Everything computed by :func:`analyse_caisson`."""

    heights: DesignHeights
    pressures: GodaPressures
    loads: CaissonLoads
    section: CaissonSection
    stability: Stability
    block: EquivalentBlock

    # -- display: a readable repr and a table for Jupyter -------------------------------------
    def _rows(self) -> list[tuple[str, str, str]]:
        """(quantity, value or range, unit and meaning) of the main results."""
        h, ld, sec, st, b = self.heights, self.loads, self.section, self.stability, self.block

        def r(values: npt.ArrayLike, scale: float = 1.0) -> str:
            return number_range((np.asarray(values, dtype=float) * scale).ravel())

        return [
            ("H1/3", r(h.H13), "m, significant wave height at the wall"),
            ("Hmax", r(h.Hmax), "m, design wave height"),
            ("P", r(ld.P, 1e-3), "kN/m, horizontal wave force"),
            ("U", r(ld.U, 1e-3), "kN/m, uplift force"),
            ("W'", r(sec.buoyant_weight, 1e-3), "kN/m, buoyant weight"),
            ("SF sliding", r(st.sliding), "mu (W' - U) / P (Goda: >= 1.2)"),
            ("SF overturning", r(st.overturning), "(W' t - M_U) / M_P (Goda: >= 1.2)"),
            ("heel pressure", r(st.heel_pressure, 1e-3), "kPa"),
            ("gamma", r(b.gamma), "H_C / B of the equivalent block"),
            ("k", r(b.k), "P / (m g)"),
            ("k'", r(b.kprime), "height of the wave force's resultant above C / H_C"),
            ("beta", r(b.buoyancy), "buoyancy / dry weight"),
            ("nu", r(b.uplift_ratio), "uplift ratio U / P"),
            ("mu", r(b.mu), "friction coefficient"),
        ]

    def _count(self) -> int:
        return int(np.asarray(self.block.k).size)

    def __repr__(self) -> str:
        """Two lines: the wave, the loads and the safety factors; the equivalent block."""
        v = {name: value for name, value, _ in self._rows()}
        w, kp = v["W'"], v["k'"]
        n = self._count()
        head = "" if n == 1 else f"{n} conditions: "
        return (f"CaissonAnalysis({head}Hmax={v['Hmax']} m, P={v['P']} kN/m, "
                f"U={v['U']} kN/m, W'={w} kN/m; SF sliding {v['SF sliding']}, "
                f"overturning {v['SF overturning']};\n  block gamma={v['gamma']}, k={v['k']}, "
                f"k'={kp}, beta={v['beta']}, nu={v['nu']}, mu={v['mu']})")

    def _repr_html_(self) -> str:
        """Goda's results and the equivalent block as a small table (Jupyter's rich display)."""
        n = self._count()
        return html_table(self._rows(), caption="Caisson analysis (Goda)"
                          + ("" if n == 1 else f", {n} conditions"),
                          header=("", "value", ""))


# Goda's design procedure takes one keyword-only argument per input of the method (site, wave,
# section, friction, options), named as in the design file and Goda (2000) (PLR0913 accepted here).
def analyse_caisson(*, depth: npt.ArrayLike, armour_depth: npt.ArrayLike, seabed_slope: npt.ArrayLike,  # noqa: PLR0913
                    period: npt.ArrayLike, width: npt.ArrayLike, base_depth: npt.ArrayLike,
                    crest: npt.ArrayLike, friction: npt.ArrayLike,
                    H0: npt.ArrayLike | None = None, H13: npt.ArrayLike | None = None,
                    Hmax: npt.ArrayLike | None = None, angle_deg: npt.ArrayLike = 0.0,
                    rotation_deg: npt.ArrayLike = 0.0, berm_width: npt.ArrayLike = 0.0,
                    buoyant_weight: npt.ArrayLike | None = None,
                    densities: Densities | None = None, impulsive: bool = True,
                    lambdas: tuple[float, float, float] = (1.0, 1.0, 1.0),
                    hmax_factor: float = HMAX_FACTOR, rho_w: float = RHO_SEAWATER,
                    g: float = G) -> CaissonAnalysis:
    """Goda's design procedure for an upright caisson, vectorised.

    Parameters
    ----------
    depth, armour_depth, seabed_slope : array_like
        ``h`` [m], ``d`` [m], ``tan theta`` of the sea bed.
    period : array_like
        ``T1/3`` [s].
    width, base_depth, crest, berm_width : array_like
        Full width ``2B``, ``h'``, ``hc``, ``BM`` [m].
    friction : array_like
        ``mu``.
    H0 : array_like, optional
        Equivalent deep-water significant height ``H0'`` [m]: heights by
        :func:`design_heights` (Goda 2000, Sect. 3.6 and 4.2).
    H13, Hmax : array_like, optional
        Heights at the wall given directly (instead of ``H0``).
    angle_deg, rotation_deg : array_like, optional
        Wave angle from the normal and its rotation toward the normal
        (Goda 2000, Sect. 4.2: up to 15 degrees) [degrees].
    buoyant_weight : array_like, optional
        ``W'`` [N/m] -- or ``densities``; exactly one of them.
    densities : Densities, optional
        Concrete fraction and densities of the caisson.
    impulsive : bool, optional
        Takahashi's impulsive coefficient on (default) or off.
    lambdas : tuple of float, optional
        ``(lambda1, lambda2, lambda3)`` (Takahashi 2002).
    hmax_factor : float, optional
        ``Hmax / (Ks H0')`` outside the surf zone (1.8).
    rho_w, g : float, optional
        Sea-water density [kg/m^3], gravity [m/s^2].

    Returns
    -------
    CaissonAnalysis
    """
    if H0 is not None:
        if H13 is not None or Hmax is not None:
            raise ValueError("give either H0 or (H13 and Hmax), not both")
        heights = design_heights(H0, period, depth, seabed_slope, g=g, hmax_factor=hmax_factor)
    elif H13 is not None and Hmax is not None:
        heights = given_heights(H13, Hmax, depth, seabed_slope)
    else:
        raise ValueError("give either H0 or both H13 and Hmax")
    if (buoyant_weight is None) == (densities is None):
        raise ValueError("give exactly one of buoyant_weight and densities")
    pressures = goda_pressures(Hmax=heights.Hmax, period=period, depth=depth, hb=heights.hb,
                               armour_depth=armour_depth, base_depth=base_depth, crest=crest,
                               berm_width=berm_width, angle_deg=angle_deg,
                               rotation_deg=rotation_deg, impulsive=impulsive, lambdas=lambdas,
                               rho_w=rho_w, g=g)
    loads = caisson_loads(pressures, base_depth, width)
    if densities is not None:
        section = section_from_densities(
            width, base_depth, crest, concrete_fraction=densities.concrete_fraction,
            concrete_density=densities.concrete, fill_density=densities.fill,
            fill_density_above=densities.fill_above, rho_w=rho_w, g=g)
    else:
        assert buoyant_weight is not None
        section = section_from_weight(as_float(buoyant_weight), width, base_depth, crest,
                                      rho_w=rho_w, g=g)
    shape = np.broadcast_shapes(loads.P.shape, section.mass.shape, np.shape(friction))
    section = CaissonSection(*(np.broadcast_to(a, shape) for a in (
        section.width, section.base_depth, section.crest, section.mass, section.buoyancy,
        section.buoyant_weight, section.height_cg, section.inertia, section.t)))
    loads = CaissonLoads(*(np.broadcast_to(a, shape) for a in (loads.P, loads.Mp, loads.U, loads.Mu)))
    return CaissonAnalysis(heights=heights, pressures=pressures, loads=loads, section=section,
                           stability=stability(section, loads, friction),
                           block=equivalent_block(section, loads, friction, g=g))
