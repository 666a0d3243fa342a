"""Design points: ``K,MU[:NAME]`` specs and CSV files with columns ``k,mu[,gamma,kprime,name]``
and, for a block with loads, ``buoyancy``, ``uplift``, ``uplift_ratio``, ``uplift_arm``,
``gyration``, ``crest``."""

from __future__ import annotations

import csv
import math
import os
import re
from dataclasses import dataclass

from ..io.textfile import NUMBER, guarded_lines, open_text_file, read_header
from ..mechanics.validation import GAMMA_MAX, GAMMA_MIN, LOAD_LIMITS, MAX_VALUE
from .points import LOAD_FIELDS, DesignPoint

__all__ = ["DesignPoint", "PointsTable", "parse_point_spec", "read_points_csv", "read_points_table",
           "MAX_POINTS", "MAX_POINTS_FILE_BYTES"]

#: Largest number of rows accepted from a points file.
MAX_POINTS = 1_000_000
#: Largest points file accepted, in bytes (checked before opening it, and again while
#: reading; a path that is not a regular file is refused: :mod:`regimemap.io.inputs`).
MAX_POINTS_FILE_BYTES = 128 * 1024 * 1024


def _number(text: str, what: str, where: str, crest: float = 1.0) -> float:
    """``text`` as the value of ``what`` (k, mu, gamma, kprime or a load), with the library's ranges."""
    if what == "gamma":
        rng, lo, hi = f"a finite number in [{GAMMA_MIN:g}, {GAMMA_MAX:g}]", GAMMA_MIN, GAMMA_MAX
    elif what == "kprime":
        rng, lo, hi = f"a number in [-1, {crest:g}]", -1.0, crest
    elif what in LOAD_LIMITS:
        lo, hi, lo_open, hi_open = LOAD_LIMITS[what]
        rng = f"a number in {'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"
        if text and NUMBER.fullmatch(text) and ((lo_open and float(text) == lo)
                                                  or (hi_open and float(text) == hi)):
            raise ValueError(f"{where}: {what} must be {rng}, got {text!r}")
    else:
        rng, lo, hi = f"a finite number >= 0 (at most {MAX_VALUE:g})", 0.0, MAX_VALUE
    if not text:
        raise ValueError(f"{where}: {what} is missing; it must be {rng}")
    if not NUMBER.fullmatch(text):
        raise ValueError(f"{where}: {what} must be {rng}, got {text!r} (not a number)")
    v = float(text)
    if not math.isfinite(v) or v < lo or v > hi:
        raise ValueError(f"{where}: {what} must be {rng}, got {text!r}")
    return v + 0.0  # fold -0.0


def parse_point_spec(spec: str) -> DesignPoint:
    """Parse ``"K,MU"`` or ``"K,MU:NAME"`` (as given to ``plot --point``).

    Raises
    ------
    ValueError
        If the spec is not two numbers >= 0 separated by a comma.
    """
    body, _, name = spec.partition(":")
    parts = body.split(",")
    if len(parts) != 2:
        raise ValueError(f"point {spec!r} must be K,MU or K,MU:NAME (e.g. 0.45,0.6:caisson-A)")
    k = _number(parts[0].strip(), "k", f"point {spec!r}")
    mu = _number(parts[1].strip(), "mu", f"point {spec!r}")
    return DesignPoint(k, mu, name.strip())


@dataclass(frozen=True)
class PointsTable:
    """The design points of a file, the line each came from, and how the file was read.

    Attributes
    ----------
    points : list of DesignPoint
    lines : list of int
        The line of the file of each point (1 = the first line).
    note : str
        How the file was read when it is not plain CSV (``""`` otherwise), e.g.
        ``semicolon-separated with decimal commas``: say so to the user.
    """

    points: list[DesignPoint]
    lines: list[int]
    note: str = ""


def _sniff(path: str) -> tuple[str, bool]:
    """The separator of the file (``,``, ``;`` or a tab) and whether numbers use decimal commas.

    A file is read as comma-separated unless its header names k and mu only
    when split at semicolons (what a spreadsheet writes where the comma is
    the decimal mark: ``k;mu`` and ``0,5;0,3``) or at tabs.
    """
    fh = open_text_file(path, "points file", MAX_POINTS_FILE_BYTES)
    with fh:
        try:
            for line in guarded_lines(fh, path, "points file", MAX_POINTS_FILE_BYTES):
                if line.strip():
                    break
            else:
                return ",", False
        except UnicodeDecodeError:
            return ",", False
    def names(sep: str) -> list[str]:
        return [c.strip().strip('"').lower() for c in line.rstrip("\r\n").split(sep)]
    if {"k", "mu"} <= set(names(",")):
        return ",", False
    for sep in (";", "\t"):
        if {"k", "mu"} <= set(names(sep)):
            return sep, sep == ";"
    return ",", False


_DECIMAL_COMMA = re.compile(r"[+-]?\d*,\d+(?:[eE][+-]?\d+)?", re.ASCII)


def read_points_csv(path: str | os.PathLike[str]) -> list[DesignPoint]:
    """Read design points from a CSV file with a header row.

    Required columns ``k`` and ``mu``; optional ``gamma``, ``kprime``,
    ``name`` and the loads ``buoyancy``, ``uplift``, ``uplift_ratio``,
    ``uplift_arm``, ``gyration``, ``crest`` (an empty cell: the caller's
    default; other columns are ignored; names are case-insensitive).  A row's
    kprime is checked against its own crest (1 when the row has none).  Blank
    lines are skipped, also before the header.  At most :data:`MAX_POINTS`
    points and :data:`MAX_POINTS_FILE_BYTES` bytes.  A file saved by a
    spreadsheet where the comma is the decimal mark (``k;mu`` and
    ``0,5;0,3``) is read too; :func:`read_points_table` says so.

    Raises
    ------
    ValueError
        Naming the file, the line and the column of the first bad value, or a
        missing or repeated column.
    """
    return read_points_table(path).points


def read_points_table(path: str | os.PathLike[str]) -> PointsTable:
    """:func:`read_points_csv`, with the line of every point and how the file was read."""
    path = os.fspath(path)
    sep, decimal_comma = _sniff(path)
    note = ""
    if sep == ";":
        note = "semicolon-separated with decimal commas (as a spreadsheet writes it)"
    elif sep == "\t":
        note = "tab-separated"
    fh = open_text_file(path, "points file", MAX_POINTS_FILE_BYTES)
    with fh:
        reader = csv.reader(guarded_lines(fh, path, "points file", MAX_POINTS_FILE_BYTES),
                            delimiter=sep)
        try:
            known = ("k", "mu", "gamma", "kprime", "name", *LOAD_FIELDS)
            cols, idx = read_header(reader, path, ("k", "mu"), known)
            points: list[DesignPoint] = []
            lines: list[int] = []
            for row in reader:
                line = reader.line_num
                if not row or all(not c.strip() for c in row):
                    continue
                where = f"{path}, line {line}"
                if len(row) > len(cols) and any(c.strip() for c in row[len(cols):]):
                    raise ValueError(f"{where}: {len(row)} fields, but the header names {len(cols)} "
                                     "columns (a value without a column; quote a name that holds the "
                                     "separator)")
                if len(row) < len(cols):
                    row = row + [""] * (len(cols) - len(row))

                def cell(c: str, row: list[str] = row) -> str:
                    v = row[idx[c]].strip()
                    if decimal_comma and c != "name" and _DECIMAL_COMMA.fullmatch(v):
                        v = v.replace(",", ".")
                    return v

                k = _number(cell("k"), "k", f"{where}, column k")
                mu = _number(cell("mu"), "mu", f"{where}, column mu")
                gamma = kprime = None
                loads: dict[str, float] = {}
                for c in LOAD_FIELDS:
                    if c in idx and cell(c):
                        loads[c] = _number(cell(c), c, f"{where}, column {c}")
                if "gamma" in idx and cell("gamma"):
                    gamma = _number(cell("gamma"), "gamma", f"{where}, column gamma")
                if "kprime" in idx and cell("kprime"):
                    kprime = _number(cell("kprime"), "kprime", f"{where}, column kprime",
                                     loads.get("crest", 1.0))
                name = cell("name") if "name" in idx else ""
                if len(points) >= MAX_POINTS:
                    raise ValueError(f"{where}: more than {MAX_POINTS} points (the limit)")
                points.append(DesignPoint(k, mu, name, gamma, kprime, **loads))
                lines.append(line)
        except (csv.Error, UnicodeDecodeError) as exc:
            raise ValueError(f"{path}, line {reader.line_num + 1}: not CSV text ({exc})") from None
    return PointsTable(points, lines, note)
