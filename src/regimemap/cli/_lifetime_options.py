"""The options of ``regimemap lifetime``, in groups, each a click decorator.

:func:`lifetime_options` (``--trials``, ``--seed``, ``--years``: the design file's values
overridden), :func:`chart_options` (``--width``, ``--target``, ``--width-tolerance``: a design
chart instead), :func:`run_options` (``--jobs``, ``--chunk``, ``--scheduler``, ``--quiet``:
where the lifetimes run) and :func:`report_options` (``--json``, ``-o``).  Each value is checked
by a function of :mod:`regimemap.io` (:mod:`regimemap.lifetime.file_options`,
:func:`regimemap.caisson.file.check_lifetime_option`), whose ValueError is the usage error.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from ..io.formats import FIGURES
from ._common import Checked, jobs_option, json_option, option_group, outputs_option, quiet_option

__all__ = ["chart_options", "lifetime_options", "report_options", "run_options"]

def _file_key(key: str) -> Callable[[str], Any]:
    def check(text: str) -> Any:
        from ..caisson.file import check_lifetime_option

        return check_lifetime_option(key, text)

    return check


def _option_check(name: str) -> Callable[[str], Any]:
    """The check ``name`` of :mod:`regimemap.lifetime.file_options`, imported on first use."""
    def check(text: str) -> Any:
        from ..lifetime import file_options as lifetime_options

        return getattr(lifetime_options, name)(text)

    return check


lifetime_options = option_group(
    click.option("--trials", type=Checked("integer", _file_key("trials")), default=None, metavar="N",
                 help="Lifetimes to simulate, 1 to 10000000 (default: [lifetime] trials, or 5000)."),
    click.option("--seed", type=Checked("integer", _file_key("seed")), default=None, metavar="S",
                 help="Root seed, a whole number >= 0: the same seed gives the same numbers, bit for "
                      "bit on one machine, to 1e-12 on another CPU (default: [lifetime] seed, or a "
                      "fresh one, reported)."),
    click.option("--years", type=Checked("integer", _file_key("years")), default=None, metavar="Y",
                 help="Design life in years, 1 to 1000 (default: [lifetime] years, or 50)."))

chart_options = option_group(
    click.option("--width", "widths", type=Checked("text", _option_check("parse_widths")), default=None,
                 metavar="A:B:N",
                 help="A design chart instead: the expected sliding distance at N widths from A to B "
                      "metres (N >= 2), all on the same random numbers, with the width for --target and "
                      "the width of Goda's deterministic design (SF = 1.2 under the 50-year wave)."),
    click.option("--target", type=Checked("number", _option_check("check_target")), default=None,
                 metavar="ESD",
                 help="With --width: the tolerable expected sliding distance in metres, > 0 "
                      "(default: [lifetime] target, or 0.1, Goda & Takagi 2000)."),
    click.option("--width-tolerance", "tolerance", type=Checked("number", _option_check("check_tolerance")),
                 default=None, metavar="M",
                 help="With --width: bisect the width for --target to M metres, 0.001 to 10 "
                      "(default 0.05); its Monte Carlo interval is printed beside it."))

report_options = option_group(
    json_option(),
    outputs_option(f"Output file (repeatable), written atomically: {FIGURES} draws the figure (with "
                   "--width: the design chart), .csv or .npz writes every lifetime (with --width: .csv "
                   "writes the chart's table)."))

run_options = option_group(
    jobs_option("Worker processes on this machine (default: one per core; 1: this process)."),
    click.option("--chunk", type=Checked("integer", _option_check("check_chunk")), default=None, metavar="N",
                 help="Lifetimes per unit of work (default 500); the numbers do not depend on it."),
    click.option("--scheduler", type=Checked("text", _option_check("check_scheduler")), default=None,
                 metavar="ADDRESS",
                 help="Run on an existing Dask cluster, e.g. tcp://host:8786 (needs the 'cluster' extra: "
                      "pip install 'regimemap[cluster]'); the numbers are those of this machine, bit for "
                      "bit when the workers' CPUs have its feature level (else to 1e-12)."),
    quiet_option())
