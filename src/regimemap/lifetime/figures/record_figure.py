"""The figure of a lifetime run's record: its exceedance figure, or its design chart.

What ``regimemap lifetime -o FIGURE`` draws: a run of lifetimes
(:func:`regimemap.lifetime.run.run_lifetime`) is drawn as the exceedance figure of its sliding
(:func:`regimemap.lifetime.figures.exceedance.lifetime_figure`) with its climate band, a design chart
(:func:`regimemap.lifetime.run.run_chart`, ``--width``) as the chart
(:func:`regimemap.lifetime.figures.chart.chart_figure`) with its band.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..results import LifetimeResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..run import ChartRecord, LifetimeRecord

__all__ = ["record_figure"]


def record_figure(record: LifetimeRecord | ChartRecord, title: str) -> Figure:
    """The exceedance figure of the record's lifetimes, or its design chart, each with its band.

    Parameters
    ----------
    record : LifetimeRecord or ChartRecord
        A run's record.
    title : str
        What the title names the section by (the command line: the design file's stem).
    """
    if isinstance(record.result, LifetimeResult):
        from .exceedance import lifetime_figure, lifetime_title

        return lifetime_figure(record.result, lifetime_title(title, record.result), band=record.band)
    from .chart import chart_figure, chart_title

    return chart_figure(record.result, chart_title(title, record.result), band=record.band)
