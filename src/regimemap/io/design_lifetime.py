"""The ``[lifetime]`` table of the design file: the climate and the options of the lifetime simulation.

:class:`LifetimeSpec` is the table as the file gives it; :data:`LIFETIME_KEYS`
and :data:`ERROR_FACTORS` the keys accepted in ``[lifetime]`` and
``[lifetime.errors]``, with what each accepts (the messages and the
documentation read them); :func:`check_lifetime_option` checks one value as the
file's (the command line's ``--years``, ``--trials``, ``--seed``);
:func:`read_lifetime` reads the table with the line of every key refused
(:func:`regimemap.io.toml_lines.key_line`); :func:`lifetime_model` turns it into
a :class:`regimemap.lifetime.LifetimeModel`.  :mod:`regimemap.io.design` reads
the whole file and re-exports the public names.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from .design_errors import DesignFileError, did_you_mean
from .toml_lines import key_line, key_text

if TYPE_CHECKING:
    from regimemap.lifetime import LifetimeModel

    from .design_record import RecordSpec

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "LIFETIME_TABLES", "MAX_TRIALS", "MAX_YEARS", "LifetimeSpec",
           "check_lifetime_option", "lifetime_model", "read_lifetime"]

#: Most lifetimes a run may simulate (its arrays take ~24 bytes a lifetime).
MAX_TRIALS = 10_000_000
#: Longest design life [years].
MAX_YEARS = 1000
#: Largest deep-water significant height H0' a climate may give [m].  The largest significant
#: heights measured are about 20 m (19 m, a North Atlantic buoy, February 2013: the WMO record);
#: above 30 m no sea has been seen, and the value is a unit slip (centimetres for metres).
MAX_HEIGHT = 30.0
#: Significant periods of wind seas and swell [s]: outside, not a sea state (tenths of a second,
#: a frequency for a period).
PERIOD_RANGE = (1.0, 30.0)
#: Largest tidal range [m]: the largest on Earth is about 16 m (Bay of Fundy).
MAX_TIDE_RANGE = 20.0
#: Most storms a year: more than one a day are not separate storms.
MAX_STORMS_PER_YEAR = 365.0
#: Longest peak sea state of one storm [hours]: a week.
MAX_STORM_HOURS = 168.0


@dataclass(frozen=True)
class LifetimeSpec:
    """``[lifetime]``: the climate and the options of a lifetime simulation, as the file gives them.

    The climate is ``H0_10`` and ``H0_50`` [m], or ``annual_maxima`` [m];
    ``errors`` holds the factors ``[lifetime.errors]`` names, as ``(ratio,
    cov)``: the others take :data:`regimemap.lifetime.DEFAULT_ERRORS`.
    ``thresholds`` None means :data:`regimemap.lifetime.DEFAULT_THRESHOLDS`,
    ``seed`` None a fresh seed for every run.  The requirements: ``target``
    (the tolerable ESD [m]), ``allowed`` (lifetime sliding [m] -> the largest
    allowed probability of exceeding it, Kim & Suh 2013) and
    ``failure_sliding`` (the sliding at which the caisson is off its mound [m],
    None: not given).  ``written`` holds the climate's values as the file
    wrote them (TOML's text of the parsed value), for the reports to echo.
    """

    years: int = 50
    trials: int = 5000
    seed: int | None = None
    distribution: str = "weibull"
    shape: float = 2.0
    H0_10: float | None = None
    H0_50: float | None = None
    annual_maxima: tuple[float, ...] | None = None
    storms_per_year: float | None = None
    storm_hours: float = 2.0
    period: float | None = None
    steepness: float | None = None
    tide_range: float = 0.0
    thresholds: tuple[float, ...] | None = None
    truncate: float | None = None
    impulsive: bool = False
    errors: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    target: float = 0.1
    allowed: Mapping[float, float] = field(default_factory=dict)
    failure_sliding: float | None = None
    written: Mapping[str, str] = field(default_factory=dict)
    record: RecordSpec | None = None
    climate_replicates: int = 0

    def climate_as_written(self) -> str:
        """The climate's keys as the file wrote them (``H0_10 = 5.0 m, H0_50 = 6.3 m``)."""
        if self.record is not None:
            return f"[lifetime.record] path = {self.record.path}"
        keys = ("annual_maxima",) if self.annual_maxima is not None else ("H0_10", "H0_50")
        return ", ".join(f"{key} = {self.written.get(key, '?')} m" for key in keys)


def _positive(x: float) -> bool:
    return x > 0.0


def _height(x: float) -> bool:
    return 0.0 < x <= MAX_HEIGHT


def _why_height(x: float) -> str:
    if x > MAX_HEIGHT:
        slip = f"; {x / 100:.4g} m in centimetres for metres?" if x / 100 <= MAX_HEIGHT else ""
        return (f"above {MAX_HEIGHT:g} m, higher than any sea measured (the largest significant "
                f"heights measured are about 20 m){slip}")
    return "not > 0"


def _why_period(x: float) -> str:
    lo, hi = PERIOD_RANGE
    if x > hi:
        return f"above {hi:g} s, longer than any sea wave; {x / 10:.3g} s in tenths of a second?"
    return f"below {lo:g} s, shorter than any sea wave that loads a breakwater; a frequency for a period?"


@dataclass(frozen=True)
class _LKey:
    accepted: str                      # what is accepted, in words
    kind: str                          # "int", "number", "text", "bool", "numbers", "pair", "limits",
    #                                    "table"
    check: Callable[[Any], bool] = lambda x: True
    why: Callable[[float], str] = lambda x: "out of range"   # why a value the check refuses is wrong


def _at_least(lo: float) -> Callable[[Any], bool]:
    return lambda x: x >= lo


#: The keys of ``[lifetime]``, in the order the messages list them.
LIFETIME_KEYS: dict[str, _LKey] = {
    "years": _LKey(f"a design life in whole years, 1 <= years <= {MAX_YEARS} (default 50)", "int",
                   lambda x: 1 <= x <= MAX_YEARS),
    "trials": _LKey(f"a number of simulated lifetimes, 1 <= trials <= {MAX_TRIALS} (default 5000)",
                    "int", lambda x: 1 <= x <= MAX_TRIALS),
    "seed": _LKey("a whole number >= 0, the root seed of the random numbers (default: a fresh one, "
                  "reported)", "int", _at_least(0)),
    "distribution": _LKey('"weibull" or "gumbel", the distribution of the storm peaks H0\' '
                          '(default "weibull")', "text", lambda x: x in ("weibull", "gumbel")),
    "shape": _LKey("a Weibull shape k > 0 (default 2; fitting annual_maxima needs k > 1)", "number",
                   _positive),
    "H0_10": _LKey(f"the 10-year return value of H0', 0 < H0_10 <= {MAX_HEIGHT:g} m (the largest "
                   "significant heights measured are about 20 m)", "number", _height, _why_height),
    "H0_50": _LKey(f"the 50-year return value of H0', H0_10 < H0_50 <= {MAX_HEIGHT:g} m", "number",
                   _height, _why_height),
    "annual_maxima": _LKey(f"a list of at least three annual maxima of H0', each 0 < H0' <= "
                           f"{MAX_HEIGHT:g} m and not all equal (instead of H0_10 and H0_50)", "numbers",
                           _height, _why_height),
    "storms_per_year": _LKey(f"a mean number of storms a year, 0.1 < storms_per_year <= "
                             f"{MAX_STORMS_PER_YEAR:g} (a Poisson number of storms, peaks over a "
                             "threshold; not with annual_maxima; default: one storm a year, its peak "
                             "the annual maximum)", "number", lambda x: 0.1 < x <= MAX_STORMS_PER_YEAR),
    "storm_hours": _LKey(f"a duration 0 < storm_hours <= {MAX_STORM_HOURS:g} in hours of each storm's "
                         "peak sea state (default 2)", "number", lambda x: 0.0 < x <= MAX_STORM_HOURS),
    "period": _LKey(f"a significant period {PERIOD_RANGE[0]:g} <= T1/3 <= {PERIOD_RANGE[1]:g} s of "
                    "sea waves for every storm (default: Goda's 3.3 H0'^0.63); not with steepness",
                    "number", lambda x: PERIOD_RANGE[0] <= x <= PERIOD_RANGE[1], _why_period),
    "steepness": _LKey("a deep-water steepness 0 < H0'/L0 <= 0.142 for every storm; not with period",
                       "number", lambda x: 0.0 < x <= 0.142),
    "tide_range": _LKey(f"a tidal range 0 <= tide_range <= {MAX_TIDE_RANGE:g} m (the largest, Bay of "
                        "Fundy, is about 16 m; default 0)", "number", lambda x: 0.0 <= x <= MAX_TIDE_RANGE),
    "thresholds": _LKey("a list of lifetime slides, each > 0 in metres, whose exceedance probability "
                        "is reported (default [0.03, 0.1, 0.3, 1, 3])", "numbers", _positive),
    "truncate": _LKey("a cut-off > 0 of the normal error factors, in standard deviations (default: "
                      "none)", "number", _positive),
    "impulsive": _LKey("true or false: Takahashi's impulsive coefficient in each wave's force "
                       "(default false)", "bool"),
    "target": _LKey("the tolerable expected sliding distance, > 0 in metres: the requirement "
                    "ESD <= target (default 0.1, Goda & Takagi 2000)", "number", _positive),
    "allowed": _LKey('a table of lifetime slides (m) and the largest allowed probability of '
                     'exceeding each, 0 <= p <= 1, e.g. {"0.1" = 0.2, "0.3" = 0.05} (Kim & Suh 2013; '
                     "default: none)", "limits"),
    "failure_sliding": _LKey("the sliding in metres at which the caisson is off its mound (the "
                             "harbour-side crest width of the mound), > 0: P(S > failure_sliding) is "
                             "the probability of failure over the life (default: none)", "number",
                             _positive),
    "errors": _LKey("the table [lifetime.errors] of the uncertainty factors (deepwater, "
                    "transformation, force, friction)", "table"),
    "record": _LKey("the table [lifetime.record] of a measured wave record (path and the options of "
                    "regimemap climate), instead of H0_10 and H0_50 or annual_maxima", "table"),
    "climate_replicates": _LKey("a number of bootstrap climates of [lifetime.record], 2 to 10000, each "
                                "run for the ESD's climate band (default: none)", "int",
                                lambda x: 2 <= x <= 10_000),
}

_PAIR = "a pair [ratio, cov] with ratio > 0 and cov >= 0, the factor ratio (1 + cov z) "
_DEFAULT = "; absent: its default in regimemap.lifetime.DEFAULT_ERRORS"
#: The keys of ``[lifetime.errors]`` (the factors of :class:`regimemap.lifetime.Errors`).
ERROR_FACTORS: dict[str, _LKey] = {
    "deepwater": _LKey(_PAIR + "on the storm's H0' (once per lifetime)" + _DEFAULT, "pair"),
    "transformation": _LKey(_PAIR + "on H1/3 at the wall (once per storm)" + _DEFAULT, "pair"),
    "force": _LKey(_PAIR + "on the wave force P and the uplift U (once per storm)" + _DEFAULT, "pair"),
    "friction": _LKey(_PAIR + "on the friction coefficient (once per storm)" + _DEFAULT, "pair"),
}

#: The key tables of ``[lifetime]`` and ``[lifetime.errors]``.
LIFETIME_TABLES = {"lifetime": LIFETIME_KEYS, "lifetime.errors": ERROR_FACTORS}
_CLIMATE = ("either H0_10 and H0_50 (the 10- and 50-year return values of H0', metres) or "
            "annual_maxima (a list of annual maxima of H0', metres)")


def check_lifetime_option(name: str, value: Any) -> Any:
    """One value of ``[lifetime]`` (``years``, ``trials``, ``seed`` ...), checked as the file's.

    Text (from the command line) is read as the key's kind: a whole number
    for ``years``, ``trials`` and ``seed``, a number for the others.

    Returns
    -------
    int or float
        The value.

    Raises
    ------
    ValueError
        ``"trials must be a number of simulated lifetimes, 1 <= trials <= ..., got '0'"``.
    """
    spec = LIFETIME_KEYS[name]
    if spec.kind not in ("int", "number"):
        raise ValueError(f"{name} is not a single number")
    got = value
    if isinstance(value, str):
        try:
            value = int(value.strip(), 10) if spec.kind == "int" else float(value.strip())
        except ValueError:
            kind = "a whole number" if spec.kind == "int" else "a number"
            raise ValueError(f"{name} must be {spec.accepted}, got {got!r} (not {kind})") from None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
            spec.kind == "int" and not isinstance(value, int)):
        raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    if spec.kind == "number":
        value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    if not spec.check(value):
        raise ValueError(f"{name} must be {spec.accepted}, got {got!r}")
    return value


class _LifetimeReader:
    """Reads ``[lifetime]`` with the line of every key in the messages."""

    def __init__(self, text: str, source: str) -> None:
        self.text = text
        self.source = source

    def where(self, table: str, key: str | None = None) -> str:
        line = key_line(self.text, table, key)
        return self.source if line is None else f"{self.source}, line {line}"

    def fail(self, table: str, key: str | None, what: str) -> DesignFileError:
        return DesignFileError(f"{self.where(table, key)}: {what}")

    def bad(self, table: str, key: str, value: Any, why: str) -> DesignFileError:
        accepted = LIFETIME_TABLES[table][key].accepted
        written = key_text(self.text, table, key) if not isinstance(value, list) else None
        shown = written if written is not None else repr(value)
        return self.fail(table, key, f"[{table}] {key} = {shown}: {why}; accepted: {accepted}")

    def check_names(self, table: str, data: Mapping[str, Any]) -> None:
        known = LIFETIME_TABLES[table]
        for key in data:
            if key not in known:
                raise self.fail(table, key, f"unknown key [{table}] {key}{did_you_mean(key, known)}; "
                                f"accepted keys in [{table}]: {', '.join(known)}")

    def number(self, table: str, data: Mapping[str, Any], key: str, value: Any,
               item: bool = False) -> float:
        """``value`` (``data[key]``, or an item of that list) checked as a number of ``key``."""
        spec = LIFETIME_TABLES[table][key]
        which = f"{value!r} in the list is " if item else ""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            found = f"{which}{_toml_type(value)}" if item else _toml_type(value)
            raise self.bad(table, key, data[key], f"expected {'numbers' if item else 'a number'}, "
                           f"found {found}")
        x = float(value)
        if not math.isfinite(x):
            raise self.bad(table, key, data[key], f"{which}not a finite number")
        if not spec.check(x):
            raise self.bad(table, key, data[key], f"{which}{spec.why(x)}")
        return x

    def value(self, table: str, data: Mapping[str, Any], key: str) -> Any:
        """The checked value of ``key`` (None when absent)."""
        if key not in data:
            return None
        kind = LIFETIME_TABLES[table][key].kind
        if kind == "number":
            return self.number(table, data, key, data[key])
        read = {"int": self._int, "text": self._text, "bool": self._bool, "numbers": self._numbers,
                "pair": self._pair, "limits": self._limits}.get(kind, self._table)
        return read(table, data, key)

    def _int(self, table: str, data: Mapping[str, Any], key: str) -> int:
        v = data[key]
        if isinstance(v, bool) or not isinstance(v, int):
            raise self.bad(table, key, v, f"expected a whole number, found {_toml_type(v)}")
        if not LIFETIME_TABLES[table][key].check(v):
            raise self.bad(table, key, v, "out of range")
        return v

    def _text(self, table: str, data: Mapping[str, Any], key: str) -> str:
        v = data[key]
        if not isinstance(v, str):
            raise self.bad(table, key, v, f"expected a string, found {_toml_type(v)}")
        if not LIFETIME_TABLES[table][key].check(v):
            raise self.bad(table, key, v, "not one of the accepted values")
        return v

    def _bool(self, table: str, data: Mapping[str, Any], key: str) -> bool:
        v = data[key]
        if not isinstance(v, bool):
            raise self.bad(table, key, v, f"expected true or false, found {_toml_type(v)}")
        return v

    def _numbers(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, ...]:
        v = data[key]
        if not isinstance(v, list):
            raise self.bad(table, key, v, f"expected a list of numbers, found {_toml_type(v)}")
        if not v:
            raise self.bad(table, key, v, "the list is empty")
        return tuple(self.number(table, data, key, x, item=True) for x in v)

    def _pair(self, table: str, data: Mapping[str, Any], key: str) -> tuple[float, float]:
        v = data[key]
        if not isinstance(v, list) or len(v) != 2:
            found = f"a list of {len(v)}" if isinstance(v, list) else _toml_type(v)
            raise self.bad(table, key, v, f"expected [ratio, cov], found {found}")
        for x in v:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
                raise self.bad(table, key, v, f"{x!r} is not a finite number")
        ratio, cov = float(v[0]), float(v[1])
        if not ratio > 0.0:
            raise self.bad(table, key, v, f"the ratio {v[0]!r} is not > 0")
        if not cov >= 0.0:
            raise self.bad(table, key, v, f"the cov {v[1]!r} is < 0")
        return ratio, cov

    def _limits(self, table: str, data: Mapping[str, Any], key: str) -> dict[float, float]:
        """``{sliding m: probability}``; a bare key ``0.1`` (TOML's dotted ``0`` . ``1``) reads as 0.1."""
        v = data[key]
        if not isinstance(v, dict):
            raise self.bad(table, key, v,
                           f"expected a table {{sliding = probability}}, found {_toml_type(v)}")
        if not v:
            raise self.bad(table, key, v, "the table is empty")
        out: dict[float, float] = {}
        for name, p in _flatten(v):
            try:
                x = float(name)
            except ValueError:
                raise self.bad(table, key, v,
                               f"the key {name!r} is not a sliding distance in metres") from None
            if not (math.isfinite(x) and x > 0.0):
                raise self.bad(table, key, v, f"the sliding {name!r} is not > 0 m")
            if isinstance(p, bool) or not isinstance(p, (int, float)) or not 0.0 <= float(p) <= 1.0:
                raise self.bad(table, key, v, f"the probability {p!r} of {name} m is not in [0, 1]")
            out[x] = float(p)
        return dict(sorted(out.items()))

    def _table(self, table: str, data: Mapping[str, Any], key: str) -> dict[str, Any]:
        v = data[key]
        if not isinstance(v, dict):
            raise self.bad(table, key, v, f"expected a table, found {_toml_type(v)}")
        return v

    def check_climate(self, t: str, got: Mapping[str, Any], data: Mapping[str, Any]) -> None:
        """The climate of return values or annual maxima: complete, consistent."""
        h10, h50, maxima = got["H0_10"], got["H0_50"], got["annual_maxima"]
        if maxima is not None and (h10 is not None or h50 is not None):
            raise self.fail(t, "annual_maxima", "[lifetime] annual_maxima together with "
                            f"{'H0_10' if h10 is not None else 'H0_50'}; accepted: {_CLIMATE}")
        if maxima is None:
            if h10 is None or h50 is None:
                if h10 is None and h50 is None:
                    raise self.fail(t, None, f"[lifetime] has no wave climate; accepted: {_CLIMATE}")
                given, missing = ("H0_10", "H0_50") if h50 is None else ("H0_50", "H0_10")
                raise self.fail(t, given, f"[lifetime] {missing} is missing ({given} = "
                                f"{data[given]!r} is given); accepted: {_CLIMATE}")
            if not h50 > h10:
                raise self.bad(t, "H0_50", data["H0_50"], f"not above [lifetime] H0_10 = {data['H0_10']!r}")
        else:
            if len(maxima) < 3:
                raise self.bad(t, "annual_maxima", data["annual_maxima"],
                               f"{len(maxima)} value{'s' if len(maxima) != 1 else ''}, fewer than three")
            if min(maxima) == max(maxima):
                raise self.bad(t, "annual_maxima", data["annual_maxima"], "the values are all equal")
            if got["storms_per_year"] is not None:
                raise self.fail(t, "storms_per_year", f"[lifetime] storms_per_year = "
                                f"{data['storms_per_year']!r} together with annual_maxima; accepted: "
                                "annual maxima are one storm a year: give H0_10 and H0_50 of the peaks "
                                "over a threshold with storms_per_year, or annual_maxima alone")
            if got["distribution"] != "gumbel" and got["shape"] is not None and not got["shape"] > 1.0:
                raise self.bad(t, "shape", data["shape"], "fitting annual_maxima with a Weibull "
                               "distribution needs k > 1 (the likelihood is unbounded for k <= 1)")

    def read(self, data: Mapping[str, Any]) -> LifetimeSpec:
        t = "lifetime"
        self.check_names(t, data)
        got = {key: self.value(t, data, key) for key in LIFETIME_KEYS}
        errors: dict[str, tuple[float, float]] = {}
        if got["errors"] is not None:
            self.check_names("lifetime.errors", got["errors"])
            for key in ERROR_FACTORS:
                pair = self.value("lifetime.errors", got["errors"], key)
                if pair is not None:
                    errors[key] = pair

        h10, h50, maxima = got["H0_10"], got["H0_50"], got["annual_maxima"]
        record = _record_table(self.text, self.source, got, data)
        if record is None:
            self.check_climate(t, got, data)
        if got["period"] is not None and got["steepness"] is not None:
            raise self.fail(t, "steepness", f"[lifetime] steepness = {data['steepness']!r} together with "
                            f"[lifetime] period = {data['period']!r}; accepted: one of them, or neither "
                            "(Goda's T1/3 = 3.3 H0'^0.63)")
        spec = LifetimeSpec(
            years=50 if got["years"] is None else got["years"],
            trials=5000 if got["trials"] is None else got["trials"],
            seed=got["seed"], distribution=got["distribution"] or "weibull",
            shape=2.0 if got["shape"] is None else got["shape"],
            H0_10=h10, H0_50=h50, annual_maxima=maxima, storms_per_year=got["storms_per_year"],
            storm_hours=2.0 if got["storm_hours"] is None else got["storm_hours"],
            period=got["period"], steepness=got["steepness"],
            tide_range=0.0 if got["tide_range"] is None else got["tide_range"],
            thresholds=None if got["thresholds"] is None else tuple(sorted(set(got["thresholds"]))),
            truncate=got["truncate"], impulsive=bool(got["impulsive"]), errors=errors,
            target=0.1 if got["target"] is None else got["target"],
            allowed={} if got["allowed"] is None else got["allowed"],
            failure_sliding=got["failure_sliding"],
            record=record, climate_replicates=got["climate_replicates"] or 0,
            written={key: _written(data[key]) for key in ("H0_10", "H0_50", "annual_maxima") if key in data})
        try:  # anything the checks above missed, said the library's way
            lifetime_model(spec)
        except ValueError as exc:
            raise self.fail(t, None, f"[lifetime]: {exc}") from None
        return spec


def _record_table(text: str, source: str, got: Mapping[str, Any], data: Mapping[str, Any]
                  ) -> RecordSpec | None:
    """``[lifetime.record]`` read by :func:`regimemap.io.design_record.read_record_table`; refused
    beside another climate; ``climate_replicates`` only with it."""
    from .design_record import read_record_table

    if got["record"] is None:
        if got["climate_replicates"] is not None:
            raise DesignFileError(f"{source}: [lifetime] climate_replicates needs a [lifetime.record] "
                                  "table (the replicates are the bootstrap of the record's fit)")
        return None
    others = [k for k in ("H0_10", "H0_50", "annual_maxima", "storms_per_year", "distribution", "shape")
              if k in data]
    if others:
        line = key_line(text, "lifetime", others[0])
        where = source if line is None else f"{source}, line {line}"
        raise DesignFileError(f"{where}: [lifetime] {others[0]} together with [lifetime.record]; "
                              "accepted: the record alone (its fit gives the climate and the storm rate)")
    return read_record_table(text, source, got["record"])


def _flatten(table: Mapping[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    """The items of a table, nested tables joined by ``.`` (``{"0": {"1": p}}`` -> ``("0.1", p)``)."""
    out: list[tuple[str, Any]] = []
    for name, value in table.items():
        full = f"{prefix}.{name}" if prefix else str(name)
        out += _flatten(value, full) if isinstance(value, dict) else [(full, value)]
    return out


def _written(value: Any) -> str:
    """A parsed TOML value as the file wrote it (the shortest text that reads back the same)."""
    if isinstance(value, list):
        return "[" + ", ".join(_written(x) for x in value) + "]"
    return repr(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)


def _toml_type(v: Any) -> str:
    """The TOML name of a parsed value's type, for the messages."""
    names = {bool: "a boolean", int: "an integer", float: "a float", str: "a string", list: "an array",
             dict: "a table"}
    return names.get(type(v), type(v).__name__)


def lifetime_model(spec: LifetimeSpec, years: int | None = None) -> LifetimeModel:
    """The :class:`regimemap.lifetime.LifetimeModel` of a ``[lifetime]`` table (``years`` instead of its own).

    ``years`` is not checked here (:func:`check_lifetime_option` does).
    """
    import numpy as np

    from regimemap.lifetime import DEFAULT_ERRORS, DEFAULT_THRESHOLDS, Climate, ErrorFactor, LifetimeModel

    law = None
    if spec.record is not None:
        from .design_record import record_climate, record_period_law

        climate = record_climate(spec.record)
        if spec.period is None and spec.steepness is None:
            law = record_period_law(spec.record)
    else:
        try:  # an overflow of the fit is named here, not printed by numpy
            with np.errstate(all="raise"):
                if spec.annual_maxima is not None:
                    climate = Climate.fit_annual_maxima(spec.annual_maxima, spec.distribution, spec.shape)
                else:
                    assert spec.H0_10 is not None and spec.H0_50 is not None
                    climate = Climate.from_return_values(spec.H0_10, spec.H0_50, spec.distribution,
                                                         spec.shape, spec.storms_per_year)
                climate.return_value(50.0)
        except (FloatingPointError, OverflowError) as exc:
            what = "annual_maxima" if spec.annual_maxima is not None else "H0_10 and H0_50"
            raise ValueError(f"the {spec.distribution} climate of {what} cannot be computed ({exc}): "
                             "the values are too far apart or too close together") from None
    errors = replace(DEFAULT_ERRORS, **{name: ErrorFactor(*pair) for name, pair in spec.errors.items()})
    return LifetimeModel(climate, years=spec.years if years is None else years,
                         storm_hours=spec.storm_hours, period=spec.period, steepness=spec.steepness,
                         tide_range=spec.tide_range, impulsive=spec.impulsive, truncate=spec.truncate,
                         period_law=law,
                         errors=errors,
                         thresholds=DEFAULT_THRESHOLDS if spec.thresholds is None else spec.thresholds)


def read_lifetime(text: str, source: str, table: Mapping[str, Any]) -> LifetimeSpec:
    """The checked ``[lifetime]`` table (``table``, as tomllib parsed it from ``text``).

    Raises
    ------
    DesignFileError
        Naming ``source``, the line of the key (from ``text``), the key, the
        value and what is accepted.
    """
    return _LifetimeReader(text, source).read(table)
