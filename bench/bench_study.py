"""Benchmark of ``regimemap study``: a whole breakwater on one and two workers, and with climate replicates.

Standalone script (not a test): ``.venv/bin/python bench/bench_study.py [--quick]``.

* 20 sections (chainage 0 to 950 m, depth 8 to 18 m, one width each) x 3 scenarios (today,
  a 1 m sea-level rise by year 50, the rise with 5 % higher and 20 % more storms) x 1000
  lifetimes of 50 years: 60 tasks, on one worker (this process) and on two worker processes
  (``jobs=2``); the speed-up and the mean time per task;
* the same breakwater's first 4 sections x 3 scenarios under the 44007 record's climate and
  10 bootstrap climates (``climate_replicates = 10``): 132 tasks on two workers (skipped
  without the shared data beside the clone);
* the CPU time per task (user + system, of the process and its workers): on a shared machine
  the wall clock depends on the other work, the CPU time much less;
* memory: each run in a fresh Python process, which reports ``resource.getrusage``'s peak
  resident size of itself (``RUSAGE_SELF``) and of the largest of its worker processes
  (``RUSAGE_CHILDREN``, the maximum over the children it waited for): the peak of the run
  alone, not of the runs before it.

``--quick`` runs 200 lifetimes a task and 3 replicates (a check that the script works).
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: The record of the replicates' run: the shared data beside the clone (not in the repository).
RECORD = Path(__file__).resolve().parents[2] / "shared" / "data" / "ndbc44007_1996-2005_hs_tz.txt"

SCENARIOS = """
[[scenario]]
name = "today"

[[scenario]]
name = "rise 1 m"
sea_level_rise = { 50 = 1.0 }

[[scenario]]
name = "rise 1 m, storms +5 %, +20 %"
sea_level_rise = { 50 = 1.0 }
wave_height_factor = { 50 = 1.05 }
storm_rate_factor = { 50 = 1.2 }
"""


def study_text(sections: int, trials: int, replicates: int = 0) -> str:
    """The example study's base design with ``sections`` sections (8 to 18 m of water) and three
    scenarios; with ``replicates``, the 44007 record's climate and that many bootstrap climates."""
    from regimemap.io.study_example import example_study_text

    text = example_study_text()
    base = text[:text.index("\n[[section]]\n")]
    base = base.replace("trials = 2000 ", f"trials = {trials} ")
    if replicates:
        for key in ("distribution = ", "shape = 2.0", "H0_10 = ", "H0_50 = "):
            base = base.replace(f"\n{key}", f"\n# {key}")
        record = f"record = {{ path = {str(RECORD)!r}, threshold = \"99.5%\" }}"
        base = base.replace("# record = { path", f"{record}\n# record = {{ path")
        base = base.replace("# climate_replicates = 200", f"climate_replicates = {replicates}")
    out = [base]
    for i in range(sections):
        depth = 8.0 + 10.0 * i / max(1, sections - 1)
        out.append(f"[[section]]\nname = \"S{i + 1:02d}\"\nchainage = {50.0 * i:g}\ndepth = {depth:.3f}\n"
                   f"armour_depth = {0.6 * depth:.3f}\nbase_depth = {0.7 * depth:.3f}\n"
                   f"widths = [{15.0 + 1.8 * (depth - 8.0):.2f}]\n")
    return "\n".join(out) + SCENARIOS


def _peak_mb() -> tuple[float, float]:
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
    return own, children


def _cpu() -> float:
    """CPU seconds (user + system) of this process and of its finished children so far."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def run_one(sections: int, trials: int, replicates: int, jobs: int) -> dict[str, float]:
    """One study in this process (called in a fresh process by :func:`measure`)."""
    from regimemap.workflows import run_study

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.toml"
        path.write_text(study_text(sections, trials, replicates), encoding="utf-8")
        t0, c0 = time.perf_counter(), _cpu()
        record = run_study(path, jobs=jobs, store=Path(tmp) / "store")
        wall, cpu = time.perf_counter() - t0, _cpu() - c0
    own, children = _peak_mb()
    tasks = sections * 3 * (1 + replicates)
    esd = [r.expected_sliding for r in record.rows]
    return {"wall": wall, "cpu": cpu, "tasks": tasks, "own_mb": own, "children_mb": children,
            "esd_max": max(esd), "rows": len(record.rows)}


def measure(sections: int, trials: int, replicates: int, jobs: int) -> dict[str, float]:
    """:func:`run_one` in a fresh Python process (its own peak memory), its result."""
    out = subprocess.run([sys.executable, __file__, "--one", str(sections), str(trials), str(replicates),
                          str(jobs)], check=True, capture_output=True, text=True, env=os.environ.copy())
    result: dict[str, float] = json.loads(out.stdout.strip().splitlines()[-1])
    return result


def _line(what: str, r: dict[str, float]) -> str:
    return (f"{what:52s} {r['wall']:8.1f} s   {r['cpu'] / r['tasks']:6.2f} CPU s/task   "
            f"peak {r['own_mb']:4.0f} MB (this process), {r['children_mb']:4.0f} MB (largest worker)")


def main(quick: bool = False) -> None:
    trials = 200 if quick else 1000
    reps = 3 if quick else 10
    load = os.getloadavg()[0]
    print(f"study: 20 sections x 3 scenarios x {trials} lifetimes (60 tasks, one width each); "
          f"load average {load:.1f} on {os.cpu_count()} cores at the start")
    one = measure(20, trials, 0, 1)
    print(_line("study, 60 tasks, one worker (this process)", one))
    two = measure(20, trials, 0, 2)
    print(_line("study, 60 tasks, two worker processes", two))
    print(f"{'speed-up 1 -> 2 workers':52s} {one['wall'] / two['wall']:8.2f} x")
    if not RECORD.is_file():
        print(f"study with climate replicates: skipped ({RECORD} not found)")
        return
    rep = measure(4, trials, reps, 2)
    print(_line(f"study, 4 x 3 x (1 + {reps} climates) = {int(rep['tasks'])} tasks, two workers", rep))


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--one":
        s, t, r, j = (int(a) for a in sys.argv[2:6])
        print(json.dumps(run_one(s, t, r, j)))
    else:
        main("--quick" in sys.argv[1:])
