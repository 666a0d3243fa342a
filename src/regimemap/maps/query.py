"""Point queries: the mode at a design point, the physics at initiation and the margin.

A designer asks "what happens to *my* caisson?": :func:`query_point` answers
for one point (k, mu) of the map, :func:`query_points` for many.  After the
regime functions of ``fluids.two_phase`` (which return the regime together with
the dimensionless groups that decided it), the answer is a
:class:`PointResult` holding

* the mode of the final map (:func:`regimemap.classify`, Section 4.7 below C);
* the reactions and accelerations at initiation of that mode, from the
  independent equations-of-motion solver (:func:`regimemap.solver.solve`) for
  the mode's contact hypothesis: ``fx``, ``fy`` (divided by m g), ``xi`` (the
  point of action of f_y from C, divided by B; -1 is the corner O, +1 is O'),
  ``xdd``, ``ydd`` (accelerations of C divided by g), ``thdd`` (theta'' B/g,
  positive counter-clockwise), ``slip`` (horizontal acceleration of the
  slipping contact divided by g; ``None`` when the contact sticks) and ``lift``
  (upward acceleration of the lifting corner divided by g; ``None`` for full
  base contact);
* every mode the equations of motion admit at the point (several on a
  boundary, and below C for mu > mu_B' = (4+g^2)/(3g), (4.49), where rigid
  contact with friction is not unique - Painleve's paradox - and Section 4.7
  of the report picks one);
* the **margin**: the smallest change of k (mu held fixed) and of mu (k held
  fixed), up or down, that changes the mode, and the mode it changes to;
* the thresholds at the point's k (mu*(k), the lines CD/AB and DC, k_A, mu_B').

How the margin is found (exact)
-------------------------------
Along a line of constant mu the rule of :func:`regimemap.classify` can only
change where mu equals one of its thresholds or where one of its conditions
flips, and each of these is the root of a *linear* equation in k:

=========================  ==================================================
OA, mu = k                  k = mu                                (3.4), (4.7)
AB/AE, k = k_A              k = 1/(gamma (1+k'))            (3.5), (4.10)
CD/AB, mu = 1/g - k k'      k = (1/g - mu)/k'            Section III.2, (4.21)
DC, mu = -1/g - k k'        k = (-1/g - mu)/k'                         (4.20)
mu = mu*(k), f_x >= 0       k = (mu d - b)/(a - mu c)           (3.24), (4.40)
mu = mu*(k), f_x <= 0       k = -(mu d + b)/(a + mu c)          (3.24), (3.45)
f_x = 0 (ak + b = 0)        k = -b/a                           cases 2/3
=========================  ==================================================

Along a line of constant k the thresholds are the values k, 1/g - k k',
-1/g - k k' and mu*(k) themselves.  Between two consecutive roots the mode is
constant, so :func:`margin` evaluates :func:`~regimemap.classify` at each root
and in the middle of each gap, walking away from the point, and stops at the
first place whose mode differs; it then bisects on ``classify`` between the
last probe with the point's mode and the first without, down to adjacent
floating-point numbers.  The reported boundary ``at`` is the first value
found with another mode, so ``classify`` gives the point's mode everywhere
strictly between the point and ``at`` and another mode at ``at``.

Search range and special values
-------------------------------
The search covers the whole half-line: k (or mu) from the point's value up
to infinity, and down to 0 inclusive.  Because the list of roots is complete,
"no change" is exact: a direction whose mode never changes (for instance mu
going up inside RE or RO) is reported as ``None``.  Going down from a value of
0 is impossible and is reported as ``None`` too.  The relative change is
``|at - x|/x``; when the point's own value x is 0 it is undefined and reported
as ``None`` (the absolute change ``delta`` is always given).  A point exactly
on a boundary has a margin of 0 in the direction that leaves its region.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass, field
from typing import Any, Iterable, Sequence

import numpy as np

from .classify import PRIORITY, _thresholds, classify
from .classify import _constants as _classify_constants
from ..mechanics.modes import Mode
from ..mechanics.block import Case, Parameters
from ..io.points import DesignPoint
from ..mechanics.solver import Hypothesis, solve
from ..mechanics.validation import check_gamma, check_kprime, check_nonnegative_array

__all__ = [
    "Crossing",
    "Margin",
    "PointResult",
    "query_point",
    "query_points",
    "margin",
    "HYPOTHESES_OF_MODE",
    "CSV_COLUMNS",
    "result_row",
    "format_result",
]

#: The contact hypotheses of each mode, in the order tried (the first admissible one is used).
HYPOTHESES_OF_MODE: dict[Mode, tuple[Hypothesis, ...]] = {}
for _h in Hypothesis:
    HYPOTHESES_OF_MODE.setdefault(_h.mode, ())
    HYPOTHESES_OF_MODE[_h.mode] += (_h,)

#: Columns of the CSV written by ``regimemap classify --points`` (:func:`results_to_rows`).
CSV_COLUMNS: tuple[str, ...] = (
    "name", "k", "mu", "gamma", "kprime", "case", "mode", "hypothesis",
    "fx", "fy", "xi", "xdd", "ydd", "thdd", "slip", "lift", "admissible",
    "margin_k", "margin_k_direction", "margin_k_at", "margin_k_to",
    "margin_mu", "margin_mu_direction", "margin_mu_at", "margin_mu_to",
)

#: Points are processed in blocks of this many (the solver builds 6x6 systems per point).
_BLOCK = 20_000
#: Largest number of bisection steps (enough to reach adjacent doubles).
_BISECT_STEPS = 1100


def _num(v: float | None) -> float | None:
    """A float for JSON: non-finite numbers become None."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


# --------------------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Crossing:
    """The nearest change of mode in one direction along k or along mu.

    Attributes
    ----------
    direction : {"up", "down"}
        Whether the value increases or decreases.
    at : float
        The first value (of k or of mu) where the mode differs from the point's.
    delta : float
        ``|at - x|``, the absolute change (x is the point's value).
    relative : float or None
        ``delta / x``; None when x is 0.
    to : Mode
        The mode just beyond the boundary (the mode at ``at`` if the region
        beyond is the point's own mode again, i.e. an isolated boundary point).
    """

    direction: str
    at: float
    delta: float
    relative: float | None
    to: Mode

    def as_dict(self) -> dict[str, Any]:
        return {
            "direction": self.direction,
            "at": _num(self.at),
            "delta": _num(self.delta),
            "relative": _num(self.relative),
            "to": self.to.label,
        }


@dataclass(frozen=True)
class Margin:
    """The smallest change of one variable (k or mu), the other held fixed, that changes the mode.

    Attributes
    ----------
    variable : {"k", "mu"}
    value : float
        The point's value of the variable.
    up, down : Crossing or None
        The nearest change when the variable increases / decreases; None when
        the mode never changes in that direction (or the value is 0 and
        cannot decrease).
    """

    variable: str
    value: float
    up: Crossing | None
    down: Crossing | None

    @property
    def nearest(self) -> Crossing | None:
        """The smaller of :attr:`up` and :attr:`down` (by absolute change; down on a tie)."""
        options = [c for c in (self.down, self.up) if c is not None]
        return min(options, key=lambda c: c.delta) if options else None

    @property
    def relative(self) -> float | None:
        """Relative change of the nearest crossing (None if none, or if the value is 0)."""
        n = self.nearest
        return None if n is None else n.relative

    def as_dict(self) -> dict[str, Any]:
        n = self.nearest
        return {
            "variable": self.variable,
            "value": _num(self.value),
            "relative": None if n is None else _num(n.relative),
            "delta": None if n is None else _num(n.delta),
            "direction": None if n is None else n.direction,
            "at": None if n is None else _num(n.at),
            "to": None if n is None else n.to.label,
            "up": None if self.up is None else self.up.as_dict(),
            "down": None if self.down is None else self.down.as_dict(),
        }


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
        :data:`~regimemap.classify.PRIORITY` order).  Section 4.7 picks the
        first, which is :attr:`mode`.
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
        -1/g - k k' (DC), ``k_A`` (3.5)/(4.10) and ``mu_Bprime`` (4.49).
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

    @property
    def several_admissible(self) -> bool:
        """True when the solver admits more than one mode at the point."""
        return len(self.admissible) > 1

    @property
    def on_boundary(self) -> bool:
        """True when the point lies on a boundary of the map (a margin of 0 in some direction)."""
        for m in (self.margin_k, self.margin_mu):
            for c in (m.up, m.down):
                if c is not None and c.delta <= 4.0 * np.spacing(max(abs(m.value), 1e-300)):
                    return True
        return False

    @property
    def nonunique(self) -> bool:
        """True inside a zone of non-uniqueness: several modes admitted off any boundary.

        This is Section 4.7's situation (below C, mu > mu_B'), as opposed to a
        point on a boundary where the modes of both sides are admissible.
        """
        return self.several_admissible and not self.on_boundary

    @property
    def chosen_by(self) -> str:
        """How the mode was chosen: ``"unique"``, ``"boundary"``, ``"Section 4.7"``, or
        ``"map only"`` when the solver admits nothing (see :attr:`solvable`)."""
        if not self.admissible:
            return "map only"
        if not self.several_admissible:
            return "unique"
        return "boundary" if self.on_boundary else "Section 4.7"

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
            "fx": _num(self.fx),
            "fy": _num(self.fy),
            "xi": _num(self.xi),
            "xdd": _num(self.xdd),
            "ydd": _num(self.ydd),
            "thdd": _num(self.thdd),
            "slip": _num(self.slip),
            "lift": _num(self.lift),
            "case": self.case.value,
            "case_description": self.case.description,
            "admissible": [m.label for m in self.admissible],
            "hypothesis_admissible": bool(self.hypothesis_admissible),
            "solvable": bool(self.solvable),
            "chosen_by": self.chosen_by,
            "margin": {"k": self.margin_k.as_dict(), "mu": self.margin_mu.as_dict()},
            "thresholds": {key: _num(v) for key, v in self.thresholds.items()},
        }


# --------------------------------------------------------------------------------------
# the margin engine (vectorised over points)
# --------------------------------------------------------------------------------------
def _constants(g: np.ndarray, kp: np.ndarray) -> tuple[np.ndarray, ...]:
    """a, b, c, d of (3.18)-(3.21), (4.42)-(4.45), computed exactly as classify does."""
    return _classify_constants(g, kp)[:4]


def _roots_along_k(mu: np.ndarray, g: np.ndarray, kp: np.ndarray) -> np.ndarray:
    """Every k where the rule of classify may change along the line of constant mu; shape (n, 7)."""
    a, b, c, d = _constants(g, kp)
    with np.errstate(divide="ignore", invalid="ignore"):
        roots = [
            mu,  # OA
            1.0 / (g * (1.0 + kp)),  # k_A
            (1.0 / g - mu) / kp,  # upper line (CD/AB)
            (-1.0 / g - mu) / kp,  # lower line (DC)
            (mu * d - b) / (a - mu * c),  # mu* with f_x >= 0
            -(mu * d + b) / (a + mu * c),  # mu* with f_x <= 0
            -b / a,  # f_x = 0
        ]
    return np.stack(roots, axis=1)


def _roots_along_mu(k: np.ndarray, g: np.ndarray, kp: np.ndarray) -> np.ndarray:
    """Every mu where the rule of classify may change along the line of constant k; shape (n, 4)."""
    _, lower, upper, mu_s, _ = _thresholds(k, g, kp)
    return np.stack([k, upper, lower, mu_s], axis=1)


def _classify_along(var: str, values: np.ndarray, other: np.ndarray, g: np.ndarray,
                    kp: np.ndarray) -> np.ndarray:
    """classify with ``var`` = values (n, m) and the other variable fixed per row."""
    o, gg, kk = (np.broadcast_to(v[:, None], values.shape) for v in (other, g, kp))
    if var == "k":
        return classify(values, o, gg, kk)
    return classify(o, values, gg, kk)


def _walk(var: str, x: np.ndarray, other: np.ndarray, g: np.ndarray, kp: np.ndarray,
          m0: np.ndarray, roots: np.ndarray, up: bool
          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nearest change of mode from x in one direction; returns (found, at, to)."""
    n = x.size
    xc = x[:, None]
    ok = np.isfinite(roots) & (roots >= 0.0)
    if up:
        ok &= roots > xc
        cand = np.sort(np.where(ok, roots, np.inf), axis=1)
    else:
        ok &= roots < xc
        cand = np.where(ok, roots, -np.inf)
        # 0 ends the search downward; it is a probe of its own
        cand = np.concatenate([cand, np.where(xc > 0.0, 0.0, -np.inf)], axis=1)
        cand = -np.sort(-cand, axis=1)
        # drop duplicated zeros (a root at 0 and the end point)
        dup = np.zeros_like(cand, dtype=bool)
        dup[:, 1:] = cand[:, 1:] == cand[:, :-1]
        cand = np.where(dup, -np.inf, cand)
        cand = -np.sort(-cand, axis=1)
    valid = np.isfinite(cand)
    m = cand.shape[1]
    # probes: mid(x, c0), c0, mid(c0, c1), c1, ..., c_{m-1}, beyond c_{m-1}
    probes = np.empty((n, 2 * m + 1))
    pvalid = np.zeros((n, 2 * m + 1), dtype=bool)
    prev = x.copy()
    prev_valid = np.ones(n, dtype=bool)
    for i in range(m):
        ci, vi = cand[:, i], valid[:, i]
        mid = np.where(vi, prev + 0.5 * (ci - prev), np.nan)
        probes[:, 2 * i] = mid
        pvalid[:, 2 * i] = vi & prev_valid
        probes[:, 2 * i + 1] = ci
        pvalid[:, 2 * i + 1] = vi & prev_valid
        prev = np.where(vi, ci, prev)
        prev_valid &= vi
    if up:
        # the open half-line beyond the last root: one probe suffices (no root there)
        probes[:, 2 * m] = 2.0 * prev + 1.0
        pvalid[:, 2 * m] = True
    else:
        pvalid[:, 2 * m] = False  # nothing below 0
        probes[:, 2 * m] = np.nan
    # a gap of zero width between equal roots has no interior
    pvalid &= np.isfinite(probes)
    safe = np.where(pvalid, probes, xc)
    modes = _classify_along(var, safe, other, g, kp)
    differs = pvalid & (modes != m0[:, None])
    found = differs.any(axis=1)
    j = np.argmax(differs, axis=1)
    rows = np.arange(n)
    hi = safe[rows, j]
    lo = np.where(j > 0, safe[rows, np.maximum(j - 1, 0)], x)
    # walk back past invalid probes so that lo is a probe with the point's mode
    # (all valid probes before j have mode m0 by construction; invalid ones were set to x)
    to = modes[rows, j]
    # a root probe (odd index) followed by a gap whose mode also differs: report the gap's mode
    nxt = np.minimum(j + 1, 2 * m)
    gap_diff = pvalid[rows, nxt] & (modes[rows, nxt] != m0)
    to = np.where((j % 2 == 1) & gap_diff, modes[rows, nxt], to)
    # bisection on classify between lo (mode m0) and hi (another mode)
    lo = np.where(found, lo, x)
    hi = np.where(found, hi, x)
    active = found.copy()
    for _ in range(_BISECT_STEPS):
        if not active.any():
            break
        idx = np.flatnonzero(active)
        l, h = lo[idx], hi[idx]
        mid = l + 0.5 * (h - l)
        stuck = (mid == l) | (mid == h)
        go = ~stuck
        if go.any():
            ii = idx[go]
            mm = mid[go]
            mk = _classify_along(var, mm[:, None], other[ii], g[ii], kp[ii])[:, 0]
            same = mk == m0[ii]
            lo[ii[same]] = mm[same]
            hi[ii[~same]] = mm[~same]
        active[idx[stuck]] = False
    return found, hi, to


def _margin_arrays(var: str, k: np.ndarray, mu: np.ndarray, g: np.ndarray, kp: np.ndarray,
                   m0: np.ndarray) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    if var == "k":
        x, other, roots = k, mu, _roots_along_k(mu, g, kp)
    else:
        x, other, roots = mu, k, _roots_along_mu(k, g, kp)
    return {
        "up": _walk(var, x, other, g, kp, m0, roots, up=True),
        "down": _walk(var, x, other, g, kp, m0, roots, up=False),
    }


def _crossing(direction: str, x: float, found: bool, at: float, to: int) -> Crossing | None:
    if not found:
        return None
    delta = abs(float(at) - x)
    rel = delta / x if x > 0.0 else None
    return Crossing(direction, float(at), delta, rel, Mode(int(to)))


def margin(k: float, mu: float, gamma: float, kprime: float) -> tuple[Margin, Margin]:
    """The margins of one point along k (mu fixed) and along mu (k fixed).

    Parameters
    ----------
    k, mu : float
        The point: force F/(mg) >= 0 and friction coefficient >= 0.
    gamma, kprime : float
        Aspect ratio H/B > 0 and force height h/H in [-1, 1].

    Returns
    -------
    (Margin, Margin)
        Along k and along mu.  See the module docstring for the method, the
        search range and the special values (None).

    Examples
    --------
    >>> mk, mm = margin(0.3, 0.2, 3.0, 0.4)
    >>> mk.nearest.to.label, round(mk.nearest.at, 6)
    ('SRO-', 0.333333)
    """
    k_arr = check_nonnegative_array("k", k).reshape(-1)
    mu_arr = check_nonnegative_array("mu", mu).reshape(-1)
    if k_arr.size != 1 or mu_arr.size != 1:
        raise ValueError("margin() takes one point; use query_points for many")
    g = np.array([check_gamma(gamma)])
    kp = np.array([check_kprime(kprime)])
    m0 = classify(k_arr, mu_arr, g, kp)
    out = []
    for var, x in (("k", float(k_arr[0])), ("mu", float(mu_arr[0]))):
        arr = _margin_arrays(var, k_arr, mu_arr, g, kp, m0)
        up = _crossing("up", x, bool(arr["up"][0][0]), arr["up"][1][0], arr["up"][2][0])
        down = _crossing("down", x, bool(arr["down"][0][0]), arr["down"][1][0], arr["down"][2][0])
        out.append(Margin(var, x, up, down))
    return out[0], out[1]


# --------------------------------------------------------------------------------------
# queries
# --------------------------------------------------------------------------------------
def _query_block(k: np.ndarray, mu: np.ndarray, g: np.ndarray, kp: np.ndarray,
                 names: Sequence[str], cases: Sequence[Case]) -> list[PointResult]:
    m0 = classify(k, mu, g, kp)
    responses = {h: solve(h, k, mu, g, kp) for h in Hypothesis}
    adm_mode: dict[Mode, np.ndarray] = {}
    for h, r in responses.items():
        adm_mode[h.mode] = adm_mode[h.mode] | r.ok if h.mode in adm_mode else r.ok
    margins = {var: _margin_arrays(var, k, mu, g, kp, m0) for var in ("k", "mu")}
    _, lower, upper, mu_s, _ = _thresholds(k, g, kp)
    with np.errstate(divide="ignore"):
        k_A = np.where(kp > -1.0, 1.0 / (g * (1.0 + kp)), np.inf)
    mu_B = (4.0 + g * g) / (3.0 * g)
    out: list[PointResult] = []
    for i in range(k.size):
        mode = Mode(int(m0[i]))
        hyps = HYPOTHESES_OF_MODE[mode]
        hyp = next((h for h in hyps if responses[h].ok[i]), hyps[0])
        r = responses[hyp]
        solvable = bool(r.solvable[i])
        nan = math.nan

        def val(arr: np.ndarray) -> float:
            return float(arr[i]) if solvable else nan

        slip = None if hyp.sigma == 0 or not solvable else float(r.slip[i])
        lift = None if hyp.contact == "full" or not solvable else float(r.lift[i])
        adm = tuple(m for m in PRIORITY if m in adm_mode and adm_mode[m][i])
        mrg = []
        for var, x in (("k", float(k[i])), ("mu", float(mu[i]))):
            arr = margins[var]
            up = _crossing("up", x, bool(arr["up"][0][i]), arr["up"][1][i], arr["up"][2][i])
            down = _crossing("down", x, bool(arr["down"][0][i]), arr["down"][1][i],
                             arr["down"][2][i])
            mrg.append(Margin(var, x, up, down))
        out.append(PointResult(
            k=float(k[i]), mu=float(mu[i]), gamma=float(g[i]), kprime=float(kp[i]),
            mode=mode, hypothesis=hyp,
            fx=val(r.fx), fy=val(r.fy), xi=val(r.xi),
            xdd=val(r.xdd), ydd=val(r.ydd), thdd=val(r.thdd),
            slip=slip, lift=lift, case=cases[i], admissible=adm,
            hypothesis_admissible=bool(r.ok[i]), solvable=solvable,
            margin_k=mrg[0], margin_mu=mrg[1],
            thresholds={
                "mu_star": float(mu_s[i]),
                "upper_line": float(upper[i]),
                "lower_line": float(lower[i]),
                "k_A": float(k_A[i]),
                "mu_Bprime": float(mu_B[i]),
            },
            name=names[i],
        ))
    return out


def query_point(k: float, mu: float, gamma: float, kprime: float, name: str = "") -> PointResult:
    """The mode at (k, mu), the physics at its initiation and its margin.

    Parameters
    ----------
    k : float
        Force F/(mg) >= 0.
    mu : float
        Coefficient of friction >= 0.
    gamma : float
        Aspect ratio H/B > 0.
    kprime : float
        Force height h/H in [-1, 1] (negative below the centre of mass).
    name : str, optional
        A label carried into the result.

    Returns
    -------
    PointResult

    Raises
    ------
    ValueError
        For a negative or non-finite k or mu, gamma <= 0 or kprime outside
        [-1, 1]; the message names the parameter and the allowed range.

    Examples
    --------
    >>> r = query_point(0.5, 0.8, gamma=3.0, kprime=0.4)
    >>> r.mode.label, r.hypothesis.name, round(r.thdd, 4) > 0
    ('RO', 'ROCK_O', True)
    """
    return query_points([DesignPoint(_scalar("k", k), _scalar("mu", mu), name)],
                        gamma=gamma, kprime=kprime)[0]


def _scalar(name: str, v: Any) -> float:
    arr = check_nonnegative_array(name, v)
    if arr.size != 1:
        raise ValueError(f"{name} must be one number, got an array of shape {arr.shape}")
    return float(arr.reshape(-1)[0])


def query_points(points: Iterable[DesignPoint | tuple[float, float]],
                 gamma: float | None = None, kprime: float | None = None) -> list[PointResult]:
    """:func:`query_point` for many points (vectorised in blocks).

    Parameters
    ----------
    points : iterable of DesignPoint or (k, mu) pairs
        A point's own ``gamma``/``kprime`` (see
        :class:`~regimemap.points.DesignPoint`) take precedence over the
        defaults below.
    gamma, kprime : float, optional
        Defaults for points that do not carry their own.

    Returns
    -------
    list of PointResult, in the order of ``points``.

    Raises
    ------
    ValueError
        If a point lacks gamma or kprime and no default is given (the message
        names the point by position and name), or any value is invalid.
    """
    g_def = None if gamma is None else check_gamma(gamma)
    kp_def = None if kprime is None else check_kprime(kprime)
    ks: list[float] = []
    mus: list[float] = []
    gs: list[float] = []
    kps: list[float] = []
    names: list[str] = []
    for i, pt in enumerate(points, start=1):
        if not isinstance(pt, DesignPoint):
            try:
                kk, mm = pt  # type: ignore[misc]
            except (TypeError, ValueError):
                raise ValueError(f"point {i}: expected a DesignPoint or a (k, mu) pair, "
                                 f"got {pt!r}") from None
            pt = DesignPoint(_scalar("k", kk), _scalar("mu", mm))
        label = f"point {i}" + (f" ({pt.name!r})" if pt.name else "")
        g = pt.gamma if pt.gamma is not None else g_def
        kp = pt.kprime if pt.kprime is not None else kp_def
        if g is None:
            raise ValueError(f"{label} has no gamma and no default gamma was given")
        if kp is None:
            raise ValueError(f"{label} has no kprime and no default kprime was given")
        try:
            ks.append(_scalar("k", pt.k))
            mus.append(_scalar("mu", pt.mu))
            gs.append(check_gamma(g))
            kps.append(check_kprime(kp))
        except ValueError as exc:
            raise ValueError(f"{label}: {exc}") from None
        names.append(pt.name)
    k = np.asarray(ks, dtype=np.float64)
    mu = np.asarray(mus, dtype=np.float64)
    g_arr = np.asarray(gs, dtype=np.float64)
    kp_arr = np.asarray(kps, dtype=np.float64)
    case_cache: dict[tuple[float, float], Case] = {}
    cases = []
    for gi, kpi in zip(gs, kps):
        key = (gi, kpi)
        if key not in case_cache:
            case_cache[key] = Parameters(gi, kpi).case
        cases.append(case_cache[key])
    out: list[PointResult] = []
    for s in range(0, k.size, _BLOCK):
        sl = slice(s, s + _BLOCK)
        out.extend(_query_block(k[sl], mu[sl], g_arr[sl], kp_arr[sl], names[sl], cases[sl]))
    return out


# --------------------------------------------------------------------------------------
# flat rows (CSV) and text
# --------------------------------------------------------------------------------------
def _fmt(v: float | None) -> str:
    if v is None or not math.isfinite(v):
        return ""
    return repr(float(v))


def result_row(r: PointResult) -> dict[str, str]:
    """One flat CSV row (:data:`CSV_COLUMNS`) of a result; empty cells for None."""
    row = {
        "name": r.name, "k": _fmt(r.k), "mu": _fmt(r.mu), "gamma": _fmt(r.gamma),
        "kprime": _fmt(r.kprime), "case": r.case.value, "mode": r.mode.label,
        "hypothesis": r.hypothesis.name,
        "fx": _fmt(r.fx), "fy": _fmt(r.fy), "xi": _fmt(r.xi), "xdd": _fmt(r.xdd),
        "ydd": _fmt(r.ydd), "thdd": _fmt(r.thdd), "slip": _fmt(r.slip), "lift": _fmt(r.lift),
        "admissible": " ".join(m.label for m in r.admissible),
    }
    for m in (r.margin_k, r.margin_mu):
        n = m.nearest
        pre = f"margin_{m.variable}"
        row[pre] = "" if n is None else _fmt(n.relative)
        row[f"{pre}_direction"] = "" if n is None else n.direction
        row[f"{pre}_at"] = "" if n is None else _fmt(n.at)
        row[f"{pre}_to"] = "" if n is None else n.to.label
    return row


def _pct(c: Crossing) -> str:
    if c.delta <= 4.0 * np.spacing(max(abs(c.at), 1e-300)):
        return "0 (on the boundary)"
    if c.relative is None:
        return f"{c.delta:.4g} (absolute; the value is 0)"
    return f"{100.0 * c.relative:.3g}%"


def format_result(r: PointResult) -> str:
    """A plain-text report of one result, for people."""
    p_side = "above" if r.kprime > 0 else ("below" if r.kprime < 0 else "at")
    lines = []
    title = f"point {r.name!r}: " if r.name else ""
    lines.append(f"{title}k = {r.k:g}, mu = {r.mu:g}   (gamma = {r.gamma:g}, k' = {r.kprime:g}: "
                 f"force {p_side} the centre of mass)")
    lines.append(f"case      {r.case.value}: {r.case.description}")
    lines.append(f"mode      {r.mode.label}  ({r.mode.description})")
    lines.append(f"at initiation (solver, hypothesis {r.hypothesis.name}"
                 + ("" if r.hypothesis_admissible or not r.solvable else ", NOT admissible")
                 + "):")
    rows = [
        ("fx", r.fx, "horizontal reaction / mg (positive to the right)"),
        ("fy", r.fy, "normal reaction / mg"),
        ("xi", r.xi, "where f_y acts, from C / B (-1 = O, +1 = O')"),
        ("xdd", r.xdd, "horizontal acceleration of C / g (negative = to the left)"),
        ("ydd", r.ydd, "vertical acceleration of C / g"),
        ("thdd", r.thdd, "angular acceleration * B/g (positive = counter-clockwise)"),
    ]
    for key, v, what in rows:
        lines.append(f"  {key:<5} = {_val(v):>11}   {what}")
    if r.slip is None and not r.solvable and r.hypothesis.sigma != 0:
        lines.append(f"  {'slip':<5} = {'n/a':>11}")
    elif r.slip is None:
        lines.append(f"  {'slip':<5} = {'none':>11}   the contact sticks")
    else:
        where = "base" if r.hypothesis.contact == "full" else f"corner {r.hypothesis.contact}"
        lines.append(f"  {'slip':<5} = {_val(r.slip):>11}   horizontal acceleration of the "
                     f"slipping {where} / g")
    if r.lift is not None:
        lines.append(f"  {'lift':<5} = {_val(r.lift):>11}   upward acceleration of the "
                     f"lifting corner / g")
    lines.append("margin    (smallest change that changes the mode, the other variable fixed)")
    for m in (r.margin_k, r.margin_mu):
        parts = []
        for direction, c in (("down", m.down), ("up", m.up)):
            if c is None:
                if direction == "down" and m.value == 0.0:
                    parts.append("down: -- (already 0)")
                else:
                    parts.append(f"{direction}: no change")
                continue
            if c.delta <= 4.0 * np.spacing(max(abs(c.at), 1e-300)):
                parts.append(f"{c.direction}: 0 (on the boundary) -> {c.to.label}")
                continue
            sign = "-" if c.direction == "down" else "+"
            parts.append(f"{c.direction}: {sign}{_pct(c)} to {m.variable} = {c.at:.6g} -> "
                         f"{c.to.label}")
        lines.append(f"  {m.variable:<3} {';  '.join(parts)}")
    adm = ", ".join(m.label for m in r.admissible) or "(none)"
    lines.append(f"admissible (solver): {adm}")
    note = ""
    if not r.solvable:
        note = ("the equations-of-motion solver reports this system as singular (at mu = mu_B', "
                "or a known limitation of its singularity test at large gamma or mu), so the "
                "physics and the admissible set are not available; the mode and the margin come "
                "from the closed-form map and stand")
        lines += textwrap.wrap(note, width=88, initial_indent="  ", subsequent_indent="  ")
        note = ""
    if r.chosen_by == "Section 4.7":
        note = (f"several modes satisfy the equations of motion here (non-uniqueness of rigid "
                f"contact with friction, below C and mu > mu_B' = {r.thresholds['mu_Bprime']:.4g}); "
                f"Section 4.7 of the report keeps {r.mode.label}")
    elif r.chosen_by == "boundary":
        note = (f"the point is on a boundary, where the modes of both sides are admissible; "
                f"the map gives it {r.mode.label}")
    if note:
        lines += textwrap.wrap(note, width=88, initial_indent="  ", subsequent_indent="  ")
    return "\n".join(lines)


def _val(v: float) -> str:
    if v is None or not math.isfinite(v):
        return "n/a"
    if v == 0.0 or abs(v) < 1e-13:
        return "0"
    return f"{v:.6g}"

