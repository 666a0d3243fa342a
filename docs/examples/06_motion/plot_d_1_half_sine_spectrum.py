r"""
D.1 — Overturning spectrum of a half-sine pulse
===============================================

The block of :doc:`/dynamics` (B = 0.2 m, γ = 3, μ = 5: no sliding) under a
half-sine pulse, over ω\ :sub:`p`/p and k\ :sub:`p`/tan α (Makris & Roussos
2000): overturning above a threshold that rises with ω\ :sub:`p`/p.

``make figures`` computes this map on 96 × 80 runs (``regimemap
dynamics-figures``) before it refines the boundaries; to keep the docs build
quick it starts here from 48 × 40 runs over the same ranges, so a feature
smaller than a cell of that grid may be missing.
"""

import dataclasses

from regimemap.dynamics.presets import DYNAMICS_FIGURES
from regimemap.motion.figures.presets import dynamics_figure

figure = DYNAMICS_FIGURES["D.1"]
quick = dataclasses.replace(figure, first=(*figure.first[:3], 48), second=(*figure.second[:3], 40))
print(quick.make_block())

fig = dynamics_figure(quick, quick.compute())
