"""The architecture page's picture, drawn from the code when the pages are built.

The house as ``tests/test_layers.py`` declares and enforces it: one column per product (its
``PRODUCTS``), one row per role (its ``ROLE`` table, and the computation at ``COMPUTE``), each
cell listing the product's modules of that role, read from ``src/regimemap``; the shared
packages (its ``LAYER`` table: the physics core, io, the index of the runs, drawing, the
command line; and its ``RUNTIME``, the process's own modules) as bands across the columns at
their layers.  Under each product's name, the products it imports (read from the source as the
layer tests read it: imports inside functions count, ``if TYPE_CHECKING:`` imports do not).
Imports point down the picture only.

Written to ``docs/_generated/architecture.svg`` (``docs/guide/architecture.md`` shows it) at
``builder-inited``, rewritten only when its bytes change: text as SVG text, no date, a fixed
hash salt, so the same code gives the same file.  Colours: Okabe and Ito's colour-blind-safe
palette, one per role.
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

#: Okabe-Ito colours (edge, fill) by role; the shared bands in grey.
ROLE_COLOURS = {"figures": ("#009E73", "#D9F0E8"), "run": ("#0072B2", "#D6E6F4"),
                "file": ("#D55E00", "#FBE3D6"), "record": ("#CC79A7", "#F5E1EC"),
                "compute": ("#555555", "#F2F2F2")}
SHARED = ("#333333", "#FFFFFF")
#: What each role's row says, left of the columns.
ROLE_WORDS = {"figures": "figures", "run": "run", "file": "input declaration", "record": "record",
              "compute": "computation"}
#: What each shared package is, in its band.
SHARED_WORDS = {"records": "what every record is made of: warnings and verdicts as data, fields, numbers "
                           "for people",
                "mechanics": "the physics: closed forms, the independent solver (numpy only)",
                "waves": "Goda-Takahashi wave loads", "dynamics": "the engine of the motion past initiation",
                "io": "files in and out, by format: atomic writes, the format registry, one writer per "
                      "data format, the input keys' declaration and reader",
                "workflows": "the index of the runs: one call per command",
                "drawing": "what every figure shares: style, figure files, the tidy pass, label placement",
                "cli": "the command line: options and one call per command",
                "process.py workers.py": "the process: its exit on Ctrl-C and SIGTERM; the one pool of "
                                         "worker processes (standard library only)"}


def read_declarations(test_file: Path) -> dict[str, Any]:
    """The ``LAYER``, ``PRODUCTS``, ``ROLE``, ``COMPUTE`` and ``RUNTIME`` literals of
    ``tests/test_layers.py``."""
    out: dict[str, Any] = {}
    for node in ast.parse(test_file.read_text(encoding="utf-8")).body:
        if not isinstance(node, (ast.Assign, ast.AnnAssign)) or node.value is None:
            continue
        targets = [node.target] if isinstance(node, ast.AnnAssign) else node.targets
        for t in targets:
            if isinstance(t, ast.Name) and t.id in ("LAYER", "PRODUCTS", "ROLE", "COMPUTE", "RUNTIME"):
                out[t.id] = ast.literal_eval(node.value)
    missing = {"LAYER", "PRODUCTS", "ROLE", "COMPUTE", "RUNTIME"} - set(out)
    if missing:
        raise ValueError(f"{test_file}: no {', '.join(sorted(missing))}")
    return out


def role_of(name: str, roles: dict[str, float]) -> str:
    """The role of a product's module or subpackage by the first word of its name."""
    word = name.split("_")[0]
    return word if word in roles else "compute"


def product_modules(src: Path, product: str, roles: dict[str, float]) -> dict[str, list[str]]:
    """The modules of one product by role: the stem of a module, ``figures/page`` in a subpackage."""
    out: dict[str, list[str]] = {}
    for path in sorted((src / product).rglob("*.py")):
        rel = path.relative_to(src / product).with_suffix("")
        if "__pycache__" in rel.parts or (len(rel.parts) == 1 and rel.name == "__init__"):
            continue
        name = "/".join(rel.parts[:-1]) + "/" if rel.name == "__init__" else "/".join(rel.parts)
        if name.endswith("/"):
            continue
        out.setdefault(role_of(rel.parts[0], roles), []).append(name)
    return out


def product_imports(src: Path, products: tuple[str, ...]) -> set[tuple[str, str]]:
    """(importer, imported) between the products of ``src`` (``src/regimemap``), read from the source."""
    edges: set[tuple[str, str]] = set()
    for path in sorted(src.rglob("*.py")):
        parts = list(path.relative_to(src.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        base = parts if path.name == "__init__.py" else parts[:-1]
        if len(parts) < 2 or parts[1] not in products:
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
                if len(name) >= 2 and name[0] == "regimemap" and name[1] in products and name[1] != parts[1]:
                    edges.add((parts[1], name[1]))
    return edges


#: A column's width and the gap between columns; a module's line and a band's height;
#: the characters of a cell's line.
COL_W, GAP, LINE_H, BAND_H, CELL_CHARS = 2.3, 0.15, 0.2, 0.42, 24
#: The width of a character of a band's name (9.5 pt bold), in the picture's units: its words follow.
CHAR_W = 0.12
#: Where the words of the rows end, left of the first column.
LEFT = -2.3


def _rows(decl: dict[str, Any]) -> list[tuple[float, str, str]]:
    """(layer, kind, name) from the bottom up: a band per shared package, a row per role."""
    rows = [(float(layer), "band", name) for name, layer in decl["LAYER"].items()]
    # the process's own modules, below every layer (the layer tests give them -0.5)
    rows.append((-0.5, "band", " ".join(m.rpartition(".")[2] + ".py" for m in decl["RUNTIME"])))
    roles = {"compute": float(decl["COMPUTE"])} | {r: float(v) for r, v in decl["ROLE"].items()}
    merged: dict[float, list[str]] = {}
    for role, layer in roles.items():
        merged.setdefault(layer, []).append(role)
    rows += [(layer, "roles", "+".join(names)) for layer, names in merged.items()]
    return sorted(rows, key=lambda r: (r[0], r[1] == "roles"))


def draw(decl: dict[str, Any], modules: dict[str, dict[str, list[str]]],
         edges: set[tuple[str, str]]) -> Any:
    """The picture as a matplotlib Figure (no pyplot)."""
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch

    products = decl["PRODUCTS"]
    rows = _rows(decl)
    width = len(products) * (COL_W + GAP)

    def cell(product: str, roles: list[str]) -> list[str]:
        names = [m for r in roles for m in modules[product].get(r, [])]
        if not names:
            return ["-"]
        lines: list[str] = []
        folders = sorted({n.rpartition("/")[0] for n in names})
        for folder in folders:   # a subpackage's modules after its name
            stems = [n.rpartition("/")[2] for n in names if n.rpartition("/")[0] == folder]
            lines += textwrap.wrap((f"{folder}/: " if folder else "") + " ".join(stems), CELL_CHARS,
                                   subsequent_indent="  " if folder else "")
        return lines

    heights = [BAND_H if kind == "band" else
               0.2 + LINE_H * max(len(cell(p, name.split("+"))) for p in products)
               for _, kind, name in rows]
    total = sum(heights) + 0.1 * len(rows) + 1.1
    fig = Figure(figsize=(11.5, 0.7 * total), dpi=100)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_axis_off()
    ax.set_xlim(LEFT - 0.1, width + 0.05)
    ax.set_ylim(-0.05, total)
    y = 0.0
    for (layer, kind, name), h in zip(rows, heights):
        if kind == "band":
            ax.add_patch(FancyBboxPatch((0, y), width - GAP, h, boxstyle="round,pad=0,rounding_size=0.06",
                                        facecolor=SHARED[1], edgecolor=SHARED[0], linewidth=1.0))
            label = name if name.endswith(".py") else f"{name}/"
            ax.text(0.12, y + h / 2, label, ha="left", va="center", fontsize=9.5, fontweight="bold")
            ax.text(max(1.7, 0.42 + CHAR_W * len(label)), y + h / 2, SHARED_WORDS.get(name, ""),
                    ha="left", va="center", fontsize=8.5, color="#333333")
        else:
            roles = name.split("+")
            ax.text(LEFT, y + h / 2, "\n".join(ROLE_WORDS[r] for r in roles), ha="left", va="center",
                    fontsize=9, color=ROLE_COLOURS[roles[0]][0], linespacing=1.4)
            for i, product in enumerate(products):
                x = i * (COL_W + GAP)
                edge, fill = ROLE_COLOURS[roles[0]]
                ax.add_patch(FancyBboxPatch((x, y), COL_W, h, boxstyle="round,pad=0,rounding_size=0.06",
                                            facecolor=fill, edgecolor=edge, linewidth=1.0))
                ax.text(x + 0.08, y + h - 0.1, "\n".join(cell(product, roles)), ha="left", va="top",
                        fontsize=7.5, family="monospace", linespacing=1.3)
        ax.text(-0.12, y + h / 2, f"{layer:g}", ha="right", va="center", fontsize=7.5, color="#777777")
        y += h + 0.1
    for i, product in enumerate(products):
        x = i * (COL_W + GAP) + COL_W / 2
        ax.text(x, y + 0.62, f"{product}/", ha="center", va="center", fontsize=11, fontweight="bold")
        used = sorted(b for a, b in edges if a == product)
        ax.text(x, y + 0.25, "uses " + ", ".join(used) if used else "uses no other product",
                ha="center", va="center", fontsize=7.5, color="#555555")
    ax.text(LEFT, y + 0.62, "layer", ha="left", va="center", fontsize=7.5, color="#777777")
    return fig


def svg_bytes(fig: Any) -> bytes:
    """The Figure as SVG, the same bytes for the same picture (text as text, no date, fixed ids)."""
    import matplotlib

    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "regimemap-architecture"}):
        out = io.BytesIO()
        fig.savefig(out, format="svg", metadata={"Date": None, "Creator": None})
    return out.getvalue()


def picture(root: Path) -> bytes:
    """The picture's SVG bytes for the checkout at ``root``."""
    decl = read_declarations(root / "tests" / "test_layers.py")
    src = root / "src" / "regimemap"
    modules = {p: product_modules(src, p, decl["ROLE"]) for p in decl["PRODUCTS"]}
    return svg_bytes(draw(decl, modules, product_imports(src, decl["PRODUCTS"])))


def write_picture(app: Sphinx) -> None:
    """``builder-inited``: draw the picture from the code and write it where its bytes changed."""
    data = picture(Path(app.srcdir).parent)
    target = Path(app.srcdir) / TARGET
    target.parent.mkdir(exist_ok=True)
    if not target.is_file() or target.read_bytes() != data:
        target.write_bytes(data)


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("builder-inited", write_picture)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
