"""The answer of a point query: :class:`PointResult`, its words and its table.

:func:`regimemap.maps.query.query_point` computes it; :data:`INITIATION_FIELDS`
describes the reactions and accelerations at initiation once, for its table here
and for the text report of :func:`regimemap.maps.record_tables.format_result`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..mechanics.block import Case, Parameters
from ..mechanics.modes import Mode
from ..mechanics.solver import Hypothesis
from ..records.htmltable import html_table
from ..records.numbers import number
from .describe import loads_text
from .margins import Margin, finite_or_none, negligible

__all__ = ["INITIATION_FIELDS", "PointResult", "margin_words"]

#: The reactions and accelerations at initiation (attributes of :class:`PointResult`) and
#: what each is, in the order they are shown.
INITIATION_FIELDS: tuple[tuple[str, str], ...] = (
    ("fx", "horizontal reaction / mg (positive to the right)"),
    ("fy", "normal reaction / mg"),
    ("xi", "where f_y acts, from C / B (-1 = O, +1 = O')"),
    ("xdd", "horizontal acceleration of C / g (negative = to the left)"),
    ("ydd", "vertical acceleration of C / g"),
    ("thdd", "angular acceleration * B/g (positive = counter-clockwise)"),
)


@dataclass(frozen=True)
class PointResult:
    """The mode at one point of the k-mu plane with the physics at initiation.

    Attributes
    ----------
    k, mu, gamma, kprime : float
        The point (force F/(mg), friction coefficient) and the parameters
        (aspect ratio H/B, force height h/H).
    name : str
        The point's name ("" if none).
    mode : Mode
        The mode of the final map (:func:`regimemap.classify`).
    hypothesis : Hypothesis
        The solver's contact hypothesis of that mode (for SL, slide left).
    fx, fy : float
        Horizontal and vertical reactions of the base divided by m g [-].
    xi : float
        Point of action of f_y measured from C, divided by B [-] (-1 at O, +1 at O').
    xdd, ydd : float
        Horizontal and vertical accelerations of C divided by g [-].
    thdd : float
        Angular acceleration theta'' B/g [-], positive counter-clockwise
        (rocking about O has thdd > 0).
    slip : float or None
        Horizontal acceleration of the slipping contact divided by g [-]
        (of C when the whole base slides, of the pivot corner in slide-rock);
        None when the contact sticks (RE, RO).
    lift : float or None
        Upward acceleration of the corner that lifts off divided by g [-];
        None for full base contact (RE, SL).
    case : Case
        The report's case of (gamma, kprime).
    admissible : tuple of Mode
        Every mode the equations of motion admit at the point (in
        :data:`~regimemap.mechanics.modes.SELECTION_ORDER`: lift-off, then
        Section 4.7's PRIORITY).  Section 4.7 (least constraint with loads)
        picks the first, which is :attr:`mode`.
    hypothesis_admissible : bool
        Whether the solver finds the chosen hypothesis admissible (True for
        valid input wherever the solver can solve; reported rather than assumed).
    solvable : bool
        False where the solver reports the system of the chosen hypothesis
        as singular; the physics (fx ... thdd) is then NaN (None in JSON) and
        the admissible set may be empty.  This happens at the singular
        friction mu = mu_B' of slide-rock, and, as a known limitation of the
        solver's singularity test, for large gamma or mu.
    margin_k, margin_mu : Margin
        The margins along k (mu fixed) and along mu (k fixed).
    thresholds : dict
        The map's thresholds at this k: ``mu_star`` (3.24)/(4.40),
        ``upper_line`` 1/g - k k' (CD above C, AB below), ``lower_line``
        -1/g - k k' (DC), ``k_A`` (3.5)/(4.10) and ``mu_Bprime`` (4.49)
        (their generalised forms with loads).
    loads : dict
        The loads of the block (``buoyancy`` ... ``crest``) when it carries any,
        else empty.
    """

    k: float
    mu: float
    gamma: float
    kprime: float
    mode: Mode
    hypothesis: Hypothesis
    fx: float
    fy: float
    xi: float
    xdd: float
    ydd: float
    thdd: float
    slip: float | None
    lift: float | None
    case: Case
    admissible: tuple[Mode, ...]
    hypothesis_admissible: bool
    margin_k: Margin
    margin_mu: Margin
    thresholds: dict[str, float] = field(default_factory=dict)
    name: str = ""
    solvable: bool = True
    loads: dict[str, Any] = field(default_factory=dict)

    @property
    def several_admissible(self) -> bool:
        """True when the solver admits more than one mode at the point."""
        return len(self.admissible) > 1

    @property
    def on_boundary(self) -> bool:
        """True when the point lies on a boundary of the map (a margin of 0 in some direction)."""
        return any(c is not None and negligible(c.delta, m.value)
                   for m in (self.margin_k, self.margin_mu) for c in (m.up, m.down))

    @property
    def nonunique(self) -> bool:
        """True inside a zone of non-uniqueness: several modes admitted off any boundary.

        This is Section 4.7's situation (below C, mu > mu_B'), as opposed to a
        point on a boundary where the modes of both sides are admissible.
        """
        return self.several_admissible and not self.on_boundary

    @property
    def chosen_by(self) -> str:
        """How the mode was chosen: ``"unique"``, ``"boundary"``, ``"Section 4.7"``
        (``"least constraint"`` for a loaded block), or ``"map only"`` when the
        solver admits nothing (see :attr:`solvable`)."""
        if not self.admissible:
            return "map only"
        if not self.several_admissible:
            return "unique"
        if self.on_boundary:
            return "boundary"
        return "least constraint" if self.loads else "Section 4.7"

    def as_dict(self) -> dict[str, Any]:
        """A JSON-ready dict (labels for modes, None for non-finite numbers)."""
        return {
            "name": self.name,
            "k": self.k,
            "mu": self.mu,
            "gamma": self.gamma,
            "kprime": self.kprime,
            "mode": self.mode.label,
            "mode_code": int(self.mode),
            "description": self.mode.description,
            "hypothesis": self.hypothesis.name,
            "contact": self.hypothesis.contact,
            **{key: finite_or_none(getattr(self, key))
               for key in (*(key for key, _ in INITIATION_FIELDS), "slip", "lift")},
            "case": self.case.value,
            "case_description": self.case.description,
            "admissible": [m.label for m in self.admissible],
            "hypothesis_admissible": bool(self.hypothesis_admissible),
            "solvable": bool(self.solvable),
            "chosen_by": self.chosen_by,
            "margin": {"k": self.margin_k.as_dict(), "mu": self.margin_mu.as_dict()},
            "thresholds": {key: finite_or_none(v) for key, v in self.thresholds.items()},
            **({"loads": dict(self.loads)} if self.loads else {}),
        }

    # -- display: a readable repr and a table for Jupyter -------------------------------------
    def _block_text(self) -> str:
        loads = loads_text(Parameters(self.gamma, self.kprime, **self.loads)) if self.loads else ""
        return f"gamma={self.gamma:g}, k'={self.kprime:g}" + (f"; {loads}" if loads else "")

    def __repr__(self) -> str:
        """Two lines: the point, the block and the mode; the margins and the main reactions."""
        name = f"{self.name!r}: " if self.name else ""
        return (f"PointResult({name}k={self.k:g}, mu={self.mu:g} ({self._block_text()}) -> "
                f"{self.mode.label} ({self.mode.description}), {self.chosen_by};\n"
                f"  margin {margin_words(self.margin_k)}, {margin_words(self.margin_mu)}; "
                f"fx={number(self.fx)}, fy={number(self.fy)}, thdd={number(self.thdd)})")

    def _repr_html_(self) -> str:
        """The answer as a small table (Jupyter's rich display)."""
        name = f"{self.name}: " if self.name else ""
        rows: list[tuple[object, ...]] = [
            ("mode", self.mode.label, self.mode.description),
            ("chosen by", self.chosen_by, "admissible (solver): "
             + (", ".join(m.label for m in self.admissible) or "none")),
            ("loads" if self.loads else "case",
             loads_text(Parameters(self.gamma, self.kprime, **self.loads)) if self.loads
             else self.case.value, "" if self.loads else self.case.description),
            *((key, getattr(self, key), what) for key, what in INITIATION_FIELDS),
            ("slip", self.slip, "acceleration of the slipping contact / g (- : sticks)"),
            ("lift", self.lift, "upward acceleration of the lifting corner / g"),
            ("margin k", margin_words(self.margin_k, with_name=False),
             "smallest change of k (mu fixed) that changes the mode"),
            ("margin mu", margin_words(self.margin_mu, with_name=False),
             "smallest change of mu (k fixed) that changes the mode"),
        ]
        return html_table(rows, caption=f"{name}k = {self.k:g}, mu = {self.mu:g} "
                          f"({self._block_text()})", header=("", "value", ""))


def margin_words(m: Margin, with_name: bool = True) -> str:
    """The nearest change of a margin in words: ``k -52.4% -> RE``, ``mu: no change``."""
    c = m.nearest
    head = f"{m.variable} " if with_name else ""
    if c is None:
        return f"{head}no change".strip() if not with_name else f"{m.variable}: no change"
    if c.on_boundary:
        return f"{head}0 (on the boundary) -> {c.to.label}"
    sign = "-" if c.direction == "down" else "+"
    if c.relative is None:
        return f"{head}{sign}{number(c.delta)} -> {c.to.label}"
    return f"{head}{sign}{number(100.0 * c.relative, 3)}% -> {c.to.label}"
