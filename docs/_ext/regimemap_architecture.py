"""The architecture page's picture, drawn from the code when the pages are built.

The packages of ``src/regimemap`` as boxes, one row per layer (the ``LAYER``
table of ``tests/test_layers.py``, which the tests enforce), the workflow
records (the subclasses of :class:`regimemap.workflows.Record` among the
package's names) inside the ``workflows`` box, and an arrow from a package to
every package it imports (read from the source as the layer tests read it:
imports inside functions count, ``if TYPE_CHECKING:`` imports do not).  The
arrows of the command line, the workflows and the drawing are coloured (who
calls whom); the imports among the packages below them are grey.

Written to ``docs/_generated/architecture.svg`` (``docs/guide/architecture.md``
shows it) at ``builder-inited``, rewritten only when its bytes change: text as
SVG text, no date, a fixed hash salt, so the same code gives the same file.
Colours: Okabe and Ito's colour-blind-safe palette.
"""

from __future__ import annotations

import ast
import io
import textwrap
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

#: Where the picture goes, relative to the documentation's source folder.
TARGET = Path("_generated") / "architecture.svg"

#: Okabe-Ito colours: the arrows of the three callers, and the boxes' fill by role.
CALLER_COLOURS = {"cli": "#D55E00", "workflows": "#0072B2", "drawing": "#009E73"}
OTHER_ARROW = "#999999"
BOX_FILL = {"cli": "#FBE3D6", "workflows": "#D6E6F4", "drawing": "#D9F0E8"}
DEFAULT_FILL = "#F2F2F2"

#: Left-to-right order of the packages that share a layer.
ROW_ORDER = ("dynamics", "maps", "lifetime", "climate")


def read_layers(test_file: Path) -> dict[str, float]:
    """The ``LAYER`` dict literal of ``tests/test_layers.py``."""
    for node in ast.parse(test_file.read_text(encoding="utf-8")).body:
        if not isinstance(node, (ast.Assign, ast.AnnAssign)) or node.value is None:
            continue
        targets = [node.target] if isinstance(node, ast.AnnAssign) else node.targets
        if any(isinstance(t, ast.Name) and t.id == "LAYER" for t in targets):
            return dict(ast.literal_eval(node.value))
    raise ValueError(f"{test_file}: no LAYER table")


def package_imports(src: Path, packages: set[str]) -> set[tuple[str, str]]:
    """(importer, imported) between the packages of ``src`` (``src/regimemap``), read from the source."""
    edges: set[tuple[str, str]] = set()
    for path in sorted(src.rglob("*.py")):
        parts = list(path.relative_to(src.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        base = parts if path.name == "__init__.py" else parts[:-1]
        if len(parts) < 2 or parts[1] not in packages:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        typing_only = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If)
                       and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"
                       for n in ast.walk(node)}
        for node in ast.walk(tree):
            if id(node) in typing_only:
                continue
            if isinstance(node, ast.Import):
                names = [alias.name.split(".") for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [(base[: len(base) - node.level + 1] if node.level else [])
                         + (node.module.split(".") if node.module else [])]
            else:
                continue
            for name in names:
                if len(name) >= 2 and name[0] == "regimemap" and name[1] in packages and name[1] != parts[1]:
                    edges.add((parts[1], name[1]))
    return edges


def workflow_records() -> list[str]:
    """The record classes among :mod:`regimemap.workflows`' names, sorted."""
    import regimemap.workflows as workflows

    record = workflows.Record
    return sorted(name for name in workflows.__all__
                  if isinstance(getattr(workflows, name), type)
                  and issubclass(getattr(workflows, name), record) and getattr(workflows, name) is not record)


def _positions(layers: dict[str, float]) -> dict[str, tuple[float, float]]:
    """Box centres: one row per layer, the bottom layer lowest; a row's boxes side by side."""
    rows: dict[float, list[str]] = {}
    for name, layer in layers.items():
        rows.setdefault(layer, []).append(name)
    out = {}
    for y, layer in enumerate(sorted(rows)):
        names = sorted(rows[layer], key=lambda n: (ROW_ORDER.index(n) if n in ROW_ORDER else -1, n))
        for i, name in enumerate(names):
            out[name] = ((i - (len(names) - 1) / 2) * 2.6, ROW_HEIGHT * y)
    return out


#: Vertical distance between two layers' rows, and a box's half width and half height.
ROW_HEIGHT, HALF_W, HALF_H = 1.5, 0.95, 0.3
#: The arrows stay within |x| < XMAX: the layers' names are to the left of it, the legend
#: and the records to the right.
XMAX = 5.0


def _hits(points: Any, box: tuple[float, float, float, float], pad: float = 0.1) -> bool:
    """Whether any of the points falls in the rectangle (x0, x1, y0, y1), widened by ``pad``."""
    x0, x1, y0, y1 = box
    return bool(((points[:, 0] > x0 - pad) & (points[:, 0] < x1 + pad)
                 & (points[:, 1] > y0 - pad) & (points[:, 1] < y1 + pad)).any())


def _route(start: tuple[float, float], end: tuple[float, float],
           others: list[tuple[float, float, float, float]]) -> tuple[float, float]:
    """The control point of a quadratic curve from start to end that passes no other box.

    The straight line when it is clear, else the least bent curve that is,
    trying either side in turn; when none is, the curve through the fewest.
    """
    import numpy as np

    (x0, y0), (x1, y1) = start, end
    mid, normal = np.array([(x0 + x1) / 2, (y0 + y1) / 2]), np.array([y1 - y0, x0 - x1])
    t = np.linspace(0.03, 0.97, 60)[:, None]
    best: tuple[int, float, float] = (10**6, float(mid[0]), float(mid[1]))
    for step in range(1, 40):
        rad = (step // 2) * 0.06 * (1 if step % 2 else -1)
        control = mid + rad * normal
        curve = (1 - t) ** 2 * np.array(start) + 2 * t * (1 - t) * control + t ** 2 * np.array(end)
        if (abs(curve[:, 0]) >= XMAX).any():
            continue
        hits = sum(_hits(curve, box) for box in others)
        if hits == 0:
            return float(control[0]), float(control[1])
        best = min(best, (hits, float(control[0]), float(control[1])))
    return best[1], best[2]


def draw(layers: dict[str, float], edges: set[tuple[str, str]], records: list[str]) -> Any:
    """The picture as a matplotlib Figure (no pyplot)."""
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyArrowPatch, FancyBboxPatch
    from matplotlib.path import Path as MplPath

    pos = _positions(layers)
    fig = Figure(figsize=(9.6, 0.95 * len({*layers.values()}) + 0.5), dpi=100)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_axis_off()
    ys = [y for _, y in pos.values()]
    ax.set_xlim(-6.2, 8.2)
    ax.set_ylim(min(ys) - 0.6, max(ys) + 0.55)
    for layer, y in sorted({(layers[n], pos[n][1]) for n in pos}):
        ax.text(-6.0, y, f"layer {layer:g}", ha="left", va="center", fontsize=9, color="#555555")
    boxes = {n: (x - HALF_W, x + HALF_W, y - HALF_H, y + HALF_H) for n, (x, y) in pos.items()}
    if "workflows" in pos:   # the records, beside the package that returns them
        x, y = pos["workflows"]
        lines = textwrap.wrap(", ".join(records), 26) if records else ["(none)"]
        ax.plot([x + HALF_W, XMAX + 0.3], [y, y], color="#0072B2", linestyle="--", linewidth=0.8, zorder=1)
        ax.text(XMAX + 0.4, y, "returns the records\n" + "\n".join(lines), ha="left", va="center",
                fontsize=8.5, linespacing=1.3, color="#0072B2", zorder=4,
                bbox={"boxstyle": "round,pad=0.35", "facecolor": "white", "edgecolor": "#0072B2",
                      "linestyle": "--", "linewidth": 0.8})
    for a, b in sorted(edges, key=lambda e: (e[0] in CALLER_COLOURS, e)):
        (xa, ya), (xb, yb) = pos[a], pos[b]
        if abs(ya - yb) < 1e-9:   # side by side
            side = 1 if xb > xa else -1
            start, end = (xa + side * HALF_W, ya), (xb - side * HALF_W, yb)
        else:
            down = 1 if ya > yb else -1
            lean = max(-0.75, min(0.75, 0.3 * (xb - xa)))
            start, end = (xa + lean * HALF_W, ya - down * HALF_H), (xb - lean * HALF_W, yb + down * HALF_H)
        control = _route(start, end, [boxes[n] for n in pos if n not in (a, b)])
        caller = a in CALLER_COLOURS
        path = MplPath([start, control, end], [MplPath.MOVETO, MplPath.CURVE3, MplPath.CURVE3])
        ax.add_patch(FancyArrowPatch(path=path, arrowstyle="-|>", mutation_scale=11 if caller else 8,
                                     linewidth=1.5 if caller else 0.8, shrinkA=0, shrinkB=0,
                                     color=CALLER_COLOURS.get(a, OTHER_ARROW), zorder=2 if caller else 1))
    for name, (x, y) in pos.items():
        ax.add_patch(FancyBboxPatch((x - HALF_W, y - HALF_H), 2 * HALF_W, 2 * HALF_H,
                                    boxstyle="round,pad=0,rounding_size=0.1",
                                    facecolor=BOX_FILL.get(name, DEFAULT_FILL),
                                    edgecolor=CALLER_COLOURS.get(name, "#333333"), linewidth=1.2, zorder=3))
        ax.text(x, y, f"{name}/", ha="center", va="center", fontsize=11, fontweight="bold", zorder=4)
    legend = [("cli imports", "cli"), ("workflows imports", "workflows"), ("drawing imports", "drawing")]
    top = max(ys) + 0.3
    for i, (text, name) in enumerate(legend + [("other imports", "")]):
        y = top - 0.3 * i
        ax.plot([XMAX + 0.4, XMAX + 0.9], [y, y], color=CALLER_COLOURS.get(name, OTHER_ARROW),
                linewidth=1.5 if name else 0.8)
        ax.text(XMAX + 1.0, y, text, ha="left", va="center", fontsize=8.5)
    return fig


def svg_bytes(fig: Any) -> bytes:
    """The Figure as SVG, the same bytes for the same picture (text as text, no date, fixed ids)."""
    import matplotlib

    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "regimemap-architecture"}):
        out = io.BytesIO()
        fig.savefig(out, format="svg", metadata={"Date": None, "Creator": None})
    return out.getvalue()


def write_picture(app: Sphinx) -> None:
    """``builder-inited``: draw the picture from the code and write it where its bytes changed."""
    root = Path(app.srcdir).parent
    layers = read_layers(root / "tests" / "test_layers.py")
    edges = package_imports(root / "src" / "regimemap", set(layers))
    data = svg_bytes(draw(layers, edges, workflow_records()))
    target = Path(app.srcdir) / TARGET
    target.parent.mkdir(exist_ok=True)
    if not target.is_file() or target.read_bytes() != data:
        target.write_bytes(data)


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("builder-inited", write_picture)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
