"""The batch of the stepper: a run's outcome does not depend on the runs beside it, bit for bit.

The runs still moving are kept as a struct of arrays that loses the runs that leave
(``_Batch.compress`` / ``retire``); every operation of a step is elementwise, so a run simulated
alone and the same run inside a batch whose other runs leave earlier or later agree exactly.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from regimemap.dynamics import Block, Pulse, simulate

# (B, gamma, mu, kprime, beta, nu, k_peak, duration): rest, slide, rock with impacts, two overturns
# at different times, a loaded caisson sliding
RUNS = np.array([
    (0.2, 3.0, 0.5, 0.0, 0.0, 0.0, 0.2, 0.5),
    (1.0, 0.5, 0.3, 0.0, 0.0, 0.0, 0.5, 0.4),
    (0.2, 3.0, 5.0, 0.0, 0.0, 0.0, 0.5, 0.5),
    (0.2, 2.0, 0.6, 0.0, 0.0, 0.0, 1.2, 0.3),
    (0.2, 3.0, 5.0, 0.0, 0.0, 0.0, 0.9, 0.6),
    (5.0, 1.1, 0.6, -0.1, 0.35, 0.25, 1.2, 3.0),
])


def _batch(rows: np.ndarray) -> tuple[Block, Pulse]:
    B, gamma, mu, kprime, beta, nu, k, T = rows.T
    return Block(B=B, gamma=gamma, mu=mu, kprime=kprime, buoyancy=beta, uplift_ratio=nu), Pulse.half_sine(k, T)


@pytest.mark.slow
@pytest.mark.parametrize("restitution", [pytest.param(None, marks=pytest.mark.portable), 0.7])
@pytest.mark.deep
def test_a_run_alone_and_in_a_batch_agree_bit_for_bit(restitution: float | None) -> None:
    together = simulate(*_batch(RUNS), restitution=restitution, history=4)
    assert len(set(together.end_time.tolist())) == len(RUNS)  # the runs leave one by one
    for i in range(len(RUNS)):
        alone = simulate(*_batch(RUNS[i:i + 1]), restitution=restitution, history=0)
        for f in dataclasses.fields(alone):
            if f.name in ("phases", "history", "unresolved"):
                continue
            a, b = getattr(alone, f.name), getattr(together, f.name)
            assert a[0] == b[i] and a.dtype == b.dtype, (i, f.name)
        assert together.phases is not None and alone.phases == [together.phases[i]]
        if i == 4:
            assert alone.history is not None and together.history is not None
            for f in dataclasses.fields(alone.history):
                assert np.array_equal(getattr(alone.history, f.name), getattr(together.history, f.name))
