r"""
Fig. 4.7a — All modes, Δ ≥ 0
============================

All modes, :math:`|k'| \leq (1+\gamma^2)/(4+\gamma^2)`.

The final map: one mode at every point of the k–μ plane. The block: :math:`\gamma = 3`,
:math:`k' = -0.3`. The caption is lost from the report's source text and is
reconstructed from the wording of its companion captions and of the paragraphs that cite
it.

Command line: ``regimemap figure 4.7a``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("4.7a")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
