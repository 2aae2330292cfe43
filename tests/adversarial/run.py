"""Run the adversarial cases and sort their outcomes: ``python -m tests.adversarial.run`` prints the count per
verdict (clear / poor / silent / wrong) and every case that is not clear, with what it gave.

A case that runs longer than :data:`SECONDS` started the work its bad input should have stopped: it is
interrupted and counted *silent*.
"""

from __future__ import annotations

import collections
import signal
import sys
import tempfile
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from roadnoise_utils.guards import RoadnoiseWarning

from .cases import CASES, Case, verdict
from .inputs import inputs

#: A bad input is refused before any work: a case still running after this many seconds is interrupted.
SECONDS = 5


@dataclass
class Warned:
    """A result and the RoadnoiseWarnings its call gave."""

    result: Any
    messages: list[str]


class Interrupted(Exception):
    """A case ran past :data:`SECONDS`."""


def _alarm(signum, frame):
    raise Interrupted(f"still running after {SECONDS} s")


def outcome(case: Case, tmp: Path) -> Any:
    """What ``case.call`` returned or raised (an :class:`Interrupted` after :data:`SECONDS`)."""
    args: list[Any] = [inputs()]
    with pytest.MonkeyPatch.context() as env:
        if "tmp" in case.needs:
            args.append(tmp)
        if "env" in case.needs:
            args.append(env)
        previous = signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(SECONDS)
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                result = case.call(*args)
            return Warned(result, [str(w.message) for w in caught if issubclass(w.category, RoadnoiseWarning)])
        except BaseException as error:  # noqa: BLE001 - the outcome is what we sort
            if isinstance(error, KeyboardInterrupt):
                raise
            return error
        finally:
            signal.alarm(0)
            signal.signal(signal.SIGALRM, previous)


def main() -> int:
    counts: collections.Counter[str] = collections.Counter()
    inputs()
    for number, case in enumerate(CASES):
        with tempfile.TemporaryDirectory() as tmp:
            got = outcome(case, Path(tmp))
        kind = "silent" if isinstance(got, Interrupted) else verdict(case, got)
        counts[kind] += 1
        if kind != "clear":
            shown = f"{type(got).__name__}: {got}" if isinstance(got, BaseException) else type(got).__name__
            print(f"{kind:6s} {case.id}: {shown[:200]!s}".replace("\n", " "))
        print(f"{number + 1}/{len(CASES)}", end="\r", file=sys.stderr)
    print(f"{len(CASES)} cases: " + ", ".join(f"{counts[k]} {k}" for k in ("clear", "poor", "silent", "wrong")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
