"""What autosummary's templates need to write the API pages and cannot find alone.

The API pages are written by ``sphinx.ext.autosummary`` (``docs/api/index.md``
lists the packages; ``docs/_templates/autosummary/api.rst`` is the one
template of a package, a room and a module page) and rendered by autodoc and
numpydoc.  :func:`api_context` computes, into ``autosummary_context``, the
three things autosummary cannot tell from the objects:

- **where a public name is defined.**  A package's names are imported lazily
  (:mod:`regimemap._lazy`) and a constant has no ``__module__``: the table of a
  package's ``__all__`` links each name to the public module that defines it
  (found from the modules' source), and documents on the package page itself
  a name whose module is private (a package's underscore module, which re-exports it);
- **which names a module documents**: the names of its ``__all__`` that it
  binds itself (``def``, ``class``, assignment), not the ones it re-exports.
  autosummary's own test reads ``__module__``, which a constant lacks, so it
  would document an imported constant twice; a type alias
  (``Box = tuple[...]``) is shown by its value and not indexed, as two modules
  name one alike;
- **the command of each workflow**: which ``regimemap`` command calls which
  ``run_*`` of :mod:`regimemap.workflows` (read from the command line's
  source) and the record it returns (its return annotation), for the table of
  the workflows page.

:func:`remove_stale_pages` deletes the generated pages of modules that no
longer exist (autosummary writes pages, never removes them).
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
import sys
import types
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.pycode import ModuleAnalyzer
from sphinx.util import logging

logger = logging.getLogger(__name__)

#: The folder of the generated pages, relative to the source folder (``docs/api/index.md``'s toctree).
GENERATED = Path("api") / "generated"
#: Pages of hand-written text that a package's page includes after its docstring.
INTRO = Path("api") / "intro"


def _public_submodules(package: Any) -> list[Any]:
    """The public modules of a package, sorted; a subpackage counts as one module (a room)."""
    if not hasattr(package, "__path__"):
        return []
    return [importlib.import_module(f"{package.__name__}.{info.name}")
            for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda i: i.name)
            if not info.name.startswith("_")]


def _walk(package: Any) -> list[Any]:
    """The package's public modules at every depth, in the order of the pages."""
    out = []
    for module in _public_submodules(package):
        out.append(module)
        out += _walk(module)
    return out


_DEFINED: dict[str, set[str]] = {}


def _defined_names(module: Any) -> set[str]:
    """Names a module binds at its top level itself (def, class, assignment), not by import."""
    name = module.__name__
    if name not in _DEFINED:
        names: set[str] = set()
        for node in ast.parse(inspect.getsource(module)).body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                names.add(node.name)
            elif isinstance(node, ast.Assign):
                names.update(t.id for target in node.targets for t in ast.walk(target)
                             if isinstance(t, ast.Name))
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                names.add(node.target.id)
        _DEFINED[name] = names
    return _DEFINED[name]


def _home(obj: Any, name: str, modules: list[Any]) -> str | None:
    """The public module among ``modules`` that defines ``obj`` under ``name`` (its own package's first)."""
    # a function or a class is defined where its __module__ says; a constant, where it is bound
    mod = getattr(obj, "__module__", None) if isinstance(obj, (type, types.FunctionType)) else None
    for module in modules:
        if (not inspect.ismodule(obj) and name in _defined_names(module)
                and getattr(module, name, None) is obj and mod in (None, module.__name__)):
            return str(module.__name__)
    return None


def _is_alias(obj: Any) -> bool:
    """A type alias (``Interval = tuple[np.ndarray, np.ndarray]``), which autodoc cannot sign."""
    return isinstance(obj, types.GenericAlias) or type(obj).__module__ == "typing" or (
        type(obj).__name__ in ("UnionType", "TypeAliasType"))


def _alias(module: Any, name: str) -> dict[str, str]:
    """The value (as written) and the ``#:`` comment of a type alias."""
    source = inspect.getsource(module)
    value = ""
    for node in ast.parse(source).body:
        if not isinstance(node, (ast.Assign, ast.AnnAssign)) or node.value is None:
            continue
        target = node.target if isinstance(node, ast.AnnAssign) else (
            node.targets[0] if len(node.targets) == 1 else None)
        if isinstance(target, ast.Name) and target.id == name:
            value = " ".join((ast.get_source_segment(source, node.value) or "").split())
    doc = ModuleAnalyzer.for_module(module.__name__).find_attr_docs().get(("", name), [])
    return {"name": name, "value": value,
            "doc": " ".join(line.strip() for line in doc if line.strip()) or "A type alias."}


def _role(obj: Any) -> str:
    if inspect.isclass(obj):
        return "class"
    return "function" if inspect.isroutine(obj) else "data"


def _package_entry(package: Any, everywhere: list[Any], rooms: bool) -> dict[str, Any]:
    """A package's names (each with the target it links to) and the pages below it."""
    own = _walk(package)
    names: list[str] = []
    here: list[dict[str, str]] = []
    for name in getattr(package, "__all__", []):
        obj = getattr(package, name)
        home = _home(obj, name, own + everywhere)
        if home is None:
            here.append({"name": name, "role": _role(obj)})
            names.append(name)
        else:
            names.append("~" + _relative(f"{home}.{name}", package.__name__))
    modules = [_relative(m.__name__, package.__name__) for m in _public_submodules(package)] if rooms else []
    return {"names": names, "here": here, "modules": modules}


def _relative(name: str, module: str) -> str:
    """``name`` relative to the page's module (autosummary resolves it there, and warns on a full one)."""
    return name.removeprefix(module + ".")


def _module_entry(module: Any) -> dict[str, Any]:
    """The names of a module's ``__all__`` it defines: autodoc's members and the type aliases."""
    below = [_relative(m.__name__, module.__name__) for m in _public_submodules(module)]
    if not hasattr(module, "__all__"):  # a room of drawing/: its modules only
        return {"names": [], "here": [], "modules": below}
    defined = _defined_names(module)
    members = [n for n in module.__all__ if n in defined]
    aliases = [n for n in members if _is_alias(getattr(module, n))]
    return {"members": [n for n in members if n not in aliases],
            "aliases": [_alias(module, n) for n in aliases],
            "modules": below}


def _commands_calling(names: set[str]) -> dict[str, list[str]]:
    """``run_*`` name -> the commands whose function calls it, directly or through its module's helpers."""
    import regimemap.cli as cli

    out: dict[str, list[str]] = {}
    for path in sorted(Path(cli.__file__).parent.glob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
        uses = {fname: {x.id for x in ast.walk(node) if isinstance(x, ast.Name)}
                | {x.attr for x in ast.walk(node) if isinstance(x, ast.Attribute)}
                for fname, node in functions.items()}
        for fname, node in functions.items():
            command = _click_name(node)
            if command is None:
                continue
            seen, todo = {fname}, [fname]
            while todo:   # the module's own helpers that the command calls
                for used in uses[todo.pop()]:
                    if used in functions and used not in seen:
                        seen.add(used)
                        todo.append(used)
            for used in sorted(set().union(*(uses[f] for f in seen)) & names):
                out.setdefault(used, []).append(command)
    return out


def _click_name(node: ast.FunctionDef) -> str | None:
    """The name in ``@click.command("name", ...)`` above a function, if any."""
    for deco in node.decorator_list:
        if (isinstance(deco, ast.Call) and isinstance(deco.func, ast.Attribute)
                and deco.func.attr == "command" and deco.args
                and isinstance(deco.args[0], ast.Constant)):
            return str(deco.args[0].value)
    return None


def _workflow_rows(everywhere: list[Any]) -> list[dict[str, str]]:
    """One row per ``run_*`` of :mod:`regimemap.workflows`: its commands, the function, its record."""
    import regimemap.workflows as workflows

    runs = sorted(n for n in workflows.__all__ if n.startswith("run_"))
    commands = _commands_calling(set(runs))
    rows = []
    for name in runs:
        function = getattr(workflows, name)
        home = _home(function, name, everywhere) or "regimemap.workflows"
        # the annotation as written (a string): the names it uses may be imported for mypy only
        written = inspect.signature(function).return_annotation
        record = (getattr(workflows, written, None) or vars(sys.modules[function.__module__]).get(written)
                  if isinstance(written, str) else written)
        record_name = getattr(record, "__name__", "")
        record_home = _home(record, record_name, everywhere) if record_name else None
        rows.append({
            "commands": ", ".join(f"``regimemap {c}``" for c in commands.get(name, [])) or "(none)",
            "function": f":func:`~{home}.{name}`",
            "record": (f":class:`~{record_home}.{record_name}`" if record_home
                       else f"``{record_name or 'None'}``"),
        })
    return rows


def api_packages() -> list[str]:
    """The packages with an API page: ``regimemap`` and its public subpackages but ``cli``.

    The command line has its reference of its own (sphinx-click, ``guide/cli.rst``).
    """
    import regimemap

    return ["regimemap"] + [info.name for info in pkgutil.iter_modules(regimemap.__path__, "regimemap.")
                            if info.ispkg and not info.name.startswith("regimemap._")
                            and info.name != "regimemap.cli"]


def api_context() -> dict[str, Any]:
    """``autosummary_context``: ``{"api": {page: entry}, "workflow_rows": [...], "intros": [...]}``.

    Each package of :func:`api_packages` is a page (``docs/api/index.md`` lists
    them), and so is every public module below it.  An entry holds, for the
    template, the targets of a package's table (``names``), the names
    documented on its page (``here``), a module's autodoc ``members`` and type
    ``aliases``, and the pages below it (``modules``).
    """
    import regimemap

    packages = api_packages()
    everywhere = [importlib.import_module(info.name)
                  for info in pkgutil.walk_packages(regimemap.__path__, "regimemap.")
                  if not any(part.startswith("_") for part in info.name.split("."))]
    api: dict[str, Any] = {}
    for name in packages:
        package = importlib.import_module(name)
        api[name] = _package_entry(package, everywhere, rooms=name != "regimemap")
        if name != "regimemap":
            for module in _walk(package):
                api[module.__name__] = _module_entry(module)
    intro_dir = Path(__file__).resolve().parents[1] / INTRO
    return {"api": api, "workflow_rows": _workflow_rows(everywhere),
            "intros": sorted(p.stem for p in intro_dir.glob("*.rst"))}


def remove_stale_pages(app: Sphinx) -> None:
    """Delete the generated pages that no entry of ``autosummary_context`` asks for.

    autosummary writes pages and never removes one, so the page of a module that
    was renamed would stay (a page in no toctree: a warning).  A public package
    without a page (left out of ``docs/api/index.md``) is a warning too.
    """
    folder = Path(app.srcdir) / GENERATED
    wanted = set(app.config.autosummary_context.get("api", {}))
    for page in folder.glob("*.rst"):
        if page.stem not in wanted:
            page.unlink()
    for package in api_packages():
        if not (folder / f"{package}.rst").is_file():
            logger.warning("the public package %s has no API page: list it in docs/api/index.md", package)


def setup(app: Sphinx) -> dict[str, Any]:
    # after autosummary has written the pages (builder-inited, priority 500)
    app.connect("builder-inited", remove_stale_pages, priority=900)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
