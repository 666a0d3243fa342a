"""Coverage of the return-value intervals, and of the ESD's climate band, measured from a known truth.

Standalone script (not a test): ``.venv/bin/python bench/bench_calibration.py [--interval METHOD]
[--records N] [--esd-records N] [--jobs J] [--quick] [--no-write]``; ``make bench`` runs it
through bench/bench.py.

* Records: hourly records of 10, 20 and 40 years from
  :func:`regimemap.climate.synthetic.synthetic_record` -- storm peaks over a base level
  ``u0 = 3 m`` at ``lambda = 8`` a year with GPD excesses of shape ``xi`` in {-0.3, 0, 0.2, 0.4}
  (the scale ``sigma`` smaller for a heavier tail, so that no storm of 40 years passes the
  reader's 30 m: the analysis is equivariant in scale, so the coverage does not depend on it);
  ``--records`` of them a case (300), each from its own child of one root seed.
* Each record goes the way a user's file goes: written as NetCDF (xarray's scipy engine) and read
  back by :func:`regimemap.io.records.read_record`, the reader of ``regimemap climate``, then
  :func:`regimemap.climate.analysis.analyse` with the default :class:`ClimateOptions` (threshold
  at the 99.5 % quantile of the hours, 48 h declustering, the GPD, the default interval) but for
  ``interval`` when ``--interval`` is given.  NetCDF rather than CSV because it is the cheapest
  supported format to write and read (a 40-year CSV costs about a second to parse; the bench has
  3,600 records) and stores the heights exactly; the part that decides coverage -- the record's
  quality control and length, the threshold, the declustering, the fit -- is the same for
  every format.
* For each case, and H10, H50, H100: the share of records whose 90 % and 95 % intervals hold the
  true value (threshold stability: :meth:`SyntheticClimate.return_value`), its binomial standard
  error ``sqrt(p (1 - p)/n)``, the share with the truth above the interval, and the median
  width over the truth.  A coverage outside 87-93 % (90 %) or 92-97.5 % (95 %) is flagged.
* The ESD's climate band (issue 33 item 4): ``--esd-records`` ten-year records of a climate with
  the example design's H0'_10 = 5.0 m and H0'_50 = 6.3 m (``xi = 0``); for each, the band of
  :func:`regimemap.lifetime.replicates.climate_band` for the example caisson
  (``regimemap caisson --example``) from ``--esd-replicates`` of the record's replicate
  climates x ``--esd-trials`` lifetimes, and whether it holds the true climate's ESD
  (``--truth-trials`` lifetimes).
* The results go to bench/results/calibration.json (per method; ``--no-write`` leaves it),
  which the docs' table and figure read.  Times are wall clock and CPU (this process and its
  workers): on a shared machine the CPU time is the one to compare.

``--quick`` runs 40 records a case and 20 ESD records (a check that the script works).
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import json
import math
import os
import sys
import tempfile
import time
import warnings
from collections.abc import Sequence
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np

from regimemap.climate.analysis import ClimateOptions, ClimateResult, analyse
from regimemap.climate.record import HS_MAX, Record
from regimemap.climate.synthetic import SyntheticClimate, synthetic_record

RESULTS = Path(__file__).with_name("results") / "calibration.json"

#: Root seed of every record of the benchmark.
ROOT_SEED = 20260033
#: The storms' rate above the base level [a year] and the base level [m].
RATE, BASE = 8.0, 3.0
#: ``(xi, sigma)`` of the cases: sigma smaller for the heavier tails (see the module docstring).
SHAPES = ((-0.3, 1.0), (0.0, 0.6), (0.2, 0.3), (0.4, 0.05))
#: Record lengths [years].
YEARS = (10.0, 20.0, 40.0)
#: Return periods [years] and interval levels.
PERIODS = (10.0, 50.0, 100.0)
LEVELS = (0.90, 0.95)
#: The goal: coverage within these bounds of each level.
GOAL = {0.90: (0.87, 0.93), 0.95: (0.92, 0.975)}


@dataclasses.dataclass(frozen=True)
class Case:
    """One cell of the table: a truth and a record length."""

    climate: SyntheticClimate
    years: float

    @property
    def name(self) -> str:
        return f"xi={self.climate.xi:+.1f} {self.years:.0f} y"


def cases(years: Sequence[float] = YEARS) -> list[Case]:
    """The cases, xi major: the 12 of the table, or those of the record lengths ``years``."""
    return [Case(SyntheticClimate(sigma=s, xi=x, rate=RATE, base=BASE), y) for x, s in SHAPES for y in YEARS
            if y in years]


def options(method: str | None, **more: Any) -> ClimateOptions:
    """The defaults a user gets, with ``interval=method`` when given (the field exists from
    issue 33 on)."""
    if method is not None:
        names = {f.name for f in dataclasses.fields(ClimateOptions)}
        if "interval" not in names:
            if method != "bootstrap":
                raise SystemExit(f"bench_calibration: this regimemap has no interval option; "
                                 f"--interval {method} is not available")
        else:
            more["interval"] = method
    return ClimateOptions(**more)


def default_method() -> str:
    """The default interval of :class:`ClimateOptions` (``bootstrap`` before issue 33)."""
    return str(getattr(ClimateOptions(), "interval", "bootstrap"))


def through_file(record: Record, folder: str, name: str) -> Record:
    """``record`` written as NetCDF and read back by the reader of ``regimemap climate``."""
    import xarray as xr

    from regimemap.io.records import read_record

    path = os.path.join(folder, name + ".nc")
    ds = xr.Dataset({"hs": ("time", record.hs, {"units": "m"})},
                    coords={"time": record.time.astype("datetime64[ns]")})
    ds.to_netcdf(path, engine="scipy",
                 encoding={"time": {"units": "hours since 2000-01-01 00:00:00", "dtype": "int32"}})
    try:
        return read_record(path)
    finally:
        os.remove(path)


def intervals(result: ClimateResult, period: float, levels: Sequence[float]) -> list[tuple[float, float]]:
    """The ``period``-year interval at each level, from one analysis (its band's interval, whatever
    the method)."""
    assert result.band is not None, "the analysis gave no interval"
    return [result.band.interval(period, lv) for lv in levels]


def run_record(task: tuple[int, int, np.random.SeedSequence, str | None]) -> dict[str, Any]:
    """One record of one case: read, analysed, its intervals (a worker's task)."""
    c, i, child, method = task
    case = cases()[c]
    warnings.simplefilter("ignore")
    record = synthetic_record(case.climate, case.years, child)
    if float(np.nanmax(record.hs)) > HS_MAX:
        return {"case": c, "index": i, "refused": True}
    with tempfile.TemporaryDirectory(prefix="regimemap-calibration-") as folder:
        record = through_file(record, folder, f"case{c}-record{i}")
    try:
        result = analyse(record, options(method))
    except ValueError as exc:
        return {"case": c, "index": i, "failed": str(exc)}
    out: dict[str, Any] = {"case": c, "index": i, "storms": result.fit.n,
                           "above_base": bool(result.fit.threshold is not None
                                              and result.fit.threshold >= case.climate.base)}
    for R in PERIODS:
        out[f"H{R:g}"] = [[lo, hi] for lo, hi in intervals(result, R, LEVELS)]
        out[f"H{R:g}_value"] = next(float(v["value"]) for v in result.return_values  # type: ignore[arg-type]
                                    if v["period"] == R)
    return out


def _cpu() -> float:
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def _summarise(case: Case, rows: list[dict[str, Any]]) -> dict[str, Any]:
    good = [r for r in rows if "storms" in r]
    out: dict[str, Any] = {
        "xi": case.climate.xi, "sigma": case.climate.sigma, "rate": case.climate.rate,
        "base": case.climate.base, "years": case.years, "records": len(rows), "analysed": len(good),
        "refused": sum(1 for r in rows if r.get("refused")), "failed": sum(1 for r in rows if "failed" in r),
        "threshold_below_base": sum(1 for r in good if not r["above_base"]),
        "median_storms": float(np.median([r["storms"] for r in good])) if good else math.nan,
        "periods": {},
    }
    for R in PERIODS:
        truth = case.climate.return_value(R)
        bounds = np.array([r[f"H{R:g}"] for r in good], dtype=float).reshape(len(good), len(LEVELS), 2)
        est = np.array([r[f"H{R:g}_value"] for r in good], dtype=float)
        per: dict[str, Any] = {"truth": truth, "median_estimate_over_truth": float(np.median(est) / truth)}
        for j, lv in enumerate(LEVELS):
            lo, hi = bounds[:, j, 0], bounds[:, j, 1]
            ok = np.isfinite(lo) & np.isfinite(hi)
            n = int(ok.sum())
            p = float(np.mean((lo[ok] <= truth) & (truth <= hi[ok]))) if n else math.nan
            key = f"{round(100 * lv)}"
            per[key] = {
                "coverage": p, "se": math.sqrt(p * (1.0 - p) / n) if n else math.nan, "n": n,
                "truth_above": float(np.mean(truth > hi[ok])) if n else math.nan,
                "truth_below": float(np.mean(truth < lo[ok])) if n else math.nan,
                "median_width_over_truth": float(np.median((hi[ok] - lo[ok]) / truth)) if n else math.nan,
                "miss": bool(not GOAL[lv][0] <= p <= GOAL[lv][1]) if n else True,
            }
        out["periods"][f"{R:g}"] = per
    return out


def coverage(method: str | None, records: int, jobs: int, years: Sequence[float] = YEARS,
             shapes: Sequence[float] | None = None) -> dict[str, Any]:
    """Every case's records (those of the record lengths ``years`` and the shapes ``shapes``) through
    the analysis, in a pool of ``jobs`` processes; a case's records are the same whichever cases run."""

    def chosen(case: Case) -> bool:
        return case.years in years and (shapes is None or case.climate.xi in shapes)

    all_cases = cases()
    roots = np.random.SeedSequence(ROOT_SEED).spawn(len(all_cases))
    tasks = [(c, i, child, method) for c, root in enumerate(roots) if chosen(all_cases[c])
             for i, child in enumerate(root.spawn(records))]
    wall, cpu = time.perf_counter(), _cpu()
    rows: list[dict[str, Any]] = []
    with contextlib.ExitStack() as stack:
        pool = stack.enter_context(ProcessPoolExecutor(jobs)) if jobs > 1 else None
        for row in (pool.map(run_record, tasks, chunksize=4) if pool is not None else map(run_record, tasks)):
            rows.append(row)
            if len(rows) % records == 0:  # a case done (the results come in task order)
                print(f"  {all_cases[row['case']].name}: {records} records, "
                      f"{time.perf_counter() - wall:.0f} s", file=sys.stderr, flush=True)
    wall, cpu = time.perf_counter() - wall, _cpu() - cpu
    summary = [_summarise(case, [r for r in rows if r["case"] == c]) for c, case in enumerate(all_cases)
               if chosen(case)]
    return {"method": method or default_method(), "records_per_case": records, "root_seed": ROOT_SEED,
            "cases": summary, "wall_seconds": wall, "cpu_seconds": cpu, "jobs": jobs}


def print_coverage(res: dict[str, Any]) -> None:
    """The coverage table: one line per case and return period."""
    print(f"coverage of the return-value intervals, method {res['method']}: {res['records_per_case']} "
          f"hourly records a case, each read from NetCDF and analysed with the defaults")
    print(f"{'case':12s} {'storms':>6s} {'R':>4s} {'truth':>6s}  {'90 % cov ± se':>14s} {'width':>6s}"
          f"  {'95 % cov ± se':>14s} {'width':>6s}  above90  note")
    for cs in res["cases"]:
        name = f"xi={cs['xi']:+.1f} {cs['years']:.0f} y"
        for R, per in cs["periods"].items():
            a, b = per["90"], per["95"]
            note = " ".join(f"MISS{lv}" for lv, x in (("90", a), ("95", b)) if x["miss"])
            print(f"{name:12s} {cs['median_storms']:6.0f} {R:>4s} {per['truth']:6.2f}  "
                  f"{100 * a['coverage']:6.1f} ± {100 * a['se']:4.1f} {a['median_width_over_truth']:6.2f}  "
                  f"{100 * b['coverage']:6.1f} ± {100 * b['se']:4.1f} {b['median_width_over_truth']:6.2f}  "
                  f"{100 * a['truth_above']:6.1f}  {note}")
        extra = [f"{cs[k]} {k.replace('_', ' ')}" for k in ("refused", "failed", "threshold_below_base")
                 if cs[k]]
        if extra:
            print(f"{'':12s} ({', '.join(extra)})")
    misses = sum(per[k]["miss"] for cs in res["cases"] for per in cs["periods"].values()
                 for k in ("90", "95"))
    print(f"{misses} of {2 * len(PERIODS) * len(res['cases'])} coverages outside the goal "
          f"(87-93 %, 92-97.5 %); "
          f"{res['wall_seconds']:.0f} s wall, {res['cpu_seconds']:.0f} s CPU on {res['jobs']} processes")


# --- the ESD's climate band ------------------------------------------------------------------

#: The ESD's truth: xi = 0 with the example design's H0'_10 = 5.0 m and H0'_50 = 6.3 m at 8 storms
#: a year: sigma = 1.3/ln 5, u0 = 5.0 - sigma ln 80.
ESD_SIGMA = 1.3 / math.log(5.0)
ESD_CLIMATE = SyntheticClimate(sigma=ESD_SIGMA, xi=0.0, rate=RATE,
                               base=5.0 - ESD_SIGMA * math.log(10.0 * RATE))
ESD_YEARS = 10.0


def _example() -> tuple[Any, Any]:
    from regimemap.io.design import example_design_text, parse_design

    d = parse_design(example_design_text(), "example.toml")
    return d.lifetime_caisson(), d.lifetime_model()


def _true_climate() -> Any:
    from regimemap.lifetime import Climate

    c = ESD_CLIMATE
    return Climate("gpd", scale=c.sigma, location=c.base, shape=c.xi, storms_per_year=c.rate)


def run_esd_record(task: tuple[int, np.random.SeedSequence, str | None, int, int]) -> dict[str, Any]:
    """One record of the ESD's climate: its analysis and its band (a worker's task)."""
    from regimemap.climate.life import climate_of, replicate_climates
    from regimemap.lifetime.replicates import climate_band

    i, child, method, replicates, trials = task
    warnings.simplefilter("ignore")
    caisson, model = _example()
    record_seed, band_seed = child.spawn(2)
    with tempfile.TemporaryDirectory(prefix="regimemap-calibration-") as folder:
        record = through_file(synthetic_record(ESD_CLIMATE, ESD_YEARS, record_seed), folder, f"esd{i}")
    result = analyse(record, options(method))
    climates = replicate_climates(result)[:replicates]
    band = climate_band(caisson, model.with_(climate=climate_of(result.fit)), climates, trials,
                        seed=int(band_seed.generate_state(1, np.uint32)[0]), jobs=1)
    return {"index": i, "lower": band.lower, "upper": band.upper, "esd": band.expected_sliding,
            "replicates": band.replicates, "H50_value": result.fit.return_value(50.0)}


def esd_coverage(method: str | None, records: int, replicates: int, trials: int, truth_trials: int,
                 jobs: int, seconds: float | None = None) -> dict[str, Any]:
    """How often the 90 % climate band of the example caisson's ESD holds the true climate's ESD.

    With ``seconds``, no record is started after that many seconds: the records are the first
    ones that finished (the same records for the same count)."""
    from regimemap.lifetime import lifetime_sliding

    caisson, model = _example()
    root = np.random.SeedSequence(ROOT_SEED + 1)
    truth_seed, records_root = root.spawn(2)
    wall, cpu = time.perf_counter(), _cpu()
    true = lifetime_sliding(caisson, model.with_(climate=_true_climate()), truth_trials,
                            int(truth_seed.generate_state(1, np.uint32)[0]), jobs=jobs)
    print(f"  true ESD {true.expected_sliding:.4f} m ± {true.std_error:.4f} m, "
          f"{time.perf_counter() - wall:.0f} s", file=sys.stderr, flush=True)
    tasks = [(i, child, method, replicates, trials) for i, child in enumerate(records_root.spawn(records))]
    rows: list[dict[str, Any]] = []
    with contextlib.ExitStack() as stack:
        pool = stack.enter_context(ProcessPoolExecutor(jobs)) if jobs > 1 else None
        pending: list[Any] = []
        for t in tasks + [None] * (2 * jobs):  # a window of 2 x jobs records in flight
            if t is not None and (seconds is None or time.perf_counter() - wall < seconds):
                pending.append(pool.submit(run_esd_record, t) if pool is not None else run_esd_record(t))
            if len(pending) >= 2 * jobs or (t is None and pending):
                first = pending.pop(0)
                row = first.result() if pool is not None else first
                rows.append(row)
                print(f"  ESD record {row['index']}: band {row['lower']:.4g} to {row['upper']:.4g} m, "
                      f"{time.perf_counter() - wall:.0f} s", file=sys.stderr, flush=True)
    records = len(rows)
    wall, cpu = time.perf_counter() - wall, _cpu() - cpu
    lo = np.array([r["lower"] for r in rows])
    hi = np.array([r["upper"] for r in rows])
    esd, se = true.expected_sliding, true.std_error
    covered = (lo <= esd) & (esd <= hi)
    p = float(covered.mean())
    # records whose verdict the truth's own Monte Carlo error (2 se) could turn
    close = int(np.count_nonzero((np.abs(lo - esd) < 2 * se) | (np.abs(hi - esd) < 2 * se)))
    return {"method": method or default_method(), "records": records, "years": ESD_YEARS,
            "climate": dataclasses.asdict(ESD_CLIMATE), "replicates": replicates, "trials": trials,
            "truth_trials": truth_trials, "true_esd": esd, "true_esd_se": se, "coverage": p,
            "se": math.sqrt(p * (1.0 - p) / records), "truth_above": float(np.mean(esd > hi)),
            "truth_below": float(np.mean(esd < lo)), "close_to_an_edge": close,
            "median_lower": float(np.median(lo)), "median_upper": float(np.median(hi)),
            "wall_seconds": wall, "cpu_seconds": cpu, "jobs": jobs}


def print_esd(res: dict[str, Any]) -> None:
    print(f"ESD climate band, method {res['method']}: {res['records']} records of {res['years']:.0f} years, "
          f"the example caisson, {res['replicates']} climates x {res['trials']} lifetimes a band")
    print(f"  true ESD {res['true_esd']:.3f} m ± {res['true_esd_se']:.3f} m "
          f"({res['truth_trials']} lifetimes); "
          f"median band {res['median_lower']:.3f} to {res['median_upper']:.3f} m")
    print(f"  the 90 % band holds it in {100 * res['coverage']:.1f} % ± {100 * res['se']:.1f} % "
          "of the records "
          f"(truth above {100 * res['truth_above']:.0f} %, below {100 * res['truth_below']:.0f} %; "
          f"{res['close_to_an_edge']} within 2 se of an edge); "
          f"{res['wall_seconds']:.0f} s wall, {res['cpu_seconds']:.0f} s CPU")


def _round(x: Any) -> Any:
    if isinstance(x, float):
        return None if not math.isfinite(x) else float(f"{x:.6g}")
    if isinstance(x, dict):
        return {k: _round(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_round(v) for v in x]
    return x


def write_results(key: str, method: str, res: dict[str, Any], path: Path = RESULTS) -> None:
    """Store ``res`` under ``key`` (``coverage`` or ``esd``) and ``method``, keeping the rest."""
    from regimemap.io.atomic import atomic_open

    data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    data.setdefault(key, {})[method] = _round(res)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_open(path, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")


#: The order of the figure's rows: the old default first.
FIGURE_ORDER = ("bootstrap", "posterior", "profile")


def draw_figure(path: Path = RESULTS) -> list[Path]:
    """bench/results/calibration.png and .svg from the results file (byte-stable on one machine)."""
    from regimemap.drawing.climate.calibration import calibration_figure
    from regimemap.drawing.save import save_figure

    coverage = json.loads(path.read_text(encoding="utf-8"))["coverage"]
    methods = [m for m in FIGURE_ORDER if m in coverage] + [m for m in coverage if m not in FIGURE_ORDER]
    fig = calibration_figure(coverage, methods)
    return [save_figure(fig, path.with_suffix(suffix)) for suffix in (".png", ".svg")]


def markdown(path: Path = RESULTS) -> str:
    """The docs' tables from the results file: per method, a row per case, the coverage of the
    90 % and 95 % intervals of H10, H50 and H100 with its standard error (bold: outside the goal),
    and the median width of the 90 % interval of H50 over the truth."""
    data = json.loads(path.read_text(encoding="utf-8"))
    out = []
    for method, res in data.get("coverage", {}).items():
        wall = ("" if res.get("wall_seconds") is None else
                f"{res['wall_seconds']:.0f} s wall on {res['jobs']} processes, ")
        out.append(f"**{method}** ({res['records_per_case']} records a case; {wall}"
                   f"{res['cpu_seconds']:.0f} s CPU in all)\n")
        out.append("| ξ | years | storms | H10 90 % | H10 95 % | H50 90 % | H50 95 % | H100 90 % | H100 95 % "
                   "| H50 90 % width / truth |")
        out.append("|---|---|---|---|---|---|---|---|---|---|")
        for cs in res["cases"]:
            cells = []
            for R in ("10", "50", "100"):
                for lv in ("90", "95"):
                    x = cs["periods"][R][lv]
                    text = f"{100 * x['coverage']:.1f} ± {100 * x['se']:.1f}"
                    cells.append(f"**{text}**" if x["miss"] else text)
            w = cs["periods"]["50"]["90"]["median_width_over_truth"]
            out.append(f"| {cs['xi']:+.1f} | {cs['years']:.0f} | {cs['median_storms']:.0f} | "
                       + " | ".join(cells) + f" | {w:.2f} |")
        out.append("")
    for method, e in data.get("esd", {}).items():
        out.append(f"ESD band, **{method}**: {100 * e['coverage']:.1f} % ± {100 * e['se']:.1f} % of "
                   f"{e['records']} records (true ESD {e['true_esd']:.3f} ± {e['true_esd_se']:.3f} m; "
                   f"{e['replicates']} climates x {e['trials']} lifetimes a band; truth above the band "
                   f"{100 * e['truth_above']:.0f} %, below {100 * e['truth_below']:.0f} %)")
    return "\n".join(out)


def combine(parts: Sequence[Path], path: Path = RESULTS) -> None:
    """Merge the coverage of runs of some cases each (``--xi``, ``--years``, ``--results``) that ran
    side by side into ``path``: the cases in the table's order, the CPU time summed, no wall time
    (the runs overlapped) and ``parts``, the runs merged."""
    merged: dict[str, dict[str, Any]] = {}
    for part in parts:
        for method, res in json.loads(part.read_text(encoding="utf-8")).get("coverage", {}).items():
            m = merged.setdefault(method, {**res, "cases": [], "wall_seconds": None, "cpu_seconds": 0.0,
                                           "parts": 0})
            if m["records_per_case"] != res["records_per_case"]:
                raise SystemExit(f"bench_calibration: {part}: {res['records_per_case']} records a case, "
                                 f"the others {m['records_per_case']}")
            m["cases"] += res["cases"]
            m["cpu_seconds"] += res["cpu_seconds"]
            m["parts"] += 1
    order = {(x, y): k for k, (x, y) in enumerate((c.climate.xi, c.years) for c in cases())}
    for method, m in merged.items():
        m["cases"].sort(key=lambda c: order[(c["xi"], c["years"])])
        write_results("coverage", method, m, path)


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--interval", default=None, help="the interval method (default: ClimateOptions' default)")
    ap.add_argument("--records", type=int, default=300, help="records a case (300)")
    ap.add_argument("--esd-records", type=int, default=100, help="records of the ESD's band (100; 0: none)")
    ap.add_argument("--esd-replicates", type=int, default=50, help="climates a band (50)")
    ap.add_argument("--esd-trials", type=int, default=80, help="lifetimes a climate (80)")
    ap.add_argument("--esd-seconds", type=float, default=None,
                    help="start no ESD record after this many seconds (default: no limit)")
    ap.add_argument("--truth-trials", type=int, default=40000, help="lifetimes of the true ESD (40000)")
    ap.add_argument("--jobs", type=int, default=2, help="processes (2)")
    ap.add_argument("--years", type=float, nargs="+", default=list(YEARS),
                    help="only the cases of these record lengths (10 20 40)")
    ap.add_argument("--xi", type=float, nargs="+", default=None,
                    help="only the cases of these shapes (-0.3 0 0.2 0.4)")
    ap.add_argument("--quick", action="store_true", help="40 records a case, 20 ESD records")
    ap.add_argument("--no-write", action="store_true", help="leave bench/results/calibration.json")
    ap.add_argument("--skip-coverage", action="store_true", help="the ESD's band only")
    ap.add_argument("--results", type=Path, default=RESULTS, help="the results file")
    ap.add_argument("--figure", action="store_true",
                    help="only draw the figure from the results file (beside it, .png and .svg)")
    ap.add_argument("--markdown", action="store_true",
                    help="only print the docs' tables from the results file")
    ap.add_argument("--combine", type=Path, nargs="+", default=None, metavar="FILE",
                    help="only merge the coverage of these results files (runs of some cases) into --results")
    a = ap.parse_args(argv)
    if a.combine:
        combine(a.combine, a.results)
        return 0
    if a.markdown:
        print(markdown(a.results))
        return 0
    if a.figure:
        for p in draw_figure(a.results):
            print(p)
        return 0
    if a.quick:
        a.records, a.esd_records, a.truth_trials = 40, 20, 10000
    method = a.interval or default_method()
    if not a.skip_coverage:
        res = coverage(a.interval, a.records, a.jobs, a.years, a.xi)
        print_coverage(res)
        if not a.no_write and not a.quick:
            write_results("coverage", method, res, a.results)
    if a.esd_records > 0:
        print()
        esd = esd_coverage(a.interval, a.esd_records, a.esd_replicates, a.esd_trials, a.truth_trials, a.jobs,
                           a.esd_seconds)
        print_esd(esd)
        if not a.no_write and not a.quick:
            write_results("esd", method, esd, a.results)
    return 0


if __name__ == "__main__":
    sys.exit(main())
