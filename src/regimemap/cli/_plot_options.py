"""Options of ``regimemap plot``, ``regimemap figure`` and ``regimemap figures``: their types
(resolution, format, modes, design points) and the steps that turn them into what a command
draws: the output path and format from ``-o`` and ``--format``, ``--modes`` checked against
the map, the design points of ``--point`` and ``--points`` that belong on it.

Importing this module does not import matplotlib; the modes and the points table are imported
when an option needs them.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from ..drawing.save import DEFAULT_DPI, DPI_RANGE
from ..io.formats import FIGURE_FORMATS, FIGURES, kind_of, suffix_error, suffix_of
from ._common import Checked, ParamType, resolution_type
from ._main import refusing
from ._writing import output_path

if TYPE_CHECKING:  # pragma: no cover
    from click.decorators import FC

    from ..maps.file_points import DesignPoint, PointsTable

__all__ = [
    "FORMATS",
    "Dpi",
    "Format",
    "FormatList",
    "Modes",
    "POINT_SPEC",
    "valid_modes",
    "check_modes_on_map",
    "resolve_output",
    "read_points",
    "read_points_file",
    "parse_formats",
    "DEFAULT_SAMPLES",
    "dpi_option",
    "format_option",
    "resolution_option",
]

#: Output formats: the figure formats of the registry (:data:`regimemap.io.formats.FIGURE_FORMATS`).
FORMATS = FIGURE_FORMATS

_LO, _HI = DPI_RANGE

#: Samples of k of a map drawn by ``plot`` and ``explore`` (``--resolution``).
DEFAULT_SAMPLES = 801


# -- option types --------------------------------------------------------------------------


class Dpi(ParamType):
    """``--dpi``: the resolution of PNG output, a number in :data:`~regimemap.drawing.save.DPI_RANGE`."""

    name = "dpi"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        try:
            v = float(value)
        except (TypeError, ValueError):
            self.fail(f"{value!r} is not a number; use a resolution in [{_LO:g}, {_HI:g}]", param, ctx)
        if not (math.isfinite(v) and _LO <= v <= _HI):
            self.fail(f"dpi must be a number in [{_LO:g}, {_HI:g}], got {value!r}", param, ctx)
        return v


class Format(ParamType):
    """``--format`` of one figure: png, svg or pdf (case and a leading dot ignored)."""

    name = "|".join(FIGURE_FORMATS)

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> str:
        v = str(value).strip().lower().lstrip(".")
        if v not in FORMATS:
            self.fail(f"unknown format {value!r}; use one of {', '.join(FORMATS)}", param, ctx)
        return v


class FormatList(ParamType):
    """``--format`` of ``figures``: a comma-separated list of formats, each once."""

    name = "FORMATS"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None
                ) -> tuple[str, ...]:
        if isinstance(value, tuple):
            return value
        try:
            return parse_formats(str(value))
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


def parse_formats(text: str) -> tuple[str, ...]:
    """The figure formats of a comma-separated list, each once, in the order given (case and a
    leading dot ignored); ValueError for none or an unknown one."""
    items = [v.strip().lower().lstrip(".") for v in text.split(",") if v.strip()]
    bad = [v for v in items if v not in FORMATS]
    if not items or bad:
        what = f"unknown format {bad[0]!r}" if bad else "no format given"
        raise ValueError(f"{what}; use a comma-separated list of {', '.join(FORMATS)}")
    return tuple(dict.fromkeys(items))


def valid_modes(loaded: bool | None = None) -> str:
    """The modes a map can show, as the messages list them (``loaded`` None: any map)."""
    from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES

    plain = ", ".join(m.label for m in MAP_MODES)
    extra = ", ".join(m.label for m in LOADED_MAP_MODES if m not in MAP_MODES)
    if loaded is None:
        return f"{plain} (and {extra} on the map of a loaded block)"
    return f"{plain}, {extra}" if loaded else plain


class Modes(ParamType):
    """``--modes``: labels of the modes that some map shows (checked against the block later)."""

    name = "MODES"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None
                ) -> tuple[Any, ...]:
        from ..mechanics.modes import LOADED_MAP_MODES, Mode

        if isinstance(value, tuple):
            return value
        out = []
        valid = valid_modes()
        for item in str(value).split(","):
            if not item.strip():
                continue
            try:
                mode = Mode.from_label(item)
            except ValueError:
                self.fail(f"unknown mode {item.strip()!r}; valid modes: {valid}", param, ctx)
            if mode not in LOADED_MAP_MODES:
                self.fail(f"mode {mode.label} never appears on a map; valid modes: {valid}",
                          param, ctx)
            out.append(mode)
        if not out:
            self.fail(f"no mode given; valid modes: {valid}", param, ctx)
        return tuple(dict.fromkeys(out))


def check_modes_on_map(modes: tuple[Any, ...] | None, loaded: bool) -> tuple[Any, ...] | None:
    """``--modes`` checked against the map: RO' and LO only on the map of a loaded block.

    The map of a loaded block (``--buoyancy``, ``--uplift``, ``--uplift-ratio``,
    ``--gyration``) shows :data:`~regimemap.mechanics.modes.LOADED_MAP_MODES`, the
    report's block :data:`~regimemap.mechanics.modes.MAP_MODES`; a mode the map cannot
    show is a usage error (exit 2) naming the modes it can.
    """
    from ..mechanics.modes import LOADED_MAP_MODES, MAP_MODES

    if modes is None:
        return None
    shown = LOADED_MAP_MODES if loaded else MAP_MODES
    bad = [m for m in modes if m not in shown]
    if bad:
        raise click.BadParameter(
            f"mode {bad[0].label} appears only on the map of a loaded block (give --buoyancy, "
            f"--uplift, --uplift-ratio or --gyration); this map's modes: {valid_modes(loaded)}",
            param_hint="'--modes'")
    return modes


def _point(text: str) -> DesignPoint:
    from ..maps.file_points import parse_point_spec

    return parse_point_spec(text)


#: ``--point K,MU[:NAME]``: one design point (:func:`regimemap.maps.file_points.parse_point_spec`).
POINT_SPEC = Checked("K,MU[:NAME]", _point)


def dpi_option() -> Callable[[FC], FC]:
    """``--dpi`` of the commands that draw the maps (``plot``, ``figure``, ``figures``)."""
    return click.option("--dpi", type=Dpi(), default=DEFAULT_DPI, show_default=True,
                        help=f"Resolution of PNG output ({_LO:g}-{_HI:g} dots per inch).")


def format_option() -> Callable[[FC], FC]:
    """``--format`` of one figure (``plot``, ``figure``), passed to the command as ``fmt``."""
    return click.option("--format", "fmt", type=Format(), default=None,
                        help=f"{FIGURES.replace('.', '')} (default: from the suffix of -o, else png).")


def resolution_option() -> Callable[[FC], FC]:
    """``--resolution`` of a drawn map (``plot``, ``explore``)."""
    return click.option("--resolution", type=resolution_type, default=DEFAULT_SAMPLES, show_default=True,
                        help="Samples of k for the region polygons and curves (2-5000).")


# -- from the options to what is drawn -------------------------------------------------------


def resolve_output(output: str | None, fmt: str | None, default_name: str) -> tuple[Path, str]:
    """The output path and format from ``-o`` and ``--format`` (usage errors exit 2).

    Parameters
    ----------
    output : str or None
        ``-o``: a file name, with or without a suffix.
    fmt : str or None
        ``--format``.
    default_name : str
        The file name without suffix when ``-o`` is not given.

    Returns
    -------
    (Path, str)
        The file to write (its folder checked) and its format.
    """
    if output is None:
        fmt = fmt or "png"
        return output_path(f"{default_name}.{fmt}", "--output"), fmt
    path = Path(output)
    suffix = suffix_of(path)
    if kind_of(suffix) == "figure":
        if fmt is not None and fmt != suffix:
            raise click.BadParameter(
                f"file suffix .{suffix} does not match --format {fmt}", param_hint="'--format'")
        fmt = suffix
    elif suffix and fmt is None:
        raise click.BadParameter(f"{suffix_error(output, 'figure')} (or give --format)",
                                 param_hint="'-o' / '--output'")
    else:
        # no suffix (or an unknown one with --format): add the format's suffix, as matplotlib does,
        # but not to a device or a FIFO (-o /dev/null), which is written into as it is
        from ..io.atomic import special_file

        fmt = fmt or "png"
        if not special_file(path):
            path = path.with_name(f"{path.name}.{fmt}")
    return output_path(path, "--output"), fmt


def read_points(files: Sequence[str], specs: Sequence[DesignPoint]) -> list[DesignPoint]:
    """Design points from ``--point`` specs and ``--points`` files, in that order.

    Parameters
    ----------
    files : sequence of str
        The ``--points`` CSV files (a bad file is a usage error; a file read
        in another dialect is noted on standard error).
    specs : sequence of DesignPoint
        The ``--point`` options.

    Returns
    -------
    list of DesignPoint
        Every point; :func:`regimemap.maps.run.run_map` keeps those of its block.
    """
    points = list(specs)
    for f in files:
        points.extend(read_points_file(f).points)
    return points


def read_points_file(path: str) -> PointsTable:
    """The table of a ``--points`` CSV file (:func:`regimemap.maps.file_points.read_points_table`):
    a file it refuses is a usage error naming ``--points``; a file read in another dialect is noted
    on standard error."""
    from ..maps.file_points import read_points_table  # imports csv: only when needed

    with refusing("'--points'"):
        table = read_points_table(path)
    if table.note:
        click.echo(f"regimemap: note: {path} is {table.note}; read as such", err=True)
    return table
