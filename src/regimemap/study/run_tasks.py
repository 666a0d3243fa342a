"""The tasks of a study: one section under one scenario and one climate, and what each returns.

A task runs in any process (:func:`run_task` takes and returns plain, picklable
data): every width of its section on common random numbers
(:func:`regimemap.lifetime.parallel.run_chunks`), or the design chart and the
bisection of the width for the section's target
(:func:`regimemap.lifetime.design_chart`), or, under a bootstrap climate, the
chart's widths alone.  Its seed is a child of the study's root seed by (section,
replicate) -- :func:`task_seed` -- and not by scenario: every scenario of a
section meets the same storms and waves (a paired comparison), so a scenario
without change gives today's numbers bit for bit.  The result is a dict of
floats (JSON: the store keeps it as it is), every one finite: a task whose lifetimes
are not (:func:`regimemap.lifetime.finite.require_finite`) raises and returns nothing,
so nothing of it is stored.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..lifetime.finite import quiet_arithmetic, require_finite

if TYPE_CHECKING:
    from regimemap.lifetime import Caisson, LifetimeModel

__all__ = ["LIMITS", "StudyTask", "run_task", "task_seed"]

#: The lifetime slides [m] whose exceedance and first year passed a study reports.
LIMITS = (0.1, 0.3)


def task_seed(root: int, section: int, replicate: int) -> int:
    """The seed of the tasks of ``section`` under climate ``replicate``: 64 bits of
    ``SeedSequence(root, spawn_key=(section, replicate))``, the same for every scenario."""
    words = np.random.SeedSequence(root, spawn_key=(section, replicate)).generate_state(2, np.uint32)
    return int(words[0]) | (int(words[1]) << 32)


@dataclass(frozen=True)
class StudyTask:
    """One task: a section's caisson, its model under a scenario and a climate, and what to run.

    Attributes
    ----------
    kind : str
        ``"widths"`` (every width, on common random numbers), ``"target"`` (the
        design chart on ``widths`` and the width for ``target``) or ``"chart"``
        (the chart's ESD alone: a bootstrap climate of a target section).
    caisson : Caisson
    model : LifetimeModel
    widths : tuple of float
    trials, seed : int
    target : float or None
    tolerance : float
    sf_impulsive : bool
        Takahashi's impulsive coefficient in the chart's deterministic width.
    label : str
        The task in words (``"section 'head', scenario 'today'"``), for its messages.
    """

    kind: str
    caisson: Caisson
    model: LifetimeModel
    widths: tuple[float, ...]
    trials: int
    seed: int
    target: float | None = None
    tolerance: float = 0.05
    sf_impulsive: bool = True
    label: str = ""


def _floats(a: Any) -> list[Any]:
    return np.asarray(a, dtype=np.float64).tolist()  # type: ignore[no-any-return]


def _summary(sliding: np.ndarray, by_year: np.ndarray, trials: int, label: str,
             widths: tuple[float, ...]) -> dict[str, Any]:
    """Per width: ESD, its standard error (None for one lifetime), P(S > limit) and the expected
    cumulative sliding by year; refused unless every lifetime's sliding is finite."""
    for w, row in zip(widths, sliding):
        require_finite("the lifetime sliding", row, f"{label}, width {w:g} m" if label else f"width {w:g} m")
    require_finite("the expected sliding by year", by_year, label)
    esd = sliding.mean(axis=1)
    se = (_floats(sliding.std(axis=1, ddof=1) / math.sqrt(trials)) if trials > 1
          else [None] * int(esd.size))
    exceed = [[float(np.mean(row > x)) for x in LIMITS] for row in sliding]
    return {"esd": _floats(esd), "std_error": se, "exceedance": exceed, "by_year": _floats(by_year)}


def run_task(task: StudyTask) -> dict[str, Any]:
    """Run one task in this process (a worker's or the parent's); a dict of plain, finite numbers.

    numpy's warnings are silenced while it runs (:func:`~regimemap.lifetime.finite.quiet_arithmetic`):
    the results are checked instead.

    Returns
    -------
    dict
        ``widths`` and, per width, ``esd``, ``std_error``, ``exceedance`` (at
        :data:`LIMITS`) and ``by_year``; a ``"target"`` task has the one width
        found (its ESD on the chart's waves) and ``required_width``,
        ``interval``, ``chart_esd`` (the chart's widths) and ``bracket`` (why
        the widths do not bracket the target, or None); a ``"chart"`` task
        ``chart_esd`` alone.

    Raises
    ------
    regimemap.lifetime.finite.NonFiniteResult
        A lifetime's sliding (or the chart's ESD) is not finite: the message names the task
        (:attr:`StudyTask.label`), the width and how many values.
    """
    with quiet_arithmetic():
        return _run(task)


def _run(task: StudyTask) -> dict[str, Any]:
    from regimemap.lifetime import design_chart
    from regimemap.lifetime.parallel import make_chunks, run_chunks

    chunks = make_chunks(task.trials, task.seed)
    caissons = tuple(task.caisson.with_width(w) for w in task.widths)
    if task.kind == "chart":
        out = run_chunks(caissons, task.model, chunks)
        require_finite("the lifetime sliding", out.sliding, task.label)
        return {"kind": "chart", "widths": list(task.widths), "chart_esd": _floats(out.sliding.mean(axis=1))}
    if task.kind == "widths":
        out = run_chunks(caissons, task.model, chunks)
        return {"kind": "widths", "widths": list(task.widths),
                **_summary(out.sliding, out.years.mean(), task.trials, task.label, task.widths)}
    assert task.target is not None
    chart = design_chart(task.caisson, task.model, task.widths, task.trials, task.seed, target=task.target,
                         tolerance=task.tolerance, sf_impulsive=task.sf_impulsive)
    require_finite("the design chart's ESD", chart.expected_sliding, task.label)
    found = chart.width_for_target
    result: dict[str, Any] = {"kind": "target", "chart_widths": list(task.widths),
                              "chart_esd": _floats(chart.expected_sliding),
                              "bracket": chart.bracket_problem(), "required_width": found,
                              "interval": None if chart.width_interval is None else
                              [chart.width_interval.lower, chart.width_interval.upper]}
    if found is None:
        return {**result, "widths": []}
    # the width found, on the chart's waves (the narrowest chart width guides the sampling, unslid)
    pair = (caissons[0], task.caisson.with_width(found))
    out = run_chunks(pair, task.model, chunks, guides=1)
    return {**result, "widths": [found], **_summary(out.sliding, out.years.mean(), task.trials, task.label,
                                                    (found,))}
