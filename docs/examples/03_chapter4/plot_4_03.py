r"""
Fig. 4.3 — Slide region
=======================

Slide region.

The region of SL alone, as the report derives it, before Section 4.7 resolves where the
regions overlap. The block: :math:`\gamma = 3`, :math:`k' = -0.3`. The caption survives
in the report.

Command line: ``regimemap figure 4.3``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("4.3")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
