r"""
Fig. 3.9a — All modes, case 1 (a)
=================================

All modes, case 1, :math:`0 \leq k' \leq (1+\gamma^2)/(3\gamma^2)`, :math:`f_x \geq 0`,
:math:`a \geq 0`.

The final map: one mode at every point of the k–μ plane. The block: :math:`\gamma = 3`,
:math:`k' = 0.2`. The caption survives in the report.

Command line: ``regimemap figure 3.9a``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("3.9a")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
