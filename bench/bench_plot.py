"""Speed of the drawing commands (issue 3).

Measures, each command as a fresh subprocess (what a user waits for):

(a) ``regimemap plot --gamma 3 --kprime 0.4 -o x.png`` against a bare script
    that imports matplotlib (Agg) and saves one line plot, interleaved, median
    of ``repeats`` runs each; target: ratio <= 1.3.  For information, also
    against the same bare script ending with ``gc.freeze()``: the console
    script skips CPython's final garbage collections that way (see
    ``regimemap.cli.console_main``), so this ratio shows regimemap's own work
    (mathtext, ~250 glyphs, the map) without that saving;
(b) whether ``regimemap --help`` imports matplotlib (target: no);
(c) ``regimemap figures --format png,svg`` (25 figures x 2 files, one process per core) into a
    temporary folder; target: <= 3.5 s; also whether two runs are byte-identical.

Python's bytecode cache is kept in a temporary ``PYTHONPYCACHEPREFIX`` and
warmed first, for both sides, as after a normal installation (this sandbox
sets ``PYTHONDONTWRITEBYTECODE``, which would make every run recompile
regimemap's sources but not matplotlib's, whose ``.pyc`` files are installed).
Wall times on a shared machine are noisy; CPU times (user + sys of the child)
are reported too.

Run ``python bench/bench_plot.py`` for a table; :func:`run` returns the numbers.
"""

from __future__ import annotations

import hashlib
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

PLOT_ARGS = ["plot", "--gamma", "3", "--kprime", "0.4", "-o"]
RATIO_TARGET = 1.3
FIGURES_TARGET_S = 3.5

BARE_SCRIPT = """\
import sys
import matplotlib
matplotlib.use("Agg")
from matplotlib.figure import Figure
from matplotlib.backends.backend_agg import FigureCanvasAgg
fig = Figure()
FigureCanvasAgg(fig)
ax = fig.add_subplot()
ax.plot([0, 1, 2], [0, 1, 4])
fig.savefig(sys.argv[1])
"""

#: The bare script, skipping the final collections as the console script does.
BARE_FROZEN_SCRIPT = BARE_SCRIPT + "import gc\ngc.freeze()\n"

HELP_PROBE = """\
import sys
from regimemap.cli import main
try:
    main(["--help"])
except SystemExit:
    pass
print("MPL", any(m == "matplotlib" or m.startswith("matplotlib.") for m in sys.modules),
      file=sys.stderr)
"""


def _regimemap_cmd() -> list[str]:
    exe = Path(sys.executable).with_name("regimemap")
    if exe.exists():
        return [str(exe)]
    found = shutil.which("regimemap")
    if found:
        return [found]
    return [sys.executable, "-c", "from regimemap.cli import main; main()"]


def _timed(cmd: list[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    """Wall and CPU (user + sys) seconds of one subprocess; raise if it fails."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}): {proc.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def _digest(folder: Path) -> str:
    h = hashlib.sha256()
    for f in sorted(folder.iterdir()):
        h.update(f.name.encode())
        h.update(f.read_bytes())
    return h.hexdigest()


def run(repeats: int = 7, figures_repeats: int = 2, cache_bytecode: bool = True) -> dict[str, Any]:
    """Run the three measurements; return a dict of numbers and verdicts.

    Parameters
    ----------
    repeats : int
        Runs of each side of (a) (interleaved); the medians are compared.
    figures_repeats : int
        Runs of (c); the fastest is reported (and the outputs compared).
    cache_bytecode : bool
        Keep bytecode in a temporary PYTHONPYCACHEPREFIX (see the module docstring).
    """
    rm = _regimemap_cmd()
    with tempfile.TemporaryDirectory(prefix="regimemap-bench-") as tmp:
        tmpd = Path(tmp)
        env = dict(os.environ)
        if cache_bytecode:
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            env["PYTHONPYCACHEPREFIX"] = str(tmpd / "pycache")
        bare = tmpd / "bare.py"
        bare.write_text(BARE_SCRIPT)
        frozen = tmpd / "bare_frozen.py"
        frozen.write_text(BARE_FROZEN_SCRIPT)
        plot_cmd = rm + PLOT_ARGS + [str(tmpd / "x.png")]
        bare_cmd = [sys.executable, str(bare), str(tmpd / "y.png")]
        frozen_cmd = [sys.executable, str(frozen), str(tmpd / "z.png")]
        # warm-up: bytecode cache, font cache, file system cache
        _timed(plot_cmd, env, tmp)
        _timed(bare_cmd, env, tmp)
        _timed(frozen_cmd, env, tmp)
        plot_w, plot_c, bare_w, bare_c, frozen_w = [], [], [], [], []
        for _ in range(repeats):
            w, c = _timed(plot_cmd, env, tmp)
            plot_w.append(w)
            plot_c.append(c)
            w, c = _timed(bare_cmd, env, tmp)
            bare_w.append(w)
            bare_c.append(c)
            frozen_w.append(_timed(frozen_cmd, env, tmp)[0])
        pm, bm = statistics.median(plot_w), statistics.median(bare_w)
        pc, bc = statistics.median(plot_c), statistics.median(bare_c)
        fm = statistics.median(frozen_w)

        # (b) does --help import matplotlib?
        probe = subprocess.run([sys.executable, "-c", HELP_PROBE], env=env, cwd=tmp,
                               capture_output=True, text=True)
        imports_mpl = "MPL True" in probe.stderr
        help_w, _ = _timed(rm + ["--help"], env, tmp)

        # (c) all figures, png + svg
        fig_times, digests, n_files = [], [], 0
        for i in range(figures_repeats):
            out = tmpd / f"figs{i}"
            out.mkdir()
            w, _ = _timed(rm + ["figures", "--out", str(out), "--format", "png,svg"], env, tmp)
            fig_times.append(w)
            n_files = len(list(out.iterdir()))
            digests.append(_digest(out))

    return {
        "repeats": repeats,
        "bytecode_cached": cache_bytecode,
        "plot_wall_median_s": pm,
        "bare_wall_median_s": bm,
        "ratio_wall": pm / bm,
        "plot_cpu_median_s": pc,
        "bare_cpu_median_s": bc,
        "ratio_cpu": pc / bc,
        "ratio_target": RATIO_TARGET,
        "ratio_ok": pm / bm <= RATIO_TARGET,
        "bare_frozen_wall_median_s": fm,
        "ratio_wall_vs_frozen_bare": pm / fm,
        "plot_wall_s": plot_w,
        "bare_wall_s": bare_w,
        "help_imports_matplotlib": imports_mpl,
        "help_wall_s": help_w,
        "figures_files": n_files,
        "figures_wall_s": min(fig_times),
        "figures_wall_all_s": fig_times,
        "figures_target_s": FIGURES_TARGET_S,
        "figures_ok": min(fig_times) <= FIGURES_TARGET_S and n_files == 50,
        "figures_identical": len(set(digests)) == 1,
        "load_average": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
    }


def _table(r: dict[str, Any]) -> str:
    ok = lambda b: "ok" if b else "FAIL"  # noqa: E731
    rows = [
        ("(a) plot -o x.png, median wall", f"{r['plot_wall_median_s']:.3f} s", ""),
        ("    bare matplotlib script, median wall", f"{r['bare_wall_median_s']:.3f} s", ""),
        ("    ratio (wall)", f"{r['ratio_wall']:.2f}",
         f"<= {r['ratio_target']}  {ok(r['ratio_ok'])}"),
        ("    ratio (CPU user+sys)", f"{r['ratio_cpu']:.2f}",
         f"({r['plot_cpu_median_s']:.3f} / {r['bare_cpu_median_s']:.3f} s)"),
        ("    bare script + gc.freeze() at exit, median wall",
         f"{r['bare_frozen_wall_median_s']:.3f} s", ""),
        ("    ratio to it (wall; information)", f"{r['ratio_wall_vs_frozen_bare']:.2f}",
         "regimemap's own work, without the exit saving"),
        ("(b) regimemap --help imports matplotlib", str(r["help_imports_matplotlib"]),
         f"must be False  {ok(not r['help_imports_matplotlib'])}"),
        ("    regimemap --help, wall", f"{r['help_wall_s']:.3f} s", ""),
        (f"(c) figures --format png,svg ({r['figures_files']} files, {os.cpu_count()} cores)",
         f"{r['figures_wall_s']:.2f} s",
         f"<= {r['figures_target_s']:g} s  {ok(r['figures_ok'])}"),
        ("    byte-identical between runs", str(r["figures_identical"]), ""),
        ("load average (1 min)", f"{r['load_average']:.2f}" if r["load_average"] is not None
         else "n/a", f"{os.cpu_count()} CPUs"),
    ]
    w0 = max(len(a) for a, _, _ in rows)
    w1 = max(len(b) for _, b, _ in rows)
    lines = [f"{a:<{w0}}  {b:>{w1}}  {c}".rstrip() for a, b, c in rows]
    lines.append(f"runs (wall, s): plot {', '.join(f'{x:.2f}' for x in r['plot_wall_s'])}; "
                 f"bare {', '.join(f'{x:.2f}' for x in r['bare_wall_s'])}; "
                 f"figures {', '.join(f'{x:.2f}' for x in r['figures_wall_all_s'])}")
    return "\n".join(lines)


def main() -> int:
    result = run()
    print(_table(result))
    good = result["ratio_ok"] and not result["help_imports_matplotlib"] and result["figures_ok"]
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
