r"""
Fig. W.4 — Goda's caisson as the uplift grows
=============================================

An atlas that sweeps a load: Goda's caisson with the uplift ratio
:math:`\nu = 0`, 0.524 (his) and 1 in the columns.  The point L, where lift-off
starts, comes in from infinity to k = 1.9.

Command line::

    regimemap atlas --gamma 0.7 --kprime -0.018 --buoyancy 0.318 --uplift-ratio 0,0.524,1 \
        --k-max 6 --mu-max 3 --view report
"""

from regimemap.drawing import atlas_figure
from regimemap.maps.figures.worked import WORKED
from regimemap.workflows import run_atlas

atlas = run_atlas([0.70], [0.0, 0.524, 1.0], sweep="uplift_ratio",
                  fixed={"kprime": -0.018, "buoyancy": 0.318, "uplift_arm": 1 / 3},
                  k_max=6.0, mu_max=3.0, view="report")
fig = atlas_figure(atlas, caption=f"Fig. W.4  {WORKED['W.4'].caption}")
