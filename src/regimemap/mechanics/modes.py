"""Modes of response at initiation, as integer codes.

The report (Chapters III and IV) names the modes RE (rest), SL (slide), RO (rock
about the left corner O), SRO- (slide-rock about O with the corner O slipping
left, x_O'' <= 0), SRO+ (slide-rock about O with O slipping right) and SRO'-
(slide-rock about the right corner O' with O' slipping left).  Two more contact
hypotheses exist for the equations-of-motion solver: rock about O' (RO') and
slide-rock about O' with O' slipping right (SRO'+).  The report shows (4.57)
that RO' is never possible; the solver confirms that neither ever wins on the
report's block.  With vertical loads (buoyancy, uplift) both can win, and a ninth mode
appears: lift-off (LO), no contact at all.

Codes are small integers so that whole maps fit in ``uint8`` arrays, after the
integer regime codes of ``fluids.two_phase``.
"""

from __future__ import annotations

from enum import IntEnum

__all__ = ["Mode", "MAP_MODES", "LOADED_MAP_MODES", "PRIORITY", "SELECTION_ORDER"]


class Mode(IntEnum):
    """A mode of response at initiation (integer code).

    Attributes
    ----------
    label : str
        The report's symbol in plain text: ``RE``, ``SL``, ``RO``, ``SRO-``,
        ``SRO+``, ``SRO'-``, ``RO'``, ``SRO'+`` or ``LO``.
    tex : str
        The symbol as matplotlib mathtext, e.g. ``$SRO_{-}$``.
    description : str
        A short English description.
    """

    RE = 0
    SL = 1
    RO = 2
    SRO_MINUS = 3
    SRO_PLUS = 4
    SRO_PRIME_MINUS = 5
    RO_PRIME = 6
    SRO_PRIME_PLUS = 7
    LO = 8

    @property
    def label(self) -> str:
        return _LABELS[self][0]

    @property
    def tex(self) -> str:
        return _LABELS[self][1]

    @property
    def description(self) -> str:
        return _LABELS[self][2]

    @classmethod
    def from_label(cls, label: str) -> Mode:
        """Return the mode whose :attr:`label` is ``label`` (case-insensitive).

        Raises
        ------
        ValueError
            If no mode has that label; the message lists the labels.
        """
        wanted = label.strip().upper().replace("’", "'")
        for mode in cls:
            if mode.label.upper() == wanted or mode.name == wanted:
                return mode
        known = ", ".join(m.label for m in cls)
        raise ValueError(f"unknown mode {label!r}; known modes: {known}")

    def __str__(self) -> str:  # pragma: no cover - trivial
        return self.label


_LABELS = {
    Mode.RE: ("RE", r"$RE$", "rest"),
    Mode.SL: ("SL", r"$SL$", "slide"),
    Mode.RO: ("RO", r"$RO$", "rock about O"),
    Mode.SRO_MINUS: ("SRO-", r"$SRO_{-}$", "slide-rock about O, O slipping left"),
    Mode.SRO_PLUS: ("SRO+", r"$SRO_{+}$", "slide-rock about O, O slipping right"),
    Mode.SRO_PRIME_MINUS: ("SRO'-", r"$SRO'_{-}$", "slide-rock about O', O' slipping left"),
    Mode.RO_PRIME: ("RO'", r"$RO'$", "rock about O'"),
    Mode.SRO_PRIME_PLUS: ("SRO'+", r"$SRO'_{+}$", "slide-rock about O', O' slipping right"),
    Mode.LO: ("LO", r"$LO$", "lift-off (no contact)"),
}

#: The modes that can appear on a map (the report's six), in code order.
MAP_MODES: tuple[Mode, ...] = (
    Mode.RE,
    Mode.SL,
    Mode.RO,
    Mode.SRO_MINUS,
    Mode.SRO_PLUS,
    Mode.SRO_PRIME_MINUS,
)

#: The modes that can appear on the map of a loaded block, in code order: the six,
#: rock about O' (where uplift near O lifts O) and lift-off.  Slide-rock about O'
#: slipping right is admissible in places but never chosen (measured,
#: ``tests/mechanics/test_loaded_regions.py``).
LOADED_MAP_MODES: tuple[Mode, ...] = MAP_MODES + (Mode.RO_PRIME, Mode.LO)

#: Section 4.7's order: where several modes are admissible the first one holds
#: (slide inside the slide region, slide-rock about O' below DC, then rock).
PRIORITY: tuple[Mode, ...] = (
    Mode.RE,
    Mode.SL,
    Mode.SRO_PRIME_MINUS,
    Mode.RO,
    Mode.SRO_MINUS,
    Mode.SRO_PLUS,
    Mode.RO_PRIME,
    Mode.SRO_PRIME_PLUS,
)

#: The order in which the solver breaks ties of Gauss's least constraint
#: (:func:`regimemap.mechanics.solver.least_constraint`): lift-off (whose
#: constraint is 0) first, then Section 4.7's :data:`PRIORITY`.  Wherever several
#: modes are admissible off the boundaries, least constraint chooses the first of
#: them in this order (measured: ``tests/mechanics/test_loaded_regions.py``).
SELECTION_ORDER: tuple[Mode, ...] = (Mode.LO,) + PRIORITY
