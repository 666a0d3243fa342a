"""What every workflow record shares: its notices and a field table for its rich display.

The standard library only, in the lowest layer, so that a record may be defined in the layer
of the data it holds (the domain packages') and written by :mod:`regimemap.io`.

A record is a frozen dataclass that holds a workflow's inputs, the intermediate
quantities a designer checks, its warnings as :class:`~regimemap.records.notices.Notice`
data, and its results.  Its :data:`Record.FIELDS` table names the fields a person
reads first, with their units and meaning; the HTML display of a notebook
(``_repr_html_``) and :meth:`Record.field_rows` read that one table.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from typing import Any, ClassVar

from .htmltable import html_table
from .notices import Notice

__all__ = ["Field", "Record"]


@dataclass(frozen=True)
class Field:
    """One row of a record's field table.

    Attributes
    ----------
    path : str
        The attribute to read, dotted for a nested one (``"result.expected_sliding"``).
    label : str
        Its name for people (the report's symbol where it has one).
    unit : str
        Its unit (``""`` for a dimensionless number).
    description : str
        What it is, in a few words.
    """

    path: str
    label: str
    unit: str = ""
    description: str = ""

    def value(self, record: object) -> Any:
        """The field's value in ``record`` (None where a step of the path is None)."""
        value: Any = record
        for part in self.path.split("."):
            if value is None:
                return None
            value = operator.attrgetter(part)(value)
        return value() if callable(value) else value


class Record:
    """Mixin of the workflow records: the field table, the notices and the HTML display.

    Subclasses are frozen dataclasses with a ``notices`` field (a tuple of
    :class:`~regimemap.records.notices.Notice`) and a class-level
    :data:`FIELDS` table.
    """

    #: The fields a person reads first, in order.
    FIELDS: ClassVar[tuple[Field, ...]] = ()
    #: The caption of the HTML table.
    CAPTION: ClassVar[str] = ""
    notices: tuple[Notice, ...]

    def field_rows(self) -> list[tuple[str, Any, str, str]]:
        """``(label, value, unit, description)`` for every field of :data:`FIELDS`."""
        return [(f.label, f.value(self), f.unit, f.description) for f in self.FIELDS]

    def _repr_html_(self) -> str:
        rows: list[tuple[object, ...]] = [(label, value, unit, text)
                                          for label, value, unit, text in self.field_rows()]
        rows += [(f"warning: {n.code}", n.message) for n in self.notices]
        return html_table(rows, caption=self.CAPTION, header=("", "value", "unit", ""))
