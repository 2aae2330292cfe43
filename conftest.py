"""Settings of the whole test run (``tests/`` and the notebooks through nbval).

The suite runs on ``-n auto`` workers (pytest-xdist, one per core, each test file on one worker:
``--dist loadfile`` keeps a notebook's cells in order on one kernel). Each worker, and every
kernel it starts, gets one BLAS thread: two BLAS pools on two cores made some notebooks run
7-9x slower. A thread count set in the environment (``OPENBLAS_NUM_THREADS`` or
``OMP_NUM_THREADS``, e.g. to check that the results do not depend on it) is honoured instead.
Stages two workers need at once are computed once: the stage cache locks per key.
"""

from __future__ import annotations

import os

BLAS_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")

if os.environ.get("PYTEST_XDIST_WORKER"):
    _threads = os.environ.get("OPENBLAS_NUM_THREADS") or os.environ.get("OMP_NUM_THREADS") or "1"
    if not _threads.isdigit() or int(_threads) < 1:
        raise ValueError(f"OPENBLAS_NUM_THREADS / OMP_NUM_THREADS = {_threads!r}: valid values are integers >= 1")
    for _name in BLAS_VARIABLES:
        os.environ.setdefault(_name, _threads)
    from threadpoolctl import threadpool_limits

    _BLAS_THREADS = threadpool_limits(int(_threads))  # the libraries numpy has already loaded

#: Notebooks nbval does not collect: the loaded FE tire's chapter computes its production mesh's stages
#: (about 10 CPU-minutes) beyond the suite's budget; tests/experiments/test_loaded_tire.py runs it alone
#: on the test mesh through papermill instead, and the reproduction runs it as it is.
collect_ignore = ["notebooks/16-loaded-fe-tire.ipynb"]
