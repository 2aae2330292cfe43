"""Threads inside one computation: two on a machine of two cores, one where the processes already share them.

The numerics that split into independent pieces (the cross-section tire's frequency blocks and
harmonics, the modal sections of a simulation, a 3-D road's wavenumber blocks) run them on
:func:`threads` threads: LAPACK, BLAS, the FFTs, ``lfilter`` and the sparse factorisations release
the GIL. Where several processes already share the cores (the test suite's workers, the
reproduction's notebooks side by side: both set ``OMP_NUM_THREADS=1``), a second thread per process
only adds contention, so the BLAS thread setting decides: ``OMP_NUM_THREADS`` (or
``OPENBLAS_NUM_THREADS``) of 1 gives one thread. The pieces and the order they are summed in do not
depend on the count: the results are the same to the last bit.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor
from typing import TypeVar

T = TypeVar("T")
R = TypeVar("R")

#: Threads at most (the machines this runs on have two cores).
MAX_THREADS = 2


def threads() -> int:
    """Threads for one computation: 1 when ``OMP_NUM_THREADS`` or ``OPENBLAS_NUM_THREADS`` is 1, else up to
    :data:`MAX_THREADS` (and the cores there are)."""
    for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS"):
        if os.environ.get(name, "").strip() == "1":
            return 1
    return max(1, min(MAX_THREADS, os.cpu_count() or 1))


def thread_map(function: Callable[[T], R], items: Iterable[T]) -> Iterator[R]:
    """``map(function, items)`` on :func:`threads` threads, results in the order of ``items``."""
    count = threads()
    if count == 1:
        return map(function, items)
    with ThreadPoolExecutor(count) as pool:
        return iter(list(pool.map(function, items)))
