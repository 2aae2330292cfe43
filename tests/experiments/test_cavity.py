"""The air cavity through the tire file's switch: the direct FRFs, the RM chain and the refusing FE stages."""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.experiments import cavity
from roadnoise_utils.repro import stages
from roadnoise_utils.tire.model import FRFResult, NotApplicable
from roadnoise_utils.tire.ring.spec import from_dict, to_dict

TIRE = "195_65R15"


def test_the_switch_is_off_by_default_and_strict():
    """Every tire file keeps the paper's model (off); a file without [cavity] is off; a switch that is
    not true/false is refused naming it; switched on, the spec round-trips through its data."""
    spec = stages.load_tire(TIRE)
    assert spec.cavity.enabled is False
    data = to_dict(spec)
    del data["cavity"]
    assert from_dict(data).cavity.enabled is False
    data = to_dict(spec)
    data["cavity"]["enabled"] = 1
    with pytest.raises(ValueError, match="enabled = 1 must be true or false"):
        from_dict(data)
    on = cavity.with_cavity(TIRE).spec
    assert on.cavity.enabled and to_dict(from_dict(to_dict(on))) == to_dict(on)


def test_the_rm_chain_carries_the_cavity():
    """With the cavity on, the tassello fits summed (the RM chain's fixed-hub H_tot) follow the direct
    H_tot with its cavity peak within 0.5 % of the peak over 0-250 Hz (0.23 % measured); the cavity
    raises the direct |H_tot| near its vertical mode several times."""
    on = cavity.with_cavity(TIRE)
    assert cavity.chain_check(on, np.arange(0.0, 251.0)) < 5e-3
    f = stages.frf_visco(on).freqs
    band = (f >= 200) & (f <= 250)
    ratio = np.abs(stages.frf_visco(on).H_tot[band]).max() / np.abs(stages.frf_visco(TIRE).H_tot[band]).max()
    assert ratio > 3.0


def test_fe_stages_without_the_cavity_refuse_it():
    on = cavity.with_cavity(TIRE)
    for stage, call in (
        ("modal_reduction", lambda: stages.modal_reduction(on)),
        ("loaded_modes", lambda: stages.loaded_modes(on)),
        ("one_sided_run", lambda: stages.one_sided_run(on, 8.0, 0.01, 0.02, "triangle", 1.25, (-0.1, 0.1))),
    ):
        with pytest.raises(ValueError, match=f"{stage}: the FE numerics of this stage do not include the air cavity"):
            call()


def test_split_against_load_and_bad_conditions():
    table = cavity.split_against_load()
    assert list(table["load (N)"]) == sorted(table["load (N)"]) and (table["split (Hz)"] > 0).all()
    assert (table["fore-aft (Hz)"] < table["vertical (Hz)"]).all()
    assert 0.8 < cavity.load_exponent(table) < 1.2  # a linear tire (the documented deviation)
    with pytest.raises(KeyError, match="cavity"):
        from roadnoise_utils.experiments.conditions import resolve

        resolve({"other": {}}, "cavity", tire=None)


def test_the_rolling_doublet_on_both_tire_models():
    """Each model's loaded doublet spreads with the speed as the closed form says (within 1 %), from its own split at
    rest; the rolling FRFs are the ring tire's (the cross-section coupling keeps its even modes only)."""
    for tire in (TIRE, f"{TIRE}_cross_section"):
        conditions = cavity.cavity_conditions(tire)
        table = cavity.rolling_split(conditions)
        assert np.all(np.diff(table["separation (Hz)"]) > 0)
        assert np.allclose(table["separation (Hz)"], table["closed form (Hz)"], rtol=0.01)
    with pytest.raises(NotApplicable, match="not applicable: rolling_cavity"):
        cavity.rolling_frfs(conditions)


def _frfs(freqs, plain_h, coupled_h, plain_g, coupled_g):
    def result(h, g):
        return FRFResult(freqs=freqs, H=h[None, :], H_tot=h, G_H=g, H_points=None, method="made up")

    return cavity.CavityFRFs(result(plain_h, plain_g), result(coupled_h, coupled_g), 230.0, (235.0, 250.0))


def test_the_resonance_and_the_stiffening_at_rest_are_read_from_both_sweeps():
    freqs = np.array([0.0, 100.0, 200.0, 250.0, 300.0])
    plain = np.array([200.0, 300.0, 100.0, 250.0, 400.0]) + 0j
    coupled = np.array([206.0, 290.0, 150.0, 2000.0, 500.0]) + 0j
    frfs = _frfs(freqs, plain, coupled, -plain, -coupled)
    assert frfs.resonance() == (250.0, 8.0)
    assert frfs.resonance(above=260.0) == (300.0, 1.25)  # only what lies above
    assert frfs.stiffening_at_rest() == pytest.approx(0.03)  # G_H(0): -206 over -200
    with pytest.raises(ValueError, match="above = 400 Hz: valid values are below the FRFs' last, 300 Hz"):
        frfs.resonance(above=400.0)
    late = _frfs(freqs[1:], plain[1:], coupled[1:], -plain[1:], -coupled[1:])
    with pytest.raises(ValueError, match="start at 100 Hz: the stiffening at rest needs 0 Hz"):
        late.stiffening_at_rest()
