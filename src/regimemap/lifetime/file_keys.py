"""The keys of the ``[lifetime]`` and ``[lifetime.errors]`` tables, declared once: what each accepts and why.

Each key of ``[lifetime]`` is one field of :class:`LifetimeSpec`, declared with
:func:`~regimemap.io.toml_keys.key`: its type, its default, what it accepts in words (the
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
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

# the largest significant height H0' a climate may give (30 m: the largest measured are about 20 m,
# 19 m at a North Atlantic buoy in February 2013, the WMO record; above, a unit slip) and the
# significant periods of sea waves, 1-30 s: the design file's limits of the physics of sea waves
from ..caisson.file_keys import MAX_HEIGHT, PERIOD_RANGE
from ..io.toml_keys import Key, key, keys_of
from .climate import WEIBULL_SHAPE_RANGE

_K_LO, _K_HI = WEIBULL_SHAPE_RANGE

if TYPE_CHECKING:
    from .file_record import RecordSpec

__all__ = ["ERROR_FACTORS", "LIFETIME_KEYS", "LIFETIME_TABLES", "MAX_HEIGHT", "MAX_STORM_HOURS",
           "MAX_STORMS_PER_YEAR", "MAX_TIDE_RANGE", "MAX_TRIALS", "MAX_YEARS", "PERIOD_RANGE",
           "ErrorsSpec", "LifetimeSpec", "check_lifetime_option"]

#: Most lifetimes a run may simulate (its arrays take ~24 bytes a lifetime).
MAX_TRIALS = 10_000_000
#: Longest design life [years].
MAX_YEARS = 1000
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


def _at_least(lo: float) -> Callable[[Any], bool]:
    return lambda x: x >= lo


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

    years: int = key(
        f"a design life in whole years, 1 <= years <= {MAX_YEARS} (default 50)",
        lambda x: 1 <= x <= MAX_YEARS, kind="int", default=50,
        example="years = 50                # design life, years")
    trials: int = key(
        f"a number of simulated lifetimes, 1 <= trials <= {MAX_TRIALS} (default 5000)",
        lambda x: 1 <= x <= MAX_TRIALS, kind="int", default=5000,
        example="trials = 5000             # lifetimes simulated (the ESD's standard error falls as "
                "1/sqrt(trials))")
    seed: int | None = key(
        "a whole number >= 0, the root seed of the random numbers (default: a fresh one, reported)",
        _at_least(0), kind="int", default=None,
        example="seed = 2026               # root seed: the same seed, the same numbers (omit: a fresh seed, "
                "reported)")
    distribution: str = key(
        '"weibull" or "gumbel", the distribution of the storm peaks H0\' (default "weibull")',
        lambda x: x in ("weibull", "gumbel"), kind="text", default="weibull",
        example="distribution = \"weibull\"  # storm peaks H0': \"weibull\" or \"gumbel\"")
    shape: float = key(
        f"a Weibull shape {_K_LO:g} <= k <= {_K_HI:g} (default 2; Goda's storm peaks take 0.75 to 2; "
        "fitting annual_maxima needs k > 1)", lambda x: _K_LO <= x <= _K_HI,
        default=2.0,
        example=f"shape = 2.0               # Weibull shape k ({_K_LO:g} to {_K_HI:g})")
    H0_10: float | None = key(
        f"the 10-year return value of H0', 0 < H0_10 <= {MAX_HEIGHT:g} m (the largest "
        "significant heights measured are about 20 m)", _height, why=_why_height, default=None,
        example="H0_10 = 5.0               # 10-year return value of H0', m")
    H0_50: float | None = key(
        f"the 50-year return value of H0', H0_10 < H0_50 <= {MAX_HEIGHT:g} m", _height,
        why=_why_height, default=None,
        example="H0_50 = 6.3               # 50-year return value of H0', m (the design wave above)")
    annual_maxima: tuple[float, ...] | None = key(
        f"a list of at least three annual maxima of H0', each 0 < H0' <= "
        f"{MAX_HEIGHT:g} m and not all equal (instead of H0_10 and H0_50)", _height,
        why=_why_height, kind="numbers", default=None,
        example="# annual_maxima = [4.1, 3.6, 5.2, 4.4, 3.9]  # instead of H0_10 and H0_50: observed annual\n"
                "                          # maxima of H0', m (at least three; Weibull needs shape > 1)")
    storms_per_year: float | None = key(
        f"a mean number of storms a year, 0.1 < storms_per_year <= "
        f"{MAX_STORMS_PER_YEAR:g} (a Poisson number of storms, peaks over a "
        "threshold; not with annual_maxima; default: one storm a year, its peak the annual maximum)",
        lambda x: 0.1 < x <= MAX_STORMS_PER_YEAR, default=None,
        example="# storms_per_year = 4     # a Poisson number of storms a year (peaks over a threshold;\n"
                "                          # not with annual_maxima); default: one storm a year, the annual "
                "maximum")
    record: RecordSpec | None = key(
        "the table [lifetime.record] of a measured wave record (path and the options of "
        "regimemap climate), instead of H0_10 and H0_50 or annual_maxima", kind="table", default=None,
        example='# record = { path = "buoy.txt", threshold = "99.5%" }  # instead of the climate above: a\n'
                "                          # measured offshore record and the options of `regimemap climate`")
    climate_replicates: int = key(
        "a number of replicate climates of [lifetime.record]'s fit, 2 to "
        "10000, each run for the ESD's climate band, on which the requirements are "
        "judged (default 50), or 0: the fitted climate alone, its uncertainty not counted",
        lambda x: x == 0 or 2 <= x <= 10_000, kind="int", default=0,
        example="# climate_replicates = 200  # with record: the ESD under 200 bootstrap climates, and its "
                "band")
    storm_hours: float = key(
        f"a duration 0 < storm_hours <= {MAX_STORM_HOURS:g} in hours of each storm's "
        "peak sea state (default 2)", lambda x: 0.0 < x <= MAX_STORM_HOURS, default=2.0,
        example="storm_hours = 2.0         # duration of each storm's peak sea state, hours")
    period: float | None = key(
        f"a significant period {PERIOD_RANGE[0]:g} <= T1/3 <= {PERIOD_RANGE[1]:g} s of "
        "sea waves for every storm (default: Goda's 3.3 H0'^0.63); not with steepness",
        lambda x: PERIOD_RANGE[0] <= x <= PERIOD_RANGE[1], why=_why_period, default=None,
        example="# period = 11.4           # a fixed T1/3 for every storm, s (default: Goda's 3.3 H0'^0.63)")
    steepness: float | None = key(
        "a deep-water steepness 0 < H0'/L0 <= 0.142 for every storm; not with period",
        lambda x: 0.0 < x <= 0.142, default=None,
        example="# steepness = 0.035       # or a fixed deep-water steepness H0'/L0 (not with period)")
    tide_range: float = key(
        f"a tidal range 0 <= tide_range <= {MAX_TIDE_RANGE:g} m (the largest, Bay of "
        "Fundy, is about 16 m; default 0)", lambda x: 0.0 <= x <= MAX_TIDE_RANGE, default=0.0,
        example="tide_range = 0.0          # tidal range, m: each storm's water level is (range/2) sin(2 pi "
                "phase)")
    thresholds: tuple[float, ...] | None = key(
        "a list of lifetime slides, each > 0 in metres, whose exceedance probability "
        "is reported (default [0.03, 0.1, 0.3, 1, 3])", _positive, kind="numbers", default=None,
        example="thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]  # lifetime slides whose exceedance is reported, m")
    truncate: float | None = key(
        "a cut-off > 0 of the normal error factors, in standard deviations (default: none)",
        _positive, default=None,
        example="# truncate = 3.0          # cut the normal error factors at +-3 standard deviations "
                "(default: none)")
    impulsive: bool = key(
        "true or false: Takahashi's impulsive coefficient in each wave's force (default false)",
        kind="bool", default=False,
        example="impulsive = false         # Takahashi's impulsive coefficient in each wave's force (default "
                "false)")
    target: float = key(
        "the tolerable expected sliding distance, > 0 in metres: the requirement "
        "ESD <= target (default 0.1, Goda & Takagi 2000)", _positive, default=0.1,
        example="target = 0.1              # the requirement ESD <= target, m (Goda & Takagi 2000; default "
                "0.1)")
    allowed: Mapping[float, float] = key(
        'a table of lifetime slides (m) and the largest allowed probability of '
        'exceeding each, 0 <= p <= 1, e.g. {"0.1" = 0.2, "0.3" = 0.05} (Kim & Suh 2013; '
        "default: none)", kind="limits", factory=dict,
        example='# allowed = {"0.1" = 0.2, "0.3" = 0.05}  # the largest allowed P(lifetime sliding > x m)\n'
                "                          # (Kim & Suh 2013; default: none)")
    failure_sliding: float | None = key(
        "the sliding in metres at which the caisson is off its mound (the "
        "harbour-side crest width of the mound), > 0: P(S > failure_sliding) is "
        "the probability of failure over the life (default: none)", _positive, default=None,
        example="# failure_sliding = 5.0   # m the caisson may slide before it is off its mound (the "
                "harbour-side\n"
                "                          # crest width of the mound): P(S > it) is the probability of "
                "failure")
    errors: Mapping[str, tuple[float, float]] = key(
        "the table [lifetime.errors] of the uncertainty factors (deepwater, "
        "transformation, force, friction)", kind="table", factory=dict)
    written: Mapping[str, str] = field(default_factory=dict)

    def climate_as_written(self) -> str:
        """The climate's keys as the file wrote them (``H0_10 = 5.0 m, H0_50 = 6.3 m``)."""
        if self.record is not None:
            return f"[lifetime.record] path = {self.record.path}"
        keys = ("annual_maxima",) if self.annual_maxima is not None else ("H0_10", "H0_50")
        return ", ".join(f"{key} = {self.written.get(key, '?')} m" for key in keys)


#: The keys of ``[lifetime]``, in the order the messages list them (the fields of :class:`LifetimeSpec`).
LIFETIME_KEYS: dict[str, Key] = keys_of(LifetimeSpec)

_PAIR = "a pair [ratio, cov] with ratio > 0 and cov >= 0, the factor ratio (1 + cov z) "
_DEFAULT = "; absent: its default in regimemap.lifetime.DEFAULT_ERRORS"


def _factor(on: str, comment: str | None = None) -> Any:
    """A factor of ``[lifetime.errors]``: what it multiplies (``on``, also the comment of its line in
    the example unless ``comment`` is given; the line's value is its default,
    :data:`regimemap.lifetime.DEFAULT_ERRORS`)."""
    return key(_PAIR + on + _DEFAULT, kind="pair", default=None, example=comment or on)


@dataclass(frozen=True, kw_only=True)
class ErrorsSpec:
    """``[lifetime.errors]``: the uncertainty factors of :class:`regimemap.lifetime.Errors` the file
    gives, each ``(ratio, cov)`` (None: its default)."""

    deepwater: tuple[float, float] | None = _factor("on the storm's H0' (once per lifetime)",
                                                    "on the storm's H0' (drawn once per lifetime)")
    transformation: tuple[float, float] | None = _factor("on H1/3 at the wall (once per storm)")
    force: tuple[float, float] | None = _factor("on the wave force P and the uplift U (once per storm)")
    friction: tuple[float, float] | None = _factor("on the friction coefficient (once per storm)")


#: The keys of ``[lifetime.errors]`` (the factors of :class:`regimemap.lifetime.Errors`).
ERROR_FACTORS: dict[str, Key] = keys_of(ErrorsSpec)

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
