"""The keys of the ``[lifetime]`` and ``[lifetime.errors]`` tables, declared once: what each accepts and why.

Each key of ``[lifetime]`` is one field of :class:`LifetimeSpec`, declared with
:func:`lifetime_key`: its type, its default, what it accepts in words (the
messages and the design-file reference read them), its TOML kind and the check of
its value, with the physical limits (heights up to 30 m, periods 1-30 s ...) and
the reason a value beyond them is refused; :data:`LIFETIME_KEYS` is read from those
fields.  :data:`ERROR_FACTORS` holds the factors of ``[lifetime.errors]``;
:func:`check_lifetime_option` checks one value as the file's (the command
line's ``--years``, ``--trials``, ``--seed``).  :mod:`regimemap.lifetime.file`
reads the tables with them.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import MISSING, dataclass, field, fields
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .file_record import RecordSpec

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "LIFETIME_TABLES", "MAX_HEIGHT", "MAX_STORM_HOURS",
           "MAX_STORMS_PER_YEAR", "MAX_TIDE_RANGE", "MAX_TRIALS", "MAX_YEARS", "PERIOD_RANGE",
           "LifetimeKey", "LifetimeSpec", "check_lifetime_option", "default_of", "example_lifetime",
           "lifetime_key"]

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
class LifetimeKey:
    """What one key of ``[lifetime]`` or ``[lifetime.errors]`` accepts: in words, its TOML kind,
    the check of its value and why a refused value is wrong."""

    accepted: str                      # what is accepted, in words
    kind: str                          # "int", "number", "text", "bool", "numbers", "pair", "limits",
    #                                    "table"
    check: Callable[[Any], bool] = lambda x: True
    why: Callable[[float], str] = lambda x: "out of range"   # why a value the check refuses is wrong
    example: str = ""                  # its lines in the commented example (none: not shown)


def _at_least(lo: float) -> Callable[[Any], bool]:
    return lambda x: x >= lo


def lifetime_key(accepted: str, kind: str, check: Callable[[Any], bool] = lambda x: True,
                 why: Callable[[float], str] = lambda x: "out of range", *, default: Any = MISSING,
                 factory: Callable[[], Any] | None = None, example: str = "") -> Any:
    """One key of ``[lifetime]``, declared once: the field of :class:`LifetimeSpec` that holds it.

    ``accepted``, ``kind``, ``check``, ``why`` and ``example`` (its lines in the commented example)
    are its :class:`LifetimeKey`; ``default`` (or ``factory``, for a table) is its value when the
    file leaves it out.
    """
    spec = LifetimeKey(accepted, kind, check, why, example)
    if factory is not None:
        return field(default_factory=factory, metadata={"key": spec})
    return field(default=default, metadata={"key": spec})


@dataclass(frozen=True, kw_only=True)
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
    Each field but ``written`` is a key, in the order the messages list them.
    """

    years: int = lifetime_key(
        f"a design life in whole years, 1 <= years <= {MAX_YEARS} (default 50)", "int",
        lambda x: 1 <= x <= MAX_YEARS, default=50,
        example="years = 50                # design life, years")
    trials: int = lifetime_key(
        f"a number of simulated lifetimes, 1 <= trials <= {MAX_TRIALS} (default 5000)", "int",
        lambda x: 1 <= x <= MAX_TRIALS, default=5000,
        example="trials = 5000             # lifetimes simulated (the ESD's standard error falls as "
                "1/sqrt(trials))")
    seed: int | None = lifetime_key(
        "a whole number >= 0, the root seed of the random numbers (default: a fresh one, reported)",
        "int", _at_least(0), default=None,
        example="seed = 2026               # root seed: the same seed, the same numbers (omit: a fresh seed, "
                "reported)")
    distribution: str = lifetime_key(
        '"weibull" or "gumbel", the distribution of the storm peaks H0\' (default "weibull")', "text",
        lambda x: x in ("weibull", "gumbel"), default="weibull",
        example="distribution = \"weibull\"  # storm peaks H0': \"weibull\" or \"gumbel\"")
    shape: float = lifetime_key(
        "a Weibull shape k > 0 (default 2; fitting annual_maxima needs k > 1)", "number", _positive,
        default=2.0,
        example="shape = 2.0               # Weibull shape k (> 0)")
    H0_10: float | None = lifetime_key(
        f"the 10-year return value of H0', 0 < H0_10 <= {MAX_HEIGHT:g} m (the largest "
        "significant heights measured are about 20 m)", "number", _height, _why_height, default=None,
        example="H0_10 = 5.0               # 10-year return value of H0', m")
    H0_50: float | None = lifetime_key(
        f"the 50-year return value of H0', H0_10 < H0_50 <= {MAX_HEIGHT:g} m", "number", _height,
        _why_height, default=None,
        example="H0_50 = 6.3               # 50-year return value of H0', m (the design wave above)")
    annual_maxima: tuple[float, ...] | None = lifetime_key(
        f"a list of at least three annual maxima of H0', each 0 < H0' <= "
        f"{MAX_HEIGHT:g} m and not all equal (instead of H0_10 and H0_50)", "numbers", _height,
        _why_height, default=None,
        example="# annual_maxima = [4.1, 3.6, 5.2, 4.4, 3.9]  # instead of H0_10 and H0_50: observed annual\n"
                "                          # maxima of H0', m (at least three; Weibull needs shape > 1)")
    storms_per_year: float | None = lifetime_key(
        f"a mean number of storms a year, 0.1 < storms_per_year <= "
        f"{MAX_STORMS_PER_YEAR:g} (a Poisson number of storms, peaks over a "
        "threshold; not with annual_maxima; default: one storm a year, its peak the annual maximum)",
        "number", lambda x: 0.1 < x <= MAX_STORMS_PER_YEAR, default=None,
        example="# storms_per_year = 4     # a Poisson number of storms a year (peaks over a threshold;\n"
                "                          # not with annual_maxima); default: one storm a year, the annual "
                "maximum")
    record: RecordSpec | None = lifetime_key(
        "the table [lifetime.record] of a measured wave record (path and the options of "
        "regimemap climate), instead of H0_10 and H0_50 or annual_maxima", "table", default=None,
        example='# record = { path = "buoy.txt", threshold = "99.5%" }  # instead of the climate above: a\n'
                "                          # measured offshore record and the options of `regimemap climate`")
    climate_replicates: int = lifetime_key(
        "a number of replicate climates of [lifetime.record]'s fit, 2 to "
        "10000, each run for the ESD's climate band, on which the requirements are "
        "judged (default 50), or 0: the fitted climate alone, its uncertainty not counted", "int",
        lambda x: x == 0 or 2 <= x <= 10_000, default=0,
        example="# climate_replicates = 200  # with record: the ESD under 200 bootstrap climates, and its "
                "band")
    storm_hours: float = lifetime_key(
        f"a duration 0 < storm_hours <= {MAX_STORM_HOURS:g} in hours of each storm's "
        "peak sea state (default 2)", "number", lambda x: 0.0 < x <= MAX_STORM_HOURS, default=2.0,
        example="storm_hours = 2.0         # duration of each storm's peak sea state, hours")
    period: float | None = lifetime_key(
        f"a significant period {PERIOD_RANGE[0]:g} <= T1/3 <= {PERIOD_RANGE[1]:g} s of "
        "sea waves for every storm (default: Goda's 3.3 H0'^0.63); not with steepness", "number",
        lambda x: PERIOD_RANGE[0] <= x <= PERIOD_RANGE[1], _why_period, default=None,
        example="# period = 11.4           # a fixed T1/3 for every storm, s (default: Goda's 3.3 H0'^0.63)")
    steepness: float | None = lifetime_key(
        "a deep-water steepness 0 < H0'/L0 <= 0.142 for every storm; not with period", "number",
        lambda x: 0.0 < x <= 0.142, default=None,
        example="# steepness = 0.035       # or a fixed deep-water steepness H0'/L0 (not with period)")
    tide_range: float = lifetime_key(
        f"a tidal range 0 <= tide_range <= {MAX_TIDE_RANGE:g} m (the largest, Bay of "
        "Fundy, is about 16 m; default 0)", "number", lambda x: 0.0 <= x <= MAX_TIDE_RANGE, default=0.0,
        example="tide_range = 0.0          # tidal range, m: each storm's water level is (range/2) sin(2 pi "
                "phase)")
    thresholds: tuple[float, ...] | None = lifetime_key(
        "a list of lifetime slides, each > 0 in metres, whose exceedance probability "
        "is reported (default [0.03, 0.1, 0.3, 1, 3])", "numbers", _positive, default=None,
        example="thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]  # lifetime slides whose exceedance is reported, m")
    truncate: float | None = lifetime_key(
        "a cut-off > 0 of the normal error factors, in standard deviations (default: none)", "number",
        _positive, default=None,
        example="# truncate = 3.0          # cut the normal error factors at +-3 standard deviations "
                "(default: none)")
    impulsive: bool = lifetime_key(
        "true or false: Takahashi's impulsive coefficient in each wave's force (default false)",
        "bool", default=False,
        example="impulsive = false         # Takahashi's impulsive coefficient in each wave's force (default "
                "false)")
    target: float = lifetime_key(
        "the tolerable expected sliding distance, > 0 in metres: the requirement "
        "ESD <= target (default 0.1, Goda & Takagi 2000)", "number", _positive, default=0.1,
        example="target = 0.1              # the requirement ESD <= target, m (Goda & Takagi 2000; default "
                "0.1)")
    allowed: Mapping[float, float] = lifetime_key(
        'a table of lifetime slides (m) and the largest allowed probability of '
        'exceeding each, 0 <= p <= 1, e.g. {"0.1" = 0.2, "0.3" = 0.05} (Kim & Suh 2013; '
        "default: none)", "limits", factory=dict,
        example='# allowed = {"0.1" = 0.2, "0.3" = 0.05}  # the largest allowed P(lifetime sliding > x m)\n'
                "                          # (Kim & Suh 2013; default: none)")
    failure_sliding: float | None = lifetime_key(
        "the sliding in metres at which the caisson is off its mound (the "
        "harbour-side crest width of the mound), > 0: P(S > failure_sliding) is "
        "the probability of failure over the life (default: none)", "number", _positive, default=None,
        example="# failure_sliding = 5.0   # m the caisson may slide before it is off its mound (the "
                "harbour-side\n"
                "                          # crest width of the mound): P(S > it) is the probability of "
                "failure")
    errors: Mapping[str, tuple[float, float]] = lifetime_key(
        "the table [lifetime.errors] of the uncertainty factors (deepwater, "
        "transformation, force, friction)", "table", factory=dict)
    written: Mapping[str, str] = field(default_factory=dict)

    def climate_as_written(self) -> str:
        """The climate's keys as the file wrote them (``H0_10 = 5.0 m, H0_50 = 6.3 m``)."""
        if self.record is not None:
            return f"[lifetime.record] path = {self.record.path}"
        keys = ("annual_maxima",) if self.annual_maxima is not None else ("H0_10", "H0_50")
        return ", ".join(f"{key} = {self.written.get(key, '?')} m" for key in keys)


def default_of(name: str) -> Any:
    """The value of ``[lifetime] name`` when the file leaves it out."""
    f = _FIELDS[name]
    if f.default is MISSING:
        return f.default_factory()  # type: ignore[operator]
    return f.default


_FIELDS = {f.name: f for f in fields(LifetimeSpec) if "key" in f.metadata}


def example_lifetime() -> str:
    """The ``[lifetime]`` table of the commented example, from the keys' lines."""
    return "[lifetime]\n" + "".join(f"{f.metadata['key'].example}\n" for f in _FIELDS.values()
                                    if f.metadata["key"].example)
#: The keys of ``[lifetime]``, in the order the messages list them (the fields of :class:`LifetimeSpec`).
LIFETIME_KEYS: dict[str, LifetimeKey] = {name: f.metadata["key"] for name, f in _FIELDS.items()}

_PAIR = "a pair [ratio, cov] with ratio > 0 and cov >= 0, the factor ratio (1 + cov z) "
_DEFAULT = "; absent: its default in regimemap.lifetime.DEFAULT_ERRORS"
#: The keys of ``[lifetime.errors]`` (the factors of :class:`regimemap.lifetime.Errors`).
ERROR_FACTORS: dict[str, LifetimeKey] = {
    "deepwater": LifetimeKey(_PAIR + "on the storm's H0' (once per lifetime)" + _DEFAULT, "pair"),
    "transformation": LifetimeKey(_PAIR + "on H1/3 at the wall (once per storm)" + _DEFAULT, "pair"),
    "force": LifetimeKey(_PAIR + "on the wave force P and the uplift U (once per storm)" + _DEFAULT, "pair"),
    "friction": LifetimeKey(_PAIR + "on the friction coefficient (once per storm)" + _DEFAULT, "pair"),
}

#: The key tables of ``[lifetime]`` and ``[lifetime.errors]``.
LIFETIME_TABLES = {"lifetime": LIFETIME_KEYS, "lifetime.errors": ERROR_FACTORS}


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
