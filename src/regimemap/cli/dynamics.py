"""``regimemap simulate`` (one run after initiation), ``regimemap outcome`` (an outcome map over two

Size: over 500 lines on purpose: three commands sharing option types, limits and outputs.
swept inputs) and ``regimemap dynamics-figures`` (the figures D.1-D.3).

The commands parse and check their options, call :mod:`regimemap.dynamics`,
and write through :mod:`regimemap.io`; matplotlib is imported only when a
figure or an animation is asked for.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ..dynamics.limits import INPUT_LIMITS, MAX_AXIS_VALUES, MAX_MAP_RUNS, MAX_STEPS, check_input
from ..dynamics.pulses import SHAPES
from ._common import (
    ParamType,
    RunError,
    check_kprime_crest,
    gamma_option,
    import_matplotlib,
    kprime_option,
    output_dir,
    output_path,
    report_written,
)
from .atlas import Values

if TYPE_CHECKING:  # pragma: no cover
    from ..dynamics import Block, Pulse

__all__ = ["simulate_cmd", "outcome_cmd", "dynamics_figures_cmd"]

FIGURE_FORMATS = ("png", "svg", "pdf")
DATA_FORMATS = ("npz", "csv")

#: Option name (without --, with _) -> the field of :class:`regimemap.dynamics.Block`.
_BLOCK_FIELD = {"half_width": "B", "gamma": "gamma", "mu": "mu", "kprime": "kprime", "gyration": "i2",
                "buoyancy": "beta", "uplift": "u", "uplift_ratio": "nu", "uplift_arm": "e_u"}
#: The inputs ``outcome`` can sweep, in the order of its options.
_SWEEPABLE = ("k_peak", "duration", "omega_p", "mu", "kprime", "gamma", "half_width", "gyration",
              "buoyancy", "uplift", "uplift_ratio", "uplift_arm")


class _Number(ParamType):
    """One number in the range of an input of :data:`regimemap.dynamics.limits.INPUT_LIMITS`."""

    name = "number"

    def __init__(self, what: str):
        self.what = what

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        lim = INPUT_LIMITS[self.what]
        try:
            v = float(str(value).strip())
        except ValueError:
            self.fail(f"{self.what} must be {lim.text}, got {value!r} (not a number)", param, ctx)
        if not lim.contains(v):
            self.fail(f"{self.what} must be {lim.text}, got {value!r}", param, ctx)
        return v + 0.0


def _values_type(what: str) -> ParamType:
    def check(v: float, what: str = what) -> float:
        return check_input(what, v)

    return Values(what, check, MAX_AXIS_VALUES)


_HELP = {
    "half_width": "Half width B of the block (m), > 0 up to 1000.",
    "mu": "Friction coefficient (0 to 100), static = kinetic.",
    "k_peak": "Peak of the pulse, F/(m g) (0 to 100); positive pushes towards O.",
    "duration": "Whole duration of the pulse (s), 1e-4 to 100.",
    "omega_p": "Instead of --duration: the pulse's circular frequency (rad/s): pi/duration, "
               "2 pi/duration for one-sine and one-cosine.",
    "restitution": "Ratio theta'+/theta'- of a rocking impact, 0 to 1 (default: Housner's plastic "
                   "impact, 1 - 1.5 sin^2(alpha) for a uniform block).",
    "buoyancy": "Buoyancy, upward through C, in units of m g (0 to <1). Default 0.",
    "uplift": "Uplift on the base, in units of m g (0 to <1; buoyancy + uplift < 1). Default 0.",
    "uplift_ratio": "Uplift proportional to the push: U = uplift m g + ratio F (0 to 10). Default 0.",
    "uplift_arm": "Where the uplift acts, from C towards O' over B (-1 to 1). Default 1/3 "
                  "(a triangular uplift pressure).",
    "gyration": "Radius of gyration about C over B (default: the uniform block's, "
                "sqrt((1 + gamma^2)/3)); at most sqrt(1 + gamma^2).",
}


def _opt(name: str, swept: bool, metavar: str, default: Any = None, required: bool = False,
         extra: str = "") -> Callable[[Any], Any]:
    flag = "--" + name.replace("_", "-")
    typ = _values_type(name) if swept else _Number(name)
    text = _HELP[name] + (extra if swept else "")
    return click.option(flag, name, type=typ, default=default, required=required,
                        metavar=("LIST" if swept else metavar), help=text)


def _block_options(swept: bool) -> Callable[[Any], Any]:
    more = " A list a,b,c or a range start:stop:count sweeps it."
    opts = [
        # simulate: --gamma, --half-width and --mu are required unless --design gives them
        (gamma_option(required=False) if not swept else
         click.option("--gamma", "gamma", required=True, type=_values_type("gamma"), metavar="LIST",
                      help="Aspect ratio gamma = H/B (0.001 to 1000), H the height of C above the "
                           "base." + more)),
        _opt("half_width", swept, "B", required=swept, extra=more),
        (kprime_option(required=False) if not swept else
         click.option("--kprime", "kprime", type=_values_type("kprime"), metavar="LIST",
                      help="Height of the push above C over H, in [-1, 1]." + more)),
        _opt("mu", swept, "MU", required=swept, extra=more),
        click.option("--pulse", "pulse", type=click.Choice(SHAPES), default=None,
                     help="Shape of the force pulse (see docs/dynamics.md)."),
        _opt("k_peak", swept, "K", extra=more),
        _opt("duration", swept, "T", extra=more),
        _opt("restitution", False, "E"),
        _opt("buoyancy", swept, "BETA", default=0.0 if not swept else None, extra=more),
        _opt("uplift", swept, "U", default=0.0 if not swept else None, extra=more),
        _opt("uplift_ratio", swept, "NU", default=0.0 if not swept else None, extra=more),
        _opt("uplift_arm", swept, "E_U", default=1.0 / 3.0 if not swept else None, extra=more),
        _opt("gyration", swept, "R", extra=more),
    ]

    def deco(f: Any) -> Any:
        for o in reversed(opts):
            f = o(f)
        return f

    return deco


def _suffix(path: str) -> str:
    return Path(path).suffix.lower().lstrip(".")


def _check_out(path: str, formats: Sequence[str], param: str, what: str) -> str:
    fmt = _suffix(path)
    if fmt not in formats:
        got = f".{fmt}" if fmt else "no suffix"
        raise click.BadParameter(f"{what} is written as {', '.join('.' + f for f in formats)} (from the "
                                 f"file suffix); got {got} in {path!r}", param_hint=f"'{param}'")
    output_path(path, param)
    return fmt


def _loads_and_gyration(gammas: Sequence[float], buoyancy: Sequence[float], uplift: Sequence[float],
                        gyration: Sequence[float] | None) -> None:
    from ..dynamics.limits import check_gyration, check_loads

    try:
        check_loads(max(buoyancy), max(uplift))
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="'--uplift' / '--buoyancy'") from None
    if gyration:
        try:
            check_gyration(max(gyration), min(gammas))
        except ValueError as exc:
            raise click.BadParameter(str(exc), param_hint="'--gyration'") from None


# -- simulate ----------------------------------------------------------------------------------


@click.command("simulate", short_help="Follow one run after initiation: phases, overturning, residuals.")
@_block_options(swept=False)
@click.option("--pulse-file", "pulse_file", type=click.Path(dir_okay=False), metavar="FILE.csv",
              help="Instead of --pulse/--k-peak/--duration: a sampled force history, a CSV with "
                   "columns t (s),k and optionally kprime (then it replaces --kprime).")
@click.option("--design", "design", type=click.Path(dir_okay=False), metavar="FILE.toml",
              help="Instead of the block and the pulse: a caisson's design file (`regimemap caisson "
                   "--example` prints one).  Runs the caisson's equivalent block under its design "
                   "wave Hmax: a half-sine of peak k = P/(m g) lasting tau0 = (0.5 - Hmax/(8 h)) T1/3 "
                   "(Shimosako & Takahashi 1999), the uplift U = nu P in phase.  The file gives "
                   "--gamma, --half-width, --kprime, --mu, the loads, --gyration and the pulse; "
                   "giving any of them too is an error.  No added mass of water.")
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
                 as_json: bool, output: str | None, plot: str | None, animate: str | None) -> None:
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

    The pulse is --pulse KIND --k-peak K --duration T (k = 0 after T), or a
    CSV --pulse-file with columns t,k[,kprime].

    --design FILE.toml (the design file of `regimemap caisson`) gives the
    block and the pulse instead: the caisson's equivalent loaded block
    under its design wave Hmax, a half-sine of peak k = P/(m g) lasting
    tau0 = (0.5 - Hmax/(8 h)) T1/3, with the uplift in phase -- the force
    history of the lifetime model.  The block is rigid: no added mass of
    water (the lifetime model has it).  A line "design ..." says where the
    numbers came from; --json adds them as "design".

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
    from ..dynamics import Block, Pulse

    block: Block | None = None
    numbers: dict[str, float] | None = None
    if design is not None:  # -- the block and the pulse from a design file -------------------
        block, pls, values, numbers = _design_run(design)
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
    # -- the pulse (with --design, the design wave's, above) -----------------------------------
    given = [n for n, v in (("--pulse", pulse), ("--k-peak", k_peak), ("--duration", duration))
             if v is not None]
    if design is None and pulse_file is not None:
        if given:
            raise click.UsageError(f"{', '.join(given)} and --pulse-file exclude each other: give a pulse "
                                   "shape or a file")
        from ..io.pulses import read_pulse_csv

        try:
            pls = read_pulse_csv(pulse_file)
        except ValueError as exc:
            raise click.BadParameter(str(exc), param_hint="'--pulse-file'") from None
        if pls.has_kprime and kprime is not None:
            raise click.UsageError(f"--kprime and the kprime column of {pulse_file} exclude each other")
    elif design is None:
        missing = [n for n in ("--pulse", "--k-peak", "--duration") if n not in given]
        if missing:
            raise click.UsageError(f"missing option(s) {', '.join(missing)}: give --pulse KIND "
                                   "--k-peak K --duration T, or --pulse-file FILE.csv")
        assert pulse is not None and k_peak is not None and duration is not None
        pls = Pulse.make(pulse, k_peak, duration)
    if kprime is None and not pls.has_kprime:
        raise click.UsageError("missing option --kprime: the height of the push above C over H, in "
                               "[-1, 1] (or a kprime column in --pulse-file)")
    _loads_and_gyration([gamma], [buoyancy], [uplift], [gyration] if gyration is not None else None)

    # -- the outputs, checked before the run -------------------------------------------------
    paths = [p for p in (output, plot, animate) if p is not None]
    if len({str(Path(p).resolve()) for p in paths}) < len(paths):
        raise click.UsageError("-o, --plot and --animate must name different files")
    if output is not None:
        _check_out(output, DATA_FORMATS, "--output", "the time history")
    if plot is not None:
        _check_out(plot, FIGURE_FORMATS, "--plot", "the plot")
    if animate is not None:
        _check_out(animate, ("gif",), "--animate", "the animation")

    from ..dynamics import simulate
    from ..dynamics.limits import estimated_steps

    if block is None:
        block = Block(B=half_width, gamma=gamma, mu=mu, kprime=kprime if kprime is not None else 0.0,
                      i2=None if gyration is None else gyration * gyration, beta=buoyancy, u=uplift,
                      nu=uplift_ratio, e_u=uplift_arm)
    T = float(pls.duration)
    steps = estimated_steps(block, T)
    if steps > MAX_STEPS:
        raise click.BadParameter(
            f"the run needs up to {steps} time steps (the pulse of {T:g} s at a step of at most "
            f"0.004/p = {0.004 / float(block.p):.3g} s, then 60/p s of free motion), more than the limit "
            f"of {MAX_STEPS}; give a shorter pulse", param_hint="'--duration'")
    want_history = bool(paths)
    sim = simulate(block, pls, restitution=restitution, history=0 if want_history else None)

    inputs: dict[str, Any] = {
        "gamma": gamma, "half_width": half_width, "kprime": kprime, "mu": mu,
        "pulse": pulse if pulse_file is None else "file", "k_peak": k_peak, "duration": duration,
        "pulse_file": pulse_file, "restitution": restitution, "buoyancy": buoyancy, "uplift": uplift,
        "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm, "gyration": gyration, "design": design,
    }
    eta = float(block.housner_ratio) if restitution is None else restitution
    derived = {"p": float(block.p), "alpha": float(block.alpha), "H": float(block.H),
               "impact_ratio": eta, "k_peak": float(pls.k_peak), "duration": T,
               "omega_p": float(pls.omega_p)}
    from ..io.dynamics import format_simulation, simulation_record

    record = simulation_record(sim, inputs, derived)
    if numbers is not None:
        from ..dynamics.design_wave import DESIGN_UNITS, NO_ADDED_MASS, PROFILE
        from ..io.dynamics import round_sig

        record["design"] = {"file": design, **{key: round_sig(v) for key, v in numbers.items()},
                            "profile": PROFILE, "added_mass_note": NO_ADDED_MASS,
                            "units": dict(DESIGN_UNITS)}

    written: list[str] = []
    H = float(block.H)
    if want_history:
        assert sim.history is not None
        hist = sim.history
        if output is not None:
            from ..io.dynamics import write_history

            try:
                write_history(output, hist, H, {k: v for k, v in inputs.items()
                                                if isinstance(v, (int, float, str))})
            except OSError as exc:
                raise RunError(f"cannot write {output}: {exc.strerror or exc}") from None
            written.append(output)
        if plot is not None or animate is not None:
            import_matplotlib()
            title = _run_title(pulse, pulse_file, k_peak, T, gamma, half_width, mu, kprime, design)
        if plot is not None:
            from ..drawing.motion import motion_figure
            from ..io.dynamics import write_motion_plot

            fig = motion_figure(hist, H=H, alpha=float(block.alpha), duration=T, title=title)
            try:
                write_motion_plot(plot, fig)
            except OSError as exc:
                raise RunError(f"cannot write {plot}: {exc.strerror or exc}") from None
            written.append(plot)
        if animate is not None:
            from ..io.dynamics import write_block_animation

            try:
                n, (w, h), speed = write_block_animation(
                    animate, hist, B=half_width, H=H, kprime=kprime if kprime is not None else 0.0,
                    overturned=bool(sim.overturned[0]), title=title)
            except OSError as exc:
                raise RunError(f"cannot write {animate}: {exc.strerror or exc}") from None
            click.echo(f"{animate}: {n} frames, {w} x {h} pixels, "
                       + ("real time" if speed == 1.0 else f"{speed:.3g} x real time"), err=True)
            written.append(animate)
    if sim.unresolved:
        click.echo(f"regimemap: warning: {sim.unresolved} step(s) had no admissible contact state "
                   "(a stuck corner was assumed)", err=True)
    if as_json:
        import json

        record["files"] = written
        click.echo(json.dumps(record, indent=1, allow_nan=False))
        return
    if numbers is not None:
        from ..dynamics.design_wave import describe_design_wave

        click.echo("design     " + describe_design_wave(numbers, design))
    click.echo(format_simulation(record))
    for p in written:
        click.echo(p)


def _run_title(pulse: str | None, pulse_file: str | None, k_peak: float | None, T: float, gamma: float,
               B: float, mu: float, kprime: float | None, design: str | None = None) -> str:
    if design is not None:  # the file gives the block: the title says which, and fits
        return f"{Path(design).name}: design wave, k = {k_peak:.4g}, τ0 = {T:.4g} s; μ = {mu:.3g}"
    kp = "" if kprime is None else f", k' = {kprime:g}"
    what = (f"{pulse} pulse, k_peak = {k_peak:g}, T = {T:g} s" if pulse_file is None
            else f"pulse {Path(pulse_file).name}")
    return f"{what}; γ = {gamma:g}, B = {B:g} m, μ = {mu:g}{kp}"


def _design_run(design: str) -> tuple[Block, Pulse, dict[str, Any], dict[str, float]]:
    """The block, the pulse, the inputs and the numbers of a design file's design wave (--design).

    Options that the file gives may not be given too; a bad file is a usage error naming the
    file and the key, as ``regimemap caisson`` reports it.
    """
    from click.core import ParameterSource

    from ..dynamics.design_wave import DESIGN_INPUTS, design_wave_inputs, design_wave_numbers, design_wave_run
    from ..io.design import DesignFileError, read_design

    ctx = click.get_current_context()
    given = [name for name in (*DESIGN_INPUTS, "pulse_file")
             if ctx.get_parameter_source(name) in (ParameterSource.COMMANDLINE, ParameterSource.ENVIRONMENT)]
    if given:
        flags = ", ".join("--" + n.replace("_", "-") for n in given)
        raise click.UsageError(f"{flags} and --design exclude each other: the design file gives the block "
                               "and the pulse (change the design file, or give the block without --design)")
    try:
        d = read_design(design)
    except DesignFileError as exc:
        raise click.BadParameter(str(exc), param_hint="'--design'") from None
    try:
        a = d.analyse()
        block, pulse = design_wave_run(a, d.site.depth, d.wave.period)
    except ValueError as exc:
        raise click.BadParameter(f"{design}: {exc}", param_hint="'--design'") from None
    return (block, pulse, design_wave_inputs(a, d.site.depth, d.wave.period),
            design_wave_numbers(a, d.site.depth, d.wave.period))


# -- outcome -----------------------------------------------------------------------------------


@click.command("outcome", short_help="Outcome map (rest, slide, rock, slide-rock, overturned) over two "
                                     "swept inputs.")
@_block_options(swept=True)
@_opt("omega_p", True, "W", extra=" A list a,b,c or a range start:stop:count sweeps it.")
@click.option("--dimensionless", is_flag=True,
              help="Draw (and export) the axes as omega_p/p and k_peak/tan(alpha) (Makris & Roussos "
                   "2000), for a k_peak, duration or omega_p sweep.")
@click.option("-o", "--output", "outputs", type=click.Path(dir_okay=False), metavar="FILE",
              multiple=True, required=True,
              help="Output file (repeatable): .png, .svg or .pdf draws the map, .npz or .csv "
                   "writes its data (atomically).")
def outcome_cmd(gamma: list[float], half_width: list[float], kprime: list[float] | None, mu: list[float],
                pulse: str | None, k_peak: list[float] | None, duration: list[float] | None,
                restitution: float | None, buoyancy: list[float] | None, uplift: list[float] | None,
                uplift_ratio: list[float] | None, uplift_arm: list[float] | None,
                gyration: list[float] | None, omega_p: list[float] | None, dimensionless: bool,
                outputs: tuple[str, ...]) -> None:
    """Simulate a grid of runs over two swept inputs and map their outcome.

    Give exactly two inputs as lists (0.2,0.5,1.2) or ranges start:stop:count
    (0.3:1.5:121, both ends included) and every other one as a single value:
    the first swept option on the command line runs along the horizontal
    axis, the second up the vertical one.  Any of --k-peak, --duration (or
    --omega-p), --mu, --kprime, --gamma, --half-width, --gyration,
    --buoyancy, --uplift, --uplift-ratio and --uplift-arm can be swept.

    Each cell gets its category: rest, slide only, rock only, slide-rock or
    overturned.  A figure (.png, .svg, .pdf) shows them as coloured, hatched
    regions with contours of the residual slide (m) and of the maximum
    rotation (deg); data (.npz, .csv) has 1-D arrays named after the swept
    options and 2-D arrays category, overturned, max_rotation (rad) and
    residual_slide (m, positive towards O) of shape (len(second), len(first)).
    At most 250000 runs; the time is about 1 ms per run on one core
    (more for long free rocking).

    \b
    Examples:
      regimemap outcome --gamma 3 --half-width 0.2 --kprime 0 --mu 0.5 \\
          --pulse half-sine --k-peak 0.3:1.5:25 --duration 0.2,0.5,1.2 -o map.png
      regimemap outcome --gamma 3 --half-width 0.2 --kprime 0 --mu 5 \\
          --pulse half-sine --omega-p 3:30:28 --k-peak 0.3:2.5:23 --dimensionless \\
          -o spectrum.svg -o spectrum.npz
    """
    ctx = click.get_current_context()
    values: dict[str, list[float] | None] = {
        "k_peak": k_peak, "duration": duration, "omega_p": omega_p, "mu": mu, "kprime": kprime,
        "gamma": gamma, "half_width": half_width, "gyration": gyration, "buoyancy": buoyancy,
        "uplift": uplift, "uplift_ratio": uplift_ratio, "uplift_arm": uplift_arm}
    # the swept inputs, in the order given on the command line (click fills ctx.params in that order)
    order = [n for n in ctx.params if n in values]
    swept = [n for n in order if values[n] is not None and len(values[n] or []) > 1]
    if len(swept) != 2:
        got = ", ".join("--" + n.replace("_", "-") for n in swept) or "none"
        raise click.UsageError(f"give exactly two swept inputs (lists a,b,c or ranges start:stop:count "
                               f"with two or more values, e.g. --k-peak 0.3:1.5:121 --duration 0.2,0.5,1.2) "
                               f"and one value for every other input; swept: {got}")
    for name in swept:
        vals = sorted(values[name] or [])
        if any(b <= a for a, b in zip(vals, vals[1:])):
            raise click.BadParameter("a value appears twice", param_hint=f"'--{name.replace('_', '-')}'")
        values[name] = vals
    if pulse is None:
        raise click.UsageError("missing option --pulse: the shape of the force pulse "
                               f"({', '.join(SHAPES)})")
    if k_peak is None:
        raise click.UsageError("missing option --k-peak: the peak of the pulse (0 to 100), one value "
                               "or a list")
    if (duration is None) == (omega_p is None):
        raise click.UsageError("give one of --duration (s) or --omega-p (rad/s)" if duration is None
                               else "--duration and --omega-p exclude each other")
    if kprime is None:
        raise click.UsageError("missing option --kprime: the height of the push above C over H, in "
                               "[-1, 1]")
    fixed = {n: (v[0] if v else None) for n, v in values.items() if n not in swept}
    defaults = {"buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0, "uplift_arm": 1.0 / 3.0}
    for n, d in defaults.items():
        if n not in swept and fixed[n] is None:
            fixed[n] = d
    _loads_and_gyration(values["gamma"] or [], values["buoyancy"] or [0.0], values["uplift"] or [0.0],
                        values["gyration"])
    if dimensionless:
        from ..dynamics.outcome import DIMENSIONLESS

        varying = [n for n in swept if n in ("gamma", "half_width", "gyration")]
        if varying:
            flag = "--" + varying[0].replace("_", "-")
            raise click.BadParameter(f"the dimensionless axes need one block, but {flag} is swept "
                                     "(p and alpha would change from cell to cell)",
                                     param_hint="'--dimensionless'")
        if not any(n in DIMENSIONLESS for n in swept):
            raise click.BadParameter("the dimensionless axes are omega_p/p and k_peak/tan(alpha): sweep "
                                     "--k-peak, --duration or --omega-p", param_hint="'--dimensionless'")
    n_runs = len(values[swept[0]] or []) * len(values[swept[1]] or [])
    if n_runs > MAX_MAP_RUNS:
        raise click.UsageError(f"{n_runs} runs exceed the limit of {MAX_MAP_RUNS}; give fewer values")

    # -- outputs ----------------------------------------------------------------------------
    if len({str(Path(p).resolve()) for p in outputs}) < len(outputs):
        raise click.BadParameter("the same file is given twice", param_hint="'-o' / '--output'")
    kinds = [_check_out(p, FIGURE_FORMATS + DATA_FORMATS, "--output", "an outcome map") for p in outputs]

    import numpy as np

    from ..dynamics import Block, outcome_map
    from ..dynamics.limits import estimated_steps

    def block_value(n: str) -> Any:
        v = fixed.get(n)
        if n == "gyration":
            return None if v is None else v * v
        return v

    bfields = {_BLOCK_FIELD[n]: block_value(n) for n in _BLOCK_FIELD if n not in swept}
    # the longest run: the smallest p of any combination, the longest pulse
    gs = np.asarray(values["gamma"] or [], dtype=np.float64)
    bs = np.asarray(values["half_width"] or [], dtype=np.float64)
    rg = values["gyration"]
    G3, B3, R3 = np.meshgrid(gs, bs, np.asarray(rg if rg else [math.nan]), indexing="ij")
    i2 = None if not rg else (R3 * R3).ravel()
    probe = Block(B=B3.ravel(), gamma=G3.ravel(), mu=0.0, i2=i2)
    if duration is not None:
        t_long = max(values["duration"] or [])
    else:
        cycles = 2.0 if pulse in ("one-sine", "one-cosine") else 1.0
        t_long = cycles * math.pi / min(values["omega_p"] or [])
    steps = estimated_steps(probe, t_long)
    if steps > MAX_STEPS:
        raise click.BadParameter(f"the longest run needs up to {steps} time steps, more than the limit of "
                                 f"{MAX_STEPS}; give shorter pulses",
                                 param_hint="'--duration'" if duration is not None else "'--omega-p'")
    lib = {n: ("i2" if n == "gyration" else _BLOCK_FIELD.get(n, n)) for n in swept}
    axes_values = {n: np.asarray(values[n] or [], dtype=np.float64) for n in swept}
    lib_values = {n: (axes_values[n] ** 2 if n == "gyration" else axes_values[n]) for n in swept}
    block = Block(**bfields)
    click.echo(f"simulating {n_runs} runs ({len(axes_values[swept[0]])} x {len(axes_values[swept[1]])}) ...",
               err=True)
    fixed_duration = fixed.get("duration")
    w_fixed = fixed.get("omega_p")
    if w_fixed is not None:  # one frequency: its duration
        fixed_duration = (2.0 if pulse in ("one-sine", "one-cosine") else 1.0) * math.pi / w_fixed
    m = outcome_map(block, pulse, (lib[swept[0]], lib_values[swept[0]]),
                    (lib[swept[1]], lib_values[swept[1]]),
                    k_peak=fixed.get("k_peak"), duration=fixed_duration, restitution=restitution)
    import dataclasses

    m = dataclasses.replace(m, first_name=swept[0], first_values=axes_values[swept[0]],
                            second_name=swept[1], second_values=axes_values[swept[1]])
    counts = np.bincount(m.category.ravel().astype(np.int64), minlength=len(m.labels))
    click.echo(f"{n_runs} runs in {m.seconds:.1f} s: "
               + ", ".join(f"{lab} {c}" for lab, c in zip(m.labels, counts.tolist()) if c), err=True)

    dim: dict[str, Any] = {}
    if dimensionless:
        from ..dynamics.outcome import DIMENSIONLESS, dimensionless_values

        for n in swept:
            if n in DIMENSIONLESS:
                dim[n] = dimensionless_values(n, axes_values[n], block, pulse)
    written: list[str] = []
    fig = None
    for path, kind in zip(outputs, kinds):
        try:
            if kind in DATA_FORMATS:
                from ..io.dynamics import write_outcome

                extra = {f"{n}_dimensionless": v for n, v in dim.items()}
                write_outcome(path, m, swept[0], swept[1], inputs=_export_inputs(fixed, pulse, restitution),
                              axes=extra)
            else:
                if fig is None:
                    import_matplotlib()
                    from ..drawing.outcome import axis_label, outcome_figure, outcome_title

                    fig, _, _ = outcome_figure(
                        m, x=dim.get(swept[0]), y=dim.get(swept[1]),
                        xlabel=axis_label(swept[0], swept[0] in dim, pulse),
                        ylabel=axis_label(swept[1], swept[1] in dim, pulse),
                        title=outcome_title(pulse, fixed, restitution))
                from ..io.figures import save_figure

                save_figure(fig, path, kind)
        except OSError as exc:
            raise RunError(f"cannot write {path}: {exc.strerror or exc}") from None
        written.append(path)
    for p in written:
        click.echo(p)


def _export_inputs(fixed: dict[str, Any], pulse: str, restitution: float | None) -> dict[str, Any]:
    out: dict[str, Any] = {"pulse": pulse}
    for n, v in fixed.items():
        if v is not None:
            out[n] = v
    if restitution is not None:
        out["restitution"] = restitution
    return out


# -- the figures D.1-D.3 -------------------------------------------------------------------------


@click.command("dynamics-figures", short_help="Draw the outcome-map figures D.1-D.3 into a folder.")
@click.option("--out", "out_dir", default=".", show_default=True, metavar="DIR",
              help="Existing, writable folder for the files.")
@click.option("--format", "formats", default="png", show_default=True, metavar="FORMATS",
              help="Comma-separated formats: png, svg, pdf.")
@click.option("--cache", "cache", default=None, metavar="DIR",
              help="Keep the computed maps in DIR (created if missing) and reuse them while the "
                   "figures' definitions and regimemap.dynamics are unchanged.")
@click.option("--list", "list_only", is_flag=True, help="List the figures; draw nothing.")
def dynamics_figures_cmd(out_dir: str, formats: str, cache: str | None, list_only: bool) -> None:
    """Draw the figures of regimemap.dynamics (D.1, D.2, D.3) into a folder.

    D.1 and D.2 are the overturning spectra of a half-sine and of a one-sine
    pulse in the dimensionless axes of Makris & Roussos (2000) and Zhang &
    Makris (2001); D.3 is a caisson under a breaking-wave pulse.  Each is an
    outcome map computed on a grid (3 to 25 s each on one core); the files
    are dyn-<ID>.<format>, byte-identical from run to run.  With --cache DIR
    the maps are kept in DIR and only drawn again next time (the same bytes),
    until the figures' definitions, regimemap.dynamics or the versions of
    regimemap or numpy change (make figures uses .cache/dynamics-figures).

    \b
    Examples:
      regimemap dynamics-figures --out figures --format png,svg
      regimemap dynamics-figures --list
    """
    from ..drawing.dynamics_presets import DYNAMICS_FIGURES

    if list_only:
        for f in DYNAMICS_FIGURES.values():
            click.echo(f"{f.id:4s} {f.caption}")
        return
    fmts = [s.strip().lower().lstrip(".") for s in formats.split(",") if s.strip()]
    bad = [f for f in fmts if f not in FIGURE_FORMATS]
    if not fmts or bad:
        what = f"unknown format {bad[0]!r}" if bad else "no format given"
        raise click.BadParameter(f"{what}; use a comma-separated list of {', '.join(FIGURE_FORMATS)}",
                                 param_hint="'--format'")
    folder = output_dir(out_dir, "--out")
    if cache is not None and Path(cache).exists() and not Path(cache).is_dir():
        raise click.BadParameter(f"{cache!r} is a file, not a folder", param_hint="'--cache'")
    import_matplotlib()
    from ..io.dynamics import cached_outcome
    from ..io.figures import save_figure

    count = 0
    for f in DYNAMICS_FIGURES.values():
        t0 = time.perf_counter()
        try:
            m, x, y, hit = cached_outcome(cache, f.id, repr(f), f.compute)
        except OSError as exc:
            raise RunError(f"cannot write to the cache {cache}: {exc.strerror or exc}") from None
        fig = f.render(data=(m, x, y))
        for fmt in dict.fromkeys(fmts):
            path = folder / f.filename(fmt)
            try:
                save_figure(fig, path, fmt)
            except OSError as exc:
                raise RunError(f"cannot write {path}: {exc.strerror or exc}") from None
            count += 1
            report_written(path)
        how = "from the cache" if hit else f"{m.category.size} runs"
        click.echo(f"{f.id}: {time.perf_counter() - t0:.1f} s ({how})", err=True)
    click.echo(f"regimemap: {count} files ({len(DYNAMICS_FIGURES)} figures x "
               f"{', '.join(dict.fromkeys(fmts))}) in {folder}", err=True)
