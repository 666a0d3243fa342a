"""`make bench`: throughput of the mode engine and timings of the drawing commands.

Prints points per second for label_grid (2000 x 2000 grid) and classify
(4 million scattered points), the solver's rate for comparison, and then the
plotting timings of bench/bench_plot.py (``regimemap plot`` against a bare matplotlib script
drawing the same polygons, and ``regimemap figures --set all``) and the outcome-map benchmark of
bench/bench_dynamics.py (a 200 x 200 map of regimemap.dynamics) and the lifetime benchmark of
bench/bench_lifetime.py (5000 lifetimes of Goda's caisson, the 21-width design chart) and the
explorer's redraw of bench/bench_explore.py, the climate analysis of a 10-year record
(``climate``), a whole breakwater's study of bench/bench_study.py (20 sections x 3 scenarios on
one and two workers, and with climate replicates) and the coverage of the return-value intervals
and of the ESD's climate band measured on records of known truth (bench/bench_calibration.py).  Times are
the best of several runs (wall clock, this machine); the targets of the issues are shown beside them.
"""

from __future__ import annotations

import importlib.util
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

import regimemap
from regimemap import classify, label_grid
from regimemap.mechanics.solver import admissible


def best_of(fn, repeat: int = 7) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def engine() -> list[tuple[str, float, str, str]]:
    rows = []
    k = np.linspace(0, 3, 2000)
    mu = np.linspace(0, 3, 2000)
    for gamma, kprime in ((3.0, 0.4), (1.0, -0.3)):
        t = best_of(lambda gamma=gamma, kprime=kprime: label_grid(k, mu, gamma, kprime))
        rows.append((f"label_grid 2000x2000 (gamma={gamma}, k'={kprime})", 4e6 / t, "points/s",
                     ">= 100e6"))
    # with loads (issue 10): Goda's caisson submerged (lift-off in view), a slender block
    # whose uplift grows with the push
    k6 = np.linspace(0, 6, 2000)
    for what, gamma, kprime, loads in (
            ("beta=0.318, nu=0.524", 0.7, -0.018, {"buoyancy": 0.318, "uplift_ratio": 0.524}),
            ("nu=1", 3.0, 0.4, {"uplift_ratio": 1.0})):
        t = best_of(lambda gamma=gamma, kprime=kprime, loads=loads:
                    label_grid(k6, mu, gamma, kprime, **loads))
        rows.append((f"label_grid 2000x2000 loaded ({gamma}, {kprime}; {what})", 4e6 / t,
                     "points/s", ">= 100e6"))
    rng = np.random.default_rng(0)
    ks = rng.uniform(0, 3, 4_000_000)
    ms = rng.uniform(0, 3, 4_000_000)
    for gamma, kprime in ((3.0, 0.4), (1.0, -0.3)):
        t = best_of(lambda gamma=gamma, kprime=kprime: classify(ks, ms, gamma, kprime), repeat=5)
        rows.append((f"classify 4e6 scattered (gamma={gamma}, k'={kprime})", 4e6 / t, "points/s",
                     ">= 20e6"))
    n = 200_000
    t = best_of(lambda: admissible(ks[:n], ms[:n], 3.0, 0.4), repeat=3)
    rows.append(("solver: every hypothesis at every point", n / t, "points/s", "(reference)"))
    return rows


#: The record of the climate benchmark: the shared data beside the clone (not in the repository).
CLIMATE_RECORD = Path(__file__).resolve().parents[2] / "shared" / "data" / "ndbc44007_1996-2005_hs_tz.txt"


def climate() -> None:
    """``regimemap climate`` without drawing: read the 10-year hourly NDBC 44007 record (82,805 rows,
    2.6 MB), take the storms over the 99.5 % quantile, fit the GPD and give its interval by each
    method with 200 replicate fits, on one core (target <= 2 s CPU, issue 27 and 33; CPU time, which a
    loaded machine inflates less than the wall); skipped when the shared data is not beside the clone."""
    if not CLIMATE_RECORD.is_file():
        print(f"climate: skipped ({CLIMATE_RECORD} not found)")
        return
    from regimemap.climate import ClimateOptions, analyse
    from regimemap.io.records import read_record

    for method in ("posterior", "profile", "bootstrap"):
        cpu = []
        for _ in range(3):
            t0 = time.process_time()
            r = analyse(read_record(CLIMATE_RECORD), ClimateOptions(replicates=200, seed=1, interval=method))
            cpu.append(time.process_time() - t0)
        rv = next(v for v in r.return_values if v["period"] == 50.0)
        name = f"climate: read + POT + GPD + {method} interval, 44007 (10 y hourly)"
        print(f"{name:64s} {min(cpu):14.2f}  {'CPU s':9s} <= 2 s")
        print(f"  50-year Hs {rv['value']:.2f} m, 90 % {method} interval {rv['lower']:.2f} to "
              f"{rv['upper']:.2f} m ({r.fit.n} storms)")


def climate_life() -> None:
    """The example caisson (``regimemap caisson --example``) at 44007: 200 posterior climates x 1000
    lifetimes on two cores (target <= 20 s, issue 27); skipped without the shared data."""
    if not CLIMATE_RECORD.is_file():
        print(f"climate band: skipped ({CLIMATE_RECORD} not found)")
        return
    from regimemap.climate import ClimateOptions, analyse
    from regimemap.climate.life import climate_of, replicate_climates
    from regimemap.io.design import example_design_text, parse_design
    from regimemap.io.records import read_record
    from regimemap.lifetime.replicates import climate_band

    d = parse_design(example_design_text(), "example.toml")
    caisson = d.lifetime_caisson()
    result = analyse(read_record(CLIMATE_RECORD), ClimateOptions(replicates=200, seed=1))
    model = d.lifetime_model().with_(climate=climate_of(result.fit))
    t0 = time.perf_counter()
    band = climate_band(caisson, model, replicate_climates(result), 1000, seed=2026, jobs=2)
    t = time.perf_counter() - t0
    name = "climate band: 200 posterior climates x 1000 lifetimes, 2 processes"
    print(f"{name:64s} {t:14.1f}  {'s':9s} <= 20 s")
    print(f"  ESD with the climate's uncertainty {band.expected_sliding:.3g} m, 90 % band "
          f"{band.lower:.3g} to {band.upper:.3g} m")


def main() -> int:
    print(f"regimemap {regimemap.__version__}, numpy {np.__version__}, Python "
          f"{platform.python_version()}, {os.cpu_count()} cores, {platform.machine()}")
    print()
    print(f"{'benchmark':64s} {'result':>14s}  {'unit':9s} target")
    for name, value, unit, target in engine():
        print(f"{name:64s} {value:14,.0f}  {unit:9s} {target}")
    print()
    climate()
    climate_life()
    plot = Path(__file__).with_name("bench_plot.py")
    if plot.exists():
        spec = importlib.util.spec_from_file_location("bench_plot", plot)
        mod = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        if hasattr(mod, "main"):
            mod.main()
        else:
            for key, value in mod.run().items():
                print(f"{key:58s} {value}")
    dynamics = Path(__file__).with_name("bench_dynamics.py")
    if dynamics.exists():  # regimemap.dynamics: the 200 x 200 outcome map, thresholds, runs/s
        spec = importlib.util.spec_from_file_location("bench_dynamics", dynamics)
        mod = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        mod.main()
    lifetime = Path(__file__).with_name("bench_lifetime.py")
    if lifetime.exists():  # regimemap.lifetime: 5000 lifetimes on one core, the 21-width chart
        spec = importlib.util.spec_from_file_location("bench_lifetime", lifetime)
        mod = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        mod.main()
    study = Path(__file__).with_name("bench_study.py")
    if study.exists():  # regimemap study: 20 sections x 3 scenarios on one and two workers, replicates
        spec = importlib.util.spec_from_file_location("bench_study", study)
        mod = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        mod.main()
    calibration = Path(__file__).with_name("bench_calibration.py")
    if calibration.exists():  # issue 33: the intervals' coverage of a known truth (<= 10 min)
        spec = importlib.util.spec_from_file_location("bench_calibration", calibration)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = mod  # its worker processes find their task functions by name
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        mod.main(["--no-write"])  # bench_calibration.py alone updates bench/results/calibration.json
    explore = Path(__file__).with_name("bench_explore.py")
    if explore.exists():  # regimemap explore: one redraw per slider step (<= 100 ms)
        spec = importlib.util.spec_from_file_location("bench_explore", explore)
        mod = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        spec.loader.exec_module(mod)
        print()
        mod.main([])
    return 0


if __name__ == "__main__":
    sys.exit(main())
