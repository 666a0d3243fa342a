"""An independent equations-of-motion solver for the onset of motion.

Written from the mechanics of a plane rigid body, not from the report's
inequalities, so that the closed-form regions of :mod:`regimemap.mechanics.regions` can be
checked against it.

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

Corner accelerations from rest (angular velocity zero)::

    x_O''  = x'' + H theta'',   y_O''  = y'' - B theta''
    x_O''' = x'' + H theta'',   y_O''' = y'' + B theta''   (for O')
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import numpy as np
from numpy.typing import ArrayLike

from .modes import PRIORITY, Mode

__all__ = [
    "Hypothesis",
    "Response",
    "TOLERANCE",
    "admissible",
    "admissible_hypotheses",
    "choose",
    "solve",
]

#: Tolerance of the admissibility conditions (dimensionless reactions/accelerations).
TOLERANCE = 1e-9


class Hypothesis(Enum):
    """A contact hypothesis at the onset of motion, with the mode it starts.

    The value is ``(mode, contact, sigma)``: ``contact`` is ``"full"`` (the whole
    base touches), ``"O"`` or ``"O'"`` (the body pivots on that corner);
    ``sigma`` is +1 when the contact slips left (friction points right), -1
    when it slips right, 0 when it sticks.
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

    @property
    def mode(self) -> Mode:
        return self.value[0]

    @property
    def contact(self) -> str:
        return self.value[1]

    @property
    def sigma(self) -> int:
        return self.value[2]


@dataclass(frozen=True)
class Response:
    """Reactions and accelerations at the onset of one hypothesis (arrays, broadcast shape).

    Attributes
    ----------
    fx, fy : ndarray
        Horizontal and vertical reactions divided by m g.
    xi : ndarray
        Point of action of f_y from C, divided by B (-1 is O, +1 is O').
    xdd, ydd : ndarray
        Accelerations of C divided by g.
    thdd : ndarray
        Angular acceleration times B/g (positive counter-clockwise).
    slip : ndarray
        Horizontal acceleration (over g) of the contact: of C when the whole
        base slides, of the pivot corner when the body rocks; zero when stuck.
    lift : ndarray
        Upward acceleration (over g) of the corner that lifts off (NaN for full contact).
    ok : ndarray of bool
        Whether every condition of the hypothesis holds (within TOLERANCE).
    solvable : ndarray of bool
        False where the linear system is singular (mu = (4+g^2)/(3g) for
        slide-rock about O slipping left, and its mirror); ``ok`` is False there.
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


def _broadcast(*values: ArrayLike) -> tuple[np.ndarray, ...]:
    return tuple(np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in values)))


def solve(hypothesis: Hypothesis, k: ArrayLike, mu: ArrayLike, gamma: ArrayLike,
          kprime: ArrayLike, tol: float = TOLERANCE) -> Response:
    """Solve the equations of motion under one contact hypothesis.

    Parameters
    ----------
    hypothesis : Hypothesis
        The contact hypothesis.
    k, mu, gamma, kprime : array_like
        Force F/(mg), friction coefficient, aspect ratio H/B and force height
        h/H; broadcast together.
    tol : float
        Tolerance of the admissibility conditions.

    Returns
    -------
    Response
        Reactions, accelerations and whether the hypothesis is admissible.
    """
    k_b, mu_b, gamma_b, kprime_b = _broadcast(k, mu, gamma, kprime)
    shape = k_b.shape
    kf, muf, gf, kpf = (v.ravel() for v in (k_b, mu_b, gamma_b, kprime_b))
    n = kf.size
    # unknowns u = [X, Y, T, fx, fy, M]
    A = np.zeros((n, 6, 6))
    rhs = np.zeros((n, 6))
    A[:, 0, 0] = 1.0
    A[:, 0, 3] = -1.0
    rhs[:, 0] = -kf
    A[:, 1, 1] = 1.0
    A[:, 1, 4] = -1.0
    rhs[:, 1] = -1.0
    A[:, 2, 2] = (1.0 + gf * gf) / 3.0
    A[:, 2, 3] = -gf
    A[:, 2, 5] = -1.0
    rhs[:, 2] = gf * kf * kpf

    contact, sigma = hypothesis.contact, hypothesis.sigma
    if contact == "full":
        A[:, 3, 1] = 1.0  # Y = 0
        A[:, 4, 2] = 1.0  # T = 0
        if sigma == 0:
            A[:, 5, 0] = 1.0  # X = 0
        else:
            A[:, 5, 3] = 1.0  # fx = sigma mu fy
            A[:, 5, 4] = -sigma * muf
    else:
        side = -1.0 if contact == "O" else 1.0  # xi/B of the pivot
        A[:, 3, 5] = 1.0  # M = side * fy
        A[:, 3, 4] = -side
        # vertical acceleration of the pivot: Y + side*T = 0 (O: Y - T, O': Y + T)
        A[:, 4, 1] = 1.0
        A[:, 4, 2] = side
        if sigma == 0:
            A[:, 5, 0] = 1.0  # horizontal acceleration of the pivot: X + gamma T = 0
            A[:, 5, 2] = gf
        else:
            A[:, 5, 3] = 1.0
            A[:, 5, 4] = -sigma * muf

    # Singular systems (e.g. 4 + g^2 - 3 mu g = 0 in (3.30)) have no unique
    # solution.  |det A| is compared with Hadamard's bound, the product of the
    # row norms, so the test does not depend on the scale of gamma, k or mu.
    det = np.linalg.det(A)
    hadamard = np.prod(np.linalg.norm(A, axis=2), axis=1)
    solvable = np.abs(det) > 1e-12 * hadamard
    A_safe = A.copy()
    A_safe[~solvable] = np.eye(6)
    rhs_safe = rhs.copy()
    rhs_safe[~solvable] = 0.0
    u = np.linalg.solve(A_safe, rhs_safe[..., None])[..., 0]
    X, Y, T, fx, fy, M = (u[:, i] for i in range(6))

    with np.errstate(divide="ignore", invalid="ignore"):
        xi = np.where(fy != 0.0, M / fy, np.nan)
    cond = solvable & (fy >= -tol)
    if contact == "full":
        slip = X if sigma != 0 else np.zeros_like(X)
        lift = np.full_like(X, np.nan)
        cond &= np.abs(M) <= fy + tol  # |xi| <= B, (3.5), (4.6)
    else:
        side = -1.0 if contact == "O" else 1.0
        slip = np.zeros_like(X) if sigma == 0 else X + gf * T  # horizontal accel. of pivot
        lift = Y - side * T  # vertical accel. of the other corner (= -2 side T)
        cond &= lift >= -tol
    if sigma == 0:
        cond &= np.abs(fx) <= muf * fy + tol
    else:
        cond &= sigma * slip <= tol  # slipping against the friction force
    resp = Response(
        hypothesis=hypothesis,
        fx=fx.reshape(shape),
        fy=fy.reshape(shape),
        xi=xi.reshape(shape),
        xdd=X.reshape(shape),
        ydd=Y.reshape(shape),
        thdd=T.reshape(shape),
        slip=slip.reshape(shape),
        lift=lift.reshape(shape),
        ok=cond.reshape(shape),
        solvable=solvable.reshape(shape),
    )
    return resp


def admissible_hypotheses(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike,
                          tol: float = TOLERANCE) -> dict[Hypothesis, np.ndarray]:
    """Admissibility (bool array) of every :class:`Hypothesis` at every point."""
    return {h: solve(h, k, mu, gamma, kprime, tol).ok for h in Hypothesis}


def admissible(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike,
               tol: float = TOLERANCE) -> dict[Mode, np.ndarray]:
    """Which modes the equations of motion admit at each point.

    Parameters
    ----------
    k, mu, gamma, kprime : array_like
        Broadcast together.
    tol : float
        Tolerance of the conditions; points on a boundary admit both sides.

    Returns
    -------
    dict[Mode, ndarray of bool]
        For each of the eight modes (slide in either direction counts as SL).
        More than one mode can be admissible at a point: on boundaries, and
        below C for mu > (4+g^2)/(3g) (Painleve-type non-uniqueness of rigid
        contact with friction); Section 4.7 of the report decides there
        (see :data:`regimemap.mechanics.modes.PRIORITY`).
    """
    hyp = admissible_hypotheses(k, mu, gamma, kprime, tol)
    out: dict[Mode, np.ndarray] = {}
    for h, ok in hyp.items():
        out[h.mode] = out[h.mode] | ok if h.mode in out else ok
    return out


def choose(admissible: dict[Mode, np.ndarray]) -> np.ndarray:
    """The solver's choice: the first admissible mode of Section 4.7's order at each point.

    Parameters
    ----------
    admissible : dict[Mode, ndarray of bool]
        As returned by :func:`admissible`.

    Returns
    -------
    ndarray of uint8
        Mode codes (:data:`~regimemap.mechanics.modes.PRIORITY` decides where several
        modes are admissible); 255 where none is (never seen for valid input).
    """
    shape = np.broadcast(*admissible.values()).shape
    out = np.full(shape, 255, dtype=np.uint8)
    free = np.ones(shape, dtype=bool)
    for mode in PRIORITY:
        if mode in admissible:
            hit = free & admissible[mode]
            out[hit] = mode
            free &= ~hit
    return out
