"""The error of a design file, and the closest known name its messages suggest.

Shared by the readers of the design file's tables (:mod:`regimemap.caisson.file`,
:mod:`regimemap.lifetime.file`).
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping

__all__ = ["DesignFileError", "did_you_mean"]


class DesignFileError(ValueError):
    """A design file that cannot be read, parsed or accepted."""


def did_you_mean(name: str, known: Mapping[str, object]) -> str:
    """`` (did you mean 'depth'?)`` for the known name closest to ``name`` (or one that differs only
    in case); "" when none is close."""
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
    if not close:
        close = [k for k in known if k.lower() == name.lower()]
    return f" (did you mean {close[0]!r}?)" if close else ""
