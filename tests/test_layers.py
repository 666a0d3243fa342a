"""The layers and their import rules, read from the source (AST), so a breach fails a test.

What every record is made of (records: notices, checks, fields, numbers for people); the
physics core -- mechanics (numpy only) -> waves -> dynamics -- and beside the engine each
product's computation; then io (files in and out, by format), each product's input declaration
(``file*``) and record (``record*``), its run (``run*``), the index of the runs (``workflows``),
drawing and each product's figures (``figures*``), and the command line (``cli``): a module
imports only from its own layer or the layers before it.  The products are the folders of
:data:`PRODUCTS`, one per command family; a product module's role is the first word of its name
(:data:`ROLE`), any other name is the product's computation.  matplotlib only under ``drawing/``
and in the products' figures, click only under ``cli/``; no module imports another module's
private (underscore) name; no import cycle between modules, counting the imports inside
functions too (they run as soon as the function does: a cycle through them is still a cycle).
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "regimemap"

#: Layer of each package that is not a product: a module may import from layers <= its own.
LAYER = {"records": -1, "mechanics": 0, "waves": 1, "dynamics": 2, "io": 3, "workflows": 3.6, "drawing": 4, "cli": 5}
#: The products: one folder each, holding its computation, input declaration, run, record and figures.
PRODUCTS = ("maps", "caisson", "motion", "lifetime", "climate", "study")
#: The layer of a product module by its role, the first word of its name (``file_keys`` is a
#: ``file``, ``figures/page`` a ``figures``): its input declaration and its record beside io, its
#: run above them, its figures beside drawing.  Any other name is the product's computation.
ROLE = {"file": 3.2, "record": 3.2, "run": 3.5, "figures": 4.2}
#: The layer of a product's computation, and of its ``__init__`` (which imports nothing but the
#: lazy loader: every name it lists is imported on first use).
COMPUTE = 2
#: The top-level modules (the package's front door and its version) sit above the
#: evaluation layer: regimemap/__init__.py re-exports maps and mechanics.
TOP = 2.5
#: The lazy loader of every package's ``__init__`` (standard library only) sits below every layer.
LAZY = "regimemap._lazy"
#: The process's own modules (standard library only): its exit on Ctrl-C and SIGTERM, and the one
#: place where worker processes start.  Every layer may use them; they import none of regimemap's
#: layers.
RUNTIME = ("regimemap.process", "regimemap.workers")


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC.parent).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


MODULES = _modules()


def _imports(name: str, path: Path) -> list[tuple[str, list[str], int, bool]]:
    """(module imported, names, line, at module level) for every import in a file."""
    return _imports_of_text(name, path.name == "__init__.py", path.read_text(encoding="utf-8"))


@functools.cache
def _imports_of_text(name: str, is_pkg: bool, text: str) -> list[tuple[str, list[str], int, bool]]:
    """:func:`_imports` of a module's text, parsed once per session for all the rules."""
    tree = ast.parse(text)
    package = name if is_pkg else name.rpartition(".")[0]
    top_level = {id(n) for n in tree.body}
    # imports under ``if TYPE_CHECKING:`` are for the type checker only: never executed
    typing_only = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If)
                   and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"
                   for n in ast.walk(node)}
    found = []
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.Import):
            for alias in node.names:
                found.append((alias.name, [], node.lineno, id(node) in top_level))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            found.append((mod, [a.name for a in node.names], node.lineno, id(node) in top_level))
    return found


def _role(module: str) -> str | None:
    """The role of a product module (``file``, ``record``, ``run``, ``figures`` or ``compute``);
    None outside the products."""
    parts = module.split(".")
    if len(parts) < 2 or parts[1] not in PRODUCTS:
        return None
    word = parts[2].split("_")[0] if len(parts) > 2 else ""
    return word if word in ROLE else "compute"


def _layer(module: str) -> float:
    if module == "regimemap.__main__":  # ``python -m regimemap``: the command line
        return LAYER["cli"]
    if module == LAZY:
        return -1
    if module in RUNTIME:
        return -0.5
    role = _role(module)
    if role is not None:
        return ROLE.get(role, COMPUTE)
    parts = module.split(".")
    if len(parts) >= 2 and parts[1] in LAYER:
        return LAYER[parts[1]]
    return TOP


def _draws(module: str) -> bool:
    """A module that draws: under ``drawing/`` or a product's figures."""
    return module.startswith("regimemap.drawing") or _role(module) == "figures"


def _engine(module: str) -> bool:
    """The engine, numpy only: mechanics, waves, dynamics and the map's computation."""
    return (module.startswith(("regimemap.mechanics", "regimemap.waves", "regimemap.dynamics"))
            or (module.startswith("regimemap.maps") and _role(module) == "compute"))


def _breaches(module: str, path: Path) -> list[str]:
    """Every breach of the import rules by one module, one line each (``module:line what``).

    The rules: an import of regimemap points down the layers (or sideways); matplotlib only where
    a module draws (:func:`_draws`), click only under ``cli/``, scipy not in the engine
    (:func:`_engine`); mechanics imports nothing of regimemap but itself and the lazy loader; no private
    (underscore) name crosses modules, and a package's private module serves that package only.
    """
    here = _layer(module)
    engine = _engine(module)
    out = []
    for imported, names, line, _top in _imports(module, path):
        at = f"{module}:{line}"
        root = imported.split(".")[0]
        if root == "matplotlib" and not _draws(module):
            out.append(f"{at} imports matplotlib (drawing/ and the figures only)")
        if root == "click" and ".cli" not in module:
            out.append(f"{at} imports click (cli/ only)")
        # (the statistics, lifetime and climate, fit with scipy: a runtime dependency)
        if engine and root == "scipy":
            out.append(f"{at} imports scipy (the engine is numpy only)")
        if root != "regimemap":
            continue
        versioned = imported in ("regimemap", "regimemap._version") and here > 0  # the version string
        if not versioned and _layer(imported) > here:
            out.append(f"{at} imports {imported} (a higher layer)")
        if (module.startswith("regimemap.mechanics") and imported != LAZY
                and not imported.startswith("regimemap.mechanics")):
            out.append(f"{at} imports {imported} (mechanics imports only mechanics)")
        if imported == module:
            continue
        private = [n for n in names if n.startswith("_") and n != "__version__"]
        if private:
            out.append(f"{at} imports private {private} from {imported}")
        # a package's private module serves that package only
        own_package = imported.rpartition(".")[0] in (module, module.rpartition(".")[0])
        if not (own_package or not imported.rpartition(".")[2].startswith("_")
                or imported.endswith("_version")):
            out.append(f"{at} imports the private module {imported}")
    return out


def test_the_import_contract():
    """Every module of the package keeps the import rules (:func:`_breaches`); one message lists
    every breach of every module."""
    assert len(MODULES) > 150  # the reader found the package
    breaches = [b for module, path in MODULES.items() for b in _breaches(module, path)]
    assert not breaches, f"{len(breaches)} import rule(s) broken:\n" + "\n".join(breaches)


def test_the_contract_catches_each_rule(tmp_path):
    """A planted breach of each rule is caught, with its module and line; the allowed imports pass."""
    def breaches(module: str, text: str, name: str = "x.py") -> list[str]:
        f = tmp_path / name
        f.write_text(text)
        return _breaches(module, f)

    assert breaches("regimemap.maps.x", "from ..drawing.style import MODE_STYLE\n") == [
        "regimemap.maps.x:1 imports regimemap.drawing.style (a higher layer)"]
    assert breaches("regimemap.io.x", "import numpy\ndef g():\n    import matplotlib.pyplot\n") == [
        "regimemap.io.x:3 imports matplotlib (drawing/ and the figures only)"]
    assert breaches("regimemap.study.record_x", "import matplotlib\nfrom .figures import f\n") == [
        "regimemap.study.record_x:1 imports matplotlib (drawing/ and the figures only)",
        "regimemap.study.record_x:2 imports regimemap.study.figures (a higher layer)"]
    assert breaches("regimemap.lifetime.x", "from .run import run_lifetime\n") == [
        "regimemap.lifetime.x:1 imports regimemap.lifetime.run (a higher layer)"]
    assert breaches("regimemap.maps.x", "from scipy import optimize\n") == [
        "regimemap.maps.x:1 imports scipy (the engine is numpy only)"]
    assert breaches("regimemap.drawing.x", "import click\n") == ["regimemap.drawing.x:1 imports click (cli/ only)"]
    assert breaches("regimemap.dynamics.x", "from scipy import optimize\n") == [
        "regimemap.dynamics.x:1 imports scipy (the engine is numpy only)"]
    assert breaches("regimemap.mechanics.x", "from ..waves.goda import x\n") == [
        "regimemap.mechanics.x:1 imports regimemap.waves.goda (a higher layer)",
        "regimemap.mechanics.x:1 imports regimemap.waves.goda (mechanics imports only mechanics)"]
    assert breaches("regimemap.cli.x", "from ..maps.query import _grid\n") == [
        "regimemap.cli.x:1 imports private ['_grid'] from regimemap.maps.query"]
    assert breaches("regimemap.cli.x", "from ..maps._helpers import grid\n") == [
        "regimemap.cli.x:1 imports the private module regimemap.maps._helpers"]
    # allowed: scipy in the statistics, the lazy loader in mechanics, the version anywhere above
    # mechanics, a package's own private module, an import for the type checker only
    assert breaches("regimemap.climate.x", "from scipy import stats\n") == []
    assert breaches("regimemap.study.figures_x", "import matplotlib\nfrom ..drawing.save import s\n"
                    "from .record import R\nfrom ..lifetime.figures.style import FS\n") == []
    assert breaches("regimemap.study.run", "from ..lifetime.run import run_lifetime\n"
                    "from .file import read_study\nfrom ..io.atomic import atomic_open\n") == []
    assert breaches("regimemap.mechanics", "from .._lazy import attach\n", "__init__.py") == []
    assert breaches("regimemap.io.x", "from .. import __version__\nfrom ._helpers import g\n"
                    "if TYPE_CHECKING:\n    from ..drawing.style import S\n") == []
    # the process's modules serve every layer and import none
    assert breaches("regimemap.workers", "from .lifetime.model import Caisson\n") == [
        "regimemap.workers:1 imports regimemap.lifetime.model (a higher layer)"]
    assert breaches("regimemap.maps.figures.batch", "from ...workers import worker_pool\n") == []
    # every breach of a module is reported, not only the first
    assert len(breaches("regimemap.waves.x", "import click\nimport matplotlib\nfrom ..cli import c\n")) == 3


def _import_graph(modules: dict[str, Path]) -> tuple[dict[str, set[str]], int]:
    """Module -> the modules of regimemap it imports, at module level or inside a function.

    Typing-only imports (``if TYPE_CHECKING:``) are left out; so is a package importing
    its own submodules (its front door).  Returns the graph and how many of its edges
    come from imports inside functions only.
    """
    graph: dict[str, set[str]] = {m: set() for m in modules}
    top_level: dict[str, set[str]] = {m: set() for m in modules}
    for module, path in modules.items():
        for imported, names, _line, top in _imports(module, path):
            if not imported.startswith("regimemap"):
                continue
            targets = [imported] + [f"{imported}.{n}" for n in names]
            for t in targets:
                if t in modules and t != module and not t.startswith(module + "."):
                    graph[module].add(t)
                    if top:
                        top_level[module].add(t)
    in_functions = sum(len(graph[m] - top_level[m]) for m in graph)
    return graph, in_functions


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """An import cycle of ``graph`` (its modules in order, the first repeated at the end), or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> list[str] | None:
        state[m] = 1
        stack.append(m)
        for t in sorted(graph[m]):
            if state.get(t) == 1:
                return stack[stack.index(t):] + [t]
            if t not in state:
                found = visit(t)
                if found:
                    return found
        stack.pop()
        state[m] = 2
        return None

    for m in sorted(graph):
        if m not in state:
            found = visit(m)
            if found:
                return found
    return None


def test_no_import_cycles():
    """No cycle, counting the imports inside functions (a lazy import is an import all the same)."""
    graph, in_functions = _import_graph(MODULES)
    # the lazy imports (matplotlib, the drawing modules inside the commands ...) are in the graph
    assert in_functions > 50, f"only {in_functions} edges from imports inside functions"
    cycle = _cycle(graph)
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_the_cycle_check_sees_imports_inside_functions(tmp_path):
    """Two modules importing each other, one of them inside a function, make a cycle."""
    pkg = tmp_path / "regimemap" / "drawing"
    pkg.mkdir(parents=True)
    (pkg / "a.py").write_text("from .b import g\n")
    (pkg / "b.py").write_text("def g():\n    from .a import f\n    return f\n")
    modules = {"regimemap.drawing.a": pkg / "a.py", "regimemap.drawing.b": pkg / "b.py"}
    graph, in_functions = _import_graph(modules)
    assert in_functions == 1
    assert _cycle(graph) == ["regimemap.drawing.a", "regimemap.drawing.b", "regimemap.drawing.a"]
    (pkg / "b.py").write_text("def g():\n    return 1\n")
    assert _cycle(_import_graph(modules)[0]) is None


def test_the_rules_can_fail(tmp_path):
    """The AST reader sees relative, absolute and function-level imports, not typing-only ones."""
    f = tmp_path / "x.py"
    f.write_text("from ..drawing.style import MODE_STYLE\nimport click\n"
                 "def g():\n    from matplotlib.figure import Figure\n"
                 "if TYPE_CHECKING:\n    import matplotlib.axes\n")
    found = _imports("regimemap.maps.x", f)
    assert not any(m == "matplotlib.axes" for m, *_ in found)
    assert ("regimemap.drawing.style", ["MODE_STYLE"], 1, True) in found
    assert ("click", [], 2, True) in found
    assert ("matplotlib.figure", ["Figure"], 4, False) in found
    assert _layer("regimemap.drawing.style") > _layer("regimemap.maps.x")


#: The packages that compute the physics (and the statistics): a module that draws
#: (:func:`_draws`) imports from them, from a product's computation and from any run only the
#: data types and pure helpers below (a record's type only for type checking), and draws what
#: its caller computed.
PHYSICS = ("mechanics", "waves", "dynamics", "workflows")


def _computes(module: str) -> bool:
    """A module whose names a figure may not call: the physics core, a product's computation, a run."""
    parts = module.split(".")
    return (len(parts) >= 2 and parts[0] == "regimemap"
            and (parts[1] in PHYSICS or _role(module) in ("compute", "run")))


#: What drawing/ may import from :data:`PHYSICS`, each with why it computes nothing.
DRAWING_MAY_IMPORT = {
    # data types, enumerations and constants: records a figure is handed
    "mechanics.block.Parameters": "the block's inputs, a record",
    "mechanics.block.Case": "a named map case, a record",
    "mechanics.block.LOAD_DEFAULTS": "the loads' default values, constants",
    "mechanics.modes.Mode": "the modes, an enumeration",
    "mechanics.modes.MAP_MODES": "the modes of a map, a constant tuple",
    "mechanics.modes.LOADED_MAP_MODES": "the modes of a loaded map, a constant tuple",
    "mechanics.validation.check_gamma": "input range check, raises ValueError",
    "mechanics.validation.check_resolution": "input range check, raises ValueError",
    "maps.mapdata.MapData": "a computed map, a record",
    "maps.mapdata.CurveData": "a computed boundary curve, a record",
    "caisson.report.CaissonReport": "a computed caisson analysis, a record",
    "caisson.report.MapView": "the sheet map's extent, a record",
    "maps.loadedmap.Margin": "a computed margin, a record",
    "maps.loadedmap.mode_label": "a mode's name in words (formatting)",
    "maps.points.DesignPoint": "a design point to mark, a record",
    "maps.query.PointResult": "a classified point, a record",
    "maps.ambiguity.AmbiguousRegion": "a computed ambiguous region, a record",
    "maps.geometry.DEFAULT_SAMPLES": "a default resolution, a constant",
    "maps.geometry.area_in_view": "area of a drawn polygon clipped to the axes (plane geometry)",
    "maps.describe.LOAD_SYMBOLS": "the loads' symbols, constants",
    "maps.describe.format_value": "number formatting",
    "maps.describe.load_items": "the loads as (symbol, value) pairs (formatting)",
    "maps.describe.loads_text": "the loads in words (formatting)",
    "maps.sweeps.SWEEPS": "the names of the sweepable inputs, constants",
    "maps.sweeps.sweep_params": "the Parameters record of one sweep value (no physics)",
    "dynamics.outcome.OutcomeMap": "a computed outcome map, a record",
    "dynamics.regions.MapGeometry": "a computed map's regions, a record",
    "dynamics.stepper.History": "a computed motion, a record",
    "dynamics.stepper.Phase": "a phase of the motion, an enumeration",
    "dynamics.stepper.OVERTURN": "an outcome code, a constant",
    "dynamics.stepper.ROCK": "an outcome code, a constant",
    "dynamics.stepper.SLIDE": "an outcome code, a constant",
    "dynamics.stepper.SLIDE_ROCK": "an outcome code, a constant",
    "dynamics.stepper.STILL_MOVING": "an outcome code, a constant",
    "lifetime.chart.DesignChart": "a computed design chart, a record",
    "lifetime.results.LifetimeResult": "a computed lifetime simulation, a record",
    "climate.analysis.ClimateResult": "a computed wave climate, a record",
    "climate.analysis.Curves": "computed return-level curves, a record",
    "climate.analysis.Diagnostics": "computed threshold diagnostics, a record",
    "climate.analysis.Sensitivity": "a computed threshold sensitivity, a record",
}
#: Computations drawing/ still makes itself, to be moved to its callers: (module, name).
DRAWING_STILL_COMPUTES: set[tuple[str, str]] = set()


def _drawing_physics_imports(modules: dict[str, Path]) -> list[tuple[str, int, str]]:
    """(drawing module, line, ``package.module.name``) for every name a module that draws imports
    from a module that computes (:func:`_computes`)."""
    found = []
    for module, path in modules.items():
        if not _draws(module):
            continue
        for imported, names, line, _top in _imports(module, path):
            if not _computes(imported) or imported.split(".")[1:2] == ["__init__"]:
                continue
            where = ".".join(imported.split(".")[1:])
            found += [(module, line, f"{where}.{n}") for n in names] if names else [(module, line, where)]
    return found


def test_drawing_only_draws():
    """drawing/ imports from the computing packages only data types and pure helpers."""
    found = _drawing_physics_imports(MODULES)
    assert len(found) > 50  # the reader sees drawing's imports (typing-only ones left out)
    bad = [f"{m}:{line} imports {name}" for m, line, name in found
           if name not in DRAWING_MAY_IMPORT
           and (m.removeprefix("regimemap.drawing."), name) not in DRAWING_STILL_COMPUTES]
    assert not bad, "drawing/ computes (hand it the result instead):\n" + "\n".join(bad)
    live = {(m.removeprefix("regimemap.drawing."), name) for m, _, name in found}
    assert DRAWING_STILL_COMPUTES <= live, f"moved already: {DRAWING_STILL_COMPUTES - live}"
    unused = set(DRAWING_MAY_IMPORT) - {name for *_, name in found}
    assert not unused, f"allowed but no longer imported (drop them): {sorted(unused)}"


def test_the_drawing_rule_can_fail(tmp_path):
    """A function-level import of a compute function from maps is seen; a data type is allowed."""
    f = tmp_path / "x.py"
    f.write_text("from ...maps.mapdata import MapData\n"
                 "def g():\n    from ...maps.mapdata import compute_map\n")
    found = _drawing_physics_imports({"regimemap.maps.figures.x": f})
    assert found == [("regimemap.maps.figures.x", 1, "maps.mapdata.MapData"),
                     ("regimemap.maps.figures.x", 3, "maps.mapdata.compute_map")]
    assert [n for *_, n in found if n not in DRAWING_MAY_IMPORT] == ["maps.mapdata.compute_map"]
    f.write_text("def g():\n    from ..run import run_map\n")  # a run computes too
    assert _drawing_physics_imports({"regimemap.maps.figures.x": f}) == [
        ("regimemap.maps.figures.x", 2, "maps.run.run_map")]
    f.write_text("from ..record import R\nfrom ...drawing.style import S\n")  # a record, the style: allowed
    assert _drawing_physics_imports({"regimemap.maps.figures.x": f}) == []


#: The longest a module of the package may be, in lines: a module that outgrows it holds two jobs.
MAX_MODULE_LINES = 500


def test_no_module_outgrows_one_job():
    """Every module of the package is at most :data:`MAX_MODULE_LINES` lines long."""
    long = {m: n for m, p in MODULES.items() if (n := len(p.read_text(encoding="utf-8").splitlines()))
            > MAX_MODULE_LINES}
    assert not long, f"split by job (at most {MAX_MODULE_LINES} lines): {long}"
