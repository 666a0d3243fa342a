"""The caisson workflow: a design file in, Goda's loads, the loaded map and the design check out.

:func:`run_caisson` is the call ``regimemap caisson`` makes: it reads a design
(:mod:`regimemap.caisson.file`), runs Goda's procedure and places the caisson on
the loaded map (:func:`regimemap.caisson.report.caisson_report`), checks the
safety factors against the required ones and, when the design has a ``[lifetime]``
table, simulates its sliding over the design life and judges those requirements too
(:func:`regimemap.lifetime.run.run_lifetime`: with a wave record, on the results
including the climate's uncertainty).  The requirements never depend on the outputs asked
for: the design sheet adds only its map.  It returns a :class:`CaissonRecord` holding the
design, the numbers a designer checks, the implausible values as
:class:`~regimemap.records.notices.Notice` data, the checks, the lifetime and, for the
design sheet, the map of panel (d).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from ..maps.loadedmap import mode_label
from ..maps.points import DesignPoint
from ..records.checks import Check, all_pass
from ..records.fields import Field, Record
from ..records.notices import Notice
from .file import Design, read_design
from .file_plausibility import implausible_notices
from .record import NUMBERS, CaissonNumbers, caisson_numbers, text_context
from .report import CaissonReport, MapView, caisson_checks, caisson_report, sheet_map

if TYPE_CHECKING:  # pragma: no cover
    from ..lifetime.replicates import ClimateBand
    from ..lifetime.results import LifetimeResult
    from ..lifetime.run import LifetimeRecord
    from ..maps.mapdata import MapData
    from ..mechanics.block import Parameters
    from ..waves import CaissonAnalysis

__all__ = ["CaissonError", "CaissonNumbers", "CaissonRecord", "ImplausibleDesignError", "run_caisson"]


class CaissonError(ValueError):
    """The design file is valid but its caisson cannot be analysed (or its lifetime simulated).

    Attributes
    ----------
    notices : tuple of Notice
        The implausible values found before the failure: a unit slip may be why.
    """

    def __init__(self, message: str, notices: tuple[Notice, ...] = ()) -> None:
        super().__init__(message)
        self.notices = notices


class ImplausibleDesignError(CaissonError):
    """``strict=True`` and the design has implausible values (likely unit slips): its notices."""


@dataclass(frozen=True)
class CaissonRecord(Record):
    """A caisson under its design wave: the inputs, the numbers, the map, the checks, the warnings.

    Attributes
    ----------
    design : Design
        The design file, read and checked.
    report : CaissonReport
        Goda's procedure, the loaded block, its mode and margins on the loaded map,
        and the wave path (:func:`regimemap.caisson.report.caisson_report`).
    numbers : CaissonNumbers
        Design heights, pressures, loads, safety factors and the equivalent block
        (``gamma``, ``kprime``, ``k``, ``mu`` ...) in engineering units.
    required : tuple of float
        The safety factors the design must reach, sliding and overturning
        (``[caisson] required_*``).
    checks : tuple of Check
        The design check: the safety factors against ``required``, then, when the
        design has ``[lifetime]``, the lifetime's requirements (with a wave record, judged
        including the climate's uncertainty) -- whatever outputs are asked for.
    notices : tuple of Notice
        The design's implausible values (code ``"implausible-value"``), and the lifetime's
        warnings.
    view : MapView or None
        Panel (d)'s view of the loaded map (computed with ``sheet=True``).
    map_data : MapData or None
        The design wave's loaded map in :attr:`view` (computed with ``sheet=True``).
    lifetime_run : LifetimeRecord or None
        The caisson's sliding over its design life (:func:`~regimemap.lifetime.run.run_lifetime`),
        judged against ``[lifetime]``'s requirements; None without ``[lifetime]``.
    """

    design: Design
    report: CaissonReport
    numbers: CaissonNumbers
    required: tuple[float, float]
    checks: tuple[Check, ...]
    notices: tuple[Notice, ...] = ()
    view: MapView | None = None
    map_data: MapData | None = None
    lifetime_run: LifetimeRecord | None = None

    CAPTION: ClassVar[str] = "Caisson under its design wave (Goda 2000) on the loaded regime map"
    #: The report's numbers with a row, as the text report words them; the mode; the verdict.
    FIELDS: ClassVar[tuple[Field, ...]] = (
        *(Field(f"numbers.{name}", s.label, s.text_unit, s.words) for name, s in NUMBERS.items() if s.label),
        Field("mode", "mode", "", "the design point's mode on the loaded map"),
        Field("verdict", "verdict", "", "the design check: PASS when every requirement is met"),
    )

    def field_rows(self) -> list[tuple[str, Any, str, str]]:
        """``(label, value, unit, description)`` of :data:`FIELDS`, the descriptions filled in as the
        text report fills them (the depth as written, where P acts)."""
        context = text_context(self.report, vars(self.numbers), self.design.written)
        return [(label, value, unit, text.format_map(context))
                for label, value, unit, text in super().field_rows()]

    @property
    def analysis(self) -> CaissonAnalysis:
        """Goda's procedure for the design wave (SI units, 0-d arrays)."""
        return self.report.analysis

    @property
    def mode(self) -> str:
        """The design point's mode on the loaded map (``RE``, ``SL`` ...)."""
        return mode_label(self.report.mode)

    @property
    def passed(self) -> bool:
        """Every requirement of :attr:`checks` is met."""
        return all_pass(self.checks)

    @property
    def verdict(self) -> str:
        """``"PASS"`` or ``"FAIL"``."""
        return "PASS" if self.passed else "FAIL"

    @property
    def parameters(self) -> Parameters:
        """The loaded block of the design wave, as every map takes it."""
        return self.report.map.parameters()

    @property
    def design_point(self) -> DesignPoint:
        """The design wave's point (k, mu) on the loaded map."""
        return DesignPoint(self.report.k, self.report.mu)

    @property
    def lifetime(self) -> LifetimeResult | None:
        """The sliding over the design life, its requirements judged (None without ``[lifetime]``)."""
        return None if self.lifetime_run is None else self.lifetime_run.result

    @property
    def band(self) -> ClimateBand | None:
        """The lifetimes under the wave record's replicate climates (None without a record)."""
        return None if self.lifetime_run is None else self.lifetime_run.band

    @property
    def record_path(self) -> str | None:
        """The wave record of ``[lifetime.record]`` (None without one)."""
        if self.design.lifetime is None:
            return None
        record = self.design.lifetime_spec().record
        return None if record is None else record.path

    @property
    def lifetime_impulsive(self) -> bool | None:
        """Whether :attr:`lifetime` included Takahashi's impulsive coefficient (None: no lifetime)."""
        if self.lifetime is None or self.design.lifetime is None:
            return None
        return self.design.lifetime.impulsive


def run_caisson(design: Design | str | Path, *, strict: bool = False, sheet: bool = False,
                jobs: int | None = None) -> CaissonRecord:
    """Goda's design procedure for a caisson, placed on the loaded regime map, and its design check.

    Parameters
    ----------
    design : Design, str or Path
        A design, or the path of a design file (:func:`regimemap.caisson.file.read_design`).
    strict : bool
        Refuse implausible values (likely unit slips), and the warnings of a ``[lifetime.record]``
        (its quality control and fit), instead of returning them as notices.
    sheet : bool
        Also compute what the design sheet draws besides the report: the loaded map of
        panel (d) (:func:`regimemap.caisson.report.sheet_map`).  The requirements do not
        depend on it: with a ``[lifetime]`` table the sliding over the design life
        (:func:`regimemap.lifetime.run.run_lifetime`, its requirements judged, with
        a wave record including the climate's uncertainty) is always run and its checks
        join the safety factors'.
    jobs : int, optional
        Processes of the lifetime simulation (default: every available core).

    Returns
    -------
    CaissonRecord

    Raises
    ------
    regimemap.caisson.file.DesignFileError
        When the file cannot be read or is not a valid design.
    ImplausibleDesignError
        With ``strict``, when the design has implausible values (its ``notices``).
    CaissonError
        When the caisson cannot be analysed or its lifetime simulated; its
        ``notices`` are the implausible values of the inputs.

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> r = run_caisson(parse_design(example_design_text()))
    >>> r.mode, r.verdict, round(r.numbers.SF_sliding, 3)
    ('RE', 'FAIL', 1.16)
    """
    d = design if isinstance(design, Design) else read_design(design)
    try:
        report = caisson_report(d.analysis_inputs())
    except ValueError as exc:  # a unit slip may be why: the implausible inputs go with it
        found = implausible_notices(d)
        if strict and found:
            raise ImplausibleDesignError(_refusal(d, found), found) from None
        raise CaissonError(str(exc), found) from None
    notices = implausible_notices(d, report.analysis)
    if strict and notices:
        raise ImplausibleDesignError(_refusal(d, notices), notices)
    required = (d.caisson.required_sliding, d.caisson.required_overturning)
    checks = tuple(caisson_checks(report, required))
    view = data = life = None
    if sheet:
        view, data = sheet_map(report)
    if d.lifetime is not None:
        life = _lifetime(d, jobs, notices, strict)
        checks += tuple(life.result.checks)
        notices += tuple(n for n in life.notices if n.code != "implausible-value")
    return CaissonRecord(design=d, report=report, numbers=CaissonNumbers.of(caisson_numbers(report)),
                         required=required, checks=checks, notices=notices, view=view, map_data=data,
                         lifetime_run=life)


def _refusal(d: Design, notices: tuple[Notice, ...], what: str = "implausible values") -> str:
    more = f" (and {len(notices) - 1} more)" if len(notices) > 1 else ""
    return f"{d.source}: {notices[0].message}{more}; strict refuses {what}"


def _lifetime(d: Design, jobs: int | None, notices: tuple[Notice, ...], strict: bool) -> LifetimeRecord:
    """The sliding over the design life of ``[lifetime]`` (with a record, under its replicate
    climates too), judged against its requirements; with ``strict`` the warnings of its
    ``[lifetime.record]`` (codes ``record-quality`` and ``fit``) are refused before the run."""
    from ..lifetime import available_cores
    from ..lifetime.run import run_lifetime
    from ..lifetime.run_design import RECORD_WARNINGS, read_lifetime_design

    try:
        inputs = read_lifetime_design(d)
    except ValueError as exc:
        raise CaissonError(str(exc), notices) from None
    warned = tuple(n for n in inputs.notices if n.code in RECORD_WARNINGS)
    if strict and warned:
        raise ImplausibleDesignError(_refusal(d, warned, "the record's warnings"), warned)
    try:
        return run_lifetime(inputs, jobs=available_cores() if jobs is None else jobs)
    except ValueError as exc:
        raise CaissonError(str(exc), notices) from None
