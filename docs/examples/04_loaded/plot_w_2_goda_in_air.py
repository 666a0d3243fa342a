r"""
Fig. W.2 — The same caisson in air
==================================

The block of :ref:`sphx_glr_auto_examples_04_loaded_plot_w_1_goda_submerged.py`
without buoyancy and uplift, on the same axes: A lies three times farther out,
rest reaches μ = 1.45, and there is no lift-off.
"""

import regimemap
from regimemap.drawing import map_figure
from regimemap.maps import DesignPoint
from regimemap.maps.figures.worked import WORKED
from regimemap.workflows import run_map

block = regimemap.Parameters(0.70, -0.018)
print(f"A at k = {block.k_A:.4f}")

record = run_map(block, points=[DesignPoint(0.2776, 0.6, "Goda's caisson")], k_max=6.0,
                 mu_max=3.0, view="report")
fig, ax, artists = map_figure(record, title=WORKED["W.2"].title)
