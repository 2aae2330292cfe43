"""A task for the reproduction's process pool in tests: importable by a spawned worker (by reference)."""

from __future__ import annotations

import time


def sleep_long(one_thread: bool) -> None:
    """Stands for the report-only models' stages: ten minutes of work the pool must not wait for."""
    time.sleep(600)
