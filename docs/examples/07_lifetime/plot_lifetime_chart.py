"""
Design chart: expected sliding against width
============================================

The expected sliding distance of Goda's caisson at 21 widths from 10 m to 25 m
(the weight in proportion to the width), all on the same random numbers, with a
band of two standard errors; the narrowest width whose ESD is at most 0.1 m
(Goda & Takagi 2000) and the width of Goda's deterministic design (sliding
safety factor 1.2 under the 50-year wave).

Command line::

    regimemap lifetime goda.toml --width 10:25:21 --target 0.1 --trials 2000 -o chart.svg
"""

import numpy as np

from regimemap.lifetime import Caisson, Climate, LifetimeModel, design_chart
from regimemap.lifetime.figures.chart import chart_figure

goda = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1, crest=3.4,
               friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)
model = LifetimeModel(Climate.from_return_values(5.0, 6.3))
chart = design_chart(goda, model, np.linspace(10.0, 25.0, 21), trials=2000, seed=2026, target=0.1)
print(f"width for an ESD of {chart.target} m: {chart.width_for_target:.1f} m; "
      f"Goda's deterministic width (SF = {chart.required_sf}): {chart.sf_width:.1f} m")

fig = chart_figure(chart)
