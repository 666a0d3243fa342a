r"""
Fig. 2.1 — The model
====================

The block of half width B and half height H with its centre of mass C, on its
corners O (left, leeward: the force pushes towards it) and O′ (right); the
force F = mgk pushes to the left at h = k′H above C; the base pushes back with
f\ :sub:`x` (positive to the right) and f\ :sub:`y`, acting at ξ from C; the block
turns by θ (counter-clockwise positive).  The report's own drawing is lost from
its source text; this one is redrawn from the definitions of its Chapter II.

Command line: ``regimemap figure 2.1``.
"""

from regimemap.maps.figures.model import model_figure

fig = model_figure()
