"""``regimemap atlas`` (small multiples) and ``regimemap animate`` (a GIF sweeping k')."""

from __future__ import annotations

from typing import Any

import click

from ..drawing.limits import (
    ANIMATION_DPI,
    ANIMATION_DPI_RANGE,
    ATLAS_DPI,
    ATLAS_DPI_RANGE,
    FPS_RANGE,
    MAX_FRAMES,
    MAX_PANELS,
)
from ..io.formats import FIGURES
from ..mechanics.validation import check_gamma
from ._common import (
    LOAD_OPTIONS,
    Values,
    axis_options,
    check_kprime_crest,
    gamma_option,
    load_options,
    output_option,
    view_option,
)
from ._main import import_matplotlib
from ._writing import checked_output, echo_notices, figure_output, report_written, writing

__all__ = ["atlas_cmd", "animate_cmd"]


def _kprime_check(v: float) -> float:
    """One k' of a list, before the crest is known: in [-1, 1], or up to the largest crest.

    :func:`_up_to_crest` then checks it against the crest given (1 by default), as
    ``regimemap plot`` checks its ``--kprime`` (:func:`regimemap.cli._common.check_kprime_crest`).
    """
    from ..mechanics.validation import LOAD_LIMITS, check_kprime

    try:
        return check_kprime(v, LOAD_LIMITS["crest"][1])
    except ValueError:
        raise ValueError(f"kprime must be a number in [-1, 1] (up to --crest), got {v!r}") from None


def _up_to_crest(kprimes: list[float], loads: dict[str, list[float]]) -> list[float]:
    """``--kprime`` checked against [-1, crest] (the lowest crest when --crest sweeps).

    The rule of ``regimemap plot`` (:func:`regimemap.cli._common.check_kprime_crest`): a
    usage error naming ``--kprime`` and the range.
    """
    crest = min(loads.get("crest", [1.0]))
    return [check_kprime_crest(kp, crest) for kp in kprimes]


def _sweep(kprimes: list[float], loads: dict[str, list[float]], axis: str
           ) -> tuple[str, list[float], dict[str, Any]]:
    """What varies along ``axis`` (columns, frames): k' or the one load given several values.

    Returns ``(sweep, values, fixed)``; a usage error if two quantities have several values.
    """
    options = {"kprime": "--kprime", **{name: opt for name, opt, *_ in LOAD_OPTIONS}}
    given: dict[str, list[float]] = {"kprime": kprimes, **loads}
    several = [name for name, values in given.items() if len(values) > 1]
    if len(several) > 1:
        names = " and ".join(options[n] for n in several)
        raise click.UsageError(
            f"one quantity per axis: {names} each have several values; the {axis} sweep one "
            f"of k' or a load, give the others one value each")
    sweep = several[0] if several else "kprime"
    fixed = {name: values[0] for name, values in given.items() if name != sweep}
    return sweep, given[sweep], fixed


def _checked_blocks(gammas: list[float], sweep: str, values: list[float], fixed: dict[str, Any]
                    ) -> list[Any]:
    """The block of every panel or frame; a usage error when one cannot exist (k' above the crest)."""
    from ..maps.sweeps import sweep_params

    try:
        return [sweep_params(g, sweep, v, fixed) for g in gammas for v in values]
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None


@click.command("atlas", short_help="Small multiples of the map: rows gamma, columns k'.")
@click.option("--gamma", "gammas", required=True, metavar="LIST",
              type=Values("gamma", check_gamma, MAX_PANELS),
              help="Aspect ratios H/B (> 0), one row each: 1,2,3 or start:stop:count.")
@click.option("--kprime", "kprimes", required=True, metavar="LIST",
              type=Values("kprime", _kprime_check, MAX_PANELS),
              help="Force heights h/H in [-1, 1] (up to --crest), one column each: -0.6,0,0.4 "
                   "or -1:1:5.")
@click.option("--share", type=click.Choice(["all", "row", "none"]), default="all",
              show_default=True,
              help="Axes shared by the whole figure, within each row, or not at all.")
@axis_options("Right end of the k axis of every panel (default: automatic).",
              "Top of the mu axis of every panel (default: automatic).")
@view_option("Each panel's own view: mu up to 1.2 (designer) or every characteristic point (report).")
@click.option("--dpi", type=click.IntRange(*ATLAS_DPI_RANGE), default=ATLAS_DPI, show_default=True,
              help="Resolution of PNG output.")
@output_option(f"Output file: {FIGURES} (written atomically).", required=True)
@load_options(sweep=MAX_PANELS)
def atlas_cmd(gammas: list[float], kprimes: list[float], share: str, k_max: float | None,
              mu_max: float | None, view: str, dpi: int, output: str,
              loads: dict[str, list[float]]) -> None:
    """Draw the all-mode map for every GAMMA (rows) and KPRIME (columns) on one page.

    The panels share their axes (--share all, the default), so regions can be
    compared by eye; --share row gives each row its own view, --share none
    each panel.  A shared view is the upper quartile of the panels' automatic
    views (a panel with k' near 0 or -1 would otherwise push the axes far
    out); panels whose point A falls outside are named on standard error;
    --k-max/--mu-max fix the view.  One legend serves all panels; each panel is titled with its
    gamma and k'.  At most 48 panels.

    Lists are comma-separated (1,2,3) or ranges start:stop:count with both
    ends included (-1:1:5 is -1, -0.5, 0, 0.5, 1).

    The columns may sweep a load instead of k': give --kprime one value and
    a list to one of --buoyancy, --uplift, --uplift-ratio, --uplift-arm,
    --gyration, --crest (one quantity per axis; the others take one value).
    The page title names the swept quantity and what the panels share.

    \b
    Examples:
      regimemap atlas --gamma 1,2,3 --kprime -0.6,-0.2,0,0.4,0.9 -o atlas.svg
      regimemap atlas --gamma 3 --kprime -1:1:5 --share none -o row.png
      regimemap atlas --gamma 0.5:3:6 --kprime -0.4 --mu-max 3 -o slender.pdf
      regimemap atlas --gamma 0.7 --kprime -0.02 --uplift-ratio 0.52 --buoyancy 0,0.3,0.6 -o b.png
    """
    kprimes = _up_to_crest(kprimes, loads)
    sweep, values, fixed = _sweep(kprimes, loads, "columns")
    n = len(gammas) * len(values)
    if n > MAX_PANELS:
        opt = "--kprime" if sweep == "kprime" else "--" + sweep.replace("_", "-")
        raise click.UsageError(
            f"{len(gammas)} gamma x {len(values)} {sweep} = {n} panels exceed the limit of "
            f"{MAX_PANELS}; give fewer values to --gamma or {opt}")
    _checked_blocks(gammas, sweep, values, fixed)
    _, fmt = figure_output(output)
    import_matplotlib()
    from ..maps.figures.atlas import write_atlas
    from ..maps.run_atlas import run_atlas

    record = run_atlas(gammas, values, sweep=sweep, fixed=fixed, share=share, k_max=k_max,
                       mu_max=mu_max, view=view)
    with writing(output):
        write_atlas(output, record, fmt=fmt, dpi=dpi)
    across = "" if sweep == "kprime" else f", columns {sweep}"
    report_written(output, f"{len(gammas)} x {len(values)} panels{across}")
    echo_notices(record.notices, _NOTE_PREFIX)


@click.command("animate", short_help="A GIF of the map as k' sweeps a range.")
@gamma_option()
@click.option("--kprime", "kprimes", required=True, metavar="RANGE",
              type=Values("kprime", _kprime_check, MAX_FRAMES),
              help="k' of the frames: start:stop:count (e.g. -1:1:41) or a list -1,-0.5,0; "
                   "in [-1, 1] (up to --crest).")
@view_option("The view of the frames: mu up to 1.2 (designer) or every characteristic point (report).")
@click.option("--fps", type=click.FloatRange(*FPS_RANGE), default=8.0, show_default=True,
              help="Frames per second.")
@click.option("--dpi", type=click.IntRange(*ANIMATION_DPI_RANGE), default=ANIMATION_DPI, show_default=True,
              help="Pixels per inch (the frame is 5.2 x 4.5 inches: 520 x 450 at 100).")
@axis_options("Right end of the k axis (default: upper quartile of the frames' automatic views).",
              "Top of the mu axis (default: upper quartile of the frames' automatic views).")
@output_option("Output GIF (written atomically).", metavar="FILE.gif", required=True)
@load_options(sweep=MAX_FRAMES)
def animate_cmd(gamma: float, kprimes: list[float], view: str, fps: float, dpi: int,
                k_max: float | None, mu_max: float | None, output: str,
                loads: dict[str, list[float]]) -> None:
    """Animate the map of GAMMA as k' runs through a range (a GIF).

    Every frame shows the all-mode map on the same axes (the upper quartile
    of the frames' automatic views, or --k-max/--mu-max; frames whose point A
    falls outside are named on standard error), its title states the
    report's case, and the frame's k' is written in the top right corner.
    At most 400 frames.

    The frames may sweep a load instead of k': give --kprime one value and a
    range to one load option (e.g. --uplift-ratio 0:1:21); the swept value is
    written in the corner, the loads in the title.

    \b
    Examples:
      regimemap animate --gamma 3 --kprime -1:1:41 -o sweep.gif
      regimemap animate --gamma 1.5 --kprime -0.8:0:17 --fps 4 --k-max 5 --mu-max 3 -o below.gif
      regimemap animate --gamma 0.7 --kprime -0.02 --buoyancy 0.32 --uplift-ratio 0:1:21 -o nu.gif
    """
    checked_output(output, "animation", hint="'-o' / '--output'")
    kprimes = _up_to_crest(kprimes, loads)
    sweep, values, fixed = _sweep(kprimes, loads, "frames")
    _checked_blocks([gamma], sweep, values, fixed)
    import_matplotlib()
    from ..maps.figures.animation import write_animation
    from ..maps.run_atlas import run_animation

    record = run_animation(gamma, values, k_max=k_max, mu_max=mu_max, view=view, sweep=sweep,
                           fixed=fixed)
    with writing(output):
        n, (w, h) = write_animation(output, record.frames, fps=fps, dpi=dpi)
    report_written(output, f"{n} frames, {w} x {h} pixels, {fps:g} frames/s")
    echo_notices(record.notices, _NOTE_PREFIX)


#: How the notes of an atlas or an animation start on standard error.
_NOTE_PREFIX = {"crammed": "regimemap: note: ", "outside-view": "note: "}
