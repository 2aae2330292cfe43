"""Settings of the whole test run (``tests/`` and the notebooks through nbval).

The suite runs on ``-n auto`` workers (pytest-xdist, one per core, each test file on one worker:
``--dist loadfile`` keeps a notebook's cells in order on one kernel). Each worker, and every
kernel it starts, gets one BLAS thread: two BLAS pools on two cores made some notebooks run
7-9x slower. Stages two workers need at once are computed once: the stage cache locks per key.
"""

from __future__ import annotations

import os

if os.environ.get("PYTEST_XDIST_WORKER"):
    os.environ.update(dict.fromkeys(("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"), "1"))
    from threadpoolctl import threadpool_limits

    _ONE_BLAS_THREAD = threadpool_limits(1)  # the libraries numpy has already loaded
