"""``regimemap simulate``: one run of a block under a force pulse, past initiation.

The command parses and checks its options (the pulse and the step count through
:mod:`regimemap.dynamics.options` and :mod:`regimemap.dynamics.limits`), calls
:func:`regimemap.dynamics.simulate`, and writes through :mod:`regimemap.io`; matplotlib is
imported only when a plot or an animation is asked for.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ._check import CHECK_HELP, exit_on_failure
from ._common import check_kprime_crest, import_matplotlib
from ._dynamics_options import (
    DATA_FORMATS,
    FIGURE_FORMATS,
    block_options,
    check_output_file,
    min_rotation_option,
    option_errors,
)
from ._inputs import DESIGN_FILE, PULSE_FILE, read_design_file
from ._plausible import STRICT_HELP, check_plausible
from ._writing import writing

if TYPE_CHECKING:  # pragma: no cover
    from ..dynamics import Block, Pulse, Simulation
    from ..mechanics.checks import Check

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
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object instead of text.")
@click.option("-o", "--output", "output", type=click.Path(dir_okay=False), metavar="FILE",
              help="Write the time history: .csv or .npz (atomically).")
@click.option("--plot", "plot", type=click.Path(dir_okay=False), metavar="FILE",
              help="Draw k(t), the slide and theta(t) with the phases shaded: .png, .svg or .pdf.")
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
    from ..dynamics import simulate
    from ..dynamics.options import block_from_options, check_loads_and_gyration, pulse_from_options

    block: Block | None = None
    numbers: dict[str, float] | None = None
    checks: list[Check] = []
    if strict and design is None:
        raise click.UsageError("--strict checks a design file: give one with --design FILE.toml")
    if check and design is None:
        raise click.UsageError("--check checks a design file's requirements: give one with --design "
                               "FILE.toml")
    if design is not None:  # -- the block and the pulse from a design file -------------------
        block, pls, values, numbers, checks = _design_run(design, strict)
        gamma, half_width, kprime, mu = values["gamma"], values["half_width"], values["kprime"], values["mu"]
        pulse, k_peak, duration = values["pulse"], values["k_peak"], values["duration"]
        buoyancy, uplift, uplift_ratio = values["buoyancy"], values["uplift"], values["uplift_ratio"]
        uplift_arm, gyration = values["uplift_arm"], values["gyration"]
    missing = [n for n, v in (("--gamma", gamma), ("--half-width", half_width), ("--mu", mu)) if v is None]
    if missing:
        raise click.UsageError(f"missing option(s) {', '.join(missing)}: give the block (--gamma, "
                               "--half-width, --mu, ...), or --design FILE.toml")
    assert gamma is not None and half_width is not None and mu is not None
    if isinstance(kprime, float):  # the block of the dynamics has the crest at H (k' <= 1)
        kprime = check_kprime_crest(kprime, 1.0)
    with option_errors():
        if design is None:  # -- the pulse (with --design, the design wave's, above) ------------
            pls = pulse_from_options(pulse, k_peak, duration, pulse_file=pulse_file, read=_read_pulse,
                                     kprime=kprime)
        check_loads_and_gyration([gamma], [buoyancy], [uplift], [gyration] if gyration is not None else None)

    want_history = _check_outputs(output, plot, animate)  # before the run

    from ..dynamics.limits import check_run_steps

    if block is None:
        block = block_from_options({"half_width": half_width, "gamma": gamma, "mu": mu, "kprime": kprime,
                                    "gyration": gyration, "buoyancy": buoyancy, "uplift": uplift,
                                    "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm})
    T = float(pls.duration)
    try:
        check_run_steps(block, T)
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="'--duration'") from None
    sim = simulate(block, pls, restitution=restitution, history=0 if want_history else None)

    inputs: dict[str, Any] = {
        "gamma": gamma, "half_width": half_width, "kprime": kprime, "mu": mu,
        "pulse": pulse if pulse_file is None else "file", "k_peak": k_peak, "duration": duration,
        "pulse_file": pulse_file, "restitution": restitution, "buoyancy": buoyancy, "uplift": uplift,
        "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm, "gyration": gyration, "design": design,
        "min_rotation": min_rotation,
    }
    housner = float(block.housner_ratio)
    # Housner's ratio assumes the block rocks on about the other corner after an impact; for a
    # squat block it is <= 0 and the impact ends the rocking (the block lands flat): no ratio
    eta = restitution if restitution is not None else (housner if housner > 0.0 else None)
    derived = {"p": float(block.p), "alpha": float(block.alpha), "H": float(block.H),
               "impact_ratio": eta, "housner_ratio": housner, "k_peak": float(pls.k_peak),
               "duration": T, "omega_p": float(pls.omega_p)}
    import math

    from ..io.dynamics import simulation_record

    record = simulation_record(sim, inputs, derived, min_rotation=math.radians(min_rotation))
    if numbers is not None:
        from ..io.checks import checks_json

        record["design"] = _design_record(design, numbers)
        record["checks"] = checks_json(checks)
    written = _write_outputs(sim, block, T, inputs, output, plot, animate) if want_history else []
    if not (sim.settled[0] or sim.overturned[0]):
        click.echo(f"regimemap: warning: the block is still moving at t = {float(sim.end_time[0]):.6g} s, "
                   f"the time limit of the run (the pulse's {T:g} s + 60/p); its rotation and slide "
                   "there are not residual (JSON: settled false, residual_* null)", err=True)
    if sim.unresolved:
        click.echo(f"regimemap: warning: {sim.unresolved} step(s) had no admissible contact state "
                   "(a stuck corner was assumed)", err=True)
    _echo_run(record, written, as_json, numbers, design, checks)
    exit_on_failure(checks, check)


def _echo_run(record: dict[str, Any], written: list[str], as_json: bool, numbers: dict[str, float] | None,
              design: str | None, checks: list[Check]) -> None:
    """Print the run: one JSON object, or the text (the design wave's line, the run, the design
    check of the file) and the paths written."""
    if as_json:
        import json

        record["files"] = written
        click.echo(json.dumps(record, indent=1, allow_nan=False))
        return
    from ..io.dynamics import format_simulation

    if numbers is not None:
        from ..dynamics.design_wave import describe_design_wave

        click.echo("design     " + describe_design_wave(numbers, design))
    click.echo(format_simulation(record))
    if checks:
        from ..io.checks import checks_lines

        click.echo("design check of the file (--check: exit status 1 when a requirement fails)")
        click.echo("\n".join(checks_lines(checks)))
    for p in written:
        click.echo(p)


def _check_outputs(output: str | None, plot: str | None, animate: str | None) -> bool:
    """Check the files asked for (different, of known formats, in writable folders); whether any is."""
    paths = [p for p in (output, plot, animate) if p is not None]
    if len({str(Path(p).resolve()) for p in paths}) < len(paths):
        raise click.UsageError("-o, --plot and --animate must name different files")
    if output is not None:
        check_output_file(output, DATA_FORMATS, "--output", "the time history")
    if plot is not None:
        check_output_file(plot, FIGURE_FORMATS, "--plot", "the plot")
    if animate is not None:
        check_output_file(animate, ("gif",), "--animate", "the animation")
    return bool(paths)


def _write_outputs(sim: Simulation, block: Block, T: float, inputs: dict[str, Any], output: str | None,
                   plot: str | None, animate: str | None) -> list[str]:
    """Write the time history (-o), its plot (--plot) and the animation (--animate); the paths."""
    written: list[str] = []
    H = float(block.H)
    assert sim.history is not None
    hist = sim.history
    if output is not None:
        from ..io.dynamics import write_history

        with writing(output):
            write_history(output, hist, H, {k: v for k, v in inputs.items()
                                            if isinstance(v, (int, float, str))})
        written.append(output)
    if plot is None and animate is None:
        return written
    import_matplotlib()
    title = _run_title(inputs, T)
    if plot is not None:
        from ..drawing.motion.history import motion_figure
        from ..drawing.save import save_figure

        fig = motion_figure(hist, H=H, alpha=float(block.alpha), duration=T, title=title)
        with writing(plot):
            save_figure(fig, plot)
        written.append(plot)
    if animate is not None:
        from ..drawing.motion.history import write_block_animation

        kprime = inputs["kprime"]
        with writing(animate):
            n, (w, h), speed = write_block_animation(
                animate, hist, B=inputs["half_width"], H=H, kprime=kprime if kprime is not None else 0.0,
                overturned=bool(sim.overturned[0]), title=title)
        click.echo(f"{animate}: {n} frames, {w} x {h} pixels, "
                   + ("real time" if speed == 1.0 else f"{speed:.3g} x real time"), err=True)
        written.append(animate)
    return written


def _design_record(design: str | None, numbers: dict[str, float]) -> dict[str, Any]:
    """The "design" object of --json: where the numbers of --design came from."""
    from ..dynamics.design_wave import DESIGN_UNITS, NO_ADDED_MASS, PROFILE
    from ..io.dynamics import round_sig

    return {"file": design, **{key: round_sig(v) for key, v in numbers.items()},
            "profile": PROFILE, "added_mass_note": NO_ADDED_MASS, "units": dict(DESIGN_UNITS)}


def _read_pulse(path: str) -> Pulse:
    """A pulse file (--pulse-file), read only when one is given."""
    from ..io.pulses import read_pulse_csv

    return read_pulse_csv(path)


def _run_title(inputs: dict[str, Any], T: float) -> str:
    """The title of the plot and the animation: the pulse and the block (or the design file)."""
    design, pulse_file, k_peak, mu = inputs["design"], inputs["pulse_file"], inputs["k_peak"], inputs["mu"]
    if design is not None:  # the file gives the block: the title says which, and fits
        return f"{Path(design).name}: design wave, k = {k_peak:.4g}, τ0 = {T:.4g} s; μ = {mu:.3g}"
    kprime = inputs["kprime"]
    kp = "" if kprime is None else f", k' = {kprime:g}"
    what = (f"{inputs['pulse']} pulse, k_peak = {k_peak:g}, T = {T:g} s" if pulse_file is None
            else f"pulse {Path(pulse_file).name}")
    return f"{what}; γ = {inputs['gamma']:g}, B = {inputs['half_width']:g} m, μ = {mu:g}{kp}"


def _design_run(design: str, strict: bool = False
                ) -> tuple[Block, Pulse, dict[str, Any], dict[str, float], list[Check]]:
    """The block, the pulse, the inputs, the numbers and the requirements (Goda's safety factors
    against the file's required ones) of a design file's design wave (--design).

    Options that the file gives may not be given too; a bad file is a usage error naming the
    file and the key, as ``regimemap caisson`` reports it.  Implausible values (likely unit
    slips) are warnings on standard error, or with ``strict`` a usage error, as ``regimemap
    caisson`` gives them (:func:`regimemap.cli._plausible.check_plausible`).
    """
    from click.core import ParameterSource

    from ..dynamics.design_wave import DESIGN_INPUTS, design_wave_inputs, design_wave_numbers, design_wave_run

    ctx = click.get_current_context()
    given = [name for name in (*DESIGN_INPUTS, "pulse_file")
             if ctx.get_parameter_source(name) in (ParameterSource.COMMANDLINE, ParameterSource.ENVIRONMENT)]
    if given:
        flags = ", ".join("--" + n.replace("_", "-") for n in given)
        raise click.UsageError(f"{flags} and --design exclude each other: the design file gives the block "
                               "and the pulse (change the design file, or give the block without --design)")
    d = read_design_file(design, "'--design'")
    try:
        a = d.analyse()
    except ValueError as exc:
        check_plausible(d, None, strict, design, "'--design'")  # a unit slip may be why
        raise click.BadParameter(f"{design}: {exc}", param_hint="'--design'") from None
    check_plausible(d, a, strict, design, "'--design'")
    try:
        block, pulse = design_wave_run(a, d.site.depth, d.wave.period)
    except ValueError as exc:
        raise click.BadParameter(f"{design}: {exc}", param_hint="'--design'") from None
    from ..maps.caisson import stability_checks

    checks = stability_checks(a, (d.caisson.required_sliding, d.caisson.required_overturning))
    return (block, pulse, design_wave_inputs(a, d.site.depth, d.wave.period),
            design_wave_numbers(a, d.site.depth, d.wave.period), checks)
