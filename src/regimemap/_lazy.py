"""Lazy public names for a package: one mechanism for every ``__init__`` (PEP 562).

A package lists which of its submodules defines each public name; :func:`attach`
returns the module-level ``__getattr__`` and ``__dir__`` that import a submodule
the first time one of its names is read, keep the value in the package's globals
(so the next read is an ordinary attribute lookup), and list the public names in
``dir()`` before any of them is imported.  The same idea as scientific Python's
``lazy_loader.attach`` (SPEC 1), in the few lines this project needs.

The names and their submodules are declared once, as the package's imports under
``if TYPE_CHECKING:`` (which mypy and IDEs read for the real types, and which never run):
:func:`attach` reads them from the package's ``__init__.py``.  The two functions are
assigned under ``if not TYPE_CHECKING:`` so that, for mypy, an unknown name is an error
and not ``Any``::

    if TYPE_CHECKING:
        from .save import save_figure

    __all__ = ["save_figure"]

    if not TYPE_CHECKING:
        __getattr__, __dir__ = attach(__name__, __file__)
"""

from __future__ import annotations

import ast
import importlib
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["attach", "typed_imports"]


def typed_imports(init_file: str) -> dict[str, list[str]]:
    """The names a package's ``__init__.py`` imports under ``if TYPE_CHECKING:``, by submodule.

    Each submodule is spelled as the module of a relative import from the package without
    its first dot: ``"fits"`` is the package's own submodule, ``".study.run"`` its sibling
    package's (so an index package such as :mod:`regimemap.workflows` names where each
    name lives).

    Raises
    ------
    ValueError
        For an import there that is not relative or renames a name (``as``): the package
        could not give it under its name.
    """
    tree = ast.parse(Path(init_file).read_text(encoding="utf-8"), init_file)
    out: dict[str, list[str]] = {}
    for node in tree.body:
        if not (isinstance(node, ast.If) and getattr(node.test, "id", None) == "TYPE_CHECKING"):
            continue
        for imp in node.body:
            if isinstance(imp, ast.Pass):
                continue
            if not isinstance(imp, ast.ImportFrom) or not imp.level or any(a.asname for a in imp.names):
                raise ValueError(f"{init_file}:{imp.lineno}: a lazy name is a relative "
                                 "'from .module import name' under 'if TYPE_CHECKING:'")
            out.setdefault("." * (imp.level - 1) + (imp.module or ""), []).extend(a.name for a in imp.names)
    return out


def attach(package: str, init_file: str) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """The ``__getattr__`` and ``__dir__`` of a package whose names are imported on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    init_file : str
        Its ``__init__.py`` (``__file__``), whose imports under ``if TYPE_CHECKING:``
        name each public name's submodule (:func:`typed_imports`).

    Returns
    -------
    __getattr__ : callable
        Imports the submodule of a listed name, stores the value in the
        package's globals and returns it; any other name raises
        :class:`AttributeError` naming the package (PEP 562).
    __dir__ : callable
        The package's names, imported or not yet, sorted: what ``dir()`` and
        tab completion list.

    Raises
    ------
    ValueError
        When a name is imported from two submodules, or not as :func:`typed_imports` reads.
    """
    home: dict[str, str] = {}
    for submodule, names in typed_imports(init_file).items():
        for name in names:
            if name in home:
                raise ValueError(f"{package}: {name!r} listed under {home[name]!r} and {submodule!r}")
            home[name] = submodule

    def __getattr__(name: str) -> Any:
        if name not in home:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(f".{home[name]}", package), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(home))

    return __getattr__, __dir__
