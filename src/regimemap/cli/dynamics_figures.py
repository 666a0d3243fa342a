"""``regimemap dynamics-figures``: the outcome-map figures D.1-D.3 of regimemap.dynamics into a folder.

Each map comes from :func:`regimemap.motion.run_maps.run_dynamics_figure` (computed, or read
from the cache) and :func:`regimemap.motion.figures.presets.dynamics_figure` draws it.
"""

from __future__ import annotations

import time
from pathlib import Path

import click

from ..io.formats import FIGURE_FORMATS
from ..motion.run_notes import dynamics_figure_note, dynamics_files_note
from ._common import quiet_option
from ._main import import_matplotlib
from ._plot_options import FormatList
from ._progress import progress_bars
from ._writing import echo_notes, output_dir, report_written, write_figure, writing

__all__ = ["dynamics_figures_cmd"]


@click.command("dynamics-figures", short_help="Draw the outcome-map figures D.1-D.3 into a folder.")
@click.option("--out", "out_dir", default=".", show_default=True, metavar="DIR",
              help="Existing, writable folder for the files.")
@click.option("--format", "formats", type=FormatList(), default="png", show_default=True,
              help=f"Comma-separated formats: {', '.join(FIGURE_FORMATS)}.")
@click.option("--cache", "cache", default=None, metavar="DIR",
              help="Keep the computed maps in DIR (created if missing) and reuse them while the "
                   "figures' definitions and regimemap.dynamics are unchanged.")
@click.option("--list", "list_only", is_flag=True, help="List the figures; draw nothing.")
@quiet_option()
def dynamics_figures_cmd(out_dir: str, formats: tuple[str, ...], cache: str | None, list_only: bool,
                         quiet: bool) -> None:
    """Draw the figures of regimemap.dynamics (D.1, D.2, D.3) into a folder.

    D.1 and D.2 are the overturning spectra of a half-sine and of a one-sine
    pulse in the dimensionless axes of Makris & Roussos (2000) and Zhang &
    Makris (2001); D.3 is a caisson under a breaking-wave pulse.  Each is an
    outcome map computed on a grid, its boundaries refined by bisection
    (2 to 25 s each on one core; a progress bar on a terminal); the files
    are dyn-<ID>.<format>, byte-identical from run to run on one machine.
    With --cache DIR the maps are kept in DIR and only drawn again next time
    (the same bytes), until the figures' definitions, regimemap.dynamics, the
    versions of regimemap or numpy or numpy's CPU dispatch level change (make
    figures uses .cache/dynamics-figures).

    \b
    Examples:
      regimemap dynamics-figures --out figures --format png,svg
      regimemap dynamics-figures --list
    """
    from ..dynamics.presets import DYNAMICS_FIGURES
    from ..motion.run_maps import run_dynamics_figure

    if list_only:
        click.echo("\n".join(f"{f.id:4s} {f.caption}" for f in DYNAMICS_FIGURES.values()))
        return
    folder = output_dir(out_dir, "--out")
    if cache is not None and Path(cache).exists() and not Path(cache).is_dir():
        raise click.BadParameter(f"{cache!r} is a file, not a folder", param_hint="'--cache'")
    import_matplotlib()
    from ..motion.figures.presets import dynamics_figure

    for f in DYNAMICS_FIGURES.values():
        t0 = time.perf_counter()
        with writing(cache, f"to the cache {cache}"):
            record = run_dynamics_figure(f, cache=cache, bars=progress_bars(quiet, " runs", f"{f.id} "))
        fig = dynamics_figure(f, record.data)
        for path in [folder / f.filename(fmt) for fmt in formats]:
            write_figure(fig, path)
            report_written(path)
        if not quiet:
            echo_notes([dynamics_figure_note(record, time.perf_counter() - t0)], prefix="")
    if not quiet:
        echo_notes([dynamics_files_note(len(DYNAMICS_FIGURES), formats, folder)])


