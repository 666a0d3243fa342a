"""Registers the command modules with the ``regimemap`` group.

Each module below defines its commands with ``@cli.command`` on import.
"""

from __future__ import annotations

import importlib

_MODULES = (
    "plot",  # plot, figure, figures
    "query",  # classify
    "export",  # export
    "atlas",  # atlas, animate
    "bench",  # (internal) nothing registered if absent
)

for _name in _MODULES:
    try:
        importlib.import_module(f"{__package__}.{_name}")
    except ModuleNotFoundError as exc:  # a module not written yet
        if exc.name != f"{__package__}.{_name}":
            raise
