"""A caisson's equivalent block under its design wave: the :class:`Block` and :class:`Pulse` of one run.

Goda's procedure (:func:`regimemap.waves.analyse_caisson`) gives the loads of
the design wave ``Hmax`` and the equivalent loaded block
(:class:`regimemap.waves.EquivalentBlock`: ``B``, ``gamma``, ``k = P/(m g)``,
``k'``, ``buoyancy`` beta_b, ``uplift_ratio`` nu = U/P, its arm ``uplift_arm`` e_u,
``gyration`` i and ``mu``).  The run puts that block under the force history
of Shimosako & Takahashi (1999) for that wave, the one
:mod:`regimemap.lifetime` uses for every wave of a storm::

    P(t) = P(Hmax) sin(pi t / tau0),   U(t) = U(Hmax) sin(pi t / tau0),
    tau0 = (0.5 - Hmax/(8 h)) T1/3                   (regimemap.waves.wave_duration)

that is a half-sine pulse of peak ``k = P(Hmax)/(m g)`` (the block's ``k``)
and duration ``tau0``; the uplift follows the force in phase because the
block's uplift is ``U = nu F`` (``u = 0``).

**No added mass.** The block of :mod:`regimemap.dynamics` is rigid and dry:
its inertia is the caisson's mass ``m`` (and :math:`I = m B^2 i^2`) alone.  The
lifetime model adds the mass of the water moved with the caisson,
:math:`M_a = 1.0855 \\rho_w h'^2` per metre (:func:`regimemap.lifetime.added_mass`),
which slows a slide; a run here slides further than the lifetime model's
``half_sine_slide`` of the same wave (by about ``M_a/m``, while both stop
within the wave).  With ``M = m`` the two agree (tests/dynamics/test_design_wave.py).

References
----------
Shimosako, K. & Takahashi, S. (1999). Application of deformation-based
reliability design for coastal structures. Proc. Coastal Structures '99.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from ..waves import CaissonAnalysis, wave_duration
from .block import Block, G
from .limits import INPUT_LIMITS, check_gyration, check_net_weight
from .pulses import Pulse

__all__ = ["DESIGN_INPUTS", "DESIGN_UNITS", "NO_ADDED_MASS", "PROFILE", "design_wave_inputs",
           "design_wave_numbers", "design_wave_run"]

#: The inputs of a run (named as in :data:`regimemap.dynamics.limits.INPUT_LIMITS`, the options of
#: ``regimemap simulate``) that the design wave supplies.
DESIGN_INPUTS: tuple[str, ...] = ("gamma", "half_width", "kprime", "mu", "buoyancy", "uplift",
                                  "uplift_ratio", "uplift_arm", "gyration", "pulse", "k_peak",
                                  "duration")

#: Units of the dimensional numbers of :func:`design_wave_numbers` (the others are dimensionless);
#: those of ``regimemap caisson --json``.
DESIGN_UNITS: dict[str, str] = {
    "Hmax": "m", "H13": "m", "depth": "m", "period": "s", "tau0": "s", "P": "kN/m", "U": "kN/m",
    "W": "kN/m", "weight": "kN/m", "mass": "t/m", "added_mass": "t/m", "B": "m", "H_C": "m",
}

#: The force history of the run, in words.
PROFILE = ("P(t) = P sin(pi t/tau0), U(t) = U sin(pi t/tau0) for 0 <= t <= tau0, "
           "tau0 = (0.5 - Hmax/(8 h)) T1/3 (Shimosako & Takahashi 1999)")

#: What the run leaves out that the lifetime model has.
NO_ADDED_MASS = ("rigid block: no added mass of water (regimemap.lifetime adds M_a = 1.0855 rho_w h'^2 "
                 "per metre, which shortens a slide)")

#: What each checked input is, for the messages.
_WHAT = {
    "gamma": "gamma = H_C/B of the caisson",
    "half_width": "the half width B of the caisson",
    "kprime": "k' = (Mp/P - H_C)/H_C, the height of the wave force above the centre of mass",
    "mu": "the friction mu ([caisson] friction)",
    "k_peak": "k = P/(m g) of the design wave",
    "buoyancy": "the buoyancy rho_w g V/(m g)",
    "uplift_ratio": "the uplift ratio U/P",
    "uplift_arm": "the uplift arm e_u = (Mu/U - B)/B",
}


def _check(name: str, values: npt.NDArray[np.float64]) -> None:
    lim = INPUT_LIMITS[name]
    for v in values.ravel().tolist():
        if not lim.contains(v):
            raise ValueError(f"{_WHAT[name]} is {v:.6g}, outside the range of a run ({name} must be "
                             f"{lim.text})")


def _check_duration(tau0: npt.NDArray[np.float64], Hmax: npt.ArrayLike, depth: npt.ArrayLike,
                    period: npt.ArrayLike) -> None:
    lim = INPUT_LIMITS["duration"]
    for t, H, h, T in zip(*(np.ravel(a).tolist() for a in np.broadcast_arrays(tau0, Hmax, depth, period)),
                          strict=True):
        if not lim.contains(t):
            why = " (Hmax >= 4 h: the formula gives no push)" if t <= 0.0 else ""
            raise ValueError(f"the design wave's duration tau0 = (0.5 - Hmax/(8 h)) T1/3 = {t:.6g} s "
                             f"(Hmax = {H:.6g} m, [site] depth = {h:g} m, [wave] period = {T:g} s) is "
                             f"outside the range of a run{why}: duration must be {lim.text} s")


def design_wave_run(analysis: CaissonAnalysis, depth: npt.ArrayLike, period: npt.ArrayLike,
                    g: float = G) -> tuple[Block, Pulse]:
    """The equivalent block of a caisson and the half-sine pulse of its design wave.

    Parameters
    ----------
    analysis : CaissonAnalysis
        Goda's procedure for the caisson (:func:`regimemap.waves.analyse_caisson`, or
        ``read_design(path).analyse()``); arrays give one run each.
    depth : array_like
        Water depth ``h`` at the wall [m] (``[site] depth``).
    period : array_like
        Significant period ``T1/3`` [s] (``[wave] period``).
    g : float
        Gravity [m/s^2]: the one the analysis was made with.

    Returns
    -------
    (Block, Pulse)
        The block: ``B``, ``gamma``, ``mu``, ``kprime``, ``i2 = i^2``, and the
        ``buoyancy``, ``uplift`` (0), ``uplift_ratio`` (U/P) and ``uplift_arm`` of the
        equivalent block; the pulse: half-sine of peak
        ``k = P/(m g)`` and duration ``tau0 = (0.5 - Hmax/(8 h)) T1/3``
        (:func:`regimemap.waves.wave_duration`).  No added mass of water (module docstring).

    Raises
    ------
    ValueError
        If a number of the block or pulse is outside the range of a run
        (:data:`regimemap.dynamics.limits.INPUT_LIMITS`; e.g. ``tau0 <= 0`` when
        ``Hmax >= 4 h``), naming it and its formula.

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> d = parse_design(example_design_text())
    >>> block, pulse = design_wave_run(d.analyse(), d.site.depth, d.wave.period)
    >>> round(float(pulse.k_peak), 4), round(float(pulse.duration), 3), pulse.shape
    (0.2776, 4.564, 'half-sine')
    """
    b = analysis.block
    tau0 = np.asarray(wave_duration(analysis.heights.Hmax, depth, period), dtype=np.float64)
    checked = {"gamma": b.gamma, "half_width": b.B, "kprime": b.kprime, "mu": b.mu, "k_peak": b.k,
               "buoyancy": b.buoyancy, "uplift_ratio": b.uplift_ratio, "uplift_arm": b.uplift_arm}
    for name, values in checked.items():
        _check(name, np.asarray(values, dtype=np.float64))
    _check_duration(tau0, analysis.heights.Hmax, depth, period)
    beta = np.asarray(b.buoyancy, dtype=np.float64)
    gamma = np.asarray(b.gamma, dtype=np.float64)
    for be, ga, i in zip(np.ravel(beta).tolist(), np.ravel(gamma).tolist(),
                         np.ravel(np.broadcast_to(b.gyration, gamma.shape)).tolist(), strict=True):
        try:
            check_net_weight(be, 0.0)
            check_gyration(i, ga)
        except ValueError as exc:
            raise ValueError(f"the caisson's section is outside the range of a run: {exc}") from None
    block = Block(B=b.B, gamma=b.gamma, mu=b.mu, kprime=b.kprime, i2=np.asarray(b.gyration) ** 2,
                  buoyancy=b.buoyancy, uplift=b.uplift, uplift_ratio=b.uplift_ratio,
                  uplift_arm=b.uplift_arm, g=g)
    return block, Pulse.half_sine(b.k, tau0)


def _one(x: Any) -> float:
    a = np.asarray(x, dtype=np.float64)
    if a.shape != ():
        raise ValueError("design_wave_inputs and design_wave_numbers take one caisson (scalar inputs)")
    return float(a) + 0.0


def design_wave_inputs(analysis: CaissonAnalysis, depth: float, period: float) -> dict[str, Any]:
    """The inputs of a run (:data:`DESIGN_INPUTS`) that the design wave of one caisson supplies.

    The values of :func:`design_wave_run`'s block and pulse, by the names of
    :data:`regimemap.dynamics.limits.INPUT_LIMITS` (the options of ``regimemap simulate``):
    ``gamma``, ``half_width`` (m), ``kprime``, ``mu``, ``buoyancy``, ``uplift`` (0),
    ``uplift_ratio``, ``uplift_arm``, ``gyration`` (i, over B), ``pulse`` (``"half-sine"``),
    ``k_peak`` and ``duration`` (tau0, s); floats.
    """
    b = analysis.block
    return {"gamma": _one(b.gamma), "half_width": _one(b.B), "kprime": _one(b.kprime), "mu": _one(b.mu),
            "buoyancy": _one(b.buoyancy), "uplift": _one(b.uplift), "uplift_ratio": _one(b.uplift_ratio),
            "uplift_arm": _one(b.uplift_arm), "gyration": _one(b.gyration), "pulse": "half-sine",
            "k_peak": _one(b.k),
            "duration": _one(wave_duration(analysis.heights.Hmax, depth, period))}


def design_wave_numbers(analysis: CaissonAnalysis, depth: float, period: float,
                        g: float = G) -> dict[str, float]:
    """Where a design-wave run's numbers come from, for one caisson (unrounded).

    Keys (units :data:`DESIGN_UNITS`, those of ``regimemap caisson --json``): the design wave
    ``Hmax``, ``H13``, the ``depth`` h and ``period`` T1/3, the pulse's duration ``tau0``, Goda's
    ``P`` and ``U`` (the peaks of the force and of the uplift), the buoyant weight ``W`` (W'),
    the dry ``weight`` m g and ``mass`` m, ``added_mass`` (0: the rigid block has none), ``B``,
    ``H_C`` and the block's ``gamma``, ``k``, ``kprime``, ``buoyancy``, ``uplift_ratio``,
    ``uplift_arm``, ``gyration`` and ``mu``.
    """
    a, b = analysis, analysis.block
    mass = _one(a.section.mass)
    return {
        "Hmax": _one(a.heights.Hmax), "H13": _one(a.heights.H13), "depth": _one(depth),
        "period": _one(period), "tau0": _one(wave_duration(a.heights.Hmax, depth, period)),
        "P": _one(a.loads.P) / 1e3, "U": _one(a.loads.U) / 1e3,
        "W": _one(a.section.buoyant_weight) / 1e3, "weight": mass * g / 1e3, "mass": mass / 1e3,
        "added_mass": 0.0, "B": _one(b.B), "H_C": _one(b.H), "gamma": _one(b.gamma), "k": _one(b.k),
        "kprime": _one(b.kprime), "buoyancy": _one(b.buoyancy), "uplift_ratio": _one(b.uplift_ratio),
        "uplift_arm": _one(b.uplift_arm), "gyration": _one(b.gyration), "mu": _one(b.mu),
    }


