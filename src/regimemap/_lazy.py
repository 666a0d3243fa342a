"""Lazy public names for a package: one mechanism for every ``__init__`` (PEP 562).

A package lists which of its submodules defines each public name; :func:`attach`
returns the module-level ``__getattr__`` and ``__dir__`` that import a submodule
the first time one of its names is read, keep the value in the package's globals
(so the next read is an ordinary attribute lookup), and list the public names in
``dir()`` before any of them is imported.  The same idea as scientific Python's
``lazy_loader.attach`` (SPEC 1), in the few lines this project needs.

Each package also imports the same names under ``if TYPE_CHECKING:`` so that mypy
and IDEs see their real types, and assigns the two functions under
``if not TYPE_CHECKING:`` so that, for mypy, an unknown name is an error and not
``Any``::

    if TYPE_CHECKING:
        from .save import save_figure

    __all__ = ["save_figure"]

    if not TYPE_CHECKING:
        __getattr__, __dir__ = attach(__name__, {"save": ["save_figure"]})
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["attach"]


def attach(package: str, submodules: Mapping[str, Sequence[str]]
           ) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """The ``__getattr__`` and ``__dir__`` of a package whose names are imported on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    submodules : mapping of str to sequence of str
        Each submodule and the public names it defines, spelled as the module of a
        relative import from the package without its first dot: ``"fits"`` is the
        package's own submodule, ``".study.run"`` its sibling package's (so an index
        package such as :mod:`regimemap.workflows` names where each name lives).

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
        When a name is listed under two submodules.
    """
    home: dict[str, str] = {}
    for submodule, names in submodules.items():
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
