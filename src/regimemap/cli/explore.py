"""``regimemap explore``: the regime map, live (sliders for gamma and k', a click, Save).

The window is :class:`regimemap.maps.figures.explore.explorer.Explorer`; this module only
parses the options, wires the explorer to the rest of the command line (the
file names of ``regimemap plot``, and the ``plot`` command that writes the
same file, on standard error) and opens the window.  :func:`open_explorer` does the same
wiring for Python and Jupyter.  Importing this module does not import matplotlib.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ..io.formats import FIGURES
from ._common import gamma_option, given_options, kprime_option, load_options
from ._inputs import DESIGN_FILE, read_design_file
from ._main import RunError, import_matplotlib
from ._plot_options import DEFAULT_SAMPLES, resolution_option
from ._writing import figure_output, report_written, writing
from .plot import plot_stem

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..maps.figures.explore.explorer import Explorer
    from ..maps.points import DesignPoint
    from ..mechanics.block import Parameters

__all__ = ["explore_cmd", "open_explorer", "plot_command_line"]

def plot_command_line(explorer: Explorer) -> str:
    """The ``regimemap plot`` command that draws the explorer's current view."""
    p = explorer.params
    words = ["regimemap", "plot", "--gamma", f"{p.gamma!r}", "--kprime", f"{p.kprime!r}"]
    for name, value in explorer.loads.items():
        words += [f"--{name.replace('_', '-')}", f"{value!r}"]
    if explorer.point is not None:
        words += ["--point", f"{explorer.point.k!r},{explorer.point.mu!r}"]
    if explorer.resolution != DEFAULT_SAMPLES:
        words += ["--resolution", str(explorer.resolution)]
    return " ".join(words)


def open_explorer(params: Parameters | None = None, *, resolution: int = DEFAULT_SAMPLES,
                  fig: Figure | None = None, echo: Any = click.echo, window: bool = True,
                  point: DesignPoint | None = None) -> Explorer:
    """An :class:`~regimemap.maps.figures.explore.explorer.Explorer` wired as ``regimemap explore`` wires it.

    A click shows the text of ``regimemap classify``
    (:func:`regimemap.io.format_result`); *Save* writes atomically
    (:func:`regimemap.drawing.save_figure`) to the file name of ``regimemap plot``
    (``regime-g3-kp0.4.png``) in the current folder, prints its path and, on
    standard error, the ``regimemap plot`` command that writes the same file.

    In Jupyter, after ``%matplotlib widget``::

        from regimemap import Parameters
        from regimemap.cli.explore import open_explorer

        ex = open_explorer(Parameters(gamma=3, kprime=0.4))
    """
    from ..drawing.save import save_figure
    from ..maps.figures.explore.explorer import Explorer
    from ..maps.mapdata import map_for_view
    from ..maps.query import classify_point
    from ..maps.record_tables import format_result

    holder: list[Explorer] = []

    def write(figure: Figure, path: Path, fmt: str, dpi: float) -> None:
        save_figure(figure, path, fmt, dpi=dpi)
        if holder and echo is not None:
            echo(f"regimemap: note: the same file as: {plot_command_line(holder[0])}"
                 + ("" if str(path) == f"{_stem(holder[0])}.png" else f" -o {path}"), err=True)

    def stem(p: Parameters) -> str:
        return _stem(holder[0]) if holder else plot_stem(p.gamma, p.kprime)

    ex = Explorer(params, compute=map_for_view, classify=classify_point, resolution=resolution,
                  fig=fig, describe=format_result, write=write,
                  file_stem=stem, echo=echo, window=window, point=point)
    holder.append(ex)
    return ex


def _stem(ex: Explorer) -> str:
    p = ex.params
    return plot_stem(p.gamma, p.kprime, ex.loads)


@click.command("explore", short_help="The regime map, live: sliders for gamma and k', click for the physics.")
@gamma_option(required=False, default=3.0, show_default=True)
@kprime_option(required=False, default=0.4, show_default=True)
@resolution_option()
@click.option("-o", "--output", metavar="FILE",
              help=f"Save the first view (as regimemap plot draws it; {FIGURES}) and "
                   "exit without opening a window.")
@click.option("--design", "design", type=DESIGN_FILE, metavar="FILE.toml",
              help="Start at a caisson's design wave: its loaded block and design point (k, mu) "
                   "from a design file (instead of --gamma, --kprime and the loads).")
@load_options
def explore_cmd(gamma: float, kprime: float, resolution: int, output: str | None, design: str | None,
                loads: dict[str, Any]) -> None:
    """Open the regime map in a window, live: sliders for GAMMA and KPRIME.

    Drag the sliders and the map is redrawn as regimemap plot draws it; tick
    'loads' for two more sliders, the buoyancy beta and the uplift ratio nu.
    Click on the map: the mode at that point, its margins and the physics at
    initiation (what regimemap classify prints) appear beside the map and on
    standard output.  'Save' writes the current view exactly as regimemap plot
    would (the same bytes) to regime-g<GAMMA>-kp<KPRIME>.png in the current
    folder and prints its path.

    --design FILE.toml starts at a caisson's design wave (`regimemap caisson
    --example` prints a design file): its loaded block (gamma, k', buoyancy,
    uplift ratio and arm, gyration, crest) and the point (k, mu) of the design
    wave marked, as `regimemap caisson` computes them; the file gives the block,
    so --gamma, --kprime and the loads may not be given too.

    A window needs a display (and a GUI backend of matplotlib, e.g. TkAgg).
    Without one the command stops with exit status 1; -o FILE saves the first
    view without a window instead (for scripts and CI).  In Jupyter, use
    regimemap.cli.explore.open_explorer with %matplotlib widget (pip install
    'regimemap[notebook]').

    \b
    Examples:
      regimemap explore
      regimemap explore --gamma 0.7 --kprime -0.02 --buoyancy 0.32 --uplift-ratio 0.52
      regimemap explore --gamma 3 --kprime 0.4 -o start.png
      regimemap explore --design goda.toml -o goda-map.png
    """
    params, point = _start(gamma, kprime, loads, design)
    path = None if output is None else figure_output(output)[0]
    import_matplotlib()
    if path is not None:
        ex = open_explorer(params, resolution=resolution, echo=None, window=False, point=point)
        with writing(path):
            ex.save(path)
        report_written(path)
        return
    from ..maps.figures.explore.text import window_problem

    problem = window_problem()
    if problem is not None:
        raise RunError(f"regimemap explore needs a display to open its window: {problem}. "
                       "Run it on a desktop (or with ssh -X), save the first view with "
                       "-o FILE, or use open_explorer in Jupyter with %matplotlib widget")
    ex = open_explorer(params, resolution=resolution, point=point)
    sys.stdout.flush()
    ex.show(f"regimemap explore ({Path(design).name if design is not None else _stem(ex)})")


def _start(gamma: float, kprime: float, loads: dict[str, Any], design: str | None
           ) -> tuple[Parameters, DesignPoint | None]:
    """The block to start from and the point marked: the options', or a design file's (--design)."""
    from ..mechanics.block import Parameters

    if design is None:
        return Parameters(gamma, kprime, **loads), None
    return _design_start(design, loads)


def _design_start(design: str, loads: dict[str, Any]) -> tuple[Parameters, DesignPoint]:
    """The loaded block and the design point of a design file's design wave (--design).

    The file gives the block: --gamma, --kprime or a load given too is a usage error; a bad
    file is a usage error naming the file, its line and the key, as ``regimemap caisson``
    reports it; implausible values are warnings on standard error
    (:func:`regimemap.caisson.run.run_caisson`, as ``regimemap caisson`` runs it).
    """
    from ._plausible import caisson_record

    given = given_options(("gamma", "kprime")) + [f"--{n.replace('_', '-')}" for n in loads]
    if given:
        raise click.UsageError(f"{', '.join(given)} and --design exclude each other: the design file "
                               "gives the block (change the design file, or give the block without --design)")
    d = read_design_file(design, "'--design'")
    record = caisson_record(d, design, param_hint="'--design'", usage_error=True)
    return record.parameters, record.design_point
