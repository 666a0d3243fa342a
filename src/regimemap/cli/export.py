"""``regimemap export``: the map as data (.npz grid, .csv grid, .json vectors)."""

from __future__ import annotations

from typing import Any

import click

from ..io.formats import record_formats
from ._common import (
    axis_options,
    gamma_option,
    kprime_option,
    load_options,
    output_option,
    resolution_type,
    view_option,
)
from ._main import refusing
from ._writing import output_path, report_written, writing

__all__ = ["export_cmd"]


@click.command("export", short_help="Write the map as a grid (.npz, .csv) or as vectors (.json).")
@gamma_option()
@kprime_option()
@axis_options("Right end of the k axis (default: automatic, as in 'plot').",
              "Top of the mu axis (default: automatic, as in 'plot').")
@click.option("--resolution", type=resolution_type, default=401, show_default=True,
              metavar="N", help="Grid samples along each axis for .npz/.csv (2 to 5000).")
@view_option("Default view: mu up to 1.2 (designer) or every characteristic point (report).")
@click.option("--format", "fmt", type=click.Choice(record_formats("map data"), case_sensitive=False),
              default=None, help="Format (default: from the suffix of -o).")
@output_option("Output file: .npz, .csv or .json (written atomically).", required=True)
@load_options
def export_cmd(gamma: float, kprime: float, k_max: float | None, mu_max: float | None,
               resolution: int, view: str, fmt: str | None, output: str,
               loads: dict[str, Any]) -> None:
    """Export the regime map for GAMMA and KPRIME as data.

    \b
    .npz   arrays k (1-D), mu (1-D), mode (2-D uint8 codes, rows mu, columns k),
           labels (label of each code: labels[mode]), gamma, kprime, case and
           the derived constants; read with numpy.load.
    .csv   columns k,mu,mode (mode as label: RE, SL, RO, SRO-, SRO+, SRO'-),
           one row per grid point, mu outer, k inner.
    .json  boundary curves as polylines with their equations, named points,
           case, parameters and constants (non-finite as null), the region
           polygons and the parts where several modes are admissible.

    The view defaults to the one 'plot' chooses (--view).  The grid has N x N points,
    N <= 5000 (25 million points at most).

    With loads (--buoyancy ... --crest) the map is the loaded block's: .npz
    holds the loads and the loaded constants (k_L where lift-off starts), .csv
    adds the columns gamma, kprime and the loads (as read by 'classify
    --points'), .json the loads, lift-off's region and the curve LO.

    \b
    Examples:
      regimemap export --gamma 3 --kprime 0.4 -o map.npz
      regimemap export --gamma 3 --kprime -0.6 --resolution 201 -o map.csv
      regimemap export --gamma 3 --kprime -0.6 --k-max 4 --mu-max 3 -o map.json
      regimemap export --gamma 0.7 --kprime -0.02 --buoyancy 0.32 --uplift-ratio 0.52 -o goda.json
    """
    from ..maps.record_export import export_map, format_of
    from ..mechanics.block import Parameters

    with refusing("'-o' / '--output'"):
        fmt = format_of(output, fmt)
    output_path(output, "--output")
    p = Parameters(gamma, kprime, **loads)
    with writing(output):
        export_map(output, p, k_max=k_max, mu_max=mu_max, resolution=resolution, fmt=fmt,
                   view=view)
    from ..maps.describe import loads_text

    what = "vector geometry" if fmt == "json" else f"{resolution} x {resolution} grid"
    extra = loads_text(p)
    report_written(output, f"{fmt}, {what}; gamma = {gamma:g}, k' = {kprime:g}"
                           f"{', ' + extra if extra else ''}")
