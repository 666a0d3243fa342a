"""Requirements and their verdicts: a computed value against a required limit.

A :class:`Check` is plain data -- the name of a requirement, the value the
design reaches, the limit it must meet and the sense of the comparison -- so
that the text report, the JSON, the figures and the exit code of ``--check``
all read one verdict.  A value that is not finite never passes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

__all__ = ["Check", "all_pass", "failed"]


@dataclass(frozen=True)
class Check:
    """One requirement: ``value`` compared with ``required``.

    Parameters
    ----------
    name : str
        What is required, in words (``"sliding safety factor"``).
    value : float
        The value the design reaches.
    required : float
        The limit.
    relation : {">=", "<="}
        ``">="``: the value must be at least ``required`` (a safety factor);
        ``"<="``: at most ``required`` (a sliding distance, a probability).
    unit : str
        The unit of ``value`` and ``required`` (``""`` for a pure number).

    Examples
    --------
    >>> Check.at_least("sliding safety factor", 1.16, 1.2).passed
    False
    >>> Check.at_most("expected sliding distance", 0.04, 0.1, "m").passed
    True
    """

    name: str
    value: float
    required: float
    relation: Literal[">=", "<="]
    unit: str = ""

    @classmethod
    def at_least(cls, name: str, value: float, required: float, unit: str = "") -> Check:
        """A requirement ``value >= required``."""
        return cls(name, float(value), float(required), ">=", unit)

    @classmethod
    def at_most(cls, name: str, value: float, required: float, unit: str = "") -> Check:
        """A requirement ``value <= required``."""
        return cls(name, float(value), float(required), "<=", unit)

    @property
    def passed(self) -> bool:
        """Whether the requirement is met (never for a value that is not finite)."""
        if not math.isfinite(self.value):
            return False
        if self.relation == ">=":
            return self.value >= self.required
        return self.value <= self.required

    @property
    def verdict(self) -> str:
        """``"PASS"`` or ``"FAIL"``."""
        return "PASS" if self.passed else "FAIL"


def failed(checks: Iterable[Check]) -> list[Check]:
    """The checks that fail, in their order."""
    return [c for c in checks if not c.passed]


def all_pass(checks: Iterable[Check]) -> bool:
    """Whether every check passes (``True`` for none)."""
    return not failed(checks)
