"""A study's record as an xarray Dataset and a NetCDF file (``regimemap study -o table.nc``).

The layout is the CSV table's, tidy: one ``row`` per section x scenario x width, with the
section, its chainage, the scenario and the width as coordinates along ``row``; a ``limit``
dimension (0.1 m, 0.3 m) for the exceedance probabilities and the years the expected
sliding passes each limit; a ``year`` dimension (service years 1..L) for the expected
cumulative sliding by year.  Not a (section, scenario, width) cube: each section has
widths of its own (and a section with a target one width per scenario, found by the run),
so a cube would be mostly empty; ``ds.set_index(row=["section", "scenario", "width"])``
gives the cube's selection (``ds.sel(section="trunk 8 m")``) after reading.

Written with xarray (the ``metocean`` extra): through netCDF4 (NetCDF-4) when it is
installed, else through scipy (NetCDF-3 classic, no binary dependency beyond scipy, a
runtime dependency already); the strings are then arrays of characters (UTF-8), which
xarray reads back as strings.  A value that does not apply (no climate band, no target,
a limit never passed) is NaN.
"""

from __future__ import annotations

import importlib.util
import math
import os
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from ..io.atomic import atomic_path
from .record import COLUMNS

if TYPE_CHECKING:
    from collections.abc import Sequence

    import xarray
    from numpy.typing import NDArray

    from .record import StudyRecord, StudyRow

__all__ = ["NO_XARRAY", "check_netcdf", "netcdf_engine", "study_dataset", "write_study_netcdf"]

#: The message when xarray is missing.
NO_XARRAY = "writing the study as NetCDF needs xarray: pip install 'regimemap[metocean]'"


def _xarray() -> Any:
    try:
        import xarray as xr
    except ImportError:
        raise ImportError(NO_XARRAY) from None
    return xr


def check_netcdf() -> None:
    """Raise :class:`ImportError` (:data:`NO_XARRAY`) now if xarray is missing, e.g. before a long run
    whose table is to be written as NetCDF."""
    if importlib.util.find_spec("xarray") is None:
        raise ImportError(NO_XARRAY)


def netcdf_engine() -> Literal["netcdf4", "scipy"]:
    """The engine :func:`write_study_netcdf` writes with: ``"netcdf4"`` if installed, else ``"scipy"``."""
    return "netcdf4" if importlib.util.find_spec("netCDF4") is not None else "scipy"


def _nan(x: float | None) -> float:
    return math.nan if x is None else float(x)


def _pair(p: tuple[float, float] | None, k: int) -> float:
    return math.nan if p is None else float(p[k])


def _variables(rows: Sequence[StudyRow], limits: list[float], years: NDArray[np.int32]
               ) -> tuple[dict[str, Any], dict[str, Any]]:
    """The variables and the ``row`` coordinates of :data:`~regimemap.study.record.COLUMNS`, in its order."""
    data: dict[str, Any] = {}
    coords: dict[str, Any] = {"row": ("row", np.arange(len(rows), dtype=np.int32),
                               {"long_name": "section x scenario x width"})}
    for column in COLUMNS:
        values = [column.of(r) for r in rows]
        meta = {"units": column.unit, "long_name": column.long_name}
        if column.kind == "coord":
            coords[column.name] = ("row", np.array(values, dtype=np.float64 if column.unit else str),
                                   meta if column.unit else {"long_name": column.long_name})
        elif column.kind == "value":
            data[column.name] = ("row", np.asarray([_nan(v) for v in values], dtype=np.float64), meta)
        elif column.kind == "limits":  # (row, limit): NaN for None or a limit not given
            data[column.name] = (("row", "limit"), np.array(
                [[_nan(dict(pairs).get(x)) for x in limits] for pairs in values],
                dtype=np.float64).reshape(-1, len(limits)), meta)
        elif column.kind == "years":
            by_year = np.full((len(rows), years.size), np.nan)
            for i, v in enumerate(values):
                by_year[i, :len(v)] = v
            data[column.name] = (("row", "year"), by_year, meta)
        else:
            for k, (name, long_name) in enumerate(zip(column.csv, column.long_name, strict=True)):
                data[name] = ("row", np.asarray([_pair(v, k) for v in values], dtype=np.float64),
                              {"units": column.unit, "long_name": long_name})
    return data, coords


def study_dataset(record: StudyRecord) -> xarray.Dataset:
    """The record's rows as a tidy :class:`xarray.Dataset`, with units and long names.

    Parameters
    ----------
    record : StudyRecord
        From :func:`regimemap.workflows.run_study`.

    Returns
    -------
    xarray.Dataset
        Dimensions ``row`` (section x scenario x width, the record's order), ``limit``
        (the tolerable sliding distances, m) and ``year`` (service years 1..L).
        Coordinates ``section``, ``chainage`` [m], ``scenario``, ``width`` [m] along ``row``.
        Variables ``expected_sliding`` and ``std_error`` [m] (row); ``exceedance``
        (P(S > limit), row x limit); ``year_over`` (the first service year whose expected
        cumulative sliding exceeds the limit, NaN: never within the life; row x limit);
        ``by_year`` [m] (the expected cumulative sliding at the end of each service year,
        row x year); ``band_low``, ``band_high`` [m] (the ESD's climate band);
        ``required_width``, ``required_width_low``, ``required_width_high`` (its Monte
        Carlo interval) and ``required_width_upper`` (the width at the climate band's upper
        level) [m].  Global attributes: the study's hash, seed, trials, years, target, the
        study file, regimemap's version and the notices.

    Raises
    ------
    ImportError
        xarray is not installed (the message names the ``metocean`` extra).
    """
    xr = _xarray()
    from .. import __version__

    rows = record.rows
    limits = sorted({x for r in rows for x, _ in r.exceedance}) or [0.1, 0.3]
    years = np.arange(1, record.years + 1, dtype=np.int32)

    data, coords = _variables(rows, limits, years)
    coords.update({
        "limit": ("limit", np.asarray(limits, dtype=np.float64),
                  {"units": "m", "long_name": "tolerable sliding distance"}),
        "year": ("year", years, {"units": "year", "long_name": "service year"}),
    })
    attrs: dict[str, str | int | float] = {
        "title": "regimemap study: expected sliding of a breakwater's sections under climate scenarios",
        "study_hash": record.study_hash,
        "seed": int(record.seed) if -2**31 <= record.seed < 2**31 else str(record.seed),  # NetCDF-3: int32
        "trials": int(record.trials),
        "years": int(record.years),
        "source": record.source or "",
        "regimemap_version": __version__,
        "notices": "\n".join(f"{n.code}: {n.message}" for n in record.notices),
    }
    if record.target is not None:
        attrs["target"] = float(record.target)
    ds: xarray.Dataset = xr.Dataset(data, coords=coords, attrs=attrs)
    return ds


def write_study_netcdf(path: str | os.PathLike[str], record: StudyRecord) -> None:
    """Write :func:`study_dataset` to ``path`` atomically (:func:`regimemap.io.atomic.atomic_path`).

    The engine is :func:`netcdf_engine`'s: NetCDF-4 through netCDF4 when installed, else
    NetCDF-3 through scipy.  A failure leaves no file (nor a half-written one).

    Raises
    ------
    ImportError
        xarray is not installed (the message names the ``metocean`` extra).
    """
    ds = study_dataset(record)
    engine = netcdf_engine()
    with atomic_path(path) as tmp:
        ds.to_netcdf(tmp, engine=engine)
