"""Outcome maps (data only): sweep two inputs, simulate every cell in one batch.

The dimensionless axes are those of Makris & Roussos (2000) and Zhang & Makris
(2001): omega_p/p and k_peak/tan(alpha), with p = sqrt(3 g/(4 R)),
R = B sqrt(1 + gamma^2) and alpha = atan(1/gamma) (Housner 1963).

References
----------
Housner, G. W. (1963). Bull. Seismol. Soc. Am. 53(2), 403-417.

Makris, N. & Roussos, Y. (2000). Geotechnique 50(3), 243-262.

Zhang, J. & Makris, N. (2001). J. Eng. Mech. 127(5), 473-483.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .block import Block, G, frequency_parameter, slenderness
from .pulses import Pulse
from .stepper import CATEGORY_LABELS, simulate

__all__ = ["OutcomeMap", "outcome_map", "SWEEPABLE", "DIMENSIONLESS", "to_dimensionless",
           "from_dimensionless", "dimensionless_values"]

FloatArray = NDArray[np.float64]

_BLOCK_FIELDS = tuple(f.name for f in fields(Block) if f.name != "g")
#: Inputs an outcome map can sweep: the pulse's k_peak, duration or omega_p, and any block field.
SWEEPABLE: tuple[str, ...] = ("k_peak", "duration", "omega_p") + _BLOCK_FIELDS


def to_dimensionless(k_peak: ArrayLike, omega_p: ArrayLike, B: float, gamma: float,
                     g: float = G) -> tuple[FloatArray, FloatArray]:
    """(omega_p/p, k_peak/tan(alpha)) of a uniform block of half width B and gamma = H/B."""
    p = frequency_parameter(B, gamma, g)
    return (np.asarray(omega_p, dtype=np.float64) / p,
            np.asarray(k_peak, dtype=np.float64) / np.tan(slenderness(gamma)))


def from_dimensionless(omega_ratio: ArrayLike, k_ratio: ArrayLike, B: float, gamma: float,
                       g: float = G) -> tuple[FloatArray, FloatArray]:
    """(k_peak, omega_p) from (omega_p/p, k_peak/tan(alpha)): the inverse of :func:`to_dimensionless`."""
    p = frequency_parameter(B, gamma, g)
    return (np.asarray(k_ratio, dtype=np.float64) * np.tan(slenderness(gamma)),
            np.asarray(omega_ratio, dtype=np.float64) * p)


#: The swept inputs that have a dimensionless form, and its name: k_peak/tan(alpha), omega_p/p.
DIMENSIONLESS: dict[str, str] = {"k_peak": "k_peak/tan(alpha)", "duration": "omega_p/p",
                                 "omega_p": "omega_p/p"}


def dimensionless_values(name: str, values: ArrayLike, block: Block, shape: str) -> FloatArray:
    """The values of a swept input in the dimensionless units of :data:`DIMENSIONLESS`.

    ``k_peak`` -> k_peak/tan(alpha), ``omega_p`` -> omega_p/p and ``duration`` -> omega_p/p
    with omega_p the pulse's (pi/duration, or 2 pi/duration for one-sine and one-cosine), for
    the block's own p (which accounts for its radius of gyration) and alpha.

    Raises
    ------
    ValueError
        For an input without a dimensionless form, or a block whose p or alpha is not one
        number (a block field that is swept).
    """
    if name not in DIMENSIONLESS:
        raise ValueError(f"{name} has no dimensionless form (only {', '.join(DIMENSIONLESS)})")
    p_all = np.asarray(block.p, dtype=np.float64)
    alpha_all = np.asarray(block.alpha, dtype=np.float64)
    if p_all.size != 1 or alpha_all.size != 1:
        raise ValueError("dimensionless axes need one block (p and alpha the same in every cell)")
    p, alpha = float(p_all.ravel()[0]), float(alpha_all.ravel()[0])
    v = np.asarray(values, dtype=np.float64)
    if name == "k_peak":
        return np.asarray(v / np.tan(alpha), dtype=np.float64)
    if name == "omega_p":
        return np.asarray(v / p, dtype=np.float64)
    return np.asarray(Pulse.make(shape, 1.0, v).omega_p, dtype=np.float64) / p


@dataclass(frozen=True)
class OutcomeMap:
    """Per-cell outcomes, arrays of shape (len(second_values), len(first_values)).

    Attributes
    ----------
    first_name, second_name : str
        Swept inputs (columns vary the first, rows the second).
    first_values, second_values : ndarray
        Their values.
    category : ndarray of int8
        Outcome code: 0 rest, 1 slide only, 2 rock only, 3 slide-rock, 4 overturned
        (labels in :attr:`labels`).
    overturned : ndarray of bool
    max_rotation : ndarray
        Largest |theta| (rad).
    residual_slide : ndarray
        Final slide of the base (m), positive towards O.
    labels : tuple of str
        Category labels by code.
    seconds : float
        Wall time of the batch.
    """

    first_name: str
    first_values: FloatArray
    second_name: str
    second_values: FloatArray
    category: NDArray[np.int8]
    overturned: NDArray[np.bool_]
    max_rotation: FloatArray
    residual_slide: FloatArray
    labels: tuple[str, ...] = CATEGORY_LABELS
    seconds: float = 0.0


def outcome_map(block: Block, shape: str, first: tuple[str, ArrayLike], second: tuple[str, ArrayLike],
                *, k_peak: ArrayLike | None = None, duration: ArrayLike | None = None,
                restitution: float | None = None, dt: float | None = None,
                pulse_params: dict[str, float] | None = None) -> OutcomeMap:
    """Simulate every combination of two swept inputs (one batch) and tabulate the outcomes.

    Parameters
    ----------
    block : Block
        The block; the swept fields are replaced.
    shape : str
        Pulse shape (see :data:`regimemap.dynamics.SHAPES`).
    first, second : (str, array_like)
        Name (one of :data:`SWEEPABLE`) and values of the inputs along the
        columns and the rows.  ``omega_p`` sets the duration through
        :meth:`Pulse.from_frequency`.
    k_peak, duration : array_like, optional
        The pulse's fixed values when not swept.
    restitution, dt : optional
        Passed to :func:`regimemap.dynamics.simulate`.
    pulse_params : dict, optional
        Shape parameters (``peak_at``, ``peak_ratio``, ``impulsive_fraction``).

    Returns
    -------
    OutcomeMap
    """
    (n1, v1), (n2, v2) = first, second
    for name in (n1, n2):
        if name not in SWEEPABLE:
            raise ValueError(f"cannot sweep {name!r}; sweepable: {', '.join(SWEEPABLE)}")
    if n1 == n2:
        raise ValueError("the two swept inputs must differ")
    a1 = np.asarray(v1, dtype=np.float64).ravel()
    a2 = np.asarray(v2, dtype=np.float64).ravel()
    X, Y = np.meshgrid(a1, a2)
    values: dict[str, Any] = {n1: X.ravel(), n2: Y.ravel()}
    params = dict(pulse_params or {})
    kp = values.get("k_peak", k_peak)
    if kp is None:
        raise ValueError("k_peak must be given or swept")
    if "omega_p" in values:
        if "duration" in values:
            raise ValueError("sweep duration or omega_p, not both")
        pulse = Pulse.from_frequency(shape, kp, values["omega_p"], **params)
    else:
        dur = values.get("duration", duration)
        if dur is None:
            raise ValueError("duration (or omega_p) must be given or swept")
        pulse = Pulse.make(shape, kp, dur, **params)
    changes = {name: val for name, val in values.items() if name in _BLOCK_FIELDS}
    blk = block.with_(**changes) if changes else block
    t0 = time.perf_counter()
    sim = simulate(blk, pulse, restitution=restitution, dt=dt, record_phases=False)
    seconds = time.perf_counter() - t0
    shape2 = X.shape
    return OutcomeMap(first_name=n1, first_values=a1, second_name=n2, second_values=a2,
                      category=sim.category.reshape(shape2), overturned=sim.overturned.reshape(shape2),
                      max_rotation=sim.max_rotation.reshape(shape2),
                      residual_slide=sim.residual_slide.reshape(shape2), seconds=seconds)
