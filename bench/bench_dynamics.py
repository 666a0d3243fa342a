"""Benchmark of regimemap.dynamics: a 200 x 200 outcome map of the Makris & Roussos (2000) block.

Standalone script (not a test): ``.venv/bin/python bench/bench_dynamics.py [n]``.

* the map: half-sine pulses, omega_p/p from 0.5 to 10 and k_peak/tan(alpha) from 0.5 to 8,
  mu = 5 (no sliding), default time step; target <= 60 s on 2 cores;
* accuracy: for five columns, the overturning threshold of the stepper (refined by a
  vectorised bisection at the default step) against the event-driven reference of
  ``tests/dynamics/_dyn_reference.py`` (scipy solve_ivp with events), and every map cell
  of those columns against the reference threshold (cells within 1 % of it excluded);
* speed: runs per second of the batch against one event-driven run at a time.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.dynamics import _dyn_reference as ref  # noqa: E402

from regimemap.dynamics import Block, Pulse, from_dimensionless, outcome_map, simulate  # noqa: E402


def main(n: int = 200) -> None:
    B, gamma = 0.2, 3.0
    block = Block(B=B, gamma=gamma, mu=5.0)
    p, alpha = float(block.p), float(block.alpha)
    ta = np.tan(alpha)
    eta = float(block.housner_ratio)
    w_ratio = np.linspace(0.5, 10.0, n)
    k_ratio = np.linspace(0.5, 8.0, n)
    k_peak, omega_p = from_dimensionless(w_ratio, k_ratio, B, gamma)
    print(f"Makris-Roussos block: B = {B:g} m, H = {B * gamma:g} m, p = {p:.4f} rad/s, "
          f"alpha = {alpha:.5f} rad, Housner ratio {eta:.4f}")
    t0 = time.perf_counter()
    m = outcome_map(block, "half-sine", ("k_peak", k_peak), ("omega_p", omega_p))
    seconds = time.perf_counter() - t0
    counts = np.bincount(m.category.ravel(), minlength=len(m.labels))
    print(f"outcome map {n} x {n} = {n * n} runs: {seconds:.1f} s ({n * n / seconds:.0f} runs/s); "
          + ", ".join(f"{lab} {c}" for lab, c in zip(m.labels, counts, strict=True)))

    # accuracy: thresholds in five columns
    cols = [int(np.argmin(np.abs(w_ratio - w))) for w in (1.0, 2.0, 4.0, 7.0, 10.0)]
    ref_time = 0.0
    ref_runs = 0
    worst = 0.0
    bad_cells = 0
    print(" omega_p/p   reference k/tan(a)   stepper k/tan(a)   error %   map cells off (outside 1 %)")
    for j in cols:
        T = np.pi / omega_p[j]

        def over(kp: float, T: float = T) -> bool:
            nonlocal ref_time, ref_runs
            t1 = time.perf_counter()
            out = ref.rocking(p, alpha, ref.half_sine(kp, T), T, eta=eta, t_end=T + 60 / p).overturned
            ref_time += time.perf_counter() - t1
            ref_runs += 1
            return out

        col = m.overturned[:, j] if m.first_name == "omega_p" else m.overturned[j, :]
        i = int(np.argmax(col))
        k_ref = ref.threshold(over, k_peak[i - 1] * 0.9, k_peak[i] * 1.1, tol=1e-6)
        lo, hi = 0.9 * k_ref, 1.1 * k_ref
        for _ in range(3):
            ks = np.linspace(lo, hi, 33)
            sim = simulate(block, Pulse.half_sine(ks, T), record_phases=False)
            a = int(np.argmax(sim.overturned))
            lo, hi = ks[a - 1], ks[a]
        k_st = 0.5 * (lo + hi)
        err = 100 * (k_st / k_ref - 1)
        worst = max(worst, abs(err))
        expect = k_peak > k_ref
        far = np.abs(k_peak / k_ref - 1) > 1e-2
        off = int(np.count_nonzero(col[far] != expect[far]))
        bad_cells += off
        print(f"{w_ratio[j]:10.3f}   {k_ref / ta:18.5f}   {k_st / ta:16.5f}   {err:7.4f}   {off}")
    print(f"worst threshold error {worst:.4f} % (target 1 %), map cells off {bad_cells}")
    per_ref = ref_time / ref_runs
    print(f"event-driven reference: {ref_runs} runs, {per_ref * 1e3:.1f} ms/run ({1 / per_ref:.0f} runs/s); "
          f"batch {n * n / seconds:.0f} runs/s = {n * n / seconds * per_ref:.0f} x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
