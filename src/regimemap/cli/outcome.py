"""``regimemap outcome``: an outcome map (rest, slide, rock, slide-rock, overturned) over two
swept inputs.

The command hands its options to :func:`regimemap.motion.file.map_options` (which sweeps,
which pulse, the limits), calls :func:`regimemap.motion.run_maps.run_outcome`, and writes the
record's data through :mod:`regimemap.motion.record_outcome` or draws it with
:mod:`regimemap.motion.figures.outcome` (matplotlib only then).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import click

from ..io.formats import FIGURE_FORMATS, FIGURES, record_formats
from ._common import outputs_option, quiet_option
from ._dynamics_options import (
    block_options,
    input_option,
    min_rotation_option,
    option_errors,
)
from ._progress import progress_bars
from ._writing import checked_output, distinct_files, write_files

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from ..motion.run_maps import OutcomeRecord

__all__ = ["outcome_cmd"]

#: The data formats of an outcome map: those of a run's history, and JSON with the boundaries.
_DATA_FORMATS = record_formats("outcome data")


@click.command("outcome", short_help="Outcome map (rest, slide, rock, slide-rock, overturned) over two "
                                     "swept inputs.")
@block_options(swept=True)
@input_option("omega_p", True, "W", extra=" A list a,b,c or a range start:stop:count sweeps it.")
@click.option("--dimensionless", is_flag=True,
              help="Draw (and export) the axes as omega_p/p and k_peak/tan(alpha) (Makris & Roussos "
                   "2000), for a k_peak, duration or omega_p sweep.")
@outputs_option(f"Output file (repeatable): {FIGURES} draws the map, .npz, .csv or .json writes its data "
                "(atomically; .json with the refined boundaries).", required=True)
@min_rotation_option()
@click.option("--no-refine", "no_refine", is_flag=True,
              help="Do not refine the boundaries between categories: draw the cells of the grid as "
                   "computed (a staircase at the grid's pitch), with no boundaries in .json.")
@quiet_option()
def outcome_cmd(gamma: list[float], half_width: list[float], kprime: list[float] | None, mu: list[float],
                pulse: str | None, k_peak: list[float] | None, duration: list[float] | None,
                restitution: float | None, buoyancy: list[float] | None, uplift: list[float] | None,
                uplift_ratio: list[float] | None, uplift_arm: list[float] | None,
                gyration: list[float] | None, omega_p: list[float] | None, dimensionless: bool,
                outputs: tuple[str, ...], min_rotation: float, no_refine: bool, quiet: bool) -> None:
    """Simulate a grid of runs over two swept inputs and map their outcome.

    Give exactly two inputs as lists (0.2,0.5,1.2) or ranges start:stop:count
    (0.3:1.5:121, both ends included) and every other one as a single value:
    the first swept option on the command line runs along the horizontal
    axis, the second up the vertical one.  Any of --k-peak, --duration (or
    --omega-p), --mu, --kprime, --gamma, --half-width, --gyration,
    --buoyancy, --uplift, --uplift-ratio and --uplift-arm can be swept.

    Each cell gets its category: rest, slide only, rock only, slide-rock,
    overturned, or still moving when the time limit came (--min-rotation
    ANGLE: rocking counts only above ANGLE degrees, shown in the title and the
    key).  Then each
    boundary between two categories is found by bisection between
    neighbouring cells, along the swept input that crosses it, to 1/1000 of
    its range (a few batches more; --no-refine skips it).  A figure (.png,
    .svg, .pdf) shows the categories as coloured, hatched regions bounded by
    those boundaries, with contours of the residual slide (m) and of the
    maximum rotation (deg); data (.npz, .csv) has 1-D arrays named after the
    swept options and 2-D arrays category, overturned, max_rotation (rad) and
    residual_slide (m, positive towards O) of shape (len(second), len(first));
    .json has the same and the boundaries as lists of points in the swept
    inputs' units.  At most 250000 runs; the time is about 1 ms per run on
    one core (more for long free rocking), with a progress bar on a terminal.

    \b
    Examples:
      regimemap outcome --gamma 3 --half-width 0.2 --kprime 0 --mu 0.5 \\
          --pulse half-sine --k-peak 0.3:1.5:25 --duration 0.2,0.5,1.2 -o map.png
      regimemap outcome --gamma 3 --half-width 0.2 --kprime 0 --mu 5 \\
          --pulse half-sine --omega-p 3:30:28 --k-peak 0.3:2.5:23 --dimensionless \\
          -o spectrum.svg -o spectrum.npz
    """
    from ..motion.file import map_options
    from ..motion.run_maps import run_outcome
    from ..motion.run_notes import outcome_start_note

    values: dict[str, list[float] | None] = {
        "k_peak": k_peak, "duration": duration, "omega_p": omega_p, "mu": mu, "kprime": kprime,
        "gamma": gamma, "half_width": half_width, "gyration": gyration, "buoyancy": buoyancy,
        "uplift": uplift, "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm}
    with option_errors():
        # the swept inputs, in the order given on the command line (click fills ctx.params in that order)
        opts = map_options(values, list(click.get_current_context().params), pulse,
                           dimensionless=dimensionless)
    _check_outputs(outputs)
    with option_errors():
        opts.check_steps()
    _note(quiet, outcome_start_note(opts))
    with option_errors():
        record = run_outcome(opts, restitution=restitution, min_rotation=min_rotation, refine=not no_refine,
                             dimensionless=dimensionless, bars=progress_bars(quiet, " runs"))
    from ..motion.record_outcome import outcome_summary

    _note(quiet, "\n".join(outcome_summary(record)))
    _write(record, outputs)
    click.echo("\n".join(outputs))


def _note(quiet: bool, text: str) -> None:
    """A note on standard error, unless --quiet."""
    if not quiet:
        click.echo(text, err=True)


def _check_outputs(outputs: tuple[str, ...]) -> None:
    """Each output file of a known format, each different and in a writable folder."""
    distinct_files(outputs, "'-o' / '--output'")
    for p in outputs:
        checked_output(p, (("an outcome map", FIGURE_FORMATS + _DATA_FORMATS),))


def _write(record: OutcomeRecord, outputs: tuple[str, ...]) -> None:
    """Write the map's data (.npz, .csv, .json) and draw its figure once (.png, .svg, .pdf)."""
    from ..motion.record_outcome import write_outcome_record

    def draw() -> Figure:
        from ..motion.figures.outcome_record import outcome_record_figure

        return outcome_record_figure(record)

    write_files(outputs, draw, data_formats=_DATA_FORMATS,
                write_data=lambda path: write_outcome_record(path, record))
