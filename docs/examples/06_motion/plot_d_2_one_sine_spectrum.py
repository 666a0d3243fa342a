"""
D.2 — Overturning spectrum of a one-sine pulse
==============================================

A one-sine pulse (Zhang & Makris 2001, type A) on a block with p = 2.14 rad/s,
α = 0.25 and the impact ratio 0.9: overturning in a lower band and above it,
the safe tongue between them, and no overturning by short pulses.

``make figures`` computes this map on 96 × 96 runs before it refines the
boundaries; to keep the docs build quick it starts here from 48 × 48 runs over
the same ranges, so a feature smaller than a cell of that grid may be missing.
"""

import dataclasses

from regimemap.dynamics.presets import DYNAMICS_FIGURES
from regimemap.motion.figures.presets import dynamics_figure

figure = DYNAMICS_FIGURES["D.2"]
quick = dataclasses.replace(figure, first=(*figure.first[:3], 48), second=(*figure.second[:3], 48))

fig = dynamics_figure(quick, quick.compute())
