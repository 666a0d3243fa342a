"""The figures of ``regimemap study``: a breakwater's sections under its climate scenarios.

:func:`study_figure` draws a :class:`~regimemap.study.record.StudyRecord` as it is,
computing nothing: ``"chainage"``, the expected sliding distance (ESD) of each section along
the breakwater, a line per scenario; ``"years"``, one section's expected cumulative sliding
against the service year, a line per scenario, with the year it passes each tolerable limit;
``"width"``, the width for the target ESD along the breakwater, a line per scenario.  The
scenarios' look is :mod:`regimemap.study.figures_style`'s; the limits, numbers and title block
:mod:`regimemap.lifetime.figures.style`'s; the limits' labels are placed clear of the curves
(:class:`~regimemap.drawing.text.labelplacer.LabelPlacer`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..drawing.save import DEFAULT_DPI
from ..drawing.style import label_axes, style_context
from ..drawing.text.labelplacer import LabelPlacer, Placed, hline_label
from ..lifetime.figures.style import (
    FS,
    LIMIT,
    LIMIT_DASHES,
    TOLERABLE,
    decade_range,
    format_log_axis,
    limit_text,
)
from .figures_style import AXES_WIDTH, draw_key, key_columns, new_frame, scenario_style, study_facts

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from .run import StudyRecord, StudyRow

__all__ = ["FIGURE_KINDS", "study_figure"]

#: The kinds of :func:`study_figure`.
FIGURE_KINDS = ("chainage", "years", "width")
#: The fixed widths of the sections without a target, on the width figure.
FIXED_WIDTH = "0.45"
#: Markers of the first service year over each tolerable limit (0.1 m, 0.3 m).
_PASS_MARKERS = ("D", "s")


def study_figure(record: StudyRecord, kind: str = "chainage", section: str | None = None, *,
                 dpi: float = DEFAULT_DPI) -> Figure:
    """A figure of a study: ESD along the chainage, sliding by service year, or required width.

    Parameters
    ----------
    record : StudyRecord
        From :func:`regimemap.workflows.run_study`.
    kind : {"chainage", "years", "width"}
        ``"chainage"``: each section's ESD at its chainage (log axis), a line per scenario
        through each section's first width, the section's other widths as open markers, error
        bars of two standard errors, the climate band as a hatched box at each section that has
        one (a lone one too; artist gid ``climate-band``), the tolerable limits (0.1 m, 0.3 m)
        as horizontal lines.  ``"years"``: the
        expected cumulative sliding at the end of each service year of ``section`` (its first
        width), a line per scenario, the limits, and the first year over each limit marked on
        the curves (the years in the key).  ``"width"``: the width for the target ESD of each
        section that asks for one, a line per scenario, its Monte Carlo interval as error bars
        and the width at the climate band's upper level as open markers; the fixed widths of
        the other sections as grey ticks.
    section : str, optional
        The section of ``"years"`` (default: the first).
    dpi : float
        Resolution of PNG output.

    Returns
    -------
    Figure
        One axes labelled ``study`` (Agg canvas, no pyplot); ``"chainage"`` and ``"width"``
        add a twin axes above it naming the sections at their chainages.

    Raises
    ------
    ValueError
        An unknown ``kind`` or ``section``; ``"width"`` of a study in which no section has a
        target.
    """
    if kind not in FIGURE_KINDS:
        raise ValueError(f"kind = {kind!r}: accepted: {', '.join(FIGURE_KINDS)}")
    names = [name for name, _ in record.sections]
    if section is not None and section not in names:
        raise ValueError(f"section = {section!r}: not a section of the study; accepted: {', '.join(names)}")
    if kind == "width" and not any(r.required_width is not None for r in record.rows):
        raise ValueError("the width figure needs a section with a target (target = ESD in a [[section]]); "
                         "no section of this study has one")
    with style_context():
        if kind == "chainage":
            return _chainage(record, dpi)
        if kind == "years":
            return _years(record, section if section is not None else names[0], dpi)
        return _width(record, dpi)


# -- shared --------------------------------------------------------------------------------------


def _first_rows(record: StudyRecord, scenario: str) -> list[StudyRow]:
    """Each section's first row under ``scenario`` (its first width), in chainage order."""
    out = []
    for name, _ in record.sections:
        rows = record.rows_for(section=name, scenario=scenario)
        if rows:
            out.append(rows[0])
    return out


def _dodge(record: StudyRecord, j: int) -> float:
    """The x offset (m) of scenario ``j``'s markers, so that their error bars stand apart."""
    ch = [c for _, c in record.sections]
    span = (max(ch) - min(ch)) or 100.0
    n = len(record.scenarios)
    return 0.008 * span * (j - 0.5 * (n - 1))


def _chainage_limits(record: StudyRecord) -> tuple[float, float]:
    ch = [c for _, c in record.sections]
    span = (max(ch) - min(ch)) or 100.0
    return min(ch) - 0.06 * span, max(ch) + 0.06 * span


def _section_names(fig: Figure, ax: Axes, sections: list[tuple[str, float]], rotate: bool) -> None:
    """The sections' names above the axes, at their chainages (a twin axes' ticks)."""
    top = ax.twiny()
    top.set_label("sections")
    top.set_xlim(ax.get_xlim())
    top.set_xticks([c for _, c in sections], [n for n, _ in sections], fontsize=FS - 1.0,
                   rotation=90.0 if rotate else 0.0)
    top.tick_params(axis="x", length=3.0, pad=2.0)


def _names_rotated(record: StudyRecord, sections: list[tuple[str, float]]) -> tuple[bool, float]:
    """Whether the names above the axes stand upright (they would not fit side by side at the
    closest two chainages), and the height (inches) they take."""
    wide = 0.6 * (FS - 1.0) * max(len(n) for n, _ in sections) + 6.0  # points, as text_size
    if len(sections) < 2:
        return False, 0.25
    lo, hi = _chainage_limits(record)
    closest = min(b - a for (_, a), (_, b) in zip(sections[:-1], sections[1:]))
    if wide <= closest / (hi - lo) * AXES_WIDTH * 72.0:
        return False, 0.25
    return True, 0.12 + wide / 72.0


def _limits(ax: Axes) -> Placed:
    """The tolerable limits as horizontal lines; their labels, to be placed."""
    out: Placed = []
    for (lim, _), dashes in zip(TOLERABLE, LIMIT_DASHES):
        ax.axhline(lim, color=LIMIT, lw=0.8, dashes=dashes, zorder=2)
        out.append(hline_label(ax, lim, f"{lim:g} m", fontsize=FS - 0.5, color="0.15"))
    return out


def _limit_key() -> list[tuple[Any, str]]:
    from matplotlib.lines import Line2D

    return [(Line2D([], [], color=LIMIT, lw=0.8, dashes=dashes), f"tolerable ESD {limit_text(lim, source)}")
            for (lim, source), dashes in zip(TOLERABLE, LIMIT_DASHES)]


def _place(fig: Figure, ax: Axes, labels: Placed, lines: list[tuple[Any, Any]]) -> None:
    with LabelPlacer(fig) as placer:
        placer.avoid_lines_of(ax)
        for x, y in lines:
            placer.avoid_line(ax, x, y)
        placer.place_all(ax, labels)


def _log_range(values: list[float]) -> tuple[float, float]:
    pos = [v for v in values if math.isfinite(v) and v > 0.0]
    marks = [lim for lim, _ in TOLERABLE]
    lo = min(pos + marks)
    hi = max(pos + marks)
    return decade_range(max(lo, hi * 1e-3) / 1.5, hi * 1.5)


# -- the ESD along the chainage ------------------------------------------------------------------


def _chainage(record: StudyRecord, dpi: float) -> Figure:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    title = (f"Expected sliding distance along the breakwater\n"
             f"{_facts(record)}")
    has_band = any(r.band is not None for r in record.rows)
    first_scenario = record.scenarios[0]
    several = any(len(record.rows_for(section=n, scenario=first_scenario)) > 1 for n, _ in record.sections)
    key: list[tuple[Any, str]] = []
    for j, sc in enumerate(record.scenarios):
        s = scenario_style(j)
        key.append((Line2D([], [], **s.line()), f"{sc}: ESD \u00b1 2 standard errors"))
        if has_band:
            key.append((Patch(facecolor=s.color, alpha=0.2, hatch=s.hatch, edgecolor=s.color, lw=0.0),
                        f"{sc}: climate band of the ESD"))
    if several:
        key.append((Line2D([], [], ls="none", marker="o", markersize=4.0, markerfacecolor="white",
                           markeredgecolor="0.2"), "a section's other widths (open markers)"))
    if any(r.expected_sliding <= 0.0 for r in record.rows):
        key.append((Line2D([], [], ls="none", marker="v", markersize=4.5, markerfacecolor="white",
                           markeredgecolor="0.2"), "ESD = 0 (no lifetime slid)"))
    key += _limit_key()
    rotate, names_h = _names_rotated(record, list(record.sections))
    fig, ax, _h = new_frame(title, key_columns(key)[1], dpi=dpi, top_extra=names_h)
    values = [v for r in record.rows for v in (r.expected_sliding, r.expected_sliding + 2 * _se(r),
                                                  *(r.band or ()))]
    y0, y1 = _log_range(values)
    ax.set_yscale("log")
    ax.set_ylim(y0, y1)
    ax.set_xlim(*_chainage_limits(record))
    lines = []
    for j, sc in enumerate(record.scenarios):
        s = scenario_style(j)
        dx = _dodge(record, j)
        first = _first_rows(record, sc)
        on_line = {id(r) for r in first}
        x = np.array([r.chainage for r in first]) + dx
        esd = np.array([r.expected_sliding for r in first])
        if has_band:  # a hatched box at every banded section (a lone one too), not a fill between them
            x_lo, x_hi = ax.get_xlim()
            half = 0.012 * (x_hi - x_lo)
            for xr, r in zip(x, first):
                if r.band is None:
                    continue
                ax.fill_between([xr - half, xr + half], max(r.band[0], y0 * 0.5), r.band[1],
                                facecolor=s.color, alpha=0.18, hatch=s.hatch, edgecolor=s.color, lw=0.0,
                                zorder=1, gid="climate-band")
        ax.plot(x, np.where(esd > 0.0, esd, np.nan), **s.line(zorder=4))
        lines.append((x, np.where(esd > 0.0, esd, np.nan)))
        for r in record.rows_for(scenario=sc):
            xr = r.chainage + dx
            if r.expected_sliding <= 0.0:
                ax.plot([xr], [0.035], transform=ax.get_xaxis_transform(), ls="none", marker="v",
                        markersize=4.5, markerfacecolor="white", markeredgecolor=s.color, zorder=5)
                continue
            se2 = 2.0 * _se(r)
            low = r.expected_sliding - se2 if r.expected_sliding - se2 > 0.0 else y0 * 0.5
            ax.plot([xr, xr], [low, r.expected_sliding + se2], color=s.color, lw=0.9, zorder=3)
            if id(r) not in on_line:
                ax.plot([xr], [r.expected_sliding], ls="none", marker=s.marker, markersize=4.0,
                        markerfacecolor="white", markeredgecolor=s.color, zorder=5)
    format_log_axis(ax, "y")
    label_axes(ax, "chainage (m)", "expected sliding distance (m)", FS)
    _section_names(fig, ax, list(record.sections), rotate)
    draw_key(fig, key, fig.get_figheight())
    _place(fig, ax, _limits(ax), lines)
    return fig


def _facts(record: StudyRecord) -> str:
    return study_facts(len(record.sections), len(record.scenarios), record.trials, record.seed, record.years)


def _se(r: StudyRow) -> float:
    return r.std_error if math.isfinite(r.std_error) else 0.0


# -- the sliding by service year -----------------------------------------------------------------


def _years(record: StudyRecord, section: str, dpi: float) -> Figure:
    from matplotlib.lines import Line2D

    chainage = dict(record.sections)[section]
    rows = [record.rows_for(section=section, scenario=sc)[0] for sc in record.scenarios]
    width = rows[0].width if len({r.width for r in rows}) == 1 else None
    at = f"b = {width:g} m" if width is not None else "the width for the target under each scenario"
    title = (f"{section} (chainage {chainage:g} m): expected cumulative sliding by service year, {at}\n"
             f"{_facts(record)}")
    key: list[tuple[Any, str]] = []
    for j, (sc, r) in enumerate(zip(record.scenarios, rows)):
        s = scenario_style(j)
        passed = [f"{lim:g} m in year {year}" for lim, year in r.passes if year is not None]
        when = ("; passes " + ", ".join(passed)) if passed else "; passes no limit"
        key.append((Line2D([], [], **s.line(marker="None")), f"{sc}{when}"))
    for (lim, _), marker in zip(TOLERABLE, _PASS_MARKERS):
        key.append((Line2D([], [], ls="none", marker=marker, markersize=5.0, markerfacecolor="0.2",
                           markeredgecolor="white"), f"first year over {lim:g} m"))
    key += _limit_key()
    fig, ax, _h = new_frame(title, key_columns(key)[1], dpi=dpi)
    years = np.arange(1, record.years + 1)
    y0, y1 = _log_range([v for r in rows for v in r.by_year])
    ax.set_yscale("log")
    ax.set_ylim(y0, y1)
    ax.set_xlim(0.0, record.years + 1.0)
    lines = []
    for j, r in enumerate(rows):
        s = scenario_style(j)
        v = np.asarray(r.by_year, dtype=np.float64)
        y = np.where(v > 0.0, v, np.nan)
        ax.plot(years[:v.size], y, **s.line(marker="None", zorder=4))
        lines.append((years[:v.size], y))
        for (_lim, year), marker in zip(r.passes, _PASS_MARKERS):
            if year is not None:
                ax.plot([year], [v[year - 1]], ls="none", marker=marker, markersize=5.0,
                        markerfacecolor=s.color, markeredgecolor="white", markeredgewidth=0.6, zorder=5)
    format_log_axis(ax, "y")
    label_axes(ax, "service year", "expected cumulative sliding (m)", FS)
    draw_key(fig, key, fig.get_figheight())
    _place(fig, ax, _limits(ax), lines)
    return fig


# -- the width for the target along the chainage -------------------------------------------------


def _width(record: StudyRecord, dpi: float) -> Figure:
    from matplotlib.lines import Line2D

    targets = [(n, c) for n, c in record.sections
               if any(r.required_width is not None for r in record.rows_for(section=n))]
    has_upper = any(r.required_width_upper is not None for r in record.rows)
    target = "the target" if record.target is None else f"{record.target:g} m"
    title = (f"Width for an expected sliding distance of {target} along the breakwater\n"
             f"{_facts(record)}")
    key: list[tuple[Any, str]] = []
    for j, sc in enumerate(record.scenarios):
        s = scenario_style(j)
        key.append((Line2D([], [], **s.line()), f"{sc}: width and its Monte Carlo interval"))
        if has_upper:
            key.append((Line2D([], [], color=s.color, lw=0.9, dashes=(2.0, 2.0), marker=s.marker,
                               markersize=4.5, markerfacecolor="white"),
                        f"{sc}: at the climate band's upper level"))
    fixed = [(r.chainage, r.width) for n, c in record.sections if (n, c) not in targets
             for r in record.rows_for(section=n, scenario=record.scenarios[0])]
    if fixed:
        key.append((Line2D([], [], ls="none", marker="_", markersize=8.0, color=FIXED_WIDTH),
                    "the fixed widths of the other sections"))
    rotate, names_h = _names_rotated(record, targets)
    fig, ax, _h = new_frame(title, key_columns(key)[1], dpi=dpi, top_extra=names_h)
    ax.set_xlim(*_chainage_limits(record))
    values: list[float] = [w for _, w in fixed]
    if fixed:
        ax.plot([c for c, _ in fixed], [w for _, w in fixed], ls="none", marker="_", markersize=8.0,
                color=FIXED_WIDTH, zorder=2)
    for j, sc in enumerate(record.scenarios):
        s = scenario_style(j)
        dx = _dodge(record, j)
        rows = [record.rows_for(section=n, scenario=sc)[0] for n, _ in targets]
        rows = [r for r in rows if r.required_width is not None]
        x = np.array([r.chainage for r in rows]) + dx
        w = np.array([r.required_width for r in rows], dtype=np.float64)
        ax.plot(x, w, **s.line(zorder=4))
        values += list(w)
        for xr, r in zip(x, rows):
            if r.required_width_interval is not None:
                lo, hi = r.required_width_interval
                ax.plot([xr, xr], [lo, hi], color=s.color, lw=0.9, marker="_", markersize=6.0, zorder=3)
                values += [lo, hi]
        up = np.array([np.nan if r.required_width_upper is None else r.required_width_upper for r in rows])
        if np.any(np.isfinite(up)):
            ax.plot(x, up, color=s.color, lw=0.9, dashes=(2.0, 2.0), marker=s.marker, markersize=4.5,
                    markerfacecolor="white", zorder=4)
            values += [float(u) for u in up if np.isfinite(u)]
    lo_w, hi_w = min(values), max(values)
    pad = 0.12 * ((hi_w - lo_w) or max(1.0, hi_w))
    ax.set_ylim(lo_w - pad, hi_w + pad)
    label_axes(ax, "chainage (m)", "caisson width $b$ (m)", FS)
    _section_names(fig, ax, targets, rotate)
    draw_key(fig, key, fig.get_figheight())
    return fig
