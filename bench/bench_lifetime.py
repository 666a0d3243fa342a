"""Benchmark of regimemap.lifetime: 5000 lifetimes x 50 years of Goda's caisson, and the design chart.

Standalone script (not a test): ``.venv/bin/python bench/bench_lifetime.py``.

* one core: 5000 lifetimes x 50 storms of Goda's worked caisson (the example
  design file's ``[lifetime]``: H0'_10 = 5.0 m, H0'_50 = 6.3 m, 2-hour storms,
  about 1.6e8 waves in all), ``jobs = 1``; target <= 5 s;
* both cores: the 21-width design chart (10 to 25 m, the same 5000 lifetimes,
  and the bisection for the 0.1 m target), ``jobs = 2``; target <= 30 s;
* memory: the peak resident size of this process and of its worker processes
  (the chunks bound it: target <= 1 GB at any number of trials);
* the sequence of every wave's height is never formed: only the waves above a
  storm's sliding height are drawn (their number is printed).
"""

from __future__ import annotations

import resource
import sys
import time

import numpy as np

from regimemap.lifetime import Caisson, Climate, LifetimeModel, design_chart, lifetime_sliding
from regimemap.lifetime.model import PERIOD_COEFFICIENT, PERIOD_EXPONENT

GODA = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1, crest=3.4,
               friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)
MODEL = LifetimeModel(Climate.from_return_values(5.0, 6.3))


def _all_waves(trials: int, seed: int) -> float:
    """How many waves the lifetimes hold in all (storms x 2 h / T1/3), for the record."""
    rng = np.random.default_rng(seed)
    H0 = MODEL.climate.quantile(rng.random(trials * MODEL.years))
    T = PERIOD_COEFFICIENT * np.maximum(H0, 1e-9) ** PERIOD_EXPONENT
    return float(np.rint(MODEL.storm_hours * 3600.0 / T).sum())


def _peak_mb() -> tuple[float, float]:
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
    return own, children


def main(trials: int = 5000) -> None:
    print(f"Goda's caisson, {trials} lifetimes x {MODEL.years} years "
          f"(about {_all_waves(trials, 0):.2g} waves): {MODEL.climate.describe()}")
    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        r = lifetime_sliding(GODA, MODEL, trials=trials, seed=2026, jobs=1)
        best = min(best, time.perf_counter() - t0)
    print(f"{'lifetime, one core (best of 3)':52s} {best:8.2f} s   target <= 5 s   "
          f"ESD {r.expected_sliding:.4f} m ± {r.std_error:.4f} m, {r.sliding_waves} sliding waves")
    t0 = time.perf_counter()
    c = design_chart(GODA, MODEL, np.linspace(10.0, 25.0, 21), trials=trials, seed=2026, jobs=2)
    chart = time.perf_counter() - t0
    found = "none" if c.width_for_target is None else f"{c.width_for_target:.3f} m"
    print(f"{'design chart, 21 widths + bisection, two cores':52s} {chart:8.2f} s   target <= 30 s   "
          f"width for 0.1 m: {found}; SF = 1.2: {c.sf_width:.3f} m")
    t0 = time.perf_counter()
    big = lifetime_sliding(GODA, MODEL, trials=10 * trials, seed=7, jobs=2)
    many = time.perf_counter() - t0
    own, children = _peak_mb()
    print(f"{f'lifetime, {10 * trials} lifetimes, two cores':52s} {many:8.2f} s   "
          f"ESD {big.expected_sliding:.4f} m ± {big.std_error:.4f} m")
    print(f"{'peak memory (this process; largest worker)':52s} {own:6.0f} MB; {children:.0f} MB   "
          "target <= 1 GB")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5000)
