"""A design point of the k-mu plane (the data type shared by queries, maps and readers)."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DesignPoint"]


@dataclass(frozen=True)
class DesignPoint:
    """A named point of the k-mu plane, optionally with its own gamma, kprime and loads.

    A load left ``None`` is the caller's default (see :func:`regimemap.query_points`).
    """

    k: float
    mu: float
    name: str = ""
    gamma: float | None = None
    kprime: float | None = None
    buoyancy: float | None = None
    uplift: float | None = None
    uplift_ratio: float | None = None
    uplift_arm: float | None = None
    gyration: float | None = None
    crest: float | None = None

    @property
    def loads(self) -> dict[str, float]:
        """The loads this point carries itself (its CSV columns), by keyword."""
        return {key: v for key in LOAD_FIELDS if (v := getattr(self, key)) is not None}


#: The load fields of a point: the keywords of the loads of :class:`~regimemap.Parameters`.
LOAD_FIELDS: tuple[str, ...] = ("buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration",
                                "crest")
