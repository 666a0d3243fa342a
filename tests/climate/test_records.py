"""The record readers on real files (excerpts of the shared data), on the NDBC sample and on broken
copies: every unreadable or impossible value names the file, the line and the column."""

from __future__ import annotations

import gzip
from pathlib import Path

import numpy as np
import pytest

from regimemap.climate.file import RecordError, read_record
from regimemap.climate.wave_record import SPIKE_JUMP, SPIKE_RATIO, find_spikes, make_record

DATA = Path(__file__).parent / "data"
NDBC44007 = DATA / "ndbc44007_1996_hs_tz.txt.gz"
OREGON = DATA / "oregon_hindcast_1990_hs.csv.gz"
STDMET = DATA / "ndbc_stdmet_sample.txt"


def _lines(path: Path) -> list[str]:
    raw = path.read_bytes()
    return (gzip.decompress(raw) if raw[:2] == b"\x1f\x8b" else raw).decode().splitlines()


def _write(tmp_path: Path, name: str, lines: list[str]) -> Path:
    p = tmp_path / name
    p.write_text("\n".join(lines) + "\n")
    return p


def test_semicolon_record_as_in_the_file():
    lines = _lines(NDBC44007)
    r = read_record(NDBC44007)
    rows = [line.split(";") for line in lines[1:]]
    assert r.time.size == len(rows)
    assert r.start == "1996-01-01T00:00Z"
    assert r.step_hours == 1.0
    np.testing.assert_array_equal(r.hs, [float(x[1]) for x in rows])
    np.testing.assert_array_equal(r.period, [float(x[2]) for x in rows])
    assert r.period_name == "Tz"
    # years = observed samples x step / 365.25 days
    assert r.years == pytest.approx(len(rows) / (24 * 365.25))


def test_csv_with_zone_and_three_hour_step():
    r = read_record(OREGON)
    lines = _lines(OREGON)[1:]
    assert r.time.size == len(lines)
    assert r.step_hours == 3.0
    assert r.period is None
    assert str(r.time[1]) == "1990-01-01T03:00:00"
    assert r.hs[0] == pytest.approx(float(lines[0].split(",")[1]))


def test_csv_zone_converted_to_utc(tmp_path):
    p = _write(tmp_path, "r.csv", ["time,Hm0,Tp", "2000-01-01T02:00+02:00,1.0,8", "2000-01-01T01:00+00:00,1.5,9",
                                   "2000-01-01T02:00Z,1.2,8"])
    r = read_record(p)
    assert [str(t) for t in r.time] == ["2000-01-01T00:00:00", "2000-01-01T01:00:00", "2000-01-01T02:00:00"]
    assert r.quality.unsorted == 0  # in order once the zones are applied
    assert r.period_name == "Tp"


def test_csv_named_columns_and_missing(tmp_path):
    p = _write(tmp_path, "r.csv", ["when,height,per", "2000-01-01 00:00,1.0,", "2000-01-01 01:00,,7",
                                   "2000-01-01 02:00,-999,7", "2000-01-01 03:00,2.0,8"])
    with pytest.raises(RecordError, match="no time column"):
        read_record(p)
    r = read_record(p, time="when", hs="height", period="per")
    assert r.quality.missing == 2
    assert np.isnan(r.period[0])


def test_ndbc_stdmet_sample():
    r = read_record(STDMET)
    body = [line.split() for line in _lines(STDMET)[2:]]
    assert r.time.size == len(body)
    assert str(r.time[0]) == "2003-01-01T00:50:00"
    expect = [np.nan if x[8] == "99.00" else float(x[8]) for x in body]
    np.testing.assert_array_equal(r.hs, expect)
    assert r.quality.missing == 2
    assert r.period_name == "DPD"
    assert read_record(STDMET, period="APD").period_name == "APD"


@pytest.mark.slow
def test_netcdf_cf_time(tmp_path):
    xr = pytest.importorskip("xarray")
    t = np.datetime64("2001-01-01T00", "s") + np.arange(48) * np.timedelta64(3600, "s")
    hs = np.linspace(1.0, 3.0, 48)
    ds = xr.Dataset({"VHM0": ("time", hs), "VTPK": ("time", hs * 3)}, coords={"time": t})
    ds["time"].encoding["units"] = "hours since 2001-01-01"
    path = tmp_path / "r.nc"
    ds.to_netcdf(path, engine="scipy")
    r = read_record(path)
    np.testing.assert_allclose(r.hs, hs)
    assert r.time[5] == t[5]
    assert r.period is None
    assert read_record(path, period="VTPK").period is not None


@pytest.mark.parametrize(("line", "match"), [
    ("1996-01-01-05; abc; 4.7", r"line 7, column 'Hs': cannot read 'abc' as a number"),
    ("1996-13-01-05; 1.0; 4.7", r"line 7, column 'time': cannot read '1996-13-01T05'"),
    ("1996-01-01-05; -0.5; 4.7", r"line 7, column 'Hs': significant wave height -0.5 m is impossible"),
    ("1996-01-01-05; 45; 4.7", r"line 7, column 'Hs': significant wave height 45 m is impossible"),
    ("1996-01-01-05; 1.0; 0", r"line 7, column 'Tz': period 0 s is impossible"),
])
def test_broken_copies_name_line_and_column(tmp_path, line, match):
    lines = _lines(NDBC44007)[:200]
    lines[6] = line
    p = _write(tmp_path, "broken.txt", lines)
    with pytest.raises(RecordError, match=match):
        read_record(p)


def test_broken_ndbc_and_csv(tmp_path):
    lines = _lines(STDMET)
    lines[5] = lines[5].replace("2003 01 01", "2003 01 xx")
    with pytest.raises(RecordError, match=r"line 6, columns YY MM DD hh mm"):
        read_record(_write(tmp_path, "n.txt", lines))
    with pytest.raises(RecordError, match=r"no significant wave height column"):
        read_record(_write(tmp_path, "c.csv", ["time,wind", "2000-01-01,3"]))
    with pytest.raises(RecordError, match=r"line 3: 1 fields, the header has 2"):
        read_record(_write(tmp_path, "c.csv", ["time,hs", "2000-01-01,3", "2000-01-02"]))
    with pytest.raises(RecordError, match=r"every significant wave height is missing"):
        read_record(_write(tmp_path, "c.csv", ["time,hs", "2000-01-01,99.0", "2000-01-02,"]))
    with pytest.raises(RecordError, match=r"broken gzip"):
        (tmp_path / "b.gz").write_bytes(NDBC44007.read_bytes()[:500])
        read_record(tmp_path / "b.gz")
    with pytest.raises(RecordError, match=r"cannot read"):
        read_record(tmp_path / "absent.csv")


def test_duplicates_and_sorting(tmp_path):
    p = _write(tmp_path, "r.csv", ["time,hs", "2000-01-01 02:00,1.2", "2000-01-01 00:00,1.0",
                                   "2000-01-01 01:00,1.1", "2000-01-01 01:00,9.9"])
    r = read_record(p)
    assert r.quality.duplicates == 1 and r.quality.unsorted == 1
    np.testing.assert_array_equal(r.hs, [1.0, 1.1, 1.2])
    assert r.quality.warnings()[0] == (
        "1 repeated time(s) with differing copies, the first observed of each kept: 2000-01-01T01:00Z "
        "(lines 4, 5) Hs 1.10 m kept, 9.90 m dropped; copies differ by up to 8.80 m in Hs")


def test_identical_copies_are_a_counted_quiet_drop():
    t = np.datetime64("2000-01-01T00", "s") + np.array([0, 1, 1, 2, 3, 3, 3]) * np.timedelta64(3600, "s")
    r = make_record("x", t, np.array([1.0, 1.1, 1.1, 1.2, 1.3, 1.3, 1.3]))
    assert r.quality.duplicates == 3 and r.quality.conflicts is None and r.quality.warnings() == []
    np.testing.assert_array_equal(r.hs, [1.0, 1.1, 1.2, 1.3])


def test_a_missing_copy_gives_way_to_the_observed_one():
    t = np.datetime64("2000-01-01T00", "s") + np.array([0, 1, 1, 2]) * np.timedelta64(3600, "s")
    r = make_record("x", t, np.array([1.0, np.nan, 1.1, 1.2]), lines=np.array([2, 3, 4, 5]))
    np.testing.assert_array_equal(r.hs, [1.0, 1.1, 1.2])
    assert r.quality.duplicates == 1 and r.quality.conflicts is None and r.quality.missing == 0


def test_conflicts_counted_with_the_largest_difference_and_the_period():
    t = np.datetime64("2000-01-01T00", "s") + np.array([0, 5, 1, 1, 2, 2, 2, 3, 3]) * np.timedelta64(3600, "s")
    hs = np.array([1.0, 1.5, 1.1, 1.4, 1.2, 2.9, 1.2, 1.3, 1.3])
    tz = np.array([5.0, 5.0, 5.0, 5.0, 6.0, 6.0, 6.0, 6.0, 7.5])
    q = make_record("x", t, hs, tz, "Tz").quality
    assert q.duplicates == 4 and q.conflicts is not None
    c = q.conflicts
    assert (c.count, c.time, c.hs, c.lines, c.period) == (3, "2000-01-01T01:00Z", (1.1, 1.4), (), (5.0, 5.0))
    assert c.hs_spread == pytest.approx(1.7) and c.period_spread == pytest.approx(1.5)
    assert q.warnings()[0].endswith("copies differ by up to 1.70 m in Hs, 1.50 s in Tz")
    only_period = make_record("x", t[[0, 7, 8]], hs[[0, 7, 8]], tz[[0, 7, 8]], "Tz").quality
    assert only_period.conflicts is not None and only_period.conflicts.hs_spread == 0.0
    assert only_period.warnings()[0].endswith("Tz 6.00 s kept, 7.50 s dropped; copies differ by up to 1.50 s in Tz")


def test_a_bad_copy_before_the_largest_storm_peak_is_named(tmp_path):
    lines = _lines(NDBC44007)
    top = 1 + int(np.argmax([float(x.split(";")[1]) for x in lines[1:]]))
    stamp, hs, tz = (x.strip() for x in lines[top].split(";"))
    bad = f"{stamp}; {float(hs) + 5.0:.4f}; {tz}"
    r = read_record(_write(tmp_path, "dup.txt", [*lines[:top], bad, *lines[top:]]))
    first = read_record(NDBC44007)
    assert r.quality.duplicates == 1 and r.quality.conflicts is not None
    assert r.hs.max() == pytest.approx(float(hs) + 5.0)  # the first copy kept, as it always was
    assert np.count_nonzero(r.hs != first.hs) == 1
    when = f"{stamp[:10]}T{stamp[11:]}:00Z"
    assert r.quality.warnings() == [
        f"1 repeated time(s) with differing copies, the first observed of each kept: {when} "
        f"(lines {top + 1}, {top + 2}) Hs {float(hs) + 5.0:.2f} m kept, {float(hs):.2f} m dropped; "
        "copies differ by up to 5.00 m in Hs"]


def test_spikes_flagged_then_dropped_on_request():
    rng = np.random.default_rng(4)
    t = np.datetime64("2000-01-01T00", "s") + np.arange(500) * np.timedelta64(3600, "s")
    hs = 1.0 + 0.3 * np.sin(np.arange(500) / 20.0) + 0.01 * rng.random(500)
    hs[[100, 333]] = [6.0, 5.0]
    r = make_record("x", t, hs)
    assert [s[0] for s in r.quality.spikes] == ["2000-01-05T04:00Z", "2000-01-14T21:00Z"]
    assert np.isfinite(r.hs[100])
    dropped = make_record("x", t, hs, drop_spikes=True)
    assert np.isnan(dropped.hs[100]) and dropped.quality.spikes_dropped
    # brute force of the definition
    brute = [i for i in range(1, 499) if hs[i] >= SPIKE_RATIO * max(hs[i - 1], hs[i + 1])
             and hs[i] - max(hs[i - 1], hs[i + 1]) >= SPIKE_JUMP]
    assert np.flatnonzero(find_spikes(hs, np.arange(500.0), 1.0)).tolist() == brute


def test_coverage_per_calendar_year():
    t = np.datetime64("2000-01-01T00", "s") + np.arange(0, 2 * 8784, 2) * np.timedelta64(3600, "s")
    hs = np.ones(t.size)
    hs[: t.size // 4] = np.nan
    r = make_record("x", t, hs)
    assert r.step_hours == 2.0
    assert r.quality.coverage[2000] == pytest.approx((8784 // 2 - t.size // 4) * 2 / 8784)
    assert r.quality.gaps == []  # missing values are not gaps in time ... but observed gaps are
    assert make_record("x", t, np.where(np.arange(t.size) == 10, np.nan, 1.0)).quality.gaps[0][2] == 4.0


def test_a_gzip_record_that_decompresses_past_the_limit_is_refused(tmp_path, monkeypatch):
    import gzip

    import regimemap.climate.file as records

    f = tmp_path / "bomb.txt.gz"
    f.write_bytes(gzip.compress(b"0" * 100_000))  # 100 kB of text in a few hundred bytes
    monkeypatch.setattr(records, "MAX_RECORD_FILE_BYTES", 50_000)
    with pytest.raises(records.RecordError, match="decompresses to more than the limit"):
        records.read_record(f)
    f.write_bytes(gzip.compress(b"0" * 100_000)[:-12])  # cut short
    monkeypatch.setattr(records, "MAX_RECORD_FILE_BYTES", 1_000_000)
    with pytest.raises(records.RecordError, match="broken gzip"):
        records.read_record(f)


@pytest.mark.parametrize(("shares", "limit", "shown"), [
    ({1991: 0.9996, 1992: 0.45}, 1.0, ["1991 (99.96 %)", "1992 (45 %)"]),  # not 1991 (100 %)
    ({1991: 0.796}, 0.8, ["1991 (79.6 %)"]),
    ({1991: 0.79999999999}, 0.8, ["1991 (79.999999999 %)"]),
    ({1991: 0.5}, 0.8, ["1991 (50 %)"]),
])
def test_a_year_below_the_coverage_never_reads_as_the_limit(shares, limit, shown):
    from regimemap.climate.wave_record import Quality

    (warning,) = Quality(missing=0, duplicates=0, unsorted=0, coverage=shares).warnings(limit)
    assert warning.endswith(", ".join(shown)), warning


@pytest.mark.parametrize(("column", "what"), [({"period": "nope"}, "period"), ({"period": "Hs"}, "period"),
                                              ({"hs": "WVHT"}, "significant wave height"),
                                              ({"time": "when"}, "time")])
def test_the_semicolon_text_refuses_a_column_it_does_not_have(column, what):
    name = next(iter(column.values()))
    with pytest.raises(RecordError, match=rf"no column '{name}' for the {what} \(columns: time, Hs, Tz"):
        read_record(NDBC44007, **column)
    assert read_record(NDBC44007, time="time", hs="hs", period="Tz").period_name == "Tz"  # its own names


def test_a_file_named_nc_that_is_not_netcdf_is_said_in_one_short_line(tmp_path):
    p = tmp_path / "x.nc"
    p.write_bytes(gzip.decompress(OREGON.read_bytes()))
    with pytest.raises(RecordError) as info:
        read_record(p)
    assert str(info.value).startswith(f"{p}: cannot open as NetCDF: not a NetCDF file (")
    assert "xarray" not in str(info.value) and "http" not in str(info.value)


@pytest.mark.parametrize(("raw", "where"), [
    (b"tim\x94e,hs\n2000-01-01,1\n", "byte 0x94 at offset 3, line 1"),
    (b"\xef\xbb\xbftime,hs\n2000-01-01,1.\x94\n", "byte 0x94 at offset 24, line 2"),  # counted with the BOM
])
def test_a_file_that_is_not_utf8_names_the_byte(tmp_path, raw, where):
    p = tmp_path / "b.csv"
    p.write_bytes(raw)
    with pytest.raises(RecordError, match=rf"^{p}: not a UTF-8 text file \(nor NetCDF\): {where}$"):
        read_record(p)
    (tmp_path / "b.csv.gz").write_bytes(gzip.compress(raw))
    with pytest.raises(RecordError, match=r"of the decompressed text"):
        read_record(tmp_path / "b.csv.gz")
