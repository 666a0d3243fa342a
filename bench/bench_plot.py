"""Speed of the drawing commands (issues 3 and 19).

Measures, each command as a fresh subprocess (what a user waits for):

(a) ``regimemap plot --gamma 3 --kprime 0.4 -o x.png`` against the *floor*: a bare
    matplotlib script (Figure + Agg canvas, no pyplot) that draws the same map without
    regimemap -- the same region polygons with their colours and hatches, the same
    boundary and construction lines, the axis labels and the (mathtext) title, in a
    figure of the same size and resolution, saved as PNG.  The polygons and lines are
    computed by regimemap once, before timing, and read by the script from an ``.npz``
    file, so the floor is what any script drawing this map must pay (importing
    matplotlib, laying out the text, rasterising the fills, writing the PNG).  Interleaved
    runs; the median of the pairwise ratios; target: plot / floor <= 1.15 (wall).
    For information: against the floor ending with ``gc.freeze()`` (the console script
    skips CPython's final garbage collections that way, see
    ``regimemap.cli.console_main``: this ratio is regimemap's own work -- click, the
    map's computation, the point names, labels and key, the tidy pass -- without that
    saving), and against the old reference, a bare script saving ONE line plot
    (issue 3's target: <= 1.3);
(b) whether ``regimemap --help`` imports matplotlib (target: no);
(c) ``regimemap figures --format png,svg --set all`` (the report's 25 figures and the
    worked figures W.1-W.4, x 2 files, one process per core, as ``make figures`` runs
    it) into a temporary folder; target: <= 5 s; also whether two runs are
    byte-identical.

Python's bytecode cache is kept in a temporary ``PYTHONPYCACHEPREFIX`` and
warmed first, for every side, as after a normal installation (this sandbox
sets ``PYTHONDONTWRITEBYTECODE``, which would make every run recompile
regimemap's sources but not matplotlib's, whose ``.pyc`` files are installed).
Wall times on a shared machine are noisy; CPU times (user + sys of the child)
are reported too.

Run ``python bench/bench_plot.py`` for a table; :func:`run` returns the numbers.
"""

from __future__ import annotations

import hashlib
import json
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
#: The map of (a): its gamma and k' (as PLOT_ARGS), the samples of ``plot``'s default.
GAMMA, KPRIME, SAMPLES = 3.0, 0.4, 801
RATIO_TARGET = 1.15
#: Issue 3's target against the one-line-plot script (kept for information).
ONE_LINE_TARGET = 1.3
FIGURES_TARGET_S = 5.0
FIGURES_ARGS = ["figures", "--format", "png,svg", "--set", "all", "--quiet"]

#: The floor: the same map drawn by a bare matplotlib script from the exported polygons.
FLOOR_SCRIPT = """\
import json
import sys

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

data = np.load(sys.argv[1])
meta = json.loads(str(data["meta"]))
fig = Figure(figsize=meta["size"], dpi=meta["dpi"])
FigureCanvasAgg(fig)
ax = fig.add_axes(meta["rect"])
for key, color, hatch in meta["polygons"]:
    patch = Polygon(data[key], closed=True, facecolor=color, edgecolor="none", hatch=hatch,
                    hatchcolor=(0.0, 0.0, 0.0, 0.35))
    patch.set_hatch_linewidth(0.45)
    ax.add_patch(patch)
for key, style in meta["lines"]:
    pts = data[key]
    ax.add_line(Line2D(pts[:, 0], pts[:, 1], **style))
ax.set_xlim(0.0, meta["k_max"])
ax.set_ylim(0.0, meta["mu_max"])
ax.set_xlabel("$k$", fontsize=12)
ax.set_ylabel(r"$\\mu$", fontsize=12, rotation=0)
ax.set_title(meta["title"], fontsize=9.5, loc="left")
fig.savefig(sys.argv[2], dpi=meta["dpi"])
"""

#: The floor, skipping the final collections as the console script does.
FLOOR_FROZEN_SCRIPT = FLOOR_SCRIPT + "import gc\ngc.freeze()\n"

#: Issue 3's reference: a bare script saving one line plot.
ONE_LINE_SCRIPT = """\
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


def export_floor(path: Path) -> dict[str, Any]:
    """Write the polygons and lines of the map of (a), as ``plot`` draws them, to ``path``.

    Run once before timing: the floor script reads them (``numpy.load``), so that it
    draws the same map without computing it.  Returns the metadata written.
    """
    import numpy as np

    from regimemap import Parameters
    from regimemap.drawing.maps.figure import map_figure
    from regimemap.drawing.save import DEFAULT_DPI
    from regimemap.drawing.style import CONSTRUCTION, DOTTED, LINE_LW, MODE_STYLE
    from regimemap.workflows.map import run_map

    fig, ax, art = map_figure(run_map(Parameters(GAMMA, KPRIME), samples=SAMPLES), dpi=DEFAULT_DPI)
    data = art.data
    arrays: dict[str, Any] = {}
    polygons, lines = [], []
    for mode in data.modes:
        st = MODE_STYLE[mode]
        for poly in data.polygons.get(mode, []):
            if len(poly) >= 3:
                key = f"polygon{len(polygons)}"
                arrays[key] = np.asarray(poly, dtype=np.float64)
                polygons.append([key, st.color, st.hatch])
    for cd in data.curves.values():
        for pts, is_boundary in cd.runs():
            if cd.dotted:
                style = dict(DOTTED)
            elif is_boundary:
                style = {"color": "black", "linewidth": LINE_LW}
            else:
                style = dict(CONSTRUCTION)
            key = f"line{len(lines)}"
            arrays[key] = np.asarray(pts, dtype=np.float64)
            lines.append([key, {k: list(v) if isinstance(v, tuple) else v
                                for k, v in style.items()}])
    meta = {"size": [float(v) for v in fig.get_size_inches()],
            "rect": [float(v) for v in ax.get_position().bounds], "dpi": float(DEFAULT_DPI),
            "k_max": float(data.k_max), "mu_max": float(data.mu_max),
            "title": art.title.get_text() if art.title is not None else "",
            "polygons": polygons, "lines": lines}
    np.savez(path, meta=np.array(json.dumps(meta)), **arrays)
    return meta


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


def _ratio(a: list[float], b: list[float]) -> float:
    """The median of the pairwise ratios a[i] / b[i] (runs taken in turn)."""
    return statistics.median(x / y for x, y in zip(a, b))


def _interleaved(cmds: dict[str, list[str]], env: dict[str, str], cwd: str, repeats: int
                 ) -> dict[str, dict[str, list[float]]]:
    """Wall and CPU seconds of each command, run in turn ``repeats`` times after a warm-up."""
    for cmd in cmds.values():  # warm-up: bytecode cache, font cache, file system cache
        _timed(cmd, env, cwd)
    out: dict[str, dict[str, list[float]]] = {k: {"wall": [], "cpu": []} for k in cmds}
    for _ in range(repeats):
        for name, cmd in cmds.items():
            w, c = _timed(cmd, env, cwd)
            out[name]["wall"].append(w)
            out[name]["cpu"].append(c)
    return out


def run(repeats: int = 7, figures_repeats: int = 2, cache_bytecode: bool = True) -> dict[str, Any]:
    """Run the three measurements; return a dict of numbers and verdicts.

    Parameters
    ----------
    repeats : int
        Runs of each command of (a), in turn; the medians and the medians of the
        pairwise ratios are reported.
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
        export_floor(tmpd / "map.npz")
        scripts = {"floor": FLOOR_SCRIPT, "floor_frozen": FLOOR_FROZEN_SCRIPT,
                   "one_line": ONE_LINE_SCRIPT}
        for name, text in scripts.items():
            (tmpd / f"{name}.py").write_text(text)
        cmds = {"plot": rm + PLOT_ARGS + [str(tmpd / "plot.png")]}
        for name in scripts:
            cmds[name] = [sys.executable, str(tmpd / f"{name}.py")]
            if name.startswith("floor"):
                cmds[name].append(str(tmpd / "map.npz"))
            cmds[name].append(str(tmpd / f"{name}.png"))
        t = _interleaved(cmds, env, tmp, repeats)
        med = {name: {k: statistics.median(v) for k, v in d.items()} for name, d in t.items()}

        # (b) does --help import matplotlib?
        probe = subprocess.run([sys.executable, "-c", HELP_PROBE], env=env, cwd=tmp,
                               capture_output=True, text=True)
        imports_mpl = "MPL True" in probe.stderr
        help_w, _ = _timed(rm + ["--help"], env, tmp)

        # (c) all figures, png + svg
        fig_times, fig_cpu, digests, n_files = [], [], [], 0
        for i in range(figures_repeats):
            out = tmpd / f"figs{i}"
            out.mkdir()
            w, c = _timed(rm + FIGURES_ARGS + ["--out", str(out)], env, tmp)
            fig_times.append(w)
            fig_cpu.append(c)
            n_files = len(list(out.iterdir()))
            digests.append(_digest(out))

    ratio_wall = _ratio(t["plot"]["wall"], t["floor"]["wall"])
    one_line = _ratio(t["plot"]["wall"], t["one_line"]["wall"])
    return {
        "repeats": repeats,
        "bytecode_cached": cache_bytecode,
        "plot_wall_median_s": med["plot"]["wall"],
        "plot_cpu_median_s": med["plot"]["cpu"],
        "floor_wall_median_s": med["floor"]["wall"],
        "floor_cpu_median_s": med["floor"]["cpu"],
        "ratio_wall": ratio_wall,
        "ratio_cpu": _ratio(t["plot"]["cpu"], t["floor"]["cpu"]),
        "ratio_target": RATIO_TARGET,
        "ratio_ok": ratio_wall <= RATIO_TARGET,
        "floor_frozen_wall_median_s": med["floor_frozen"]["wall"],
        "ratio_wall_vs_frozen_floor": _ratio(t["plot"]["wall"], t["floor_frozen"]["wall"]),
        "ratio_cpu_vs_frozen_floor": _ratio(t["plot"]["cpu"], t["floor_frozen"]["cpu"]),
        "one_line_wall_median_s": med["one_line"]["wall"],
        "ratio_wall_vs_one_line": one_line,
        "ratio_cpu_vs_one_line": _ratio(t["plot"]["cpu"], t["one_line"]["cpu"]),
        "one_line_target": ONE_LINE_TARGET,
        "plot_wall_s": t["plot"]["wall"],
        "floor_wall_s": t["floor"]["wall"],
        "help_imports_matplotlib": imports_mpl,
        "help_wall_s": help_w,
        "figures_files": n_files,
        "figures_wall_s": min(fig_times),
        "figures_cpu_s": min(fig_cpu),
        "figures_wall_all_s": fig_times,
        "figures_target_s": FIGURES_TARGET_S,
        "figures_ok": min(fig_times) <= FIGURES_TARGET_S and n_files > 0 and n_files % 2 == 0,
        "figures_identical": len(set(digests)) == 1,
        "load_average": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
    }


def _table(r: dict[str, Any]) -> str:
    ok = lambda b: "ok" if b else "FAIL"  # noqa: E731
    rows = [
        ("(a) plot -o x.png, median wall (CPU)",
         f"{r['plot_wall_median_s']:.3f} s", f"({r['plot_cpu_median_s']:.3f} s CPU)"),
        ("    floor: bare script drawing the same map, median wall (CPU)",
         f"{r['floor_wall_median_s']:.3f} s", f"({r['floor_cpu_median_s']:.3f} s CPU)"),
        ("    plot / floor (wall)", f"{r['ratio_wall']:.2f}",
         f"<= {r['ratio_target']}  {ok(r['ratio_ok'])}"),
        ("    plot / floor (CPU user+sys)", f"{r['ratio_cpu']:.2f}", ""),
        ("    plot / floor + gc.freeze() at exit (wall, CPU; information)",
         f"{r['ratio_wall_vs_frozen_floor']:.2f}",
         f"{r['ratio_cpu_vs_frozen_floor']:.2f} CPU: regimemap's own work, without the exit saving"),
        ("    plot / one-line-plot script (wall, CPU; information)",
         f"{r['ratio_wall_vs_one_line']:.2f}",
         f"{r['ratio_cpu_vs_one_line']:.2f} CPU (issue 3: <= {r['one_line_target']})"),
        ("(b) regimemap --help imports matplotlib", str(r["help_imports_matplotlib"]),
         f"must be False  {ok(not r['help_imports_matplotlib'])}"),
        ("    regimemap --help, wall", f"{r['help_wall_s']:.3f} s", ""),
        (f"(c) figures --set all --format png,svg ({r['figures_files']} files, "
         f"{os.cpu_count()} cores)", f"{r['figures_wall_s']:.2f} s",
         f"<= {r['figures_target_s']:g} s  {ok(r['figures_ok'])}  "
         f"({r['figures_cpu_s']:.2f} s CPU)"),
        ("    byte-identical between runs", str(r["figures_identical"]), ""),
        ("load average (1 min)", f"{r['load_average']:.2f}" if r["load_average"] is not None
         else "n/a", f"{os.cpu_count()} CPUs"),
    ]
    w0 = max(len(a) for a, _, _ in rows)
    w1 = max(len(b) for _, b, _ in rows)
    lines = [f"{a:<{w0}}  {b:>{w1}}  {c}".rstrip() for a, b, c in rows]
    lines.append(f"runs (wall, s): plot {', '.join(f'{x:.2f}' for x in r['plot_wall_s'])}; "
                 f"floor {', '.join(f'{x:.2f}' for x in r['floor_wall_s'])}; "
                 f"figures {', '.join(f'{x:.2f}' for x in r['figures_wall_all_s'])}")
    return "\n".join(lines)


def main() -> int:
    result = run()
    print(_table(result))
    good = result["ratio_ok"] and not result["help_imports_matplotlib"] and result["figures_ok"]
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
