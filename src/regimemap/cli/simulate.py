"""``regimemap simulate``: one run of a block under a force pulse, past initiation.

The command parses its options, calls :func:`regimemap.motion.run.run_simulation`
(which checks how they go together and runs), writes the record through :mod:`regimemap.io`
and draws it through :mod:`regimemap.motion.figures.history`; matplotlib is imported only when a
plot or an animation is asked for.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..io.formats import FIGURE_FORMATS, FIGURES
from ._check import CHECK_HELP, exit_on_failure
from ._common import check_kprime_crest, given_options, json_option, output_option
from ._dynamics_options import (
    block_options,
    min_rotation_option,
    option_errors,
)
from ._inputs import DESIGN_FILE, PULSE_FILE
from ._main import import_matplotlib
from ._plausible import STRICT_HELP
from ._writing import checked_output, echo_notes, echo_notices, write_figure, writing

if TYPE_CHECKING:  # pragma: no cover
    from ..motion.run import SimulationRecord

__all__ = ["simulate_cmd"]


@click.command("simulate", short_help="Follow one run after initiation: phases, overturning, residuals.")
@block_options(swept=False)
@click.option("--pulse-file", "pulse_file", type=PULSE_FILE, metavar="FILE.csv",
              help="Instead of --pulse/--k-peak/--duration: a sampled force history, a CSV with "
                   "columns t (s),k and optionally kprime (then it replaces --kprime).")
@click.option("--design", "design", type=DESIGN_FILE, metavar="FILE.toml",
              help="Instead of the block and the pulse: a caisson's design file (`regimemap caisson "
                   "--example` prints one).  Runs the caisson's equivalent block under its design "
                   "wave Hmax: a half-sine of peak k = P/(m g) lasting tau0 = (0.5 - Hmax/(8 h)) T1/3 "
                   "(Shimosako & Takahashi 1999), the uplift U = nu P in phase.  The file gives "
                   "--gamma, --half-width, --kprime, --mu, the loads, --gyration and the pulse; "
                   "giving any of them too is an error.  No added mass of water.")
@click.option("--strict", is_flag=True, help=STRICT_HELP + " (With --design.)")
@click.option("--check", "check", is_flag=True,
              help="With --design: the design file's requirements, Goda's sliding and overturning safety "
                   "factors of its design wave at least [caisson] required_* (1.2), one line each, PASS or "
                   "FAIL; " + CHECK_HELP[0].lower() + CHECK_HELP[1:])
@min_rotation_option()
@json_option()
@output_option("Write the time history: .csv or .npz (atomically).")
@click.option("--plot", "plot", type=click.Path(dir_okay=False), metavar="FILE",
              help=f"Draw k(t), the slide and theta(t) with the phases shaded: {FIGURES}.")
@click.option("--animate", "animate", type=click.Path(dir_okay=False), metavar="FILE.gif",
              help="Draw the block moving, to scale, as a GIF.")
def simulate_cmd(gamma: float | None, half_width: float | None, kprime: float | None, mu: float | None,
                 pulse: str | None, k_peak: float | None, duration: float | None,
                 restitution: float | None, buoyancy: float, uplift: float, uplift_ratio: float,
                 uplift_arm: float, gyration: float | None, pulse_file: str | None, design: str | None,
                 strict: bool, check: bool, min_rotation: float, as_json: bool, output: str | None,
                 plot: str | None, animate: str | None) -> None:
    """Simulate one block under one force pulse, from rest, past initiation.

    The block (half width B, aspect ratio gamma = H/B with H the height of the
    centre of mass C above the base, friction mu) is pushed towards its left
    corner O by F = k(t) m g acting k' H above C.  The run follows rest,
    slide, rock about either corner, slide-rock, free flight and impacts until
    the block comes to rest or overturns (Moreau-Jean time stepping, see
    docs/dynamics.md).

    Prints the phases of the motion with their start times and the outcome:
    overturned or not, the largest rotation (rad and deg), the residual
    rotation, the residual slide of the base (m, positive towards O), the
    number of impacts and the mode at t = 0+.  --json prints the same as one
    object (numbers to 12 significant digits) with the inputs.

    The category is "slide-rock" or "rock only" when a rocking phase occurred,
    however small; --min-rotation ANGLE (degrees) counts rocking only when the
    largest rotation exceeds ANGLE.  A run that has not come to rest when the
    time limit (duration + 60/p) ends is "still moving": it says so, with no
    residuals (JSON "settled": false, "residual_*": null) and a warning on
    stderr.

    The pulse is --pulse KIND --k-peak K --duration T (k = 0 after T), or a
    CSV --pulse-file with columns t,k[,kprime].

    --design FILE.toml (the design file of `regimemap caisson`) gives the
    block and the pulse instead: the caisson's equivalent loaded block
    under its design wave Hmax, a half-sine of peak k = P/(m g) lasting
    tau0 = (0.5 - Hmax/(8 h)) T1/3, with the uplift in phase -- the force
    history of the lifetime model.  The block is rigid: no added mass of
    water (the lifetime model has it).  A line "design ..." says where the
    numbers came from; --json adds them as "design".  Values that are valid
    but implausible for a breakwater (likely unit slips: a depth over 100 m,
    a section heavier than 30 kN/m^3 ...) are warnings on stderr, as
    `regimemap caisson` gives them; --strict makes them an error (exit 2).
    With --design the run lists the file's requirements -- Goda's sliding and
    overturning safety factors of the design wave against [caisson]
    required_sliding and required_overturning, the check of `regimemap
    caisson` -- one line each, PASS or FAIL (--json: "checks"); --check
    exits 1 when one fails.  The run itself has no limit of its own: what
    the caisson does beyond the factors is what it shows.

    \b
    Examples:
      regimemap simulate --gamma 3 --half-width 0.2 --kprime 0 --mu 5 \\
          --pulse half-sine --k-peak 0.5 --duration 0.5
      regimemap simulate --gamma 3 --half-width 0.2 --kprime 0 --mu 0.35 \\
          --pulse half-sine --k-peak 0.6 --duration 0.5 --json --plot run.png
      regimemap simulate --gamma 1.1 --half-width 10 --kprime -0.1 --mu 0.6 \\
          --buoyancy 0.35 --uplift-ratio 0.25 --pulse breaking --k-peak 1.2 \\
          --duration 4 -o run.csv --animate caisson.gif
      regimemap simulate --gamma 3 --half-width 0.2 --mu 5 --pulse-file record.csv
      regimemap caisson --example > goda.toml
      regimemap simulate --design goda.toml --json
    """
    from ..motion.run import IMPLAUSIBLE, run_simulation

    _check_design_flags(design, strict, check)
    want_history = _check_outputs(output, plot, animate)  # before the run
    if design is None and isinstance(kprime, float):  # the block of the dynamics has the crest at H
        kprime = check_kprime_crest(kprime, 1.0)
    source = design if design is not None else {
        "gamma": gamma, "half_width": half_width, "kprime": kprime, "mu": mu, "pulse": pulse,
        "k_peak": k_peak, "duration": duration, "pulse_file": pulse_file, "buoyancy": buoyancy,
        "uplift": uplift, "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm, "gyration": gyration}
    with option_errors():
        record = run_simulation(source, restitution=restitution, history=want_history,
                                min_rotation=min_rotation, strict=strict)
    echo_notices(n for n in record.notices if n.code == IMPLAUSIBLE)  # about the inputs: first
    written = _write_outputs(record, output, plot, animate)
    echo_notices(n for n in record.notices if n.code != IMPLAUSIBLE)
    if as_json:
        from ..motion.record_simulation import simulation_json

        click.echo(simulation_json(record, written))
    else:
        from ..motion.record_simulation import format_simulation

        click.echo("\n".join([format_simulation(record), *written]))
    exit_on_failure(record.checks, check)


def _check_design_flags(design: str | None, strict: bool, check: bool) -> None:
    """--strict and --check need --design; the options --design gives may not be given too."""
    if strict and design is None:
        raise click.UsageError("--strict checks a design file: give one with --design FILE.toml")
    if check and design is None:
        raise click.UsageError("--check checks a design file's requirements: give one with --design "
                               "FILE.toml")
    if design is None:
        return
    from ..dynamics.design_wave import DESIGN_INPUTS

    given = given_options((*DESIGN_INPUTS, "pulse_file"))
    if given:
        flags = ", ".join(given)
        raise click.UsageError(f"{flags} and --design exclude each other: the design file gives the block "
                               "and the pulse (change the design file, or give the block without --design)")


def _check_outputs(output: str | None, plot: str | None, animate: str | None) -> bool:
    """Check the files asked for (different, of known formats, in writable folders); whether any is."""
    paths = [p for p in (output, plot, animate) if p is not None]
    if len({str(Path(p).resolve()) for p in paths}) < len(paths):
        raise click.UsageError("-o, --plot and --animate must name different files")
    if output is not None:
        checked_output(output, "time history")
    if plot is not None:
        checked_output(plot, (("the plot", FIGURE_FORMATS),), "--plot")
    if animate is not None:
        checked_output(animate, "animation", "--animate")
    return bool(paths)


def _write_outputs(record: SimulationRecord, output: str | None, plot: str | None,
                   animate: str | None) -> list[str]:
    """Write the time history (-o), its plot (--plot) and the animation (--animate); the paths."""
    written: list[str] = []
    if output is not None:
        from ..motion.record_simulation import write_simulation_history

        with writing(output):
            write_simulation_history(output, record)
        written.append(output)
    if plot is None and animate is None:
        return written
    import_matplotlib()
    if plot is not None:
        from ..motion.figures.history import simulation_figure

        write_figure(simulation_figure(record), plot)
        written.append(plot)
    if animate is not None:
        from ..motion.figures.history import simulation_animation
        from ..motion.run_notes import animation_note

        with writing(animate):
            n, size, speed = simulation_animation(animate, record)
        echo_notes([animation_note(animate, n, size, speed)], prefix="")
        written.append(animate)
    return written
