r"""
Fig. W.1 — Goda's caisson, submerged
====================================

Goda's worked upright breakwater (:doc:`/waves`, Section 8) as the loaded
block: :math:`\gamma = 0.70`, :math:`k' = -0.018`, buoyancy
:math:`\beta = 0.318` of the dry weight, uplift ratio :math:`\nu = 0.524` at the
arm :math:`e_u = 1/3` (Goda's triangle).  His design point k = 0.278, μ = 0.6
rests, close to OA (sliding safety factor 1.16).

Command line::

    regimemap plot --gamma 0.7 --kprime -0.018 --buoyancy 0.318 --uplift-ratio 0.524 \
        --point 0.2776,0.6:Goda --k-max 6 --mu-max 3 --view report
"""

import regimemap
from regimemap.drawing import map_figure
from regimemap.maps import DesignPoint
from regimemap.maps.figures.worked import WORKED
from regimemap.workflows import run_map

block = regimemap.Parameters(0.70, -0.018, buoyancy=0.318, uplift_ratio=0.524)
goda = DesignPoint(0.2776, 0.6, "Goda's caisson")

code = regimemap.classify(goda.k, goda.mu, 0.70, -0.018, buoyancy=0.318, uplift_ratio=0.524)
mode = regimemap.Mode(code)
print(f"Goda's design point: {mode.label}; A at k = {block.k_A:.4f}")

record = run_map(block, points=[goda], k_max=6.0, mu_max=3.0, view="report")
fig, ax, artists = map_figure(record, title=WORKED["W.1"].title)
