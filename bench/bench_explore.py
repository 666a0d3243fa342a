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
``classify``), the heavier situation.
"""

from __future__ import annotations

import statistics
import time

import matplotlib

matplotlib.use("Agg")

from regimemap import Parameters  # noqa: E402
from regimemap.drawing.explore import Explorer  # noqa: E402

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


def run() -> dict[str, tuple[float, float, float]]:
    """Median wall, median CPU and 90th-percentile wall milliseconds of an update, by case."""
    out: dict[str, tuple[float, float, float]] = {}
    for label, params, which, values, final, point in CASES:
        ex = Explorer(params, echo=None)
        try:
            ex.click(*point)
            ex.fig.canvas.draw()
            wall, cpu = _sweep(ex, which, values, final)
        finally:
            ex.close()
        p90 = statistics.quantiles(wall, n=10)[-1]
        out[label] = (1e3 * statistics.median(wall), 1e3 * statistics.median(cpu), 1e3 * p90)
    return out


def main() -> None:
    print(f"regimemap explore: one update = set_gamma/set_kprime + fig.canvas.draw() "
          f"(Agg, matplotlib {matplotlib.__version__}, default resolution 801, a clicked point)")
    for label, (wall, cpu, p90) in run().items():
        target = f"target <= {TARGET_MS:.0f} ms" if label.startswith("drag") else "(for information)"
        print(f"{'explore update, ' + label:60s} {wall:6.1f} ms wall (90 %: {p90:5.1f}) "
              f"{cpu:6.1f} ms CPU   {target}")


if __name__ == "__main__":
    main()
