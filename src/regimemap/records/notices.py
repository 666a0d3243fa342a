"""Warnings as data: a :class:`Notice` is what a workflow tells its user besides its results.

A workflow (:mod:`regimemap.workflows`) does not print: it returns its warnings in
its record, each a :class:`Notice` with a stable ``code`` a script can test, the
sentence a person reads, and the quantity (and value) it is about.  The command
line prints them on standard error (``regimemap: warning: MESSAGE``); a notebook
reads them from the record.  The standard library only, in the lowest layer so
that every layer may make one.

>>> n = Notice("still-moving", "the block is still moving", quantity="end_time", value=9.5)
>>> n.as_dict()
{'code': 'still-moving', 'message': 'the block is still moving', 'quantity': 'end_time', 'value': 9.5}
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

__all__ = ["Notice"]


@dataclass(frozen=True)
class Notice:
    """One warning of a workflow, as data.

    Attributes
    ----------
    code : str
        A short stable identifier, lower case with hyphens (``"still-moving"``,
        ``"implausible-value"``): what a script tests.
    message : str
        The sentence a person reads (no ``regimemap: warning:`` prefix).
    quantity : str or None
        The input or result the warning is about (a parameter or key name).
    value : float or None
        Its value, when it has one.
    """

    code: str
    message: str
    quantity: str | None = None
    value: float | None = None

    def as_dict(self) -> dict[str, Any]:
        """The notice as a JSON-ready dictionary (the four fields)."""
        return {"code": self.code, "message": self.message, "quantity": self.quantity, "value": self.value}
