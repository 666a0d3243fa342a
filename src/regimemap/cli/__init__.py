"""The ``regimemap`` command line (click).

A thin layer: each command parses and validates its options, calls the
library, and writes files atomically.  matplotlib is imported only inside the
commands that draw, so ``regimemap --help`` and the non-plotting commands start
fast.  Commands live in their own modules and are added to the group below.
"""

from __future__ import annotations

import gc
import sys
from typing import NoReturn

import click

from .. import __version__
from ._common import CONTEXT_SETTINGS
from ._logging import verbose_option
from ._main import gc_paused_at_start, run_main

__all__ = ["cli", "main", "console_main"]


@click.group(context_settings=CONTEXT_SETTINGS)
@click.version_option(__version__, "--version", "-V", prog_name="regimemap")
@verbose_option
def cli() -> None:
    """Regime maps of a freestanding rigid block pushed by a horizontal force.

    For a block of aspect ratio GAMMA = H/B on a base with friction MU, pushed
    by F = m g k at height h = KPRIME*H above its centre of mass, regimemap
    tells which motion starts: rest (RE), slide (SL), rock (RO) or slide-rock
    (SRO-, SRO+, SRO'-).

    \b
    Examples:
      regimemap plot --gamma 3 --kprime 0.4
      regimemap plot --gamma 3 --kprime -0.2 --show-ambiguity -o map.svg
      regimemap figure 3.9a -o fig.svg
      regimemap figures --out figures --format png,svg
      regimemap classify --gamma 3 --kprime 0.4 --k 0.45 --mu 0.6
      regimemap export --gamma 3 --kprime 0.4 -o map.json
      regimemap atlas --gamma 1,2,3 --kprime -0.6,-0.2,0,0.4,0.9 -o atlas.svg
      regimemap animate --gamma 3 --kprime -1:1:41 -o sweep.gif
      regimemap caisson --example > goda.toml
      regimemap lifetime goda.toml -o life.png
      regimemap lifetime goda.toml --width 10:25:16 -o chart.svg
      regimemap -v lifetime goda.toml -o life.png
      regimemap study --example > breakwater.toml
      regimemap study breakwater.toml --jobs 2 -o table.csv
      regimemap climate buoy.csv -o return-levels.png
    """


def _register(group: click.Group) -> None:
    """Compose the group explicitly, each command added by name (as pyhf does).

    Importing a command module is cheap: matplotlib and the library's heavy
    parts are imported inside the commands that use them.
    """
    from .atlas import animate_cmd, atlas_cmd
    from .caisson import caisson_cmd
    from .climate import climate_cmd
    from .dynamics_figures import dynamics_figures_cmd
    from .explore import explore_cmd
    from .export import export_cmd
    from .lifetime import lifetime_cmd
    from .outcome import outcome_cmd
    from .plot import figure_command, figures_command, plot_command
    from .query import classify_cmd
    from .simulate import simulate_cmd
    from .study import study_cmd

    for command in (plot_command, figure_command, figures_command, classify_cmd, export_cmd, atlas_cmd,
                    animate_cmd, caisson_cmd, lifetime_cmd, study_cmd, climate_cmd, simulate_cmd, outcome_cmd,
                    dynamics_figures_cmd, explore_cmd):
        group.add_command(command)


_register(cli)


def main(argv: list[str] | None = None, *, exiting: bool = False) -> NoReturn:
    """Run the command line with ``argv`` and exit; errors become one line on stderr.

    ``exiting``: the process ends with this call (the console script), so after
    Ctrl-C or SIGTERM a second one is ignored rather than interrupting the exit.

    The cyclic garbage collector is paused while the process starts (see
    ``regimemap.cli._main.import_matplotlib``) and restored before exiting,
    so ``main`` can be called from Python (it raises ``SystemExit``).
    """
    with gc_paused_at_start():
        code = run_main(cli, argv, exiting=exiting)
    sys.exit(code)


def console_main() -> NoReturn:
    """The ``regimemap`` console script and ``python -m regimemap``: :func:`main`, then exit
    without CPython's final garbage collections.

    At exit CPython collects every object still alive (the whole of matplotlib,
    the figure) several times while it tears the modules down: ~0.13 s of a
    0.6 s ``regimemap plot``.  Freezing them first (``gc.freeze``) skips that
    work; the process ends anyway, atexit handlers still run and the standard
    streams are still flushed (every output file is closed before this point).
    """
    try:
        main(exiting=True)
    finally:
        gc.freeze()
