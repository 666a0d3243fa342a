"""``regimemap caisson``: from a design file to loads, safety factors and the loaded map."""

from __future__ import annotations

import click

from ..io.formats import FIGURES
from ._check import check_option, exit_on_failure
from ._common import json_option, output_option
from ._inputs import DESIGN_FILE, read_design_file
from ._main import import_matplotlib
from ._plausible import STRICT_RECORD_HELP, caisson_record
from ._writing import checked_output, print_report, write_figure

__all__ = ["caisson_cmd"]


@click.command(
    "caisson",
    short_help="Goda loads, safety factors and the mode on the loaded map of a caisson (design file).",
)
@click.argument("design", required=False, type=DESIGN_FILE, metavar="DESIGN.toml")
@click.option("--example", is_flag=True,
              help="Print the commented example design file (Goda's worked caisson) and exit.")
@json_option()
@output_option(f"Also write a one-page design sheet ({FIGURES}), atomically.", metavar="SHEET.pdf")
@click.option("--strict", is_flag=True, help=STRICT_RECORD_HELP)
@check_option
def caisson_cmd(design: str | None, example: bool, as_json: bool, output: str | None, strict: bool,
                check: bool) -> None:
    """Goda's design procedure for a vertical-breakwater caisson, placed on the regime map.

    Reads DESIGN.toml (site, design wave, caisson; `regimemap caisson --example`
    prints a commented one) and prints the design heights, Goda's pressures
    (kPa), the loads per metre (kN/m, kN m/m), the safety factors, the
    equivalent loaded block (gamma, k, k', buoyancy, uplift ratio and arm,
    gyration), its mode on the loaded map with its margins (how much more k,
    or less mu, changes the mode), and how the caisson fares as the wave
    grows from 0.5 to 1.5 times the design heights.  Goda's safety factors
    are both >= 1 exactly when the map says rest.  Goda's pressures include
    Takahashi's impulsive coefficient alpha_I unless the file says
    `impulsive = false` in [caisson] (the header names the setting).

    When the file has a [lifetime] table it also simulates the sliding over
    the design life (as `regimemap lifetime` does) and reports its ESD; with a
    [lifetime.record] it names the record and its fit, and gives the ESD
    including the climate's uncertainty and its 90 % band.

    The report ends with the design check, each requirement PASS or FAIL:
    the sliding and overturning safety factors at least [caisson]
    required_sliding and required_overturning (1.2 by default), and, with
    [lifetime], its requirements (ESD at most target, the allowed
    exceedances; with a record judged including the climate's uncertainty)
    -- the same requirements with or without -o (--json: "checks" and
    "verdict").  With --check the exit status is 1 when any requirement
    fails (after the report and the sheet are written); usage errors exit 2.

    With -o SHEET.pdf (or any figure format) it also writes a one-page design sheet:
    the cross-section, the pressure diagram, the loaded map with the design
    point and its path as the wave grows, and the numbers -- and, when the file
    has a [lifetime] table, the sliding over the design life (with a record,
    its climate band); its path follows the report on standard output
    (with --json, as the key "sheet").

    \b
    Examples:
      regimemap caisson --example > goda.toml
      regimemap caisson goda.toml
      regimemap caisson goda.toml --json
      regimemap caisson goda.toml -o sheet.pdf
      regimemap caisson goda.toml --check
    """
    if example:
        _print_example(design, as_json, output)
        return
    source = _check_arguments(design, output)
    d = read_design_file(source, "'DESIGN.toml'")
    if output is not None:  # before the lifetime is simulated for it
        import_matplotlib()
    record = caisson_record(d, source, strict=strict, sheet=output is not None)
    if output is not None:  # the sheet first: a failure leaves no report half-printed
        from ..caisson.figures.page import caisson_sheet

        write_figure(caisson_sheet(record), output)
    from ..caisson.run_report import caisson_report_json, caisson_report_text

    # with --json the sheet's path is inside the one JSON object
    print_report(as_json, lambda: caisson_report_text(record, source),
                 lambda: caisson_report_json(record, source, output), [output] if output is not None else [])
    exit_on_failure(record.checks, check)


def _print_example(design: str | None, as_json: bool, output: str | None) -> None:
    """``--example``: print the commented example design file; it takes nothing else."""
    from ..caisson.file import example_design_text

    if design is not None or as_json or output is not None:
        raise click.UsageError("--example prints the example file and takes nothing else "
                               "(no DESIGN.toml, --json or -o)", ctx=click.get_current_context())
    click.echo(example_design_text(), nl=False)


def _check_arguments(design: str | None, output: str | None) -> str:
    """The design file's path, given; the sheet's file a .pdf, .svg or .png in a writable folder."""
    if design is None:
        raise click.UsageError("missing DESIGN.toml (a design file; `regimemap caisson --example` "
                               "prints one)", ctx=click.get_current_context())
    if output is not None:
        checked_output(output, "design sheet")
    return design
