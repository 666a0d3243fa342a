"""The allowed sizes of the atlas and the animation, importable without drawing anything.

The command line builds its options from these numbers (``regimemap atlas``, ``regimemap
animate``); this module imports nothing, so ``regimemap --help`` does not load the drawing
modules (or the maps they draw) to learn them.  :mod:`regimemap.maps.figures.atlas` and
:mod:`regimemap.maps.figures.animation` re-export them under the same names.
"""

from __future__ import annotations

__all__ = [
    "ANIMATION_DPI",
    "ANIMATION_DPI_RANGE",
    "ATLAS_DPI",
    "ATLAS_DPI_RANGE",
    "FPS_RANGE",
    "MAX_FRAMES",
    "MAX_PANELS",
]

#: Largest number of frames of an animation.
MAX_FRAMES = 400
#: Resolution of the frames of an animation by default, and the range allowed.
ANIMATION_DPI = 100
ANIMATION_DPI_RANGE: tuple[int, int] = (30, 300)
#: Frames per second of an animation: the range allowed.
FPS_RANGE: tuple[float, float] = (0.5, 50.0)

#: Largest number of panels of an atlas (rows x columns): :data:`regimemap.maps.sweeps.MAX_PANELS`.
MAX_PANELS = 48
#: Resolution (dots per inch) of an atlas by default, and the range allowed.
ATLAS_DPI = 150
ATLAS_DPI_RANGE: tuple[int, int] = (30, 600)
