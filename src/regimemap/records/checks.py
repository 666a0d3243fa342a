"""Requirements and their verdicts: a computed value against a required limit.

A :class:`Check` is plain data -- the name of a requirement, the value the
design reaches, the limit it must meet and the sense of the comparison -- so
that the text report, the JSON, the figures and the exit code of ``--check``
all read one verdict, written here as text lines (:func:`checks_lines`) and as JSON
(:func:`checks_json`).  A value that is not finite never passes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from .numbers import rounded

__all__ = ["Check", "all_pass", "checks_json", "checks_lines", "failed"]


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


def _number(value: float, unit: str) -> str:
    text = f"{value:.4g}"
    return f"{text} {unit}" if unit else text


def checks_lines(checks: Sequence[Check]) -> list[str]:
    """One line per requirement, PASS or FAIL first, then the overall verdict.

    Examples
    --------
    >>> for line in checks_lines([Check.at_least("sliding safety factor", 1.16, 1.2)]):
    ...     print(line)
    FAIL  sliding safety factor 1.16 >= 1.2
    verdict: FAIL (1 of 1 requirements not met)
    """
    lines = [f"{c.verdict}  {c.name} {_number(c.value, c.unit)} {c.relation} {_number(c.required, c.unit)}"
             for c in checks]
    bad = sum(not c.passed for c in checks)
    lines.append("verdict: PASS (every requirement met)" if all_pass(checks)
                 else f"verdict: FAIL ({bad} of {len(checks)} requirements not met)")
    return lines


def checks_json(checks: Sequence[Check]) -> list[dict[str, Any]]:
    """``[{"name", "value", "required", "relation", "unit", "pass"}, ...]`` (numbers to 12 digits)."""
    rows = [{"name": c.name, "value": float(c.value), "required": float(c.required), "relation": c.relation,
             "unit": c.unit, "pass": c.passed} for c in checks]
    return rounded(rows)
