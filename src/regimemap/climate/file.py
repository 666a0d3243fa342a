"""Readers of wave records: CSV, the semicolon text of the shared data, NDBC standard meteorological
files and NetCDF; each gives a :class:`regimemap.climate.wave_record.Record` with its quality control.

* CSV: a header row; an ISO time column (with or without a time zone: times with one are turned
  into UTC) and a significant-wave-height column, an optional period column, found by their
  common names (:data:`TIME_NAMES`, :data:`HS_NAMES`, :data:`PERIOD_NAMES`, any case) or named.
* The semicolon text: a header line, then ``YYYY-MM-DD-HH; Hs; Tz`` (the shared data's format).
* NDBC standard meteorological data (https://www.ndbc.noaa.gov/faq/measdes.shtml): a header line
  ``#YY  MM DD hh mm WDIR WSPD GST  WVHT   DPD   APD MWD ...``, a second line of units, and
  ``99.00`` / ``99.0`` / ``999`` where a value is missing; the period is ``DPD`` (dominant) unless
  ``period="APD"``.
* NetCDF with a CF time coordinate (xarray; the optional extra ``metocean``).

A text file may be gzip-compressed (``.gz``).

Every unreadable time or value is a :class:`RecordError` naming the file, the line and the column;
a negative height, a height above :data:`regimemap.climate.wave_record.HS_MAX` or a period outside
(0, :data:`regimemap.climate.wave_record.PERIOD_MAX`] is impossible and an error too.  Values equal to
a missing code (:data:`MISSING_CODES`) or empty are missing, and counted.
"""

from __future__ import annotations

import csv
import io
import math
import zlib
from collections.abc import Sequence
from datetime import datetime, timezone
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..io.inputs import InputFileError, NotUTF8Error, check_input_file, read_limited, utf8_text
from .wave_record import HS_MAX, PERIOD_MAX, Record, make_record

__all__ = ["HS_NAMES", "MISSING_CODES", "PERIOD_NAMES", "TIME_NAMES", "RecordError", "read_record"]

FloatArray = NDArray[np.float64]

#: Time column names, in order of preference (compared without case).
TIME_NAMES = ("time", "time_index", "datetime", "date_time", "timestamp", "date")
#: Significant-wave-height names (``significant_wave_height`` also as a prefix).
HS_NAMES = ("hs", "hm0", "vhm0", "swh", "wvht", "significant_wave_height")
#: Period names, in order of preference.
PERIOD_NAMES = ("tp", "tz", "dpd", "apd")
#: Values that mean "missing" in wave records (NDBC's 99.00 and 999, the common -999 and 9999).
MISSING_CODES = (99.0, 999.0, 9999.0, -99.0, -999.0, -9999.0)
_MISSING_TEXT = {"", "nan", "na", "n/a", "null", "mm", "-"}


#: The suffixes of a NetCDF file (which must then start as one: ``CDF``, or HDF5's signature).
NETCDF_SUFFIXES = (".nc", ".nc4", ".cdf", ".netcdf")


class RecordError(ValueError):
    """A record that cannot be read: the message names the file, the line and the column."""


#: The largest wave record read, compressed or not [bytes]: 128 MiB, some five centuries of
#: hourly sea states written as text (a ten-year hourly record is 2.6 MB).
MAX_RECORD_FILE_BYTES = 128 * 1024 * 1024


def check_record_file(path: str | Path) -> None:
    """Refuse ``path`` unless it is a regular file of at most :data:`MAX_RECORD_FILE_BYTES`.

    Raises
    ------
    InputFileError
        Naming the path and the reason (a folder, a FIFO, a device, too large).
    """
    check_input_file(path, max_bytes=MAX_RECORD_FILE_BYTES, what="wave record")


def _gunzip(p: str, raw: bytes) -> bytes:
    """The gzip file ``raw`` decompressed, at most :data:`MAX_RECORD_FILE_BYTES` of it."""
    d = zlib.decompressobj(16 + zlib.MAX_WBITS)
    try:
        out = d.decompress(raw, MAX_RECORD_FILE_BYTES + 1)
    except zlib.error as exc:
        raise RecordError(f"{p}: a broken gzip file ({exc})") from None
    if len(out) > MAX_RECORD_FILE_BYTES or d.unconsumed_tail:
        raise RecordError(f"{p}: decompresses to more than the limit of "
                          f"{MAX_RECORD_FILE_BYTES // (1024 * 1024)} MiB of a wave record")
    if not d.eof:
        raise RecordError(f"{p}: a broken gzip file (it ends before its end of stream)")
    return out


def _float(text: str, where: str) -> float:
    s = text.strip()
    if s.lower() in _MISSING_TEXT:
        return math.nan
    try:
        v = float(s)
    except ValueError:
        raise RecordError(f"{where}: cannot read {s!r} as a number") from None
    if v in MISSING_CODES or not math.isfinite(v):
        return math.nan
    return v


def _check_values(path: str, hs: FloatArray, period: FloatArray | None, lines: Sequence[int],
                  hs_name: str, period_name: str | None) -> None:
    """Impossible heights and periods: an error naming the first offending line."""
    with np.errstate(invalid="ignore"):
        bad = np.flatnonzero((hs < 0.0) | (hs > HS_MAX))
    if bad.size:
        i = int(bad[0])
        raise RecordError(f"{path}, line {lines[i]}, column {hs_name!r}: significant wave height "
                          f"{hs[i]:g} m is impossible (accepted: 0 to {HS_MAX:g} m, or a missing code)")
    if period is not None:
        with np.errstate(invalid="ignore"):
            bad = np.flatnonzero((period <= 0.0) | (period > PERIOD_MAX))
        if bad.size:
            i = int(bad[0])
            raise RecordError(f"{path}, line {lines[i]}, column {period_name!r}: period {period[i]:g} s "
                              f"is impossible (accepted: > 0 to {PERIOD_MAX:g} s, or a missing code)")


def _utc(text: str) -> str:
    """An ISO time as naive UTC text (a zone, if any, applied)."""
    s = text.strip()
    if s.endswith("Z"):
        s = s[:-1] + "+00:00"
    t = datetime.fromisoformat(s)
    if t.tzinfo is not None:
        t = t.astimezone(timezone.utc).replace(tzinfo=None)
    return t.isoformat()


def _times(texts: list[str], lines: Sequence[int], path: str, column: str) -> NDArray[np.datetime64]:
    """ISO times to datetime64[s] (UTC): numpy at once, else one by one to name the bad line."""
    stripped = [s.strip() for s in texts]
    if stripped and all(s.endswith("+00:00") for s in stripped):
        stripped = [s[:-6] for s in stripped]
    elif stripped and all(s.endswith("Z") for s in stripped):
        stripped = [s[:-1] for s in stripped]
    if not any(("+" in s[10:] or s[10:].count("-") or s.endswith("Z")) for s in stripped):
        try:
            return np.array(stripped, dtype="datetime64[s]")
        except ValueError:
            pass
    out = []
    for s, line in zip(texts, lines):
        try:
            out.append(_utc(s))
        except ValueError:
            raise RecordError(f"{path}, line {line}, column {column!r}: cannot read {s.strip()!r} as an "
                              "ISO time (such as 1996-01-01T00:00 or 1996-01-01 00:00:00+00:00)") from None
    return np.array(out, dtype="datetime64[s]")


def _find(names: list[str], wanted: str | None, choices: Sequence[str], what: str, path: str,
          prefix: bool = False) -> int | None:
    low = [n.strip().lower() for n in names]
    if wanted is not None:
        if wanted.strip().lower() not in low:
            raise RecordError(f"{path}: no column {wanted!r} for the {what} (columns: {', '.join(names)})")
        return low.index(wanted.strip().lower())
    for c in choices:
        if c in low:
            return low.index(c)
        if prefix and c == choices[-1]:
            for i, n in enumerate(low):
                if n.startswith(c):
                    return i
    return None


def _read_csv(path: str, text: str, time: str | None, hs: str | None, period: str | None,
              drop_spikes: bool) -> Record:
    rows = list(csv.reader(io.StringIO(text)))
    header = [h.strip() for h in rows[0]]
    it = _find(header, time, TIME_NAMES, "time", path)
    ih = _find(header, hs, HS_NAMES, "significant wave height", path, prefix=True)
    if it is None:
        raise RecordError(f"{path}: no time column (looked for {', '.join(TIME_NAMES)}; name it with --time)")
    if ih is None:
        raise RecordError(f"{path}: no significant wave height column (looked for "
                          f"{', '.join(HS_NAMES)}*; name it with --hs)")
    ip = _find(header, period, PERIOD_NAMES, "period", path)
    data = [(k + 2, r) for k, r in enumerate(rows[1:]) if any(c.strip() for c in r)]
    lines = [k for k, _ in data]
    width = len(header)
    for k, r in data:
        if len(r) != width:
            raise RecordError(f"{path}, line {k}: {len(r)} fields, the header has {width}")
    h = np.array([_float(r[ih], f"{path}, line {k}, column {header[ih]!r}") for k, r in data])
    p = None if ip is None else np.array([_float(r[ip], f"{path}, line {k}, column {header[ip]!r}")
                                          for k, r in data])
    t = _times([r[it] for _, r in data], lines, path, header[it])
    pname = None if ip is None else header[ip]
    _check_values(path, h, p, lines, header[ih], pname)
    return make_record(path, t, h, p, pname, drop_spikes, lines=np.asarray(lines, dtype=np.int64))


#: The columns of the semicolon text, as its messages name them: a column option must name one of these
#: (its own), as it names a column of a CSV file.
SEMICOLON_COLUMNS = ("time", "Hs", "Tz")


def _read_semicolon(path: str, lines_text: list[str], drop_spikes: bool, time: str | None = None,
                    hs_name: str | None = None, period: str | None = None) -> Record:
    given = ((time, "time"), (hs_name, "significant wave height"), (period, "period"))
    for column, (wanted, what) in zip(SEMICOLON_COLUMNS, given):
        if wanted is not None and wanted.strip().lower() != column.lower():
            raise RecordError(f"{path}: no column {wanted!r} for the {what} (columns: "
                              f"{', '.join(SEMICOLON_COLUMNS)}; the semicolon text's {what} is {column!r})")
    times, hs, tz, lines = [], [], [], []
    for k, line in enumerate(lines_text[1:], start=2):
        if not line.strip():
            continue
        parts = line.split(";")
        if len(parts) < 2:
            raise RecordError(f"{path}, line {k}: expected 'YYYY-MM-DD-HH; Hs; Tz', got {line.strip()!r}")
        stamp = parts[0].strip()
        if len(stamp) == 13 and stamp[10] == "-":
            stamp = stamp[:10] + "T" + stamp[11:]
        times.append(stamp)
        hs.append(_float(parts[1], f"{path}, line {k}, column 'Hs'"))
        tz.append(_float(parts[2], f"{path}, line {k}, column 'Tz'") if len(parts) > 2 else math.nan)
        lines.append(k)
    t = _times(times, lines, path, "time")
    h, p = np.array(hs), np.array(tz)
    _check_values(path, h, p, lines, "Hs", "Tz")
    return make_record(path, t, h, p, "Tz", drop_spikes, lines=np.asarray(lines, dtype=np.int64))


def _read_ndbc(path: str, lines_text: list[str], period: str | None, drop_spikes: bool) -> Record:
    header = lines_text[0].lstrip("#").split()
    names = [n.upper() for n in header]
    for need in ("MM", "DD", "HH", "WVHT"):
        if need not in names:
            raise RecordError(f"{path}, line 1: an NDBC header without {need} (columns: {' '.join(header)})")
    iy = names.index("YYYY") if "YYYY" in names else names.index("YY") if "YY" in names else None
    if iy is None:
        raise RecordError(f"{path}, line 1: an NDBC header without YY (columns: {' '.join(header)})")
    pname = (period or "DPD").upper()
    if pname not in names:
        raise RecordError(f"{path}: no column {pname!r} for the period (columns: {' '.join(header)})")
    ip, ih = names.index(pname), names.index("WVHT")
    imin = names.index("MM", names.index("HH")) if names.count("MM") > 1 else None
    im, idd, ihh = names.index("MM"), names.index("DD"), names.index("HH")
    times, hs, per, lines = [], [], [], []
    for k, line in enumerate(lines_text[1:], start=2):
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        if len(f) < len(names):
            raise RecordError(f"{path}, line {k}: {len(f)} fields, the header has {len(names)}")
        try:
            y = int(f[iy])
            y = y + 1900 if y < 100 else y
            stamp = datetime(y, int(f[im]), int(f[idd]), int(f[ihh]),
                             0 if imin is None else int(f[imin])).isoformat()
        except ValueError:
            raise RecordError(f"{path}, line {k}, columns YY MM DD hh mm: cannot read "
                              f"{' '.join(f[:5])!r} as a date and time") from None
        times.append(stamp)
        hs.append(_float(f[ih], f"{path}, line {k}, column 'WVHT'"))
        per.append(_float(f[ip], f"{path}, line {k}, column {pname!r}"))
        lines.append(k)
    if not times:
        raise RecordError(f"{path}: no data lines after the header")
    h, p = np.array(hs), np.array(per)
    _check_values(path, h, p, lines, "WVHT", pname)
    return make_record(path, np.array(times, dtype="datetime64[s]"), h, p, pname, drop_spikes,
                       lines=np.asarray(lines, dtype=np.int64))


def _read_netcdf(path: str, time: str | None, hs: str | None, period: str | None,
                 drop_spikes: bool) -> Record:
    try:
        import xarray as xr
    except ImportError:
        raise RecordError(f"{path}: reading NetCDF needs xarray and a NetCDF engine: "
                          "pip install 'regimemap[metocean]'") from None
    try:
        ds = xr.open_dataset(path)
    except Exception as exc:  # the engines raise many kinds
        if "xarray's" in str(exc) and "IO backends" in str(exc):  # NetCDF-4 (HDF5) without netCDF4
            raise RecordError(f"{path}: cannot open as NetCDF: no installed engine reads it (NetCDF-4 "
                              "needs netCDF4: pip install 'regimemap[metocean]')") from None
        raise RecordError(f"{path}: cannot open as NetCDF ({exc})") from None
    with ds:
        names = [str(v) for v in ds.variables]
        it = _find(names, time, TIME_NAMES, "time", path)
        ih = _find(names, hs, HS_NAMES, "significant wave height", path, prefix=True)
        if it is None or not np.issubdtype(ds[names[it]].dtype, np.datetime64):
            raise RecordError(f"{path}: no CF time variable (looked for {', '.join(TIME_NAMES)} with "
                              "units such as 'hours since 1990-01-01'; name it with --time)")
        if ih is None:
            raise RecordError(f"{path}: no significant wave height variable (looked for "
                              f"{', '.join(HS_NAMES)}*; name it with --hs)")
        ip = _find(names, period, PERIOD_NAMES, "period", path)
        t = np.asarray(ds[names[it]].values).astype("datetime64[s]")
        h = np.asarray(ds[names[ih]].values, dtype=np.float64).ravel()
        p = None if ip is None else np.asarray(ds[names[ip]].values, dtype=np.float64).ravel()
    if h.size != t.size:
        raise RecordError(f"{path}: variable {names[ih]!r} has {h.size} values, time has {t.size} "
                          "(a record of one point is expected)")
    h = np.where(np.isin(h, MISSING_CODES), np.nan, h)
    if p is not None:
        p = np.where(np.isin(p, MISSING_CODES), np.nan, p)
    _check_values(path, h, p, [k + 1 for k in range(h.size)], names[ih], None if ip is None else names[ip])
    return make_record(path, t, h, p, None if ip is None else names[ip], drop_spikes)


def _is_netcdf(raw: bytes) -> bool:
    """Whether ``raw`` starts as NetCDF does: classic ``CDF``, or NetCDF-4's HDF5 signature (at 0, or
    after a user block of 512, 1024, 2048 ... bytes)."""
    if raw[:3] == b"CDF":
        return True
    at = 0
    while at < len(raw):
        if raw[at:at + 4] == b"\x89HDF":
            return True
        at = 512 if at == 0 else 2 * at
    return False


def _text(path: str, raw: bytes, gzipped: bool) -> str:
    """``raw`` as UTF-8 text (a byte-order mark dropped); else an error naming the first byte that is
    not UTF-8, its offset (in the decompressed text of a gzip file) and its line."""
    try:
        return utf8_text(raw)
    except NotUTF8Error as exc:
        where = exc.where.replace(", line", " of the decompressed text, line") if gzipped else exc.where
        raise RecordError(f"{path}: not a UTF-8 text file (nor NetCDF): {where}") from None


def read_record(path: str | Path, time: str | None = None, hs: str | None = None,
                period: str | None = None, drop_spikes: bool = False) -> Record:
    """Read a wave record, its format told by its suffix (``.nc``) or its first line.

    Parameters
    ----------
    path : str or Path
        The file.
    time, hs, period : str, optional
        Column (or variable) names, instead of the common names.
    drop_spikes : bool, optional
        Remove the isolated spikes instead of only flagging them.

    Returns
    -------
    Record

    Raises
    ------
    RecordError
        The file cannot be read, or a value is unreadable or impossible (file, line, column named).
    """
    p = str(path)
    try:
        raw = read_limited(p, max_bytes=MAX_RECORD_FILE_BYTES, what="wave record")
    except InputFileError as exc:
        raise RecordError(f"{p}: cannot read the wave record: {exc.reason}") from None
    except OSError as exc:
        raise RecordError(f"{p}: cannot read ({exc.strerror or exc})") from None
    gzipped = raw[:2] == b"\x1f\x8b"
    if gzipped:
        raw = _gunzip(p, raw)
    try:
        if _is_netcdf(raw):
            return _read_netcdf(p, time, hs, period, drop_spikes)
        if Path(p).suffix.lower() in NETCDF_SUFFIXES:
            raise RecordError(f"{p}: cannot open as NetCDF: not a NetCDF file (it starts with neither "
                              "'CDF' nor HDF5's signature)")
        text = _text(p, raw, gzipped)
        lines = text.splitlines()
        if not lines or not any(line.strip() for line in lines[1:]):
            raise RecordError(f"{p}: no data (a header line and at least one line of values expected)")
        first = lines[0].lstrip()
        if first.startswith("#YY") or first.startswith("YY"):
            return _read_ndbc(p, lines, period, drop_spikes)
        if ";" in first:
            return _read_semicolon(p, lines, drop_spikes, time, hs, period)
        return _read_csv(p, text, time, hs, period, drop_spikes)
    except RecordError:
        raise
    except ValueError as exc:
        raise RecordError(str(exc) if str(exc).startswith(p) else f"{p}: {exc}") from None
