"""The records of the dynamics' workflows: one run past initiation (:class:`SimulationRecord`),
an outcome map (:class:`OutcomeRecord`) and one of the figures D.1-D.3
(:class:`DynamicsFigureRecord`).

Plain data made by :func:`regimemap.workflows.run_simulation`,
:func:`~regimemap.workflows.run_outcome` and :func:`~regimemap.workflows.run_dynamics_figure`,
written by :mod:`regimemap.io` and drawn by :mod:`regimemap.drawing`; defined here, beside the
data they hold, so that io (the layer above) may name them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import NDArray

from ..records.fields import Field, Record
from ..records.notices import Notice

if TYPE_CHECKING:  # pragma: no cover
    from ..dynamics.block import Block
    from ..dynamics.outcome import OutcomeMap
    from ..dynamics.presets import DynamicsFigure
    from ..dynamics.pulses import Pulse
    from ..dynamics.results import Simulation
    from ..records.checks import Check
    from .file import MapOptions

__all__ = ["DynamicsFigureRecord", "OutcomeRecord", "SimulationRecord"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class SimulationRecord(Record):
    """One run of :func:`run_simulation`: its inputs, what a designer checks, its warnings, the run.

    Attributes
    ----------
    block : Block
        The block of the run (one run: scalar fields).
    pulse : Pulse
        Its force pulse.
    inputs : dict
        The inputs as given, by the names of ``regimemap simulate``'s options: ``gamma``,
        ``half_width`` (m), ``kprime``, ``mu``, ``pulse`` (the shape, ``"file"`` for a sampled
        history), ``k_peak``, ``duration`` (s), ``pulse_file``, ``restitution``, ``buoyancy``,
        ``uplift``, ``uplift_ratio``, ``uplift_arm``, ``gyration``, ``design`` (the design
        file) and ``min_rotation`` (degrees); None where not given.
    design : str or None
        The design file the block and the pulse came from.
    design_numbers : dict or None
        Where a design file's numbers came from
        (:func:`regimemap.dynamics.design_wave.design_wave_numbers`: Hmax, tau0, P, U ...).
    checks : tuple of Check
        The design file's requirements: Goda's sliding and overturning safety factors of the
        design wave against ``[caisson] required_*`` (:func:`regimemap.caisson.report.stability_checks`).
    p, alpha, H : float
        Frequency parameter (rad/s), slenderness angle atan(1/gamma) (rad) and height of the
        centre of mass above the base (m).
    housner_ratio : float
        Housner's (I + m(H^2 - B^2))/(I + m(H^2 + B^2)); <= 0 for a squat block.
    impact_ratio : float or None
        The ratio of a rocking impact used: ``restitution`` if given, else Housner's; None when
        Housner's does not apply (a squat block: its rocking ends at the first impact).
    k_peak, duration, omega_p : float
        The pulse's peak |k|, duration (s) and circular frequency (rad/s).
    min_rotation : float
        Rocking counts only above this largest rotation (degrees).
    simulation : Simulation
        The run (its time history when asked for).
    notices : tuple of Notice
        ``implausible-value`` (a design file's value valid but unlikely, a unit slip),
        ``still-moving`` (not at rest at the time limit), ``unresolved-contact`` (steps with no
        admissible contact state).
    """

    block: Block
    pulse: Pulse
    inputs: dict[str, Any]
    design: str | None
    design_numbers: dict[str, float] | None
    checks: tuple[Check, ...]
    p: float
    alpha: float
    H: float
    housner_ratio: float
    impact_ratio: float | None
    k_peak: float
    duration: float
    omega_p: float
    min_rotation: float
    simulation: Simulation
    notices: tuple[Notice, ...] = ()

    CAPTION: ClassVar[str] = "regimemap simulate: one run past initiation"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("p", "p", "rad/s", "frequency parameter sqrt(m g R / I_O)"),
        Field("alpha", "α", "rad", "slenderness angle atan(1/γ)"),
        Field("H", "H", "m", "height of the centre of mass above the base"),
        Field("housner_ratio", "Housner's ratio", "", "(I + m(H² − B²))/(I + m(H² + B²))"),
        Field("impact_ratio", "impact ratio", "", "θ̇+/θ̇− of a rocking impact (None: not applicable)"),
        Field("k_peak", "k_peak", "", "peak of the pulse, F/(m g)"),
        Field("duration", "duration", "s", "duration of the pulse"),
        Field("omega_p", "ω_p", "rad/s", "circular frequency of the pulse"),
        Field("category", "outcome", "", "rest, slide only, rock only, slide-rock, overturned, still moving"),
        Field("max_rotation", "max |θ|", "rad", "largest rotation"),
        Field("residual_slide", "residual slide", "m",
              "of the base, positive towards O (None: still moving)"),
    )

    @property
    def derived(self) -> dict[str, float | None]:
        """The quantities a designer checks, by name: p, alpha, H, impact_ratio, housner_ratio,
        k_peak, duration, omega_p."""
        return {"p": self.p, "alpha": self.alpha, "H": self.H, "impact_ratio": self.impact_ratio,
                "housner_ratio": self.housner_ratio, "k_peak": self.k_peak, "duration": self.duration,
                "omega_p": self.omega_p}

    @property
    def category(self) -> str:
        """The outcome of the run, rocking counted above :attr:`min_rotation`."""
        from ..dynamics.stepper import CATEGORY_LABELS

        return CATEGORY_LABELS[int(self.simulation.categories(math.radians(self.min_rotation))[0])]

    @property
    def overturned(self) -> bool:
        """Whether the block overturned."""
        return bool(self.simulation.overturned[0])

    @property
    def finished(self) -> bool:
        """Whether the run ended at rest or overturned (not at the time limit)."""
        return bool(self.simulation.settled[0] or self.simulation.overturned[0])

    @property
    def max_rotation(self) -> float:
        """The largest |theta| (rad)."""
        return float(self.simulation.max_rotation[0])

    @property
    def residual_slide(self) -> float | None:
        """The residual slide of the base (m, positive towards O); None while still moving."""
        return float(self.simulation.residual_slide[0]) if self.finished else None


@dataclass(frozen=True)
class OutcomeRecord(Record):
    """An outcome map of :func:`run_outcome`: its inputs, the map and what is derived from it.

    Attributes
    ----------
    options : MapOptions
        The inputs: the pulse shape, the two swept inputs (columns, rows) and their values,
        the fixed ones (:func:`regimemap.motion.file.map_options`).
    restitution : float or None
        The ratio of a rocking impact; None is Housner's plastic impact.
    min_rotation : float
        Rocking counts only above this largest rotation (degrees).
    block : Block
        The block of the map (a swept field holds its first value).
    outcome : OutcomeMap
        The map, its axes named and valued as the swept inputs (``first_name``, ``first_values``
        ...), its boundaries refined unless ``refine=False``.
    counts : dict
        The number of cells of each category, by label (every label, zeros included).
    dimensionless_axes : dict
        With ``dimensionless``: the swept inputs among k_peak, duration and omega_p by name, their
        values as omega_p/p or k_peak/tan(alpha) (Makris & Roussos 2000).
    notices : tuple of Notice
    """

    options: MapOptions
    restitution: float | None
    min_rotation: float
    block: Block
    outcome: OutcomeMap
    counts: dict[str, int]
    dimensionless_axes: dict[str, FloatArray] = field(default_factory=dict)
    notices: tuple[Notice, ...] = ()

    CAPTION: ClassVar[str] = "regimemap outcome: an outcome map over two swept inputs"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("options.shape", "pulse", "", "shape of the force pulse"),
        Field("options.swept", "swept", "", "the inputs along the columns and the rows"),
        Field("n_runs", "runs", "", "cells of the grid"),
        Field("counts", "categories", "", "cells of each category"),
        Field("outcome.seconds", "grid time", "s", "time of the grid's runs"),
        Field("outcome.refined", "refined", "", "boundaries refined by bisection to 1/1000 of each axis"),
    )

    @property
    def n_runs(self) -> int:
        """The cells (runs) of the grid."""
        return self.options.n_runs

    @property
    def inputs(self) -> dict[str, Any]:
        """The inputs not swept, as the data files hold them: ``pulse`` (the shape), the fixed
        values given, ``restitution`` and ``min_rotation`` (degrees) when given."""
        out: dict[str, Any] = {"pulse": self.options.shape}
        out.update({n: v for n, v in self.options.fixed.items() if v is not None})
        if self.restitution is not None:
            out["restitution"] = self.restitution
        if self.min_rotation:
            out["min_rotation"] = self.min_rotation
        return out

    @property
    def extra_axes(self) -> dict[str, FloatArray]:
        """The dimensionless axes as the data files name them (``k_peak_dimensionless`` ...)."""
        return {f"{n}_dimensionless": v for n, v in self.dimensionless_axes.items()}


@dataclass(frozen=True)
class DynamicsFigureRecord(Record):
    """One of the figures D.1-D.3 of :func:`run_dynamics_figure`: its definition and its map.

    Attributes
    ----------
    figure : DynamicsFigure
        The figure's block, pulse and swept inputs (:data:`regimemap.dynamics.presets.DYNAMICS_FIGURES`).
    outcome : OutcomeMap
        Its map, boundaries refined.
    x, y : ndarray
        The values of the map's columns and rows as drawn (dimensionless for D.1 and D.2).
    from_cache : bool
        Whether the map was read from the cache.
    notices : tuple of Notice
    """

    figure: DynamicsFigure
    outcome: OutcomeMap
    x: FloatArray
    y: FloatArray
    from_cache: bool = False
    notices: tuple[Notice, ...] = ()

    CAPTION: ClassVar[str] = "regimemap dynamics-figures: one figure's outcome map"
    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("figure.id", "figure", "", "D.1, D.2 or D.3"),
        Field("outcome.category.size", "runs", "", "cells of the grid"),
        Field("refine_runs", "boundary runs", "", "runs of the bisection of the boundaries"),
        Field("from_cache", "from the cache", "", "whether the map was read from the cache"),
    )

    @property
    def data(self) -> tuple[OutcomeMap, FloatArray, FloatArray]:
        """The map and the values of its columns and rows as drawn."""
        return self.outcome, self.x, self.y

    @property
    def refine_runs(self) -> int:
        """The runs of the bisection of the boundaries (0 when not refined)."""
        return self.outcome.crossings.runs if self.outcome.crossings is not None else 0
