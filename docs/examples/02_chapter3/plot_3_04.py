r"""
Fig. 3.4 — Rock region, case 2
==============================

Rock region, case 2, :math:`(4+\gamma^2)/(3\gamma^2) \leq k' \leq 1`, :math:`f_x \geq
0`, :math:`a \leq 0`.

The region of RO alone, as the report derives it. The block: :math:`\gamma = 3`,
:math:`k' = 0.85` (:math:`G`: :math:`k = b/|a| = 0.905`, where :math:`f_x = 0`; shown up
to a little beyond :math:`G`). The caption is lost from the report's source text and is
reconstructed from the wording of its companion captions and of the paragraphs that cite
it.

Command line: ``regimemap figure 3.4``.
"""

from regimemap.drawing import render_preset
from regimemap.maps.figures.presets import get_preset
from regimemap.workflows import run_map

preset = get_preset("3.4")
print(f"gamma = {preset.gamma:g}, k' = {preset.kprime:g}, case {preset.params.case.value}, "
      f"modes {[m.label for m in preset.modes]}, raw region: {preset.raw}")

fig = render_preset(preset, run_map(**preset.map_keywords))
