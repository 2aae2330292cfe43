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


def test_prony_states_updated_in_place_as_by_the_formula():
    """The in-place update (BLAS axpy on each row) equals the closed formula and refuses arrays it cannot write."""
    from roadnoise_utils.tire.rubber import PronyBranches, prony_series

    branches = PronyBranches(prony_series(ru.tire.FractionalZener(3.0, 1.0e-3, 0.3)), 1.0e-4)
    rng = np.random.default_rng(0)
    states = rng.normal(size=(branches.weights.size, 50))
    old, new = rng.normal(size=50), rng.normal(size=50)
    expected = branches.update(states, old, new)
    branches.update_in_place(states, old, new)
    assert np.abs(states - expected).max() < 1e-14
    fused, history = branches.update(expected, new, old), np.full(50, np.nan)  # a second step, with its history
    branches.update_in_place(states, new, old, history)
    assert np.abs(states - fused).max() < 1e-14
    assert np.abs(history - branches.history(fused, old)).max() < 1e-13
    with pytest.raises(ValueError, match="C-contiguous"):
        branches.update_in_place(np.asfortranarray(states), old, new)


def test_shared_prony_states_give_each_compounds_separate_states_bit_for_bit():
    """Compounds fitted on one grid of relaxation times share their states: three steps of the shared
    update give every compound's history and extra force exactly (==) as its own states would; the
    union keeps each time once; branches of another time step are refused."""
    from roadnoise_utils.tire.rubber import PronyBranches, SharedPronyStates, prony_series

    laws = {
        "soft": ru.tire.FractionalZener(3.0, 1.0e-3, 0.3),
        "stiff": ru.tire.FractionalZener(1.5, 1.0e-4, 0.5),
        "slow": ru.tire.FractionalZener(2.0, 1.0e-1, 0.2),
    }
    dt, size = 1.0e-4, 40000  # more than one chunk
    branches = {c: PronyBranches(prony_series(law), dt) for c, law in laws.items()}
    assert len({b.times.size for b in branches.values()}) > 1  # different zero weights: the rows differ
    rng = np.random.default_rng(2)
    u = [rng.normal(size=size) for _ in range(4)]
    shared = SharedPronyStates(branches, size)
    assert shared.times.size == np.unique(np.concatenate([b.times for b in branches.values()])).size
    histories = shared.start(u[0])
    own = {c: np.tile(u[0], (b.weights.size, 1)) for c, b in branches.items()}
    own_history = {c: b.history(own[c], u[0]) for c, b in branches.items()}
    for old, new in zip(u[:-1], u[1:]):
        shared.update_in_place(old, new, histories)
        for c, b in branches.items():
            b.update_in_place(own[c], old, new, own_history[c])
            assert np.array_equal(histories[c], own_history[c])
            assert np.array_equal(shared.states[shared.rows[c]], own[c])
            assert np.array_equal(shared.extra(c, new), b.extra(own[c], new))
    other = {"soft": branches["soft"], "late": PronyBranches(prony_series(laws["stiff"]), 2 * dt)}
    with pytest.raises(ValueError, match="another time step"):
        SharedPronyStates(other, 10)
