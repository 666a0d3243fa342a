"""A design point of the k-mu plane (the data type shared by queries, maps and readers)."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DesignPoint"]


@dataclass(frozen=True)
class DesignPoint:
    """A named point of the k-mu plane, optionally with its own gamma and kprime."""

    k: float
    mu: float
    name: str = ""
    gamma: float | None = None
    kprime: float | None = None
