"""``regimemap classify``: the mode at a design point, its physics and its margin."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import click

from ..io.formats import suffix_of
from ..mechanics.validation import MAX_VALUE
from ._common import Checked, gamma_option, json_option, kprime_option, load_options, output_option
from ._inputs import POINTS_FILE
from ._main import RunError
from ._plot_options import read_points_file
from ._writing import output_path, print_report, report_written, writing

if TYPE_CHECKING:
    from ..maps.points import DesignPoint

__all__ = ["classify_cmd"]


def _non_negative(what: str) -> Checked:
    """A finite float >= 0 (k, mu)."""
    def check(text: str) -> float:
        try:
            v = float(text)
        except ValueError:
            v = math.nan
        if not (math.isfinite(v) and 0.0 <= v <= MAX_VALUE):
            raise ValueError(f"{what} must be a finite number in [0, {MAX_VALUE:g}], got {text!r}")
        return v

    return Checked("number", check)


@click.command(
    "classify",
    short_help="Mode, physics at initiation and margin at a design point (or a CSV of points).",
)
@gamma_option(required=False)
@kprime_option(required=False)
@click.option("--k", "k", type=_non_negative("k"), metavar="K",
              help=f"Force F/(mg) in [0, {MAX_VALUE:g}] (one point).")
@click.option("--mu", "mu", type=_non_negative("mu"), metavar="MU",
              help=f"Friction coefficient in [0, {MAX_VALUE:g}] (one point).")
@click.option("--points", "points_file", type=POINTS_FILE,
              metavar="FILE.csv",
              help="Classify every row of a CSV with columns k,mu and optionally gamma,kprime,name.")
@json_option("Print JSON (one object per point) instead of text / CSV.")
@output_option("With --points: write to FILE (atomically) instead of standard output; a .json suffix "
               "selects JSON.")
@load_options
def classify_cmd(gamma: float | None, kprime: float | None, k: float | None, mu: float | None,
                 points_file: str | None, as_json: bool, output: str | None,
                 loads: dict[str, Any]) -> None:
    """Which motion starts at a design point (k, mu), and how far it is from changing.

    For one point prints the mode of the map (Section 4.7 of the report below
    the centre of mass), the reactions and accelerations at initiation from
    the equations of motion (fx, fy divided by m g; xi, where f_y acts, over
    B; xdd, ydd over g; thdd = theta'' B/g; slip, the acceleration of the
    slipping contact over g, none when it sticks), the report's case, every
    mode the equations admit there, and the margin: the smallest relative
    change of k (mu fixed) and of mu (k fixed), up or down, that changes the
    mode, with the mode it changes to.  The search covers all k >= 0 and
    mu >= 0 exactly; "no change" means none exists; relative changes from a
    value of 0 are not defined (the absolute change is given).

    With --points FILE.csv every row is classified; rows without gamma or
    kprime use --gamma/--kprime (required only then).  Output is CSV (or
    JSON with --json or an -o FILE.json).

    With loads (--buoyancy ... --crest, or the CSV columns buoyancy, uplift,
    uplift_ratio, uplift_arm, gyration, crest, which take precedence) the
    block is the loaded one: lift-off (LO) is a mode, the report's lines
    move, and where several modes are admissible the map keeps the one of
    least constraint ("chosen by least constraint").  The CSV output then
    adds the loads and chosen_by.

    \b
    Examples:
      regimemap classify --gamma 3 --kprime 0.4 --k 0.5 --mu 0.8
      regimemap classify --gamma 3 --kprime -0.6 --k 3.5 --mu 2.3 --json
      regimemap classify --points caissons.csv --gamma 3 -o results.csv
      regimemap classify --points caissons.csv -o results.json
      regimemap classify --gamma 0.7 --kprime -0.02 --buoyancy 0.32 --uplift-ratio 0.52 --k 0.28 --mu 0.6
    """
    points, to_json = _classify_input(gamma, kprime, k, mu, points_file, as_json, output)
    from ..maps.run_query import run_query

    try:
        record = run_query(points, gamma=gamma, kprime=kprime, **loads)
    except ValueError as exc:
        raise RunError(str(exc)) from None
    if points_file is None:
        from ..maps.record_tables import format_result, result_json

        point = record.results[0]
        print_report(as_json, lambda: format_result(point), lambda: result_json(point))
        return
    from ..maps.record_tables import results_text

    text = results_text(record.results, to_json)
    if output is None:
        click.echo(text, nl=False)
        return
    from ..io.atomic import atomic_open

    with writing(output), atomic_open(output, "w", encoding="utf-8", newline="") as fh:
        fh.write(text)
    report_written(output, f"{len(record.results)} point(s) classified")


def _classify_input(gamma: float | None, kprime: float | None, k: float | None, mu: float | None,
                    points_file: str | None, as_json: bool, output: str | None
                    ) -> tuple[list[DesignPoint], bool]:
    """The points to classify (``--k/--mu`` or the rows of ``--points``) and whether to
    write JSON; a usage error for options that do not go together or a point without
    its gamma or k'."""
    if points_file is None:
        return [_one_point(gamma, kprime, k, mu, output)], as_json
    if k is not None or mu is not None:
        raise click.UsageError("--k/--mu and --points exclude each other: give one point or a file")
    points = _points_of_file(points_file, gamma, kprime)
    to_json = as_json or (output is not None and suffix_of(output) == "json")
    if output is not None:
        output_path(output, "--output")
    return points, to_json


def _one_point(gamma: float | None, kprime: float | None, k: float | None, mu: float | None,
               output: str | None) -> DesignPoint:
    """The point of ``--k``/``--mu``; a usage error for ``-o`` or an option missing."""
    from ..maps.file_points import DesignPoint

    if output is not None:
        raise click.UsageError("-o/--output is for --points; one point prints to standard "
                               "output", ctx=click.get_current_context())
    missing = [n for n, v in (("--gamma", gamma), ("--kprime", kprime), ("--k", k),
                              ("--mu", mu)) if v is None]
    if missing:
        raise click.UsageError(
            f"missing option(s) {', '.join(missing)}: give --gamma (> 0), --kprime (in [-1, 1]), "
            "--k (>= 0) and --mu (>= 0), or --points FILE.csv")
    assert k is not None and mu is not None
    return DesignPoint(k, mu)


def _points_of_file(points_file: str, gamma: float | None, kprime: float | None
                    ) -> list[DesignPoint]:
    """The rows of ``--points``; a usage error for a bad file or a row without its gamma or
    k' when no ``--gamma``/``--kprime`` gives it."""
    table = read_points_file(points_file)
    for line, pt in zip(table.lines, table.points):
        for opt, own, default in (("--gamma", pt.gamma, gamma), ("--kprime", pt.kprime, kprime)):
            if own is None and default is None:
                who = f"{points_file}, line {line}" + (f" ({pt.name!r})" if pt.name else "")
                col = opt.lstrip("-")
                raise click.UsageError(
                    f"{opt} is required: {who} has no {col} value "
                    f"(give {opt} or add a {col} column)")
    return list(table.points)
