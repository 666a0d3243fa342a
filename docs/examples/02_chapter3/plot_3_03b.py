r"""
Fig. 3.3b — Rock region, case 1 (b)
===================================

Rock region, case 1, :math:`(1+\gamma^2)/(3\gamma^2) \leq k' \leq
(4+\gamma^2)/(3\gamma^2) \leq 1`, :math:`f_x \geq 0`, :math:`a \geq 0`.

The region of RO alone, as the report derives it. The block: :math:`\gamma = 3`,
:math:`k' = 0.425`. The caption survives in the report.

Command line: ``regimemap figure 3.3b``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("3.3b")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
