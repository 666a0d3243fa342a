"""Wave loads on a vertical-breakwater caisson and its equivalent loaded block.

From a site, a design wave and a caisson section to the inputs of the regime
map (numpy only, SI units, vectorised over broadcast arrays):

* :func:`wavelength`, :func:`wavenumber` -- linear dispersion to machine
  precision;
* :func:`design_heights` -- Goda's ``H1/3`` and ``Hmax`` at the wall from
  ``H0'`` and ``T1/3`` (surf zone and nonlinear shoaling);
* :func:`goda_pressures` -- Goda's pressures with Takahashi's impulsive
  coefficient;
* :func:`caisson_loads`, :func:`stability` -- ``P``, ``Mp``, ``U``, ``Mu``,
  safety factors, heel pressure;
* :func:`equivalent_block`, :func:`static_rest_check` -- the loaded block of
  the regime map and its closed-form rest check;
* :func:`analyse_caisson` -- all of the above in one call;
* :func:`wave_duration` -- how long a wave pushes: the duration of Shimosako
  & Takahashi's half-sine force profile.

See :doc:`/waves` (``docs/waves.md``) for every formula with its source.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import attach

if TYPE_CHECKING:  # the real names, for mypy and IDEs; imported on first use at run time
    from .analysis import CaissonAnalysis, Densities, analyse_caisson
    from .block import EquivalentBlock, RestCheck, equivalent_block, static_rest_check
    from .caisson import (
        CaissonLoads,
        CaissonSection,
        Stability,
        caisson_loads,
        heel_pressure,
        section_from_densities,
        section_from_weight,
        stability,
    )
    from .dispersion import deep_water_wavelength, wavelength, wavenumber
    from .heights import (
        HMAX_FACTOR,
        DesignHeights,
        breaker_height,
        design_heights,
        given_heights,
        linear_shoaling_coefficient,
        shoaling_coefficient,
    )
    from .pressure import (
        GODA_ROTATION_DEG,
        GodaPressures,
        effective_angle,
        goda_pressures,
        impulsive_coefficient,
    )
    from .timing import wave_duration

__all__ = [
    "GODA_ROTATION_DEG", "HMAX_FACTOR", "CaissonAnalysis", "CaissonLoads", "CaissonSection",
    "Densities", "DesignHeights", "EquivalentBlock", "GodaPressures", "RestCheck", "Stability",
    "analyse_caisson", "breaker_height", "caisson_loads", "deep_water_wavelength", "design_heights",
    "effective_angle", "equivalent_block", "given_heights", "goda_pressures", "heel_pressure",
    "impulsive_coefficient", "linear_shoaling_coefficient", "section_from_densities",
    "section_from_weight", "shoaling_coefficient", "stability", "static_rest_check",
    "wave_duration", "wavelength", "wavenumber",
]


if not TYPE_CHECKING:  # hidden from mypy, so that an unknown name is an error, not Any
    __getattr__, __dir__ = attach(__name__, __file__)
