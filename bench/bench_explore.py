"""Benchmark of ``regimemap explore``: how long one update of the live map takes (issue 21).

Standalone script (not a test): ``.venv/bin/python bench/bench_explore.py``.

An update is what a slider does: :meth:`Explorer.set_gamma` or
:meth:`Explorer.set_kprime` (the map redrawn by ``draw_map`` at the default
resolution, 801 samples of k) followed by ``fig.canvas.draw()`` of the whole
explorer figure (map, key, sliders, the panel), on the Agg backend, at the
figure's screen resolution (100 dpi).  A GUI draws the same Agg picture and
then copies it to the screen.  Median (and 90th percentile) of the steps of
a sweep of one slider, wall clock and CPU time:

* while a slider is dragged (``final=False``), gamma and then k' across the
  centre of mass (the maps below C have more lines and labels): target <= 100 ms;
* on the release of the mouse, or a call from code (``final=True``): the same
  plus the mode symbols, ``plot``'s legibility pass (``tidy_figure``) and the
  panel's answer at the clicked point -- once per drag, for information;
* dragging gamma for Goda's submerged caisson (the loaded map, lift-off in view).

Each case starts with a clicked point (the panel holds the full answer of
``classify``), the heavier situation.  On a shared machine the wall clock
follows the other processes (CPU time much less): ``--repeat N`` runs every
case N times and reports, for each number, the best of the N runs.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from typing import NamedTuple

import matplotlib

matplotlib.use("Agg")

from regimemap import Parameters  # noqa: E402
from regimemap.drawing.explore.explorer import Explorer  # noqa: E402
from regimemap.maps.mapdata import map_for_view  # noqa: E402
from regimemap.maps.query import classify_point  # noqa: E402

TARGET_MS = 100.0


def _sweep(ex: Explorer, which: str, values: list[float], final: bool
           ) -> tuple[list[float], list[float]]:
    """Move one slider through ``values``; (wall, CPU) seconds of each update but the first 3."""
    setter = ex.set_gamma if which == "gamma" else ex.set_kprime
    wall: list[float] = []
    cpu: list[float] = []
    for i, v in enumerate(values):
        w0, c0 = time.perf_counter(), time.process_time()
        setter(v, final=final)
        ex.fig.canvas.draw()
        if i >= 3:  # the first updates warm the caches
            wall.append(time.perf_counter() - w0)
            cpu.append(time.process_time() - c0)
    if not final:
        ex.finish()  # the release
    return wall, cpu


def _steps(a: float, b: float, n: int) -> list[float]:
    return [a + (b - a) * i / (n - 1) for i in range(n)]


#: (label, block, slider, values, final, clicked point)
CASES = (
    ("drag gamma 3 -> 4.5 (k' = 0.4)", Parameters(3.0, 0.4), "gamma", _steps(3.0, 4.5, 33),
     False, (0.45, 0.6)),
    ("drag k' 0.4 -> -0.6 (gamma = 3)", Parameters(3.0, 0.4), "kprime", _steps(0.4, -0.6, 33),
     False, (0.45, 0.6)),
    ("release / from code: gamma 3 -> 4.5", Parameters(3.0, 0.4), "gamma", _steps(3.0, 4.5, 13),
     True, (0.45, 0.6)),
    ("drag gamma 0.7 -> 1 (Goda's caisson, loads)",
     Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524), "gamma", _steps(0.7, 1.0, 23),
     False, (0.2776, 0.6)),
)


class Timing(NamedTuple):
    """Milliseconds of an update of one case (medians and 90th percentile over its steps)."""

    wall: float  #: median wall clock
    cpu: float  #: median CPU time of this process
    p90: float  #: 90th percentile of the wall clock
    fastest: float  #: the fastest step (wall clock)


def run(repeat: int = 1) -> dict[str, Timing]:
    """The timings of an update, by case; with ``repeat`` > 1, the best of that many runs."""
    out: dict[str, Timing] = {}
    for _ in range(repeat):
        for label, params, which, values, final, point in CASES:
            ex = Explorer(params, compute=map_for_view, classify=classify_point, echo=None)
            try:
                ex.click(*point)
                ex.fig.canvas.draw()
                wall, cpu = _sweep(ex, which, values, final)
            finally:
                ex.close()
            p90 = statistics.quantiles(wall, n=10)[-1]
            now = Timing(1e3 * statistics.median(wall), 1e3 * statistics.median(cpu), 1e3 * p90,
                         1e3 * min(wall))
            best = out.get(label)
            out[label] = now if best is None else Timing(*map(min, zip(best, now)))
    return out


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=1, metavar="N",
                        help="run every case N times, report the best of each number")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"regimemap explore: one update = set_gamma/set_kprime + fig.canvas.draw() "
          f"(Agg, matplotlib {matplotlib.__version__}, default resolution 801, a clicked point; "
          f"load average {load:.1f} on {os.cpu_count()} cores"
          + (f", best of {args.repeat} runs" if args.repeat > 1 else "") + ")")
    for label, t in run(args.repeat).items():
        target = f"target <= {TARGET_MS:.0f} ms" if label.startswith("drag") else "(for information)"
        print(f"{'explore update, ' + label:60s} {t.wall:6.1f} ms wall (90 %: {t.p90:5.1f}, "
              f"fastest {t.fastest:5.1f}) {t.cpu:6.1f} ms CPU   {target}")


if __name__ == "__main__":
    main()
