"""``regimemap plot``, ``regimemap figure`` and ``regimemap figures``.

Importing this module does not import matplotlib (``regimemap --help`` stays
fast); the commands import :mod:`regimemap.drawing` when they run.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import click

from ..io.formats import FIGURE_FORMATS
from ..records.numbers import short
from ._common import (
    axis_options,
    gamma_option,
    jobs_option,
    kprime_option,
    load_options,
    quiet_option,
    view_option,
)
from ._inputs import POINTS_FILE
from ._main import RunError, import_matplotlib
from ._plot_options import (
    DEFAULT_SAMPLES,
    FORMATS,
    POINT_SPEC,
    FormatList,
    Modes,
    check_modes_on_map,
    dpi_option,
    format_option,
    read_points,
    resolution_option,
    resolve_output,
)
from ._writing import echo_notices, output_dir, report_written, write_figure

if TYPE_CHECKING:  # pragma: no cover
    from ..maps.run import MapRecord
    from ..maps.run_atlas import AtlasRecord

__all__ = ["DEFAULT_SAMPLES", "FORMATS", "check_modes_on_map", "figure_command", "figure_maps",
           "figures_command", "plot_command", "plot_stem"]



# -- helpers -------------------------------------------------------------------------------


#: Short names of the loads in file names.
_LOAD_STEM = {"buoyancy": "b", "uplift": "u", "uplift_ratio": "nu", "uplift_arm": "eu",
              "gyration": "i", "crest": "crest"}


def plot_stem(gamma: float, kprime: float, loads: dict[str, Any] | None = None) -> str:
    """The default file name of ``plot`` without suffix: ``regime-g<gamma>-kp<kprime>``.

    Numbers are written shortest (``%g``): ``regime-g3-kp0.4``, ``regime-g2.5-kp-0.3``;
    the loads given follow, ``regime-g0.7-kp-0.02-b0.32-nu0.52``.
    """
    extra = "".join(f"-{_LOAD_STEM[k]}{short(v)}" for k, v in (loads or {}).items())
    return f"regime-g{short(gamma)}-kp{short(kprime)}{extra}"


# -- plot ------------------------------------------------------------------------------------


@click.command("plot", short_help="Draw the regime map of one gamma and kprime.")
@gamma_option()
@kprime_option()
@click.option("-o", "--output", metavar="FILE",
              help=f"Output file; its suffix ({', '.join('.' + f for f in FIGURE_FORMATS)}) sets the format. "
                   "Default: regime-g<GAMMA>-kp<KPRIME>.<format>.")
@format_option()
@view_option("designer: mu up to 1.2 and k far enough to show every boundary that crosses that band, "
             "with arrows at the edge to the points outside; report: every characteristic point in view.")
@axis_options("Right end of the k axis (wins over --view).", "Top of the mu axis (wins over --view).",
              metavars=False)
@resolution_option()
@dpi_option()
@click.option("--title", default=None,
              help="Title above the map (mathtext allowed); '' for none. "
                   "Default: what is shown, the report's case, gamma and kprime.")
@click.option("--no-curves", is_flag=True, help="Do not draw the boundary curves and points.")
@click.option("--no-labels", is_flag=True, help="Do not write the mode symbols in the regions.")
@click.option("--no-legend", is_flag=True, help="Do not draw the legend.")
@click.option("--modes", type=Modes(), default=None,
              help="Comma-separated modes to shade, e.g. RE,SL,RO (default: all). "
                   "Valid: RE, SL, RO, SRO-, SRO+, SRO'-, and on the map of a loaded block "
                   "RO' and LO.")
@click.option("--raw", is_flag=True,
              help="Shade each mode's region as the report derives it, before Section 4.7 "
                   "resolves overlaps (regions may overlap; use with --modes).")
@click.option("--point", "point_specs", type=POINT_SPEC, multiple=True,
              help="Mark a design point K,MU or K,MU:NAME (repeatable).")
@click.option("--points", "points_files", type=POINTS_FILE, multiple=True, metavar="FILE.csv",
              help="Mark design points from a CSV file with columns k,mu[,gamma,kprime,name] "
                   "(repeatable); rows with another gamma/kprime are skipped with a warning.")
@click.option("--show-ambiguity", is_flag=True,
              help="Also mark where the equations of motion admit several modes, with the "
                   "mode the map keeps (Section 4.7, below C; least constraint with loads).")
@load_options
def plot_command(gamma: float, kprime: float, output: str | None, fmt: str | None,
                 view: str, k_max: float | None, mu_max: float | None, resolution: int, dpi: float,
                 title: str | None, no_curves: bool, no_labels: bool, no_legend: bool,
                 modes: tuple[Any, ...] | None, raw: bool, point_specs: tuple[Any, ...],
                 points_files: tuple[str, ...], show_ambiguity: bool,
                 loads: dict[str, Any]) -> None:
    """Draw the regime map of a block for one GAMMA and KPRIME.

    Shades the region of each mode (rest RE, slide SL, rock RO, slide-rock SRO-,
    SRO+, SRO'-), draws the boundary curves mu*(k), mu**(k) and the report's
    lines with the named points (O, A, B', C, D ...), and writes PNG, SVG or PDF
    (from the suffix of -o, or --format).  The view shows the friction
    coefficients of real contacts, mu up to 1.2 (--view report: every
    characteristic point).  Without -o the file is
    regime-g<GAMMA>-kp<KPRIME>.<format> in the current folder, e.g.
    regime-g3-kp0.4.png.

    \b
    Examples:
      regimemap plot --gamma 3 --kprime 0.4
      regimemap plot --gamma 3 --kprime 0.4 -o map.svg
      regimemap plot --gamma 3 --kprime -0.3 --format pdf -o figs/below
      regimemap plot --gamma 3 --kprime 0.4 --point 0.45,0.6:caisson-A
      regimemap plot --gamma 3 --kprime 0.4 --points design.csv --k-max 2
      regimemap plot --gamma 3 --kprime 0.4 --modes RO,SRO- --no-labels
      regimemap plot --gamma 1 --kprime -0.99 --view report
      regimemap plot --gamma 0.7 --kprime -0.02 --buoyancy 0.32 --uplift-ratio 0.52

    With loads (--buoyancy, --uplift, --uplift-ratio, --uplift-arm, --gyration,
    --crest) the map is that of the loaded block: lift-off (LO) appears, the
    title states the loads, and the default file name carries them.
    """
    from ..mechanics.block import Parameters

    path, fmt = resolve_output(output, fmt, plot_stem(gamma, kprime, loads))
    params = Parameters(gamma, kprime, **loads)
    modes = check_modes_on_map(modes, params.loaded)
    points = read_points(points_files, point_specs)
    import_matplotlib()
    from ..maps.figures.figure import map_figure
    from ..maps.figures.mapplot import MapStyle
    from ..maps.run import run_map

    record = run_map(params, view=view, k_max=k_max, mu_max=mu_max, modes=modes, raw=raw,
                     samples=resolution, curves=not no_curves, points=points,
                     ambiguity=show_ambiguity)
    echo_notices(record.notices)
    style = MapStyle(curves=not no_curves, labels=not no_labels, legend=not no_legend, title=title)
    fig, _, _ = map_figure(record, style=style, dpi=dpi)
    write_figure(fig, path, fmt, dpi)
    report_written(path)


# -- figure / figures ------------------------------------------------------------------------



def _figure_id(fid: str) -> str:
    """The id of the report's figure ``fid`` as the report writes it; a usage error naming the
    nearest ids when there is none."""
    from ..maps.figures.presets import FIGURE_IDS, MODEL_FIGURE_ID, get_preset, normalise_id, suggest_ids
    from ..maps.figures.worked import WORKED

    if normalise_id(fid) == MODEL_FIGURE_ID:
        return MODEL_FIGURE_ID
    if fid.strip().upper() in WORKED:  # the worked figures of the loaded block: W.1, W.2 ...
        return WORKED[fid.strip().upper()].id
    try:
        return get_preset(fid).id
    except KeyError:
        near = suggest_ids(fid)
        hint = f" Did you mean {' or '.join(near)}?" if near else ""
        raise click.BadParameter(
            f"no figure {fid!r} in the report.{hint} Known: {MODEL_FIGURE_ID}, {', '.join(FIGURE_IDS)}",
            param_hint="'FIGURE_ID'") from None


@click.command("figure", short_help="Draw one figure of the report.")
@click.argument("figure_id", metavar="FIGURE_ID")
@click.option("-o", "--output", metavar="FILE",
              help=f"Output file ({', '.join('.' + f for f in FIGURE_FORMATS)}); default fig-<ID>.<format>.")
@format_option()
@dpi_option()
def figure_command(figure_id: str, output: str | None, fmt: str | None, dpi: float) -> None:
    """Draw one figure of the report (e.g. 2.1, 3.9a, 4.7b).

    Fig. 2.1 is the model: the block of half width B and half height H
    (gamma = H/B), the force F = mgk at h = k'H above the centre of mass C,
    and the reactions of the base.

    Each figure uses parameters strictly inside its caption's case (see
    'regimemap figures --list').  Without -o the file is fig-<ID>.<format>.

    \b
    Examples:
      regimemap figure 2.1
      regimemap figure 3.9a
      regimemap figure 4.7a -o fig47a.pdf
      regimemap figure 3.11 --format svg --dpi 300
    """
    fid = _figure_id(figure_id)
    path, fmt = resolve_output(output, fmt, f"fig-{fid}")
    import_matplotlib()
    from ..maps.figures.batch import render_figure

    write_figure(render_figure(fid, figure_maps(fid), dpi=dpi), path, fmt, dpi)
    report_written(path)


@click.command("figures", short_help="Draw all 25 figures of the report.")
@click.option("--out", "out_dir", default=".", show_default=True, metavar="DIR",
              help="Folder for the files (created if its parent folder exists).")
@click.option("--format", "formats", type=FormatList(), default="png", show_default=True,
              help=f"Comma-separated formats: {', '.join(FIGURE_FORMATS)}.")
@dpi_option()
@click.option("--list", "list_only", is_flag=True,
              help="List the figures with their parameters and captions; draw nothing.")
@click.option("--set", "which", type=click.Choice(["report", "worked", "all"]), default="report",
              show_default=True,
              help="The report's 25 figures, the worked figures of the loaded block "
                   "(W.1, W.2 ...: submerged caissons), or both.")
@jobs_option("Worker processes (default: one per core).")
@quiet_option("No progress bar on standard error.")
def figures_command(out_dir: str, formats: tuple[str, ...], dpi: float, list_only: bool,
                    which: str, jobs: int | None, quiet: bool) -> None:
    """Draw all 25 figures of the report (and the worked figures W.1 ...) into a folder.

    Writes fig-<ID>.<format> for every figure (2.1, 3.1 ... 3.11, 4.2 ... 4.7b) and
    every format, on every core of the machine (--jobs to choose).  On one
    machine the output is byte-identical from run to run, whatever the number of
    processes.
    PNGs are 150 dpi by default (use --dpi 300 for print; SVG and PDF are vector).

    \b
    Examples:
      regimemap figures
      regimemap figures --out figures --format png,svg
      regimemap figures --out paper --format pdf
      regimemap figures --list
      regimemap figures --out figures --format png,svg --set all

    --set worked draws the worked figures of the loaded block instead (W.1:
    Goda's caisson submerged, W.2: in air, W.3: a slender block lifting off,
    W.4: the uplift ratio swept); --set all draws both.
    """
    from ..maps.figures.presets import MODEL_FIGURE_ID, PRESETS
    from ..maps.figures.worked import WORKED

    if list_only:
        from ..maps.figures.listing import figure_listing

        click.echo("\n".join(figure_listing(which)))
        return
    folder = output_dir(out_dir, "--out", create=True)

    import_matplotlib()
    from ..maps.figures.batch import write_figures

    ids = [] if which == "worked" else [MODEL_FIGURE_ID, *PRESETS]
    if which != "report":
        ids += list(WORKED)
    from ._progress import progress_bar

    try:  # the file that failed is known only from the error (not writing(path))
        with progress_bar(len(ids), "figures", quiet, unit=" figures") as step:
            written = write_figures(folder, ids, formats, dpi, figure_maps, jobs=jobs, progress=step)
    except OSError as exc:
        where = f"cannot write {exc.filename}" if exc.filename else "cannot write a figure"
        raise RunError(f"{where}: {exc.strerror or exc}") from None
    for path in written:
        report_written(path)


def figure_maps(fid: str) -> MapRecord | AtlasRecord | None:
    """The maps a figure of the report shows, by its id, from the workflows (None for the model
    figure, 2.1): what :func:`regimemap.maps.figures.batch.render_figure` draws."""
    from ..maps.figures.presets import MODEL_FIGURE_ID, get_preset
    from ..maps.figures.worked import WORKED
    from ..maps.run import run_map
    from ..maps.run_atlas import run_atlas

    if fid == MODEL_FIGURE_ID:
        return None
    worked = WORKED.get(fid.strip().upper())
    if worked is None:
        return run_map(**get_preset(fid).map_keywords)
    return run_atlas(**worked.atlas_keywords) if worked.sweep else run_map(**worked.map_keywords)
