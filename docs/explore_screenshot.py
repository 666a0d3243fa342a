"""The explorer's screenshot of the docs (``docs/_static/explore.png``): a real TkAgg window.

Run it under a virtual X server, from the project's root::

    xvfb-run -a -s "-screen 0 1400x800x24" .venv/bin/python docs/explore_screenshot.py

(optionally with the output file as argument).  It opens ``regimemap explore``
for Goda's submerged caisson, as the command does
(:func:`regimemap.cli.explore.open_explorer`), clicks its design point, moves
the pointer there (the toolbar shows its coordinates), and grabs the window
from the X server.  Under Xvfb there is no window manager, so no title bar;
with the same fonts the PNG is the same bytes from run to run.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

#: Goda's caisson, submerged (the gallery's and the guide's example), and its design point.
GODA = {"gamma": 0.7, "kprime": -0.018, "buoyancy": 0.318, "uplift_ratio": 0.524}
POINT = (0.279, 0.602)
OUT = Path(__file__).resolve().parent / "_static" / "explore.png"


def main(out: Path = OUT) -> Path:
    """Take the screenshot and write it to ``out`` (PNG); return the path."""
    if not os.environ.get("DISPLAY"):
        sys.exit("no DISPLAY: run under xvfb-run (see the docstring)")
    import matplotlib

    matplotlib.use("TkAgg")
    import matplotlib.pyplot as plt
    from matplotlib.backend_bases import MouseEvent
    from PIL import ImageGrab

    from regimemap import Parameters
    from regimemap.cli.explore import open_explorer

    ex = open_explorer(Parameters(**GODA), echo=lambda *_: None)
    ex.click(*POINT)
    plt.show(block=False)  # map the window (no event loop: this script drives Tk)
    window = ex.fig.canvas.manager.window  # type: ignore[union-attr]
    plt.pause(0.5)
    x, y = ex.ax.transData.transform(POINT)
    MouseEvent("motion_notify_event", ex.fig.canvas, x, y)._process()  # type: ignore[attr-defined]
    for _ in range(5):  # let Tk draw the canvas and the toolbar's message
        window.update()
    box = (window.winfo_rootx(), window.winfo_rooty(),
           window.winfo_rootx() + window.winfo_width(), window.winfo_rooty() + window.winfo_height())
    image = ImageGrab.grab(bbox=box, xdisplay=os.environ["DISPLAY"]).convert("RGB")
    ex.close()
    out.parent.mkdir(parents=True, exist_ok=True)
    image.save(out, optimize=True)
    return out


if __name__ == "__main__":
    print(main(Path(sys.argv[1]) if len(sys.argv) > 1 else OUT))
