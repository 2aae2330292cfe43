"""Threads inside one computation: the pieces of a stage on the machine's cores (two at most).

The numerics that split into independent pieces (the cross-section tire's frequency blocks and
harmonics, the modal sections of a simulation, a 3-D road's wavenumber blocks) run them on
:func:`threads` threads: LAPACK, BLAS (one thread each), the FFTs, ``lfilter`` and the sparse
factorisations release the GIL. Beside another process (the test suite's second worker, the
reproduction's second notebook) the second thread only shares a busy core, at little cost (these
threads wait on locks, they do not spin as BLAS pools do); when that process waits for a stage this
one computes, or has finished, it halves the stage's time. ``ROADNOISE_THREADS=1`` runs everything
on one thread. The pieces and the order they are summed in do not depend on the count: the results
are the same to the last bit.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor
from typing import TypeVar

from . import settings

T = TypeVar("T")
R = TypeVar("R")

#: Threads at most (the machines this runs on have two cores).
MAX_THREADS = 2


def threads() -> int:
    """Threads for one computation: ``ROADNOISE_THREADS`` (1 or 2), else up to :data:`MAX_THREADS` (and the cores
    there are)."""
    setting = settings.choice("ROADNOISE_THREADS", ("1", "2"))
    if setting is not None:
        return int(setting)
    return max(1, min(MAX_THREADS, os.cpu_count() or 1))


def thread_map(function: Callable[[T], R], items: Iterable[T]) -> Iterator[R]:
    """``map(function, items)`` on :func:`threads` threads, results in the order of ``items``."""
    count = threads()
    if count == 1:
        return map(function, items)
    with ThreadPoolExecutor(count) as pool:
        return iter(list(pool.map(function, items)))
