r"""
Fig. W.3 — A slender block lifted as it is pushed
=================================================

A slender block (:math:`\gamma = 3`, :math:`k' = 0.4`) whose uplift grows as fast
as the push (:math:`\nu = 1`): slide-rock about O slipping right (SRO₊) opens
beyond G, and the block lifts off beyond L.
"""

import regimemap
from regimemap.drawing import map_figure
from regimemap.maps.figures.worked import WORKED
from regimemap.workflows import run_map

block = regimemap.Parameters(3.0, 0.4, uplift_ratio=1.0)
fig, ax, artists = map_figure(run_map(block, view="report"), title=WORKED["W.3"].title)
print("modes on the map:", ", ".join(mode.label for mode in artists.polygons))
