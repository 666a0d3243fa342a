r"""
D.3 — A caisson under a breaking-wave pulse
===========================================

A caisson 20 m wide and 22 m high (B = 10 m, γ = 1.1, μ = 0.6, k′ = −0.1,
buoyancy 0.35 mg, uplift 0.25 F) under the breaking-wave pulse, over the peak
k\ :sub:`peak` and the duration: it slides before it can rock; the contours give
the residual slide.  The map of ``make figures`` (61 × 45 runs).
"""

import numpy as np

from regimemap.dynamics.presets import DYNAMICS_FIGURES
from regimemap.motion.figures.presets import dynamics_figure

figure = DYNAMICS_FIGURES["D.3"]
print(figure.make_block())

outcomes, k_peak, duration = figure.compute()
for code, label in enumerate(outcomes.labels):
    print(f"{label:>12}: {np.count_nonzero(outcomes.category == code):5d} runs")

fig = dynamics_figure(figure, (outcomes, k_peak, duration))
