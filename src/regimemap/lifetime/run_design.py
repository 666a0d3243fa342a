"""A design file read for the lifetime workflows: its ``[lifetime]`` model, its caisson and its warnings.

:func:`read_lifetime_design` reads (or takes) a design file once for
:func:`regimemap.lifetime.run.run_lifetime` and :func:`~regimemap.lifetime.run.run_chart`;
its implausible values (likely unit slips, :func:`regimemap.caisson.file_plausibility.implausible_values`)
are notices, which a caller may refuse before the run.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from ..records.notices import Notice

if TYPE_CHECKING:
    from ..caisson.file import Design, LifetimeSpec
    from . import Caisson, LifetimeModel

__all__ = ["RECORD_WARNINGS", "LifetimeDesign", "read_lifetime_design"]

#: The codes of the warnings of a ``[lifetime.record]``: its quality control and its fit
#: (``--strict`` refuses them, as ``regimemap climate --strict`` does).
RECORD_WARNINGS = ("record-quality", "fit")


@dataclass(frozen=True)
class LifetimeDesign:
    """A design file read for the lifetime workflows.

    Attributes
    ----------
    source : str or None
        The design file (None for a :class:`~regimemap.caisson.file.Design` given as an object).
    design : Design
    spec : LifetimeSpec
        Its ``[lifetime]`` table.
    model : LifetimeModel
        The climate and options over the design life.
    caisson : Caisson
        The section at its site.
    notices : tuple of Notice
        The implausible values of the file (code ``implausible-value``; likely unit slips), and the
        warnings of its ``[lifetime.record]`` (codes ``record-quality`` and ``fit``).
    """

    source: str | None
    design: Design
    spec: LifetimeSpec
    model: LifetimeModel
    caisson: Caisson
    notices: tuple[Notice, ...] = ()


def read_lifetime_design(design: Design | str | Path, years: int | None = None) -> LifetimeDesign:
    """Read a design file (or take a parsed one) for :func:`run_lifetime` and :func:`run_chart`.

    Parameters
    ----------
    design : Design, str or Path
        The design file or its parsed :class:`~regimemap.caisson.file.Design`.
    years : int, optional
        Design life instead of the file's ``years``.

    Raises
    ------
    regimemap.caisson.file.DesignFileError
        The file cannot be read, or has no ``[lifetime]`` table.
    ValueError
        ``years`` out of range.
    """
    from ..caisson.file import Design, read_design
    from ..caisson.file_plausibility import implausible_values

    source = None if isinstance(design, Design) else str(design)
    d = design if isinstance(design, Design) else read_design(design)
    spec = d.lifetime_spec()
    model = d.lifetime_model(years=years)
    caisson = d.lifetime_caisson()
    try:
        analysis = d.analyse()
    except ValueError:
        analysis = None
    named = d.source if source is None else source
    notices = tuple(Notice("implausible-value", f"{named}: {item}", quantity=item.key, value=item.value)
                    for item in implausible_values(d, analysis))
    if spec.record is not None:  # the record's quality control, as `regimemap climate` reports it
        from .file_record import record_analysis

        fitted = record_analysis(spec.record)
        notices += tuple(Notice("record-quality", f"{spec.record.path}: {w}") for w in fitted.warnings()
                         if w not in fitted.notes)
        notices += tuple(Notice("fit", f"{spec.record.path}: {n}") for n in fitted.notes)
    return LifetimeDesign(source, d, spec, model, caisson, notices)
