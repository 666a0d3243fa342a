"""The records of a whole breakwater's study: one row per section x scenario x width
(:class:`StudyRow`) and the study's record (:class:`StudyRecord`).

Plain data made by :func:`regimemap.workflows.run_study`, written by :mod:`regimemap.io`
(CSV, JSON, NetCDF) and drawn by :mod:`regimemap.study.figures`; defined here, beside the
lifetimes they summarise, so that io (the layer above) may name them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..mechanics.checks import Check
from ..mechanics.notices import Notice
from ..mechanics.records import Field, Record

__all__ = ["StudyCheck", "StudyRecord", "StudyRow"]


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
