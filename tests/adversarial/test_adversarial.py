"""Every adversarial case (:mod:`.cases`) is refused before any work, with the exception its case names and a
message naming the parameter (or the file and its key); a doubtful but valid value warns, naming it."""

from __future__ import annotations

import pytest

from .cases import CASES, verdict
from .run import Interrupted, outcome


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_is_refused_naming_the_parameter(case, tmp_path):
    got = outcome(case, tmp_path)
    assert not isinstance(got, Interrupted), f"{case.id}: the work started ({got})"
    assert verdict(case, got) == "clear", f"{case.id}: {type(got).__name__}: {got}"


def test_the_suite_covers_at_least_150_cases_over_the_api_files_and_settings():
    kinds = {c.id.split("-")[0] for c in CASES}
    assert len(CASES) >= 150
    assert {"fit_tasselli", "simulate", "cleat_input", "tire file", "road csv", "uff", "crg"} <= kinds
    assert any(c.id.startswith("setting-") for c in CASES)
