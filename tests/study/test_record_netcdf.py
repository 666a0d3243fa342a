"""A study's record as an xarray Dataset and a NetCDF file: layout, units, round trip, atomic writes.

The records are built by hand (:func:`hand_record`, also used by the figures' tests), so the tests
do not depend on a run: three sections (two with fixed widths, one with a target) under two
scenarios, with and without a climate band.
"""

from __future__ import annotations

import math
import sys

import numpy as np
import pytest

from regimemap.records.notices import Notice
from regimemap.study.run import StudyRecord, StudyRow

YEARS = 10
LIMITS = (0.1, 0.3)


def _row(section: str, chainage: float, scenario: str, width: float, esd: float, *,
         band: bool = False, target: bool = False, years: int = YEARS) -> StudyRow:
    """A row whose expected cumulative sliding grows linearly to ``esd`` over the life."""
    by_year = tuple(esd * (y + 1) / years for y in range(years))
    passes = tuple((x, next((y + 1 for y, v in enumerate(by_year) if v > x), None)) for x in LIMITS)
    return StudyRow(
        section=section, chainage=chainage, scenario=scenario, width=width, expected_sliding=esd,
        std_error=0.1 * esd, exceedance=((0.1, min(1.0, esd / 2)), (0.3, min(1.0, esd / 6))),
        by_year=by_year, passes=passes, band=(0.6 * esd, 1.8 * esd) if band else None,
        required_width=width if target else None,
        required_width_interval=(width - 2.0, width + 3.0) if target else None,
        required_width_upper=(width + 4.0 if band else None) if target else None)


def hand_record(*, band: bool = False, target: bool = True, years: int = YEARS,
                notices: tuple[Notice, ...] = ()) -> StudyRecord:
    """Three sections (0, 250, 500 m) x two scenarios; the last section by target when ``target``."""
    rows = []
    for scenario, f in (("today", 1.0), ("rise 1 m", 2.5)):
        rows += [_row("trunk 8 m", 0.0, scenario, w, f * e, band=band, years=years)
                 for w, e in ((12.0, 0.08), (15.0, 0.02))]
    for scenario, f in (("today", 1.0), ("rise 1 m", 2.5)):
        rows.append(_row("trunk 12 m", 250.0, scenario, 20.0, f * 0.05, band=band, years=years))
    for scenario, w in (("today", 30.0), ("rise 1 m", 34.0)):
        rows.append(_row("head 18 m", 500.0, scenario, w if target else 30.0, 0.1 if target else 0.2,
                         band=band, target=target, years=years))
    return StudyRecord(source="breakwater.toml", study_hash="ab" * 32, seed=2026, trials=300, years=years,
                       sections=(("trunk 8 m", 0.0), ("trunk 12 m", 250.0), ("head 18 m", 500.0)),
                       scenarios=("today", "rise 1 m"), target=0.1 if target else None,
                       rows=tuple(rows), notices=notices)


xr = pytest.importorskip("xarray")

from regimemap.study.record_netcdf import (  # noqa: E402
    check_netcdf,
    netcdf_engine,
    study_dataset,
    write_study_netcdf,
)


def test_the_dataset_is_the_table_row_by_row() -> None:
    rec = hand_record(band=True)
    ds = study_dataset(rec)
    assert dict(ds.sizes) == {"row": len(rec.rows), "limit": 2, "year": YEARS}
    assert list(ds["limit"].values) == [0.1, 0.3]
    assert list(ds["year"].values) == list(range(1, YEARS + 1))
    for i, r in enumerate(rec.rows):
        assert ds["section"].values[i] == r.section and ds["scenario"].values[i] == r.scenario
        assert ds["width"].values[i] == r.width and ds["chainage"].values[i] == r.chainage
        assert ds["expected_sliding"].values[i] == r.expected_sliding
        assert ds["std_error"].values[i] == r.std_error
        assert list(ds["exceedance"].values[i]) == [p for _, p in r.exceedance]
        assert list(ds["by_year"].values[i]) == list(r.by_year)
        assert ds["by_year"].values[i, -1] == r.expected_sliding
        years = [np.nan if y is None else y for _, y in r.passes]
        np.testing.assert_array_equal(ds["year_over"].values[i], years)
        assert (ds["band_low"].values[i], ds["band_high"].values[i]) == r.band
    # the target section's rows carry the width, its interval and the band's width; the others NaN
    head = ds.where(ds["section"] == "head 18 m", drop=True)
    assert list(head["required_width"].values) == [30.0, 34.0]
    assert list(head["required_width_low"].values) == [28.0, 32.0]
    assert list(head["required_width_upper"].values) == [34.0, 38.0]
    assert np.all(np.isnan(ds.where(ds["section"] != "head 18 m", drop=True)["required_width"].values))


def test_every_variable_has_units_and_a_long_name() -> None:
    ds = study_dataset(hand_record())
    for name in [*ds.data_vars, "chainage", "width", "limit", "year"]:
        assert ds[name].attrs.get("long_name"), name
        assert ds[name].attrs.get("units"), name
    assert ds["expected_sliding"].attrs["units"] == "m"
    assert ds["exceedance"].attrs["units"] == "1"
    assert ds["year_over"].attrs["units"] == "year"


def test_global_attributes_name_the_run() -> None:
    import regimemap

    notice = Notice("target-not-bracketed", "section 'head 18 m': no width meets it", "width", None)
    ds = study_dataset(hand_record(notices=(notice,)))
    assert ds.attrs["study_hash"] == "ab" * 32
    assert (ds.attrs["seed"], ds.attrs["trials"], ds.attrs["years"]) == (2026, 300, YEARS)
    assert ds.attrs["target"] == 0.1 and ds.attrs["source"] == "breakwater.toml"
    assert ds.attrs["regimemap_version"] == regimemap.__version__
    assert ds.attrs["notices"] == "target-not-bracketed: section 'head 18 m': no width meets it"
    assert "target" not in study_dataset(hand_record(target=False)).attrs


def test_without_a_band_or_a_target_the_values_are_nan() -> None:
    ds = study_dataset(hand_record(band=False, target=False))
    for name in ("band_low", "band_high", "required_width", "required_width_low", "required_width_high",
                 "required_width_upper"):
        assert np.all(np.isnan(ds[name].values)), name


def test_round_trip_through_netcdf(tmp_path) -> None:
    rec = hand_record(band=True)
    path = tmp_path / "table.nc"
    write_study_netcdf(path, rec)
    with xr.open_dataset(path) as back:
        back.load()
    xr.testing.assert_identical(back, study_dataset(rec))
    assert [str(s) for s in back["section"].values] == [r.section for r in rec.rows]
    cube = back.set_index(row=["section", "scenario", "width"])
    assert float(cube.sel(section="trunk 12 m", scenario="rise 1 m")["expected_sliding"].values[0]) == 0.125
    assert [p.name for p in tmp_path.iterdir()] == ["table.nc"]  # no temporary file left


def test_the_same_record_gives_the_same_bytes(tmp_path) -> None:
    rec = hand_record(band=True)
    a, b = tmp_path / "a.nc", tmp_path / "b.nc"
    write_study_netcdf(a, rec)
    write_study_netcdf(b, rec)
    assert a.read_bytes() == b.read_bytes()
    if netcdf_engine() == "scipy":
        assert a.read_bytes()[:3] == b"CDF"  # NetCDF-3 classic


def test_a_failed_write_leaves_no_file(tmp_path, monkeypatch) -> None:
    path = tmp_path / "table.nc"
    path.write_bytes(b"old")

    def fail(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", fail)
    with pytest.raises(OSError):
        write_study_netcdf(path, hand_record())
    assert [p.name for p in tmp_path.iterdir()] == ["table.nc"] and path.read_bytes() == b"old"


def test_without_xarray_the_error_names_the_extra(monkeypatch) -> None:
    check_netcdf()  # installed here: nothing to say
    monkeypatch.setitem(sys.modules, "xarray", None)
    with pytest.raises(ImportError, match=r"regimemap\[metocean\]"):
        study_dataset(hand_record())
    monkeypatch.setattr("importlib.util.find_spec", lambda name, *a: None)
    with pytest.raises(ImportError, match=r"needs xarray: pip install 'regimemap\[metocean\]'"):
        check_netcdf()


def test_a_large_seed_is_kept_whole() -> None:
    import dataclasses

    ds = study_dataset(dataclasses.replace(hand_record(), seed=2**40 + 1))
    assert ds.attrs["seed"] == str(2**40 + 1)
    assert not math.isnan(float(ds["expected_sliding"].values[0]))


def test_every_file_writes_the_declared_fields_of_a_row_in_their_order() -> None:
    """A study row's fields are declared once (COLUMNS): the CSV's columns, the JSON's keys and the
    NetCDF's variables are those names, in that order, and carry its units and words."""
    import csv
    import io

    from regimemap.study.record import COLUMNS, LIMITS
    from regimemap.study.record_table import STUDY_COLUMNS, study_csv_text, study_json

    rec = hand_record(band=True)
    header = next(csv.reader(io.StringIO(study_csv_text(rec))))
    assert tuple(header) == STUDY_COLUMNS == tuple(n for c in COLUMNS for n in c.csv_columns)
    assert header[6:8] == [f"p_exceed_{x:g}" for x in LIMITS] and "by_year" not in header
    assert [list(row) for row in study_json(rec)["rows"]] == [[c.name for c in COLUMNS]] * len(rec.rows)
    ds = study_dataset(rec)
    names = [n for c in COLUMNS if c.kind != "coord" for n in (c.csv if c.kind == "pair" else (c.name,))]
    assert list(ds.data_vars) == names
    for c in COLUMNS:
        for name, words in ((zip(c.csv, c.long_name, strict=True)) if c.kind == "pair" else ((c.name, c.long_name),)):
            assert ds[name].attrs["long_name"] == words and ds[name].attrs.get("units", "") == c.unit
