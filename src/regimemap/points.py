"""Design points: ``K,MU[:NAME]`` specs and CSV files with columns ``k,mu[,gamma,kprime,name]``."""

from __future__ import annotations

import csv
import math
import os
from dataclasses import dataclass
from typing import Iterable

__all__ = ["DesignPoint", "parse_point_spec", "read_points_csv", "MAX_POINTS"]

#: Largest number of rows accepted from a points file.
MAX_POINTS = 1_000_000


@dataclass(frozen=True)
class DesignPoint:
    """A named point of the k-mu plane, optionally with its own gamma and kprime."""

    k: float
    mu: float
    name: str = ""
    gamma: float | None = None
    kprime: float | None = None


def _number(text: str, what: str, where: str, lo: float = 0.0, hi: float = math.inf,
            lo_open: bool = False) -> float:
    try:
        v = float(text)
    except (TypeError, ValueError):
        raise ValueError(f"{where}: {what} must be a number, got {text!r}") from None
    if not math.isfinite(v) or v < lo or v > hi or (lo_open and v <= lo):
        if what == "gamma":
            rng = "a finite number > 0"
        elif what == "kprime":
            rng = "a number in [-1, 1]"
        else:
            rng = "a finite number >= 0"
        raise ValueError(f"{where}: {what} must be {rng}, got {text!r}")
    return v


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


def read_points_csv(path: str | os.PathLike[str]) -> list[DesignPoint]:
    """Read design points from a CSV file with a header row.

    Required columns ``k`` and ``mu``; optional ``gamma``, ``kprime`` and
    ``name`` (other columns are ignored).  Blank lines are skipped.

    Raises
    ------
    ValueError
        Naming the file, the line and the column of the first bad value, or a
        missing column.
    """
    path = os.fspath(path)
    try:
        fh = open(path, newline="", encoding="utf-8-sig")
    except OSError as exc:
        raise ValueError(f"cannot read points file {path!r}: {exc.strerror}") from None
    with fh:
        reader = csv.reader(fh)
        try:
            header = next(reader)
        except StopIteration:
            raise ValueError(f"{path}: empty file; expected a header with columns k,mu") from None
        except (csv.Error, UnicodeDecodeError) as exc:
            raise ValueError(f"{path}, line 1: not CSV text ({exc})") from None
        cols = [h.strip().lower() for h in header]
        missing = [c for c in ("k", "mu") if c not in cols]
        if missing:
            raise ValueError(
                f"{path}, line 1: missing column(s) {', '.join(missing)}; the header must name k and mu"
            )
        idx = {c: cols.index(c) for c in ("k", "mu", "gamma", "kprime", "name") if c in cols}
        points: list[DesignPoint] = []
        try:
            rows: Iterable[list[str]] = reader
            for row in rows:
                line = reader.line_num
                if not row or all(not c.strip() for c in row):
                    continue
                if len(row) < len(cols):
                    row = row + [""] * (len(cols) - len(row))
                where = f"{path}, line {line}"

                def cell(c: str) -> str:
                    return row[idx[c]].strip()

                k = _number(cell("k"), "k", f"{where}, column k")
                mu = _number(cell("mu"), "mu", f"{where}, column mu")
                gamma = kprime = None
                if "gamma" in idx and cell("gamma"):
                    gamma = _number(cell("gamma"), "gamma", f"{where}, column gamma", lo_open=True)
                if "kprime" in idx and cell("kprime"):
                    kprime = _number(cell("kprime"), "kprime", f"{where}, column kprime", -1.0, 1.0)
                name = cell("name") if "name" in idx else ""
                points.append(DesignPoint(k, mu, name, gamma, kprime))
                if len(points) > MAX_POINTS:
                    raise ValueError(f"{path}: more than {MAX_POINTS} points")
        except (csv.Error, UnicodeDecodeError) as exc:
            raise ValueError(f"{path}, line {reader.line_num}: not CSV text ({exc})") from None
    return points
