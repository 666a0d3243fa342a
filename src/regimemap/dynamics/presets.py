"""The outcome maps of the report's figures D.1-D.3: what ``regimemap dynamics-figures`` computes.

=====  ===========================================================================
D.1    Overturning spectrum of a half-sine pulse (Makris & Roussos 2000): the
       block of docs/dynamics.md (B = 0.2 m, gamma = 3, mu = 5: no sliding), axes
       omega_p/p and k_p/tan(alpha); overturning above a threshold that rises with
       omega_p/p.
D.2    Overturning spectrum of a one-sine pulse (Zhang & Makris 2001, type A):
       p = 2.14 rad/s, alpha = 0.25, impact ratio 0.9 (the verification case of
       docs/dynamics.md); overturning with and without impact, and the safe
       region between them.
D.3    A vertical-breakwater caisson (20 m wide, 22 m high, mu = 0.6, buoyancy
       0.35, uplift 0.25 F) under the breaking-wave pulse: rest or slide, and
       how far it slides.
=====  ===========================================================================

Each map is computed on a grid coarser than ``bench/bench_dynamics.py``'s
200 x 200 (the sizes below), so that ``make figures`` stays within about a
minute, and its boundaries are refined by bisection to 10^-3 of each axis
(:func:`regimemap.dynamics.outcome.refine_map`): the regions are drawn as
polygons bounded by them, not as cells
(:func:`regimemap.motion.figures.presets.dynamics_figure`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .block import Block
from .outcome import Bars, MapRuns, OutcomeMap, dimensionless_values, from_dimensionless, staged_outcome_map

__all__ = ["DynamicsFigure", "DYNAMICS_FIGURES", "DYNAMICS_FIGURE_IDS"]


@dataclass(frozen=True)
class DynamicsFigure:
    """One outcome-map figure: the block, the pulse, the two swept inputs and the caption.

    Attributes
    ----------
    id : str
        ``D.1`` ...; the files are ``dyn-<id>.<format>``.
    caption : str
    block : dict
        Keyword arguments of :class:`regimemap.dynamics.Block` (or of
        :meth:`Block.from_frequency` when ``from_frequency`` is set).
    shape : str
        Pulse shape.
    first, second : (name, start, stop, count)
        The swept inputs (columns, rows): ``k_peak``, ``duration`` in physical units,
        or ``omega_ratio`` (omega_p/p) and ``k_ratio`` (k_p/tan alpha) in dimensionless ones.
    restitution : float or None
    from_frequency : (p, alpha) or None
    title : str
    """

    id: str
    caption: str
    block: dict[str, float]
    shape: str
    first: tuple[str, float, float, int]
    second: tuple[str, float, float, int]
    title: str
    restitution: float | None = None
    from_frequency: tuple[float, float] | None = None
    params: dict[str, float] = field(default_factory=dict)

    def filename(self, fmt: str) -> str:
        """``dyn-D.1.png`` and the like."""
        return f"dyn-{self.id}.{fmt}"

    def make_block(self) -> Block:
        """The block of the figure."""
        if self.from_frequency is not None:
            p, alpha = self.from_frequency
            return Block.from_frequency(p, alpha, **self.block)
        return Block(**self.block)

    @property
    def dimensionless(self) -> bool:
        return self.first[0] == "omega_ratio"

    def axes(self) -> tuple[MapRuns, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The runs of the map, the swept values of its columns and rows, and their values as
        drawn."""
        blk = self.make_block()
        a = np.linspace(*self.first[1:3], self.first[3])
        b = np.linspace(*self.second[1:3], self.second[3])
        params = self.params or None
        if self.dimensionless:
            B, gamma = float(np.asarray(blk.B)), float(np.asarray(blk.gamma))
            k, w = from_dimensionless(a, b, B, gamma, blk.g)
            # from_dimensionless assumes the uniform block's p and alpha: the figure's blocks are uniform
            runs = MapRuns(blk, self.shape, "omega_p", "k_peak", restitution=self.restitution,
                           pulse_params=params)
            return (runs, w, k, dimensionless_values("omega_p", w, blk, self.shape),
                    dimensionless_values("k_peak", k, blk, self.shape))
        runs = MapRuns(blk, self.shape, self.first[0], self.second[0], restitution=self.restitution,
                       pulse_params=params)
        return runs, a, b, a, b

    def compute(self, bars: Bars | None = None) -> tuple[OutcomeMap, np.ndarray, np.ndarray]:
        """The outcome map, its boundaries refined, and the values of its columns and rows as drawn.

        ``bars(total, description)`` gives a progress bar to each stage
        (:func:`regimemap.dynamics.outcome.staged_outcome_map`).
        """
        runs, v1, v2, x, y = self.axes()
        return staged_outcome_map(runs, v1, v2, bars=bars), x, y


DYNAMICS_FIGURES: dict[str, DynamicsFigure] = {f.id: f for f in (
    DynamicsFigure(
        id="D.1",
        caption="Overturning spectrum of a half-sine pulse (Makris & Roussos 2000): B = 0.2 m, gamma = 3, "
                "mu = 5, Housner's impact ratio; omega_p/p 0.5-10, k_p/tan(alpha) 0.25-8 (96 x 80 runs)",
        block={"B": 0.2, "gamma": 3.0, "mu": 5.0}, shape="half-sine",
        first=("omega_ratio", 0.5, 10.0, 96), second=("k_ratio", 0.25, 8.0, 80),
        title="D.1  half-sine pulse: B = 0.2 m, γ = 3, μ = 5 (no sliding)"),
    DynamicsFigure(
        id="D.2",
        caption="Overturning spectrum of a one-sine pulse (Zhang & Makris 2001, type A): p = 2.14 rad/s, "
                "alpha = 0.25, impact ratio 0.9, mu = 5; omega_p/p 0.5-10, k_p/tan(alpha) 0.25-12 "
                "(96 x 96 runs)",
        block={"mu": 5.0}, from_frequency=(2.14, 0.25), restitution=0.9, shape="one-sine",
        first=("omega_ratio", 0.5, 10.0, 96), second=("k_ratio", 0.25, 12.0, 96),
        title="D.2  one-sine pulse: p = 2.14 rad/s, α = 0.25, impact ratio 0.9, μ = 5"),
    DynamicsFigure(
        id="D.3",
        caption="Caisson (B = 10 m, gamma = 1.1, mu = 0.6, k' = -0.1, buoyancy 0.35, uplift 0.25 F) under "
                "the breaking-wave pulse; k_peak 0.1-1.6, duration 0.5-6 s (61 x 45 runs)",
        block={"B": 10.0, "gamma": 1.1, "mu": 0.6, "kprime": -0.1, "buoyancy": 0.35, "uplift_ratio": 0.25},
        shape="breaking", first=("k_peak", 0.1, 1.6, 61), second=("duration", 0.5, 6.0, 45),
        title="D.3  caisson under a breaking-wave pulse\nB = 10 m, γ = 1.1, μ = 0.6, k' = −0.1, "
              "buoyancy 0.35 mg, uplift 0.25 F"),
)}

#: The ids, in order.
DYNAMICS_FIGURE_IDS: tuple[str, ...] = tuple(DYNAMICS_FIGURES)
