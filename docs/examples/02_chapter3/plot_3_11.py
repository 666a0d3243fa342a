r"""
Fig. 3.11 — All modes, case 3
=============================

All modes, case 3, :math:`(4+\gamma^2)/(3\gamma^2) \leq k' \leq 1`, :math:`f_x \leq 0`,
:math:`a \leq 0`.

The final map: one mode at every point of the k–μ plane. The block: :math:`\gamma = 3`,
:math:`k' = 0.85` (:math:`G`: :math:`k = b/|a| = 0.905`, where :math:`f_x = 0`; shown
mostly beyond :math:`G`). The caption survives in the report.

Command line: ``regimemap figure 3.11``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("3.11")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
