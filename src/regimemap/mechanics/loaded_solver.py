"""Equations-of-motion solver for the onset of motion under vertical loads (issue 10).

The arbiter of :mod:`regimemap.mechanics.loaded`: written from the mechanics of
a plane rigid body, not from the closed forms, so that those can be checked
against it.

Model (per unit m g, lengths per unit B)
----------------------------------------
A rigid block of mass m, centre C at the origin, stands on a rigid base at
depth ``gamma = H_C/B`` below C; the base runs from O = (-1, -gamma) (leeward,
left) to O' = (1, -gamma) (seaward, right).  Coulomb friction mu (static =
kinetic).  Besides gravity (-1 at C) the block carries

* the push F = k to the LEFT at height ``kprime*gamma`` above C;
* buoyancy ``beta``, upward through C's vertical;
* uplift ``U = u + nu*k``, upward at ``x = e_u`` (``e_u`` in [-1, 1]).

So the applied load (horizontal, vertical, moment about C, counter-clockwise
positive) is::

    Fx = -k,   Fy = -W with W = 1 - beta - U,   Mc = S = gamma*k*kprime + e_u*U

Unknowns ``u = [X, Y, T, fx, fy, M]``: accelerations of C over g, angular
acceleration times B/g, base reactions over m g and ``M = fy*xi`` (xi the point of
action of fy from C, over B).  The moment of inertia about C is ``m B^2 i2``.
The three dynamic rows (the only rows carrying the loads)::

    X - fx            = Fx
    Y - fy            = Fy
    i2 T - gamma fx - M = Mc

and three contact rows per hypothesis, with a right-hand side that is zero
when the block starts from rest (:func:`contact_rows`; they are kept apart so
that other loads, and later non-zero velocities, can reuse them).  Corner
accelerations from rest: ``x_O'' = X + gamma T``, ``y_O'' = Y - T``,
``y_O''' = Y + T``.

A hypothesis is *admissible* when its conditions hold within ``tol``: normal
reaction >= 0; ``|fx| <= mu fy`` when sticking; slip opposing friction when
slipping; the lifting corner accelerating upward when pivoting; ``|xi| <= 1``
in full contact; both corners accelerating upward in lift-off (LO: no contact).

Selection (:func:`least_constraint`): among the admissible hypotheses the one
minimising Gauss's constraint ``(a - a_free)^T M (a - a_free)`` with
``M = diag(1, 1, i2)``; this equals ``fx^2 + fy^2 + (gamma fx + M)^2/i2``.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .modes import Mode

__all__ = [
    "LIFT_OFF",
    "TOLERANCE",
    "LoadedHypothesis",
    "LoadedResponse",
    "applied_loads",
    "default_i2",
    "dynamic_rows",
    "contact_rows",
    "solve_loaded",
    "admissible_loaded",
    "admissible_hypotheses_loaded",
    "least_constraint",
    "SELECTION_ORDER",
]

#: Mode code of lift-off (no contact); the codes 0..7 are :class:`~regimemap.modes.Mode`.
LIFT_OFF: int = 8

#: Tolerance of the admissibility conditions (dimensionless reactions/accelerations).
TOLERANCE = 1e-9

Float = NDArray[np.float64]
Bool = NDArray[np.bool_]


class LoadedHypothesis(Enum):
    """A contact hypothesis at the onset of motion: ``(code, contact, sigma)``.

    ``contact`` is ``"full"``, ``"O"``, ``"O'"`` or ``"none"`` (lift-off);
    ``sigma`` is +1 when the contact slips left (friction to the right), -1 when
    it slips right, 0 when it sticks.
    """

    REST = (int(Mode.RE), "full", 0)
    SLIDE_LEFT = (int(Mode.SL), "full", +1)
    SLIDE_RIGHT = (int(Mode.SL), "full", -1)
    ROCK_O = (int(Mode.RO), "O", 0)
    ROCK_O_PRIME = (int(Mode.RO_PRIME), "O'", 0)
    SLIDE_ROCK_O_LEFT = (int(Mode.SRO_MINUS), "O", +1)
    SLIDE_ROCK_O_RIGHT = (int(Mode.SRO_PLUS), "O", -1)
    SLIDE_ROCK_O_PRIME_LEFT = (int(Mode.SRO_PRIME_MINUS), "O'", +1)
    SLIDE_ROCK_O_PRIME_RIGHT = (int(Mode.SRO_PRIME_PLUS), "O'", -1)
    LIFT_OFF = (LIFT_OFF, "none", 0)

    @property
    def code(self) -> int:
        """Mode code (uint8 value; :data:`LIFT_OFF` for lift-off)."""
        return int(self.value[0])

    @property
    def contact(self) -> str:
        return str(self.value[1])

    @property
    def sigma(self) -> int:
        return int(self.value[2])


#: Tie-break among hypotheses of equal constraint (boundaries): Section 4.7's
#: order (``regimemap.classify.PRIORITY``) with lift-off first.
SELECTION_ORDER: tuple[int, ...] = (
    LIFT_OFF,
    int(Mode.RE),
    int(Mode.SL),
    int(Mode.SRO_PRIME_MINUS),
    int(Mode.RO),
    int(Mode.SRO_MINUS),
    int(Mode.SRO_PLUS),
    int(Mode.RO_PRIME),
    int(Mode.SRO_PRIME_PLUS),
)


@dataclass(frozen=True)
class LoadedResponse:
    """Reactions and accelerations of one hypothesis (arrays of the broadcast shape).

    ``fx, fy`` reactions over m g; ``xi`` point of action of fy over B (NaN when
    fy = 0); ``xdd, ydd`` accelerations of C over g; ``thdd`` angular acceleration
    times B/g; ``slip`` horizontal acceleration of the slipping contact (0 when
    sticking); ``lift`` upward acceleration of the corner(s) that leave the base
    (the smaller of the two for lift-off; NaN in full contact); ``constraint``
    Gauss's constraint; ``ok`` admissible; ``solvable`` the system is regular.
    """

    hypothesis: LoadedHypothesis
    fx: Float
    fy: Float
    xi: Float
    xdd: Float
    ydd: Float
    thdd: Float
    slip: Float
    lift: Float
    constraint: Float
    ok: Bool
    solvable: Bool


def default_i2(gamma: Any) -> Any:
    """Squared radius of gyration about C over B^2 of a uniform block: (1 + gamma^2)/3."""
    return (1.0 + gamma * gamma) / 3.0


def applied_loads(k: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *, buoyancy: ArrayLike = 0.0,
                  uplift: ArrayLike = 0.0, uplift_ratio: ArrayLike = 0.0,
                  uplift_arm: ArrayLike = 1.0 / 3.0) -> tuple[Float, Float, Float]:
    """Applied generalised load ``(Fx, Fy, Mc)`` per unit m g (moment per unit m g B)."""
    k_, g, kp, beta, u, nu, eu = (np.asarray(v, dtype=np.float64)
                                  for v in (k, gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm))
    up = u + nu * k_
    return -k_, -(1.0 - beta - up), g * k_ * kp + eu * up


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


def contact_rows(hypothesis: LoadedHypothesis, mu: Float, gamma: Float) -> tuple[Float, Float]:
    """The three contact rows of ``hypothesis`` and their right-hand side (zero from rest).

    Full contact: ``Y = 0, T = 0`` and ``X = 0`` (stick) or ``fx = sigma mu fy``
    (slip).  Pivot at a corner with ``xi = s`` (s = -1 at O, +1 at O'): ``M = s fy``,
    ``Y + s T = 0`` (the corner keeps to the base) and ``X + gamma T = 0`` (stick)
    or ``fx = sigma mu fy``.  Lift-off: ``fx = fy = M = 0``.
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
        A[:, 0, 1] = 1.0
        A[:, 1, 2] = 1.0
        if sigma == 0:
            A[:, 2, 0] = 1.0
        else:
            A[:, 2, 3] = 1.0
            A[:, 2, 4] = -sigma * mu
        return A, rhs
    side = -1.0 if contact == "O" else 1.0
    A[:, 0, 5] = 1.0
    A[:, 0, 4] = -side
    A[:, 1, 1] = 1.0
    A[:, 1, 2] = side
    if sigma == 0:
        A[:, 2, 0] = 1.0
        A[:, 2, 2] = gamma
    else:
        A[:, 2, 3] = 1.0
        A[:, 2, 4] = -sigma * mu
    return A, rhs


def _inputs(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, buoyancy: ArrayLike,
            uplift: ArrayLike, uplift_ratio: ArrayLike, uplift_arm: ArrayLike,
            gyration: ArrayLike | None) -> tuple[tuple[int, ...], list[Float]]:
    g_arr = np.asarray(gamma, dtype=np.float64)
    i2: ArrayLike = default_i2(g_arr) if gyration is None else np.asarray(gyration, dtype=np.float64) ** 2
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in (
        k, mu, gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm, i2)))
    shape = arrs[0].shape
    return shape, [np.ascontiguousarray(a).ravel() for a in arrs]


def solve_loaded(hypothesis: LoadedHypothesis, k: ArrayLike, mu: ArrayLike, gamma: ArrayLike,
                 kprime: ArrayLike, *, buoyancy: ArrayLike = 0.0, uplift: ArrayLike = 0.0,
                 uplift_ratio: ArrayLike = 0.0, uplift_arm: ArrayLike = 1.0 / 3.0,
                 gyration: ArrayLike | None = None, tol: float = TOLERANCE) -> LoadedResponse:
    """Solve the 6x6 system of one hypothesis at every point and test its conditions.

    All arguments broadcast together.  ``gyration`` is the radius of gyration
    about C over B (``I = m B^2 gyration^2``); None is the uniform block,
    ``gyration^2 = (1 + gamma^2)/3``.  The other parameters are those of
    :func:`regimemap.mechanics.loaded.classify_loaded`.
    """
    shape, (kf, muf, gf, kpf, bf, uf, nuf, ef, i2f) = _inputs(
        k, mu, gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm, gyration)
    n = kf.size
    Fx, Fy, Mc = applied_loads(kf, gf, kpf, buoyancy=bf, uplift=uf, uplift_ratio=nuf, uplift_arm=ef)
    A = np.zeros((n, 6, 6))
    rhs = np.zeros((n, 6))
    A[:, :3] = dynamic_rows(gf, i2f)
    rhs[:, 0], rhs[:, 1], rhs[:, 2] = Fx, Fy, Mc
    A[:, 3:], rhs[:, 3:] = contact_rows(hypothesis, muf, gf)

    # singular systems (e.g. i2 + 1 - mu gamma = 0 for slide-rock about O slipping
    # left) have no unique solution: |det A| against Hadamard's bound
    det = np.linalg.det(A)
    hadamard = np.prod(np.linalg.norm(A, axis=2), axis=1)
    solvable = np.abs(det) > 1e-12 * hadamard
    A[~solvable] = np.eye(6)
    rhs[~solvable] = 0.0
    sol = np.linalg.solve(A, rhs[..., None])[..., 0]
    X, Y, T, fx, fy, M = (np.asarray(sol[:, j], dtype=np.float64) for j in range(6))

    with np.errstate(divide="ignore", invalid="ignore"):
        xi = np.where(fy != 0.0, M / fy, np.nan)
    contact, sigma = hypothesis.contact, hypothesis.sigma
    cond = solvable & (fy >= -tol)
    if contact == "none":
        slip = np.zeros_like(X)
        lift = np.minimum(Y - T, Y + T)
        cond &= lift >= -tol
    elif contact == "full":
        slip = X if sigma != 0 else np.zeros_like(X)
        lift = np.full_like(X, np.nan)
        cond &= np.abs(M) <= fy + tol
    else:
        side = -1.0 if contact == "O" else 1.0
        slip = X + gf * T if sigma != 0 else np.zeros_like(X)
        lift = Y - side * T
        cond &= lift >= -tol
    if contact != "none":
        if sigma == 0:
            cond &= np.abs(fx) <= muf * fy + tol
        else:
            cond &= sigma * slip <= tol
    mr = gf * fx + M
    constraint = fx * fx + fy * fy + mr * mr / i2f
    return LoadedResponse(
        hypothesis=hypothesis,
        fx=fx.reshape(shape), fy=fy.reshape(shape), xi=xi.reshape(shape),
        xdd=X.reshape(shape), ydd=Y.reshape(shape), thdd=T.reshape(shape),
        slip=slip.reshape(shape), lift=lift.reshape(shape),
        constraint=constraint.reshape(shape), ok=cond.reshape(shape),
        solvable=solvable.reshape(shape),
    )


def _all(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, kw: dict[str, Any],
         tol: float) -> dict[LoadedHypothesis, LoadedResponse]:
    return {h: solve_loaded(h, k, mu, gamma, kprime, tol=tol, **kw) for h in LoadedHypothesis}


def admissible_hypotheses_loaded(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *,
                                 tol: float = TOLERANCE, **loads: Any) -> dict[LoadedHypothesis, Bool]:
    """Admissibility (bool array) of every :class:`LoadedHypothesis`; ``loads`` as :func:`solve_loaded`."""
    return {h: r.ok for h, r in _all(k, mu, gamma, kprime, loads, tol).items()}


def admissible_loaded(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *,
                      tol: float = TOLERANCE, **loads: Any) -> dict[int, Bool]:
    """Admissibility per mode code (slide in either direction is SL; LO is :data:`LIFT_OFF`)."""
    out: dict[int, Bool] = {}
    for h, ok in admissible_hypotheses_loaded(k, mu, gamma, kprime, tol=tol, **loads).items():
        out[h.code] = out[h.code] | ok if h.code in out else ok
    return out


def least_constraint(k: ArrayLike, mu: ArrayLike, gamma: ArrayLike, kprime: ArrayLike, *,
                     tol: float = TOLERANCE, rtol: float = 1e-9, **loads: Any
                     ) -> tuple[NDArray[np.uint8], dict[int, Bool], dict[int, Float]]:
    """The mode chosen by Gauss's principle of least constraint at every point.

    Among the admissible hypotheses, the one of least constraint
    ``fx^2 + fy^2 + (gamma fx + M)^2/i2``; hypotheses within ``rtol`` (relative)
    of the least tie and are decided by :data:`SELECTION_ORDER`.

    Returns
    -------
    codes : ndarray of uint8
        Chosen mode codes (255 where nothing is admissible).
    admissible : dict[int, ndarray of bool]
        Admissibility per mode code.
    constraint : dict[int, ndarray]
        Gauss's constraint per mode code (inf where not admissible).
    """
    res = _all(k, mu, gamma, kprime, loads, tol)
    adm: dict[int, Bool] = {}
    cons: dict[int, Float] = {}
    for h, r in res.items():
        val = np.where(r.ok, r.constraint, np.inf)
        if h.code in cons:
            adm[h.code] = adm[h.code] | r.ok
            cons[h.code] = np.minimum(cons[h.code], val)
        else:
            adm[h.code] = r.ok
            cons[h.code] = val
    best = np.min(np.stack([cons[c] for c in SELECTION_ORDER]), axis=0)
    shape = best.shape
    out = np.full(shape, 255, dtype=np.uint8)
    free = np.ones(shape, dtype=bool)
    lim = best + rtol * (1.0 + best)
    for c in SELECTION_ORDER:
        hit = free & (cons[c] <= lim)
        out[hit] = c
        free &= ~hit
    return out, adm, cons
