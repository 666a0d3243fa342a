"""An independent equations-of-motion solver for the onset of motion.

Written from the mechanics of a plane rigid body, not from the report's
inequalities, so that the closed-form regions of :mod:`regimemap.mechanics.regions` can be
checked against it.  The contact hypotheses, their solution and the choice among them are
one argument, kept whole in one module of some length.

Model (Chapter II of the report)
--------------------------------
A rectangle 2B wide and 2H high, mass m, centre C at the origin, rests on a rigid
base with Coulomb friction mu (static = kinetic).  A force F = m g k pushes it to
the *left* at height h = k' H above C.  The base acts at x = xi (from C) with a
horizontal reaction f_x (positive right) and a normal reaction f_y (up).  The
corners are O = (-B, -H) (left) and O' = (B, -H) (right); theta is positive
counter-clockwise and I = m (B^2 + H^2)/3.  Starting from rest (no velocities),
the equations of motion are (3.6)-(3.11), (4.24)-(4.26)::

    m x''      = f_x - F
    m y''      = f_y - m g
    I theta''  = f_x H + f_y xi + F h

In the dimensionless unknowns used here, ``X = x''/g``, ``Y = y''/g``,
``T = theta'' B/g``, ``fx = f_x/(m g)``, ``fy = f_y/(m g)`` and ``M = fy xi/B``
(so ``xi/B = M/fy``), with gamma = H/B::

    X - fx                         = -k
    Y - fy                         = -1
    (1+gamma^2)/3 T - gamma fx - M = gamma k k'

Each contact hypothesis adds three linear equations (contact kinematics and the
friction law), and the 6x6 system is solved numerically for every point.  A
hypothesis is *admissible* when all of its conditions hold: normal reaction >= 0;
``|fx| <= mu fy`` when the contact sticks; the slip acceleration opposing the
friction force when it slips; the lifting corner accelerating upward when the
body rocks; the normal reaction inside the base, ``|xi| <= B``, when the base is
in full contact.  Conditions are tested with a small tolerance, so points on a
boundary are admissible for the hypotheses on both sides.

Loads.  Buoyancy, uplift and another inertia change only the
right-hand side and the inertia of the three dynamic rows (:func:`dynamic_rows`,
:func:`applied_loads`): :math:`Y - f_y = -W` with :math:`W = 1 - \\beta - U` and
:math:`i^2 T - \\gamma f_x - M = S` with :math:`S = \\gamma k k' + e_u U` (see
:mod:`regimemap.mechanics.loads`).  The contact rows (:func:`contact_rows`) do
not depend on the loads; a tenth hypothesis, lift-off (no contact:
``fx = fy = M = 0``), is admissible when both corners accelerate upward.

Choice.  Where several hypotheses are admissible, :func:`least_constraint`
takes the one minimising Gauss's constraint
:math:`(a - a_\\mathrm{free})^T \\mathsf{M} (a - a_\\mathrm{free})`,
:math:`\\mathsf{M} = \\mathrm{diag}(1, 1, i^2)`, which is
:math:`f_x^2 + f_y^2 + (\\gamma f_x + M)^2/i^2`; ties (boundaries) are broken by
:data:`~regimemap.mechanics.modes.SELECTION_ORDER`.
On the report's block this is Section 4.7's choice (:func:`choose`), tested.

Corner accelerations from rest (angular velocity zero)::

    x_O''  = x'' + H theta'',   y_O''  = y'' - B theta''
    x_O''' = x'' + H theta'',   y_O''' = y'' + B theta''   (for O')
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .loads import applied_moment, default_i2, net_load, uplift_load
from .modes import SELECTION_ORDER, Mode

__all__ = [
    "Hypothesis",
    "Response",
    "TOLERANCE",
    "admissible",
    "admissible_hypotheses",
    "applied_loads",
    "choose",
    "contact_rows",
    "dynamic_rows",
    "least_constraint",
    "solve",
]

#: Tolerance of the admissibility conditions (dimensionless reactions/accelerations).
TOLERANCE = 1e-9

Float = NDArray[np.float64]
Bool = NDArray[np.bool_]


class Hypothesis(Enum):
    """A contact hypothesis at the onset of motion, with the mode it starts.

    The value is ``(mode, contact, sigma)``: ``contact`` is ``"full"`` (the whole
    base touches), ``"O"`` or ``"O'"`` (the body pivots on that corner) or
    ``"none"`` (lift-off); ``sigma`` is +1 when the contact slips left (friction
    points right), -1 when it slips right, 0 when it sticks.
    """

    REST = (Mode.RE, "full", 0)
    SLIDE_LEFT = (Mode.SL, "full", +1)
    SLIDE_RIGHT = (Mode.SL, "full", -1)
    ROCK_O = (Mode.RO, "O", 0)
    ROCK_O_PRIME = (Mode.RO_PRIME, "O'", 0)
    SLIDE_ROCK_O_LEFT = (Mode.SRO_MINUS, "O", +1)
    SLIDE_ROCK_O_RIGHT = (Mode.SRO_PLUS, "O", -1)
    SLIDE_ROCK_O_PRIME_LEFT = (Mode.SRO_PRIME_MINUS, "O'", +1)
    SLIDE_ROCK_O_PRIME_RIGHT = (Mode.SRO_PRIME_PLUS, "O'", -1)
    LIFT_OFF = (Mode.LO, "none", 0)

    @property
    def mode(self) -> Mode:
        return Mode(self.value[0])

    @property
    def contact(self) -> str:
        return str(self.value[1])

    @property
    def sigma(self) -> int:
        return int(self.value[2])


@dataclass(frozen=True)
class Response:
    """Reactions and accelerations at the onset of one hypothesis (arrays, broadcast shape).

    Attributes
    ----------
    fx, fy : ndarray
        Horizontal and vertical reactions divided by m g.
    xi : ndarray
        Point of action of f_y from C, divided by B (-1 is O, +1 is O'; NaN when f_y = 0).
    xdd, ydd : ndarray
        Accelerations of C divided by g.
    thdd : ndarray
        Angular acceleration times B/g (positive counter-clockwise).
    slip : ndarray
        Horizontal acceleration (over g) of the contact: of C when the whole
        base slides, of the pivot corner when the body rocks; zero when stuck.
    lift : ndarray
        Upward acceleration (over g) of the corner that lifts off (NaN for full
        contact; the smaller of the two corners' for lift-off).
    ok : ndarray of bool
        Whether every condition of the hypothesis holds (within TOLERANCE).
    solvable : ndarray of bool
        False where the linear system is singular (mu = (4+g^2)/(3g) for
        slide-rock about O slipping left, and its mirror); ``ok`` is False there.
    constraint : ndarray
        Gauss's constraint :math:`f_x^2 + f_y^2 + (\\gamma f_x + M)^2/i^2` (0 for lift-off).
    """

    hypothesis: Hypothesis
    fx: np.ndarray
    fy: np.ndarray
    xi: np.ndarray
    xdd: np.ndarray
    ydd: np.ndarray
    thdd: np.ndarray
    slip: np.ndarray
    lift: np.ndarray
    ok: np.ndarray
    solvable: np.ndarray
    constraint: np.ndarray


def applied_loads(k: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *, buoyancy: ArrayLike = 0.0,
                  uplift: ArrayLike = 0.0, uplift_ratio: ArrayLike = 0.0,
                  uplift_arm: ArrayLike = 1.0 / 3.0) -> tuple[Float, Float, Float]:
    """The applied load ``(Fx, Fy, Mc) = (-k, -W, S)`` per unit m g (moment per unit m g B)."""
    k_, g, kp, beta, u, nu, eu = (np.asarray(v, dtype=np.float64)
                                  for v in (k, gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm))
    U = uplift_load(k_, u, nu)
    return -k_, -net_load(k_, beta, u, nu), applied_moment(k_, g, kp, eu, U)


def dynamic_rows(gamma: Float, i2: Float) -> Float:
    """The three rows of the equations of motion, shape ``(n, 3, 6)`` (unknowns X, Y, T, fx, fy, M)."""
    n = gamma.size
    A = np.zeros((n, 3, 6))
    A[:, 0, 0] = 1.0
    A[:, 0, 3] = -1.0
    A[:, 1, 1] = 1.0
    A[:, 1, 4] = -1.0
    A[:, 2, 2] = i2
    A[:, 2, 3] = -gamma
    A[:, 2, 5] = -1.0
    return A


def contact_rows(hypothesis: Hypothesis, mu: Float, gamma: Float) -> tuple[Float, Float]:
    """The three contact rows of ``hypothesis`` and their right-hand side (zero from rest).

    Full contact: ``Y = 0, T = 0`` and ``X = 0`` (stick) or ``fx = sigma mu fy``
    (slip).  Pivot at a corner with ``xi = s`` (s = -1 at O, +1 at O'): ``M = s fy``,
    ``Y + s T = 0`` (the corner keeps to the base) and ``X + gamma T = 0`` (stick)
    or ``fx = sigma mu fy``.  Lift-off: ``fx = fy = M = 0``.  The loads never
    enter these rows.
    """
    n = mu.size
    A = np.zeros((n, 3, 6))
    rhs = np.zeros((n, 3))
    contact, sigma = hypothesis.contact, hypothesis.sigma
    if contact == "none":
        A[:, 0, 3] = 1.0
        A[:, 1, 4] = 1.0
        A[:, 2, 5] = 1.0
        return A, rhs
    if contact == "full":
        A[:, 0, 1] = 1.0  # Y = 0
        A[:, 1, 2] = 1.0  # T = 0
        if sigma == 0:
            A[:, 2, 0] = 1.0  # X = 0
        else:
            A[:, 2, 3] = 1.0  # fx = sigma mu fy
            A[:, 2, 4] = -sigma * mu
        return A, rhs
    side = -1.0 if contact == "O" else 1.0  # xi/B of the pivot
    A[:, 0, 5] = 1.0  # M = side * fy
    A[:, 0, 4] = -side
    A[:, 1, 1] = 1.0  # vertical acceleration of the pivot: Y + side*T = 0
    A[:, 1, 2] = side
    if sigma == 0:
        A[:, 2, 0] = 1.0  # horizontal acceleration of the pivot: X + gamma T = 0
        A[:, 2, 2] = gamma
    else:
        A[:, 2, 3] = 1.0
        A[:, 2, 4] = -sigma * mu
    return A, rhs


def _solve_system(A: Float, rhs: Float) -> tuple[Float, Float]:
    """The determinants of the systems ``A u = rhs`` (shape ``(n, 6, 6)``, ``(n, 6)``) and their
    solutions (not finite where the determinant is 0).

    The dynamic rows (the first three, :func:`dynamic_rows`) have a diagonal block on the
    accelerations: eliminating the accelerations leaves, for the reactions f = (fx, fy, M), the
    3x3 Schur complement ``S f = r2 - A21 D^-1 r1`` with ``S = A22 - A21 D^-1 A12``, solved by
    Cramer's rule for every point at once; ``det A = det D det S``.  The same solution as a
    general 6x6 solve (``numpy.linalg``) to rounding, about ten times faster on a sweep.
    """
    d = np.stack([A[:, 0, 0], A[:, 1, 1], A[:, 2, 2]], axis=1)  # D, the diagonal block
    A12, A21 = A[:, :3, 3:], A[:, 3:, :3]
    r1, r2 = rhs[:, :3, None], rhs[:, 3:, None]
    w = A21 / d[:, None, :]  # A21 D^-1
    S = A[:, 3:, 3:] - w @ A12
    y0, y1, y2 = (r2 - w @ r1)[:, :, 0].T
    (a, b_, c), (d_, e, f), (g, h, i) = np.ascontiguousarray(S.transpose(1, 2, 0))
    c0, c1, c2 = e * i - f * h, f * g - d_ * i, d_ * h - e * g  # cofactors of the first row
    det_s = a * c0 + b_ * c1 + c * c2
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv = 1.0 / det_s
        react = np.stack([(y0 * c0 + y1 * (c * h - b_ * i) + y2 * (b_ * f - c * e)) * inv,
                          (y0 * c1 + y1 * (a * i - c * g) + y2 * (c * d_ - a * f)) * inv,
                          (y0 * c2 + y1 * (b_ * g - a * h) + y2 * (a * e - b_ * d_)) * inv], axis=1)
        acc = (r1 - A12 @ react[:, :, None])[:, :, 0] / d
    return np.prod(d, axis=1) * det_s, np.concatenate([acc, react], axis=1)


def solve(hypothesis: Hypothesis, k: ArrayLike, mu: ArrayLike, gamma: ArrayLike,
          kprime: ArrayLike, tol: float = TOLERANCE, *, buoyancy: ArrayLike = 0.0,
          uplift: ArrayLike = 0.0, uplift_ratio: ArrayLike = 0.0, uplift_arm: ArrayLike = 1.0 / 3.0,
          gyration: ArrayLike | None = None) -> Response:
    """Solve the equations of motion under one contact hypothesis.

    Parameters
    ----------
    hypothesis : Hypothesis
        The contact hypothesis.
    k, mu, gamma, kprime : array_like
        Force F/(mg), friction coefficient, aspect ratio H/B and force height
        h/H; broadcast together (with the loads).
    tol : float
        Tolerance of the admissibility conditions.
    buoyancy, uplift, uplift_ratio, uplift_arm, gyration : array_like, keyword-only
        The loads of :class:`~regimemap.mechanics.block.Parameters` (gyration
        None: the uniform block).  Not checked here.

    Returns
    -------
    Response
        Reactions, accelerations, Gauss's constraint and whether the hypothesis is admissible.
    """
    g_arr = np.asarray(gamma, dtype=np.float64)
    i2_in: ArrayLike = default_i2(g_arr) if gyration is None else np.asarray(gyration, dtype=np.float64) ** 2
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in (
        k, mu, gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm, i2_in)))
    shape = arrs[0].shape
    kf, muf, gf, kpf, bf, uf, nuf, ef, i2 = (np.ascontiguousarray(a).ravel() for a in arrs)
    n = kf.size
    # unknowns u = [X, Y, T, fx, fy, M]: three dynamic rows, three contact rows
    A = np.zeros((n, 6, 6))
    rhs = np.zeros((n, 6))
    A[:, :3] = dynamic_rows(gf, i2)
    rhs[:, 0], rhs[:, 1], rhs[:, 2] = applied_loads(kf, gf, kpf, buoyancy=bf, uplift=uf,
                                                    uplift_ratio=nuf, uplift_arm=ef)
    A[:, 3:], rhs[:, 3:] = contact_rows(hypothesis, muf, gf)

    # Singular systems (e.g. 4 + g^2 - 3 mu g = 0 in (3.30)) have no unique
    # solution.  |det A| is compared with Hadamard's bound, the product of the
    # row norms, so the test does not depend on the scale of gamma, k or mu.
    det, u = _solve_system(A, rhs)
    hadamard = np.prod(np.linalg.norm(A, axis=2), axis=1)
    solvable = np.abs(det) > 1e-12 * hadamard
    u[~solvable] = 0.0
    X, Y, T, fx, fy, M = (u[:, i] for i in range(6))

    with np.errstate(divide="ignore", invalid="ignore"):
        xi = np.where(fy != 0.0, M / fy, np.nan)
    contact, sigma = hypothesis.contact, hypothesis.sigma
    cond = solvable & (fy >= -tol)
    if contact == "none":
        slip = np.zeros_like(X)
        lift = np.minimum(Y - T, Y + T)  # both corners rise
        cond &= lift >= -tol
    elif contact == "full":
        slip = X if sigma != 0 else np.zeros_like(X)
        lift = np.full_like(X, np.nan)
        cond &= np.abs(M) <= fy + tol  # |xi| <= B, (3.5), (4.6)
    else:
        side = -1.0 if contact == "O" else 1.0
        slip = np.zeros_like(X) if sigma == 0 else X + gf * T  # horizontal accel. of pivot
        lift = Y - side * T  # vertical accel. of the other corner
        cond &= lift >= -tol
    if contact != "none":
        if sigma == 0:
            cond &= np.abs(fx) <= muf * fy + tol
        else:
            cond &= sigma * slip <= tol  # slipping against the friction force
    mr = gf * fx + M
    constraint = fx * fx + fy * fy + mr * mr / i2
    return Response(
        hypothesis=hypothesis,
        fx=fx.reshape(shape), fy=fy.reshape(shape), xi=xi.reshape(shape),
        xdd=X.reshape(shape), ydd=Y.reshape(shape), thdd=T.reshape(shape),
        slip=slip.reshape(shape), lift=lift.reshape(shape),
        ok=cond.reshape(shape), solvable=solvable.reshape(shape),
        constraint=constraint.reshape(shape),
    )


def _solve_all(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, tol: float,
               loads: dict[str, Any]) -> dict[Hypothesis, Response]:
    return {h: solve(h, k, mu, gamma, kprime, tol, **loads) for h in Hypothesis}


def admissible_hypotheses(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike,
                          tol: float = TOLERANCE, **loads: Any) -> dict[Hypothesis, np.ndarray]:
    """Admissibility (bool array) of every :class:`Hypothesis`; ``loads`` as :func:`solve`."""
    return {h: r.ok for h, r in _solve_all(k, mu, gamma, kprime, tol, loads).items()}


def _by_mode(hyp: dict[Hypothesis, np.ndarray]) -> dict[Mode, np.ndarray]:
    out: dict[Mode, np.ndarray] = {}
    for h, ok in hyp.items():
        out[h.mode] = out[h.mode] | ok if h.mode in out else ok
    return out


def admissible(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike,
               tol: float = TOLERANCE, **loads: Any) -> dict[Mode, np.ndarray]:
    """Which modes the equations of motion admit at each point.

    Parameters
    ----------
    k, mu, gamma, kprime : array_like
        Broadcast together.
    tol : float
        Tolerance of the conditions; points on a boundary admit both sides.
    **loads
        ``buoyancy``, ``uplift``, ``uplift_ratio``, ``uplift_arm``, ``gyration``
        (keyword-only, as :func:`solve`; ``crest`` is accepted and ignored).

    Returns
    -------
    dict[Mode, ndarray of bool]
        For each of the nine modes (slide in either direction counts as SL).
        More than one mode can be admissible at a point: on boundaries, and
        below C for mu > (4+g^2)/(3g) (Painleve-type non-uniqueness of rigid
        contact with friction); Section 4.7 of the report decides there
        (see :data:`regimemap.mechanics.modes.PRIORITY`), and Gauss's least
        constraint in general (:func:`least_constraint`).
    """
    loads.pop("crest", None)
    return _by_mode(admissible_hypotheses(k, mu, gamma, kprime, tol, **loads))


def choose(admissible: dict[Mode, np.ndarray],
           constraint: dict[Mode, np.ndarray] | None = None) -> np.ndarray:
    """The solver's choice at each point among the admissible modes.

    Parameters
    ----------
    admissible : dict[Mode, ndarray of bool]
        As returned by :func:`admissible`.
    constraint : dict[Mode, ndarray], optional
        Gauss's constraint per mode (as :func:`least_constraint` returns): the
        admissible mode of least constraint is chosen, ties broken by
        :data:`~regimemap.mechanics.modes.SELECTION_ORDER`.  Without it, the
        first admissible mode of that order (Section 4.7's :data:`PRIORITY`
        after lift-off), which is least constraint's choice wherever it was
        measured (``tests/test_loaded_*.py``).

    Returns
    -------
    ndarray of uint8
        Mode codes; 255 where none is admissible (never seen for valid input).
    """
    shape = np.broadcast(*admissible.values()).shape
    out = np.full(shape, 255, dtype=np.uint8)
    free = np.ones(shape, dtype=bool)
    if constraint is None:
        for mode in SELECTION_ORDER:
            if mode in admissible:
                hit = free & admissible[mode]
                out[hit] = mode
                free &= ~hit
        return out
    cons = {m: np.where(admissible[m], constraint[m], np.inf) for m in SELECTION_ORDER if m in admissible}
    best = np.min(np.stack(list(cons.values())), axis=0)
    lim = best + 1e-9 * (1.0 + best)
    for mode, c in cons.items():
        hit = free & np.isfinite(c) & (c <= lim)
        out[hit] = mode
        free &= ~hit
    return out


def least_constraint(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike,
                     tol: float = TOLERANCE, **loads: Any
                     ) -> tuple[NDArray[np.uint8], dict[Mode, Bool], dict[Mode, Float]]:
    """The mode chosen by Gauss's principle of least constraint at every point.

    Among the admissible hypotheses, the one of least constraint
    :math:`f_x^2 + f_y^2 + (\\gamma f_x + M)^2/i^2`; hypotheses within 1e-9 (relative)
    of the least tie and are decided by :data:`~regimemap.mechanics.modes.SELECTION_ORDER`.

    Returns
    -------
    codes : ndarray of uint8
        Chosen mode codes (255 where nothing is admissible).
    admissible : dict[Mode, ndarray of bool]
        Admissibility per mode.
    constraint : dict[Mode, ndarray]
        Gauss's constraint per mode (the least of its hypotheses; inf where not admissible).
    """
    loads.pop("crest", None)
    res = _solve_all(k, mu, gamma, kprime, tol, loads)
    adm: dict[Mode, Bool] = {}
    cons: dict[Mode, Float] = {}
    for h, r in res.items():
        val = np.where(r.ok, r.constraint, np.inf)
        m = h.mode
        if m in cons:
            adm[m] = adm[m] | r.ok
            cons[m] = np.minimum(cons[m], val)
        else:
            adm[m] = r.ok
            cons[m] = val
    return choose(adm, cons), adm, cons

