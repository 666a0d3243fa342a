"""Run the blocks of a lifetime simulation: in this process, in local processes, or on Dask.

Chunks are runs of consecutive blocks (:mod:`regimemap.lifetime.engine`); each
block has its own stream spawned from the root seed, so the concatenated
result does not depend on the chunk size, on ``jobs`` or on the cluster.
Dask (``distributed``) is imported only when a scheduler address is given.  The local
processes are those of :func:`regimemap.workers.worker_pool`, the one place where
regimemap starts processes (Ctrl-C, SIGTERM and a dead parent end them at once).
"""

from __future__ import annotations

import contextlib
import logging
import math
import os
import time
from collections.abc import Callable, Generator, Iterable, Sequence
from concurrent.futures import Future
from dataclasses import dataclass
from typing import Any, TypeVar

import numpy as np

from ..workers import WorkerPool, worker_pool
from .engine import BLOCK, BlockResult, simulate_blocks
from .finite import quiet_arithmetic
from .model import Caisson, LifetimeModel

__all__ = ["Chunk", "ClusterUnavailable", "make_chunks", "run_chunk", "run_chunks",
           "root_seed", "submit_all", "worker_pool"]

_T = TypeVar("_T")

_log = logging.getLogger(__name__)

#: Lifetimes per chunk by default: a few seconds of work, ~tens of MB.
DEFAULT_CHUNK = 500

#: Seconds to wait for a Dask scheduler before giving up (``REGIMEMAP_DASK_TIMEOUT`` overrides).
DASK_CONNECT_TIMEOUT = 10.0

#: Seconds given to closing the connection to a Dask scheduler.
DASK_CLOSE_TIMEOUT = 3.0


class ClusterUnavailable(RuntimeError):
    """Dask's ``distributed`` is not installed, or the scheduler cannot be reached."""


@dataclass(frozen=True)
class Chunk:
    """Blocks ``first_block .. first_block + len(streams) - 1`` and how many lifetimes to keep."""

    first_block: int
    streams: tuple[np.random.SeedSequence, ...]
    keep: int


def root_seed(seed: int | None) -> int:
    """The root seed: ``seed``, or fresh entropy from the operating system when None."""
    if seed is None:
        entropy = np.random.SeedSequence().entropy
        assert isinstance(entropy, int)
        return entropy
    if seed < 0:
        raise ValueError(f"seed must be >= 0, got {seed!r}")
    return int(seed)


def make_chunks(trials: int, seed: int, chunk: int = DEFAULT_CHUNK) -> list[Chunk]:
    """Cut ``trials`` lifetimes into chunks of whole blocks (``chunk`` rounded up to blocks)."""
    if trials < 1:
        raise ValueError(f"trials must be >= 1, got {trials!r}")
    n_blocks = math.ceil(trials / BLOCK)
    streams = np.random.SeedSequence(seed).spawn(n_blocks)
    per = max(1, math.ceil(chunk / BLOCK))
    out = []
    for first in range(0, n_blocks, per):
        these = tuple(streams[first:first + per])
        keep = min(trials - first * BLOCK, len(these) * BLOCK)
        out.append(Chunk(first, these, keep))
    return out


def run_chunk(caissons: tuple[Caisson, ...], model: LifetimeModel, chunk: Chunk,
              guides: int = 0) -> BlockResult:
    """Simulate one chunk's blocks and keep its share of the lifetimes (``guides``: :func:`run_chunks`);
    numpy's warnings silenced, the results are checked (:mod:`regimemap.lifetime.finite`)."""
    with quiet_arithmetic():
        parts = simulate_blocks(caissons, model, chunk.streams, guides=guides, keep=chunk.keep)
    return BlockResult.join(parts, chunk.keep)


def _serial(caissons: tuple[Caisson, ...], model: LifetimeModel,
            chunks: Sequence[Chunk], guides: int) -> Generator[BlockResult, None, None]:
    for c in chunks:
        yield run_chunk(caissons, model, c, guides)


def submit_all(pool: WorkerPool, fn: Callable[..., _T],
               arguments: Iterable[tuple[Any, ...]]) -> list[Future[_T]]:
    """``pool.submit(fn, *args)`` for each ``args``: their futures, in order."""
    return [pool.submit(fn, *args) for args in arguments]


def _processes(caissons: tuple[Caisson, ...], model: LifetimeModel, chunks: Sequence[Chunk],
               jobs: int, guides: int) -> Generator[BlockResult, None, None]:
    with worker_pool(jobs) as pool:
        futures = submit_all(pool, run_chunk, ((caissons, model, c, guides) for c in chunks))
        for f in futures:  # in order: the result does not depend on which finishes first
            yield f.result()


def _dask(caissons: tuple[Caisson, ...], model: LifetimeModel, chunks: Sequence[Chunk],
          scheduler: str, guides: int) -> Generator[BlockResult, None, None]:
    try:
        from distributed import Client
    except ImportError:
        raise ClusterUnavailable(
            "--scheduler needs Dask's distributed package: pip install 'regimemap[cluster]'") from None
    timeout = float(os.environ.get("REGIMEMAP_DASK_TIMEOUT", DASK_CONNECT_TIMEOUT))
    try:
        client = Client(scheduler, timeout=f"{timeout:g}s")
    except Exception as exc:  # noqa: BLE001 - any failure to connect: a bad address, a refusal, a timeout
        raise ClusterUnavailable(f"cannot reach the Dask scheduler at {scheduler!r}: "
                                 f"{str(exc) or type(exc).__name__}") from None
    futures = []
    try:
        futures = client.map(run_chunk, [caissons] * len(chunks), [model] * len(chunks), list(chunks),
                             [guides] * len(chunks), pure=False)
        for f in futures:
            yield f.result()
    except BaseException:  # an interrupt, an error, or the generator closed early: nothing left running
        with contextlib.suppress(Exception):
            client.cancel(futures)
        raise
    finally:
        with contextlib.suppress(Exception):
            client.close(timeout=DASK_CLOSE_TIMEOUT)


def run_chunks(caissons: tuple[Caisson, ...], model: LifetimeModel, chunks: Sequence[Chunk], *,
               jobs: int = 1, scheduler: str | None = None,
               progress: Callable[[int], None] | None = None, guides: int = 0) -> BlockResult:
    """Run every chunk and join their results in order.

    Parameters
    ----------
    caissons : tuple of Caisson
        One or more widths of the same section.
    model : LifetimeModel
        Climate and options.
    chunks : sequence of Chunk
        From :func:`make_chunks`.
    jobs : int, optional
        Local worker processes (1: this process).
    scheduler : str, optional
        Address of a running Dask scheduler (``tcp://host:8786``): the chunks
        run on its workers instead.
    progress : callable, optional
        Called with the number of lifetimes of each finished chunk.
    guides : int, optional
        The first ``guides`` caissons only choose the waves (their sliding
        heights count in the sampling threshold) and are not slid; the result
        has the rows of ``caissons[guides:]``.

    Returns
    -------
    BlockResult
        The lifetimes of all chunks, in order.
    """
    if scheduler is not None:
        results: Generator[BlockResult, None, None] = _dask(caissons, model, chunks, scheduler, guides)
        where = f"on the Dask scheduler at {scheduler}"
    elif jobs > 1 and len(chunks) > 1:
        results = _processes(caissons, model, chunks, min(jobs, len(chunks)), guides)
        where = f"in {min(jobs, len(chunks))} processes"
    else:
        results = _serial(caissons, model, chunks, guides)
        where = "in this process"
    total = sum(c.keep for c in chunks)
    _log.info("%d lifetimes of %d years x %d width%s in %d chunk%s %s", total, model.years, len(caissons),
              "s" if len(caissons) != 1 else "", len(chunks), "s" if len(chunks) != 1 else "", where)
    parts = []
    t0 = last = time.perf_counter()
    with contextlib.closing(results):  # an exception here (in progress) stops the workers too
        for i, r in enumerate(results, start=1):
            parts.append(r)
            now = time.perf_counter()
            _log.debug("chunk %d/%d: %d lifetimes, %d sliding waves, %.2f s", i, len(chunks),
                       int(r.storms.size), r.sliding_waves, now - last)
            last = now
            if progress is not None:
                progress(int(r.storms.size))
    seconds = time.perf_counter() - t0
    _log.info("%d chunks done in %.2f s (%.0f lifetimes/s)", len(chunks), seconds,
              total / seconds if seconds > 0 else float("inf"))
    return BlockResult.join(parts)
