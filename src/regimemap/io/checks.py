"""The verdict of the requirements as text lines and JSON (``checks``)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..mechanics.checks import Check, all_pass
from .numbers import round_sig

__all__ = ["checks_json", "checks_lines"]


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
    return [{"name": c.name, "value": round_sig(c.value), "required": round_sig(c.required),
             "relation": c.relation, "unit": c.unit, "pass": c.passed} for c in checks]
