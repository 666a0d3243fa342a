"""The record types every workflow uses: :class:`~regimemap.mechanics.records.Field`,
:class:`~regimemap.mechanics.records.Record` and :class:`~regimemap.mechanics.notices.Notice`
(defined in the lowest layer, so that io may write the records)."""

from __future__ import annotations

from ..mechanics.notices import Notice
from ..mechanics.records import Field, Record

__all__ = ["Field", "Notice", "Record"]
