"""The records of a whole breakwater's study: one row per section x scenario x width
(:class:`StudyRow`) and the study's record (:class:`StudyRecord`).

Plain data made by :func:`regimemap.workflows.run_study`, written by :mod:`regimemap.io`
(CSV, JSON, NetCDF) and drawn by :mod:`regimemap.study.figures`; defined here, beside the
lifetimes they summarise, so that io (the layer above) may name them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar, Literal

from ..records.checks import Check
from ..records.fields import Field, Record
from ..records.notices import Notice

__all__ = ["COLUMNS", "LIMITS", "Column", "StudyCheck", "StudyRecord", "StudyRow"]


@dataclass(frozen=True)
class StudyRow:
    """One section under one scenario at one width (see :class:`StudyRecord`)."""

    section: str
    chainage: float
    scenario: str
    width: float
    expected_sliding: float
    std_error: float
    exceedance: tuple[tuple[float, float], ...]
    by_year: tuple[float, ...]
    passes: tuple[tuple[float, int | None], ...]
    band: tuple[float, float] | None
    required_width: float | None = None
    required_width_interval: tuple[float, float] | None = None
    required_width_upper: float | None = None


#: The tolerable sliding distances [m] of a row's exceedance probabilities and years in the CSV table.
LIMITS = (0.1, 0.3)


@dataclass(frozen=True)
class Column:
    """One field of a study row, declared once: the CSV table, the JSON rows and the NetCDF
    variables are written from :data:`COLUMNS`, in its order.

    Attributes
    ----------
    name : str
        Its key in the JSON rows and its variable in the NetCDF file.
    unit : str
        Its unit (``"1"``: a probability; ``""``: none).
    long_name : str or tuple of str
        What it is, in words (the NetCDF ``long_name``); a pair's two ends, each.
    kind : str
        ``"coord"`` (a coordinate along ``row``), ``"value"`` (a number, None or NaN where it
        does not apply), ``"limits"`` (``(limit, value)`` pairs: a CSV column per limit of
        :data:`LIMITS`, a JSON object by limit, a NetCDF ``limit`` dimension), ``"pair"``
        (``(low, high)`` or None: two CSV columns and NetCDF variables, a JSON list) or
        ``"years"`` (a value per service year: JSON and NetCDF only).
    csv : tuple of str
        Its CSV columns (and a pair's NetCDF variables); default: ``name``, or ``name`` and
        the limit for ``"limits"``.
    attr : str
        The :class:`StudyRow` attribute, where it is not ``name``.
    """

    name: str
    unit: str
    long_name: str | tuple[str, str]
    kind: Literal["coord", "value", "limits", "pair", "years"] = "value"
    csv: tuple[str, ...] = ()
    attr: str = ""

    def of(self, row: StudyRow) -> Any:
        """Its value in ``row``."""
        return getattr(row, self.attr or self.name)

    @property
    def csv_columns(self) -> tuple[str, ...]:
        """Its columns in the CSV table."""
        if self.kind == "limits":
            prefix = self.csv[0] if self.csv else self.name
            return tuple(f"{prefix}_{x:g}" for x in LIMITS)
        if self.kind == "years":
            return ()
        return self.csv or (self.name,)


_BAND = "end of the ESD's climate band (NaN: no record climate)"
_INTERVAL = "end of the required width's Monte Carlo interval"

#: The fields of a study row, in the order of every file (units: m, years; probabilities).
COLUMNS: tuple[Column, ...] = (
    Column("section", "", "section", "coord"),
    Column("chainage", "m", "chainage of the section along the breakwater", "coord"),
    Column("scenario", "", "climate scenario", "coord"),
    Column("width", "m", "caisson width", "coord"),
    Column("expected_sliding", "m", "expected sliding distance over the design life (ESD)"),
    Column("std_error", "m", "Monte Carlo standard error of the ESD"),
    Column("exceedance", "1", "probability that the lifetime's sliding exceeds the limit", "limits",
           ("p_exceed",)),
    Column("band", "m", (f"lower {_BAND}", f"upper {_BAND}"), "pair", ("band_low", "band_high")),
    Column("year_over", "year", "first service year whose expected cumulative sliding exceeds the limit "
           "(NaN: never within the design life)", "limits", attr="passes"),
    Column("by_year", "m", "expected cumulative sliding at the end of the service year", "years"),
    Column("required_width", "m", "width for the target ESD (NaN: the section has no target)"),
    Column("required_width_interval", "m", ("lower " + _INTERVAL, "upper " + _INTERVAL), "pair",
           ("required_width_low", "required_width_high")),
    Column("required_width_upper", "m", "width for the target ESD at the climate band's upper level"),
)


@dataclass(frozen=True)
class StudyRecord(Record):
    """A study's results: one row per section x scenario x width, in the study's order.

    Attributes
    ----------
    source : str or None
        The study file.
    study_hash : str
        sha256 of the study's canonical content (what the store remembers).
    seed, trials, years : int
        Root seed, lifetimes per task, design life.
    sections : tuple of (str, float)
        (name, chainage [m]) in file order.
    scenarios : tuple of str
        In file order.
    target : float or None
        The target ESD [m] if a section asks for one.
    rows : tuple of StudyRow
        Section-major, then scenario, then width.
    notices : tuple of Notice
    """

    source: str | None
    study_hash: str
    seed: int
    trials: int
    years: int
    sections: tuple[tuple[str, float], ...]
    scenarios: tuple[str, ...]
    target: float | None
    rows: tuple[StudyRow, ...]
    notices: tuple[Notice, ...]

    FIELDS: ClassVar[tuple[Field, ...]] = (
        Field("source", "study", "", "the study file"),
        Field("seed", "seed", "", "the root seed of every task"),
        Field("trials", "trials", "", "lifetimes per task"),
        Field("years", "L", "years", "design life"),
        Field("target", "target ESD", "m", "the tolerable expected sliding distance"),
    )
    CAPTION: ClassVar[str] = "A breakwater's sections under climate scenarios"

    def rows_for(self, section: str | None = None, scenario: str | None = None) -> tuple[StudyRow, ...]:
        """The rows of one section and/or one scenario (None: all)."""
        return tuple(r for r in self.rows if (section is None or r.section == section)
                     and (scenario is None or r.scenario == scenario))


@dataclass(frozen=True)
class StudyCheck:
    """The requirement of one section under one scenario (``regimemap study --check``).

    Attributes
    ----------
    section, scenario : str
    check : Check
        The value against the limit: the ESD [m] against the section's target, or the width
        found for the target [m] against the section's width.  A value that is not finite
        (no width found) never passes.
    basis : str
        What was judged, in words: which width and which ESD (of the design's climate, or at
        the climate band's upper level), or which width.
    """

    section: str
    scenario: str
    check: Check
    basis: str

    @property
    def passed(self) -> bool:
        """Whether the requirement is met."""
        return self.check.passed
