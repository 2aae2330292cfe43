"""A task for the reproduction's process pool in tests: importable by a spawned worker (by reference)."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path


def sleep_long(one_thread: bool) -> None:
    """Stands for the report-only models' stages: ten minutes of work the pool must not wait for."""
    time.sleep(600)


def fail_soon(one_thread: bool) -> None:
    """Stands for report-only stages that fail while a chapter runs in the other worker: raises once
    the file named by ``SLOW_TASK_WAIT_FOR`` exists (the chapter writes it; 60 s at most)."""
    marker = Path(os.environ["SLOW_TASK_WAIT_FOR"])
    deadline = time.monotonic() + 60.0
    while not marker.exists() and time.monotonic() < deadline:
        time.sleep(0.1)
    raise RuntimeError("a report-only stage failed")


def chapter_deaf_to_sigterm(path, timeout: int, one_thread: bool) -> None:
    """Stands for a worker executing a notebook, which SIGTERM does not end (nbclient's handler shuts
    its kernel down and returns): ignores SIGTERM, writes ``SLOW_TASK_WAIT_FOR`` and runs ten minutes."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    Path(os.environ["SLOW_TASK_WAIT_FOR"]).write_text(str(os.getpid()))
    time.sleep(600)
