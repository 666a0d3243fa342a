"""Parameter sweeps of the loaded block (issue 10) shared by tests/test_loaded_*.py."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from regimemap import Parameters
from regimemap.mechanics.curves import named_points

GAMMAS = [0.3, 0.8, 1.5, 3.0, 6.0]

#: (buoyancy, uplift, uplift_ratio, uplift_arm, gyration): hand-picked load cases,
#: from each load alone to heavy combinations with lift-off, rest failing about O',
#: Q < 0 (rest impossible), f_y of rocking about O negative, and other inertias.
LOAD_CASES: list[tuple[float, float, float, float, float | None]] = [
    (0.4, 0.0, 0.0, 1 / 3, None),
    (0.0, 0.3, 0.0, 1 / 3, None),
    (0.0, 0.0, 0.5, 1 / 3, None),
    (0.0, 0.0, 0.0, 1 / 3, 0.5),
    (0.0, 0.0, 0.0, 1 / 3, 3.0),
    (0.3, 0.2, 0.4, -0.8, None),
    (0.5, 0.6, 0.8, 1.0, 1.2),
    (0.2, 0.9, 0.0, -1.0, 0.5),
    (0.0, 0.0, 2.0, 0.0, None),
    (0.6, 0.3, 1.5, -0.5, 2.0),
    (0.1, 1.2, 0.3, 0.7, None),
]


def random_loads(rng: np.random.Generator) -> dict[str, Any]:
    """One random load case (each load absent with probability 0.3)."""
    return dict(
        buoyancy=float(rng.uniform(0, 0.99)) * (rng.random() < 0.7),
        uplift=float(rng.exponential(0.4)) * (rng.random() < 0.7),
        uplift_ratio=float(rng.exponential(0.4)) * (rng.random() < 0.7),
        uplift_arm=float(rng.uniform(-1, 1)),
        gyration=None if rng.random() < 0.5 else float(rng.uniform(0.2, 3.0)),
    )


def loaded_sweep(n_random: int = 60, seed: int = 0) -> list[tuple[float, float, dict[str, Any]]]:
    """(gamma, kprime, loads): the hand-picked cases on a small (gamma, kprime) grid, then random ones."""
    out: list[tuple[float, float, dict[str, Any]]] = []
    for i, (beta, u, nu, eu, gy) in enumerate(LOAD_CASES):
        for j, g in enumerate(GAMMAS):
            kp = [-1.0, -0.5, 0.0, 0.5, 1.0][(i + j) % 5]
            out.append((g, kp, dict(buoyancy=beta, uplift=u, uplift_ratio=nu, uplift_arm=eu, gyration=gy)))
    rng = np.random.default_rng(seed)
    for _ in range(n_random):
        g = float(math.exp(rng.uniform(math.log(0.3), math.log(6.0))))
        crest = 1.0 if rng.random() < 0.7 else float(rng.uniform(0.5, 2.0))
        kp = float(rng.uniform(-1.0, crest))
        loads = random_loads(rng)
        loads["crest"] = crest
        out.append((g, kp, loads))
    return out


def view(gamma: float, kprime: float, loads: dict[str, Any]) -> tuple[float, float]:
    """k and mu ranges that hold every named point of the loaded map (capped)."""
    par = Parameters(gamma, kprime, **loads)
    pts = named_points(par).values()
    marks = [1.0] + [p.k for p in pts if math.isfinite(p.k)]
    k_hi = min(3.0 * max(marks), 60.0)
    mus = [1.0, par.mu_Bprime, 1.0 / gamma] + [p.mu for p in pts if math.isfinite(p.mu)]
    mu_hi = min(2.0 * max(mus), 60.0)
    return k_hi, mu_hi


def sample(gamma: float, kprime: float, loads: dict[str, Any], n: int, seed: int = 0
           ) -> tuple[np.ndarray, np.ndarray]:
    k_hi, mu_hi = view(gamma, kprime, loads)
    rng = np.random.default_rng(seed)
    return rng.uniform(0, k_hi, n), rng.uniform(0, mu_hi, n)
