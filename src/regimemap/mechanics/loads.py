"""The load model of a block: vertical loads, inertia, and the constants they change.

Besides gravity and the push F = m g k (to the left, at height ``kprime*H``
above the centre of mass C) the block may carry

* buoyancy :math:`\\beta m g` upward through C's vertical;
* uplift :math:`U = (u + \\nu k) m g` upward at :math:`e_u B` from C towards O' (the
  seaward corner; :math:`e_u = 1/3` is Goda's triangle, zero under O);
* any inertia :math:`I = m B^2 i^2` (``gyration = i``; None is the uniform block,
  :math:`i^2 = (1 + \\gamma^2)/3`).

Per unit m g (moments per unit m g B) the net downward load is
:math:`W = 1 - \\beta - U` and the applied moment about C (counter-clockwise, i.e.
lifting O') is :math:`S = \\gamma k k' + e_u U`.  The derivation of every constant
below is in ``docs/derivation.md``.  With :math:`\\mathit{extra} = 3 i^2 - (1 + \\gamma^2)`
(exactly 0.0 for the uniform block), :math:`A_0 = 4 + \\gamma^2 + \\mathit{extra}` and
:math:`d_0 = d + \\mathit{extra}`::

    P  = gamma(1+k') + nu(1+e_u)       Q  = 1 - beta - u(1+e_u)     rest about O: k P <= Q
    P' = gamma(1+k') - nu(1-e_u)       Q' = 1 - beta - u(1-e_u)     rest about O': Q' + k P' >= 0
    a_O  = a + (extra - 3 gamma nu (1+e_u))   b_O  = b Q     (3 D f_x of rocking about O)
    c_O  = c - nu (d0 - 3 e_u)                d_O  = d0 (1-beta-u) + 3 e_u u
    a_O' = a + (extra + 3 gamma nu (1-e_u))   b_O' = b Q'    (3 D f_x of rocking about O')
    c_O' = c + nu (d0 + 3 e_u)                d_O' = d0 (1-beta-u) - 3 e_u u

with a, b, c, d the report's (3.18)-(3.21).  At zero loads every added term is
``+ 0.0``, ``- 0.0`` or ``* 1.0``, exact in IEEE arithmetic, so each constant
is the report's bit for bit, and so is every closed form built on them
(:mod:`regimemap.mechanics.constants`).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

__all__ = [
    "BlockConstants",
    "applied_moment",
    "block_constants",
    "coefficients",
    "default_i2",
    "net_load",
    "subset",
    "uplift_load",
]

#: A float or an array of floats (the forms broadcast like numpy ufuncs).
Num = Any


def coefficients(gamma: Num, kprime: Num) -> tuple[Num, Num, Num, Num]:
    """a, b, c, d of (3.18)-(3.21) and (4.42)-(4.45) (k' signed).

    Parameters
    ----------
    gamma : float or ndarray
        Aspect ratio H/B.
    kprime : float or ndarray
        Force height h/H, signed.

    Returns
    -------
    (a, b, c, d)
        :math:`a = 4 + \\gamma^2 - 3 \\gamma^2 k'`, :math:`b = 3 \\gamma`,
        :math:`c = 3 \\gamma (1 + k')`, :math:`d = 1 + 4 \\gamma^2` (g = :math:`\\gamma`).
    """
    g2 = gamma * gamma
    a = 4.0 + g2 - 3.0 * g2 * kprime
    b = 3.0 * gamma
    c = 3.0 * gamma * (1.0 + kprime)
    d = 1.0 + 4.0 * g2
    return a, b, c, d




def default_i2(gamma: Num) -> Num:
    """Squared radius of gyration about C over B^2 of a uniform block: (1 + gamma^2)/3."""
    return (1.0 + gamma * gamma) / 3.0


def uplift_load(k: Num, uplift: Num, uplift_ratio: Num) -> Num:
    """U = u + nu k: the uplift per unit m g."""
    return uplift + uplift_ratio * k


def net_load(k: Num, buoyancy: Num, uplift: Num, uplift_ratio: Num) -> Num:
    """W = 1 - beta - u - nu k: the net downward load per unit m g (1 at zero loads)."""
    return (1.0 - buoyancy - uplift) - uplift_ratio * k


def applied_moment(k: Num, gamma: Num, kprime: Num, uplift_arm: Num, U: Num) -> Num:
    """S = gamma k k' + e_u U: the applied moment about C per unit m g B (counter-clockwise)."""
    return gamma * k * kprime + uplift_arm * U


class BlockConstants(NamedTuple):
    """The parameters of a block and its generalised constants (floats, or arrays that broadcast).

    Built by :func:`block_constants`; the names are those of the module docstring
    (``Pp``, ``Qp`` for P', Q'; ``aO``..``dO`` for rocking about O, ``aP``..``dP``
    about O').
    """

    gamma: Num
    kprime: Num
    buoyancy: Num
    uplift: Num
    uplift_ratio: Num
    uplift_arm: Num
    i2: Num
    extra: Num
    a: Num
    b: Num
    c: Num
    d: Num
    A0: Num
    d0: Num
    P: Num
    Q: Num
    Pp: Num
    Qp: Num
    aO: Num
    bO: Num
    cO: Num
    dO: Num
    aP: Num
    bP: Num
    cP: Num
    dP: Num

    @property
    def w0(self) -> Num:
        """W at k = 0: 1 - beta - u."""
        return 1.0 - self.buoyancy - self.uplift


def block_constants(gamma: Num, kprime: Num, buoyancy: Num = 0.0, uplift: Num = 0.0,
                    uplift_ratio: Num = 0.0, uplift_arm: Num = 1.0 / 3.0,
                    gyration: Num | None = None) -> BlockConstants:
    """The generalised constants of a block (no checks: see :mod:`regimemap.mechanics.validation`).

    ``a, b, c, d`` are computed as :func:`regimemap.mechanics.constants.coefficients`
    computes them; the others as in the module docstring.
    """
    g, kp, beta, u, nu, eu = gamma, kprime, buoyancy, uplift, uplift_ratio, uplift_arm
    g2 = g * g
    if gyration is None:
        i2 = default_i2(g)
        extra = 0.0
    else:
        i2 = gyration * gyration
        extra = 3.0 * i2 - (1.0 + g2)
    a, b, c, d = coefficients(g, kp)  # (3.18)-(3.21), (4.42)-(4.45)
    A0 = (4.0 + g**2) + extra
    d0 = d + extra
    w0 = 1.0 - beta - u
    return BlockConstants(
        gamma=g, kprime=kp, buoyancy=beta, uplift=u, uplift_ratio=nu, uplift_arm=eu, i2=i2,
        extra=extra, a=a, b=b, c=c, d=d, A0=A0, d0=d0,
        P=g * (1.0 + kp) + nu * (1.0 + eu), Q=1.0 - beta - u * (1.0 + eu),
        Pp=g * (1.0 + kp) - nu * (1.0 - eu), Qp=1.0 - beta - u * (1.0 - eu),
        aO=a + (extra - 3.0 * g * nu * (1.0 + eu)), bO=b * (1.0 - beta - u * (1.0 + eu)),
        cO=c - nu * (d0 - 3.0 * eu), dO=d0 * w0 + 3.0 * eu * u,
        aP=a + (extra + 3.0 * g * nu * (1.0 - eu)), bP=b * (1.0 - beta - u * (1.0 - eu)),
        cP=c + nu * (d0 + 3.0 * eu), dP=d0 * w0 - 3.0 * eu * u,
    )


def subset(cst: BlockConstants, shape: tuple[int, ...], index: Any) -> BlockConstants:
    """The constants at ``index`` of points of ``shape`` (array fields broadcast, then indexed)."""
    return BlockConstants(*(np.broadcast_to(v, shape)[index] if np.ndim(v) else v for v in cst))
