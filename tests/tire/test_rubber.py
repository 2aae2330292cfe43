"""The fractional-Zener rubber law: its limits, passivity and the compound table."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru


def test_viscoelastic_law_limits():
    law = ru.load_tire("165_65R14").compounds["tread"].law()
    assert law.ratio(0.0) == pytest.approx(1.0)  # relaxed modulus at 0 Hz
    assert abs(law.ratio(1e12) - law.modulus_ratio) < 1e-3 * law.modulus_ratio  # glassy limit
    w = 2 * 3.141592653589793 * 100.0
    assert law.ratio(-w) == pytest.approx(law.ratio(w).conjugate())  # real impulse response
    assert law.loss_factor(w) > 0  # passive


def test_bad_laws_are_refused():
    with pytest.raises(ValueError, match="modulus_ratio"):
        ru.tire.FractionalZener(1.0, 1e-4, 0.5)
    with pytest.raises(ValueError, match="order"):
        ru.tire.FractionalZener(2.0, 1e-4, 1.5)


def test_compound_table_reports_the_storage_rise():
    laws = {name: c.law() for name, c in ru.load_tire("165_65R14").compounds.items()}
    table = ru.tire.compound_table(laws)
    w1, w250 = 2 * np.pi * 1.0, 2 * np.pi * 250.0
    expected = laws["tread"].storage(w250) / laws["tread"].storage(w1) - 1
    assert table.loc["tread", "storage rise 1->250 Hz"] == pytest.approx(expected)
    assert (table.filter(like="loss factor") > 0).all().all()
