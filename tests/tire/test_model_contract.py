"""The tire-model interface's contract, on every registered model: what the RM pipeline relies on.

Each model is tried on a small tire (the ring on a coarse mesh; the cross-section on its coarse
grid, ``coarse_section``, whose stages the cavity's tests share; the tire from files written from
the coarse ring): its footprint partitions the contact nodes with weights summing to 1, the
load balances, the tasselli's FRFs add up to H_tot (paper Eq. i), H_tot(0) = -G_H(0) = K_v, its
files round-trip exactly, and a capability it lacks says so by name.
"""

from __future__ import annotations

from types import ModuleType

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro.cache import module_closure
from roadnoise_utils.tire.model import CAPABILITIES, REGISTRY, NotApplicable

COARSE_RING = {"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1}
#: H_tot(0) and -G_H(0) against K_v (-): the ring's FRFs hold the footprint against sliding while its
#: statics let it slide (5.5e-5 on the 165/65 R14), the cross-section's arc spreading (5e-6).
STATIC_TOLERANCE = 1e-3
#: The hub force against the load (-): the cross-section's rim reaction sees its contact forces spread
#: over an arc of its grid (the sinc of half a grid step: 4.7e-6 on the 165/65 R14's 3 mm grid, 1.8e-5 on
#: the coarse 6 mm one); the ring's is 1e-12.
HUB_TOLERANCE = 5e-5
#: sum_i H_i against H_tot (-): both computed from one solve on the FE models (round-off, 1e-10).
SUPERPOSITION_TOLERANCE = 1e-9


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The coarse ring written as a tire from files (flat road and drum, binary UFF 58)."""
    ring = ru.tire_model(ru.load_tire("165_65R14").replace(**COARSE_RING))
    folder = tmp_path_factory.mktemp("frf_file")
    cases = [ring.case("flat"), ring.case("drum", drum_radius=1.25)]
    return ring, ru.export_frf_files(ring, folder, cases, "coarse_ring")


@pytest.fixture(scope="module", params=sorted(REGISTRY))
def model(request, exported, coarse_section, small_loaded):
    kind = request.param
    if kind == "ring":
        return exported[0]
    if kind == "cross-section":
        return ru.tire_model(coarse_section)
    if kind == "frf-file":
        return ru.tire_model(exported[1])
    if kind == "loaded-fe":
        return small_loaded
    pytest.fail(f"no small test tire for the registered model {kind!r}: add one here")


def test_every_registered_model_is_tried():
    assert {"ring", "cross-section", "frf-file", "loaded-fe"} <= set(REGISTRY)


def test_the_stages_built_on_its_results_fingerprint_all_of_its_code(model):
    """The fits, runs and sweeps made from a model's results fingerprint its own module and every
    package module it imports (its footprint's tasselli among them), so an edit of any of them
    recomputes those stages: not only the numerics its ``frf_runs`` names."""
    names = {item.__name__ if isinstance(item, ModuleType) else item.__module__ for item in model.code_runs()}
    closure = module_closure(names)
    assert type(model).__module__ in closure and "roadnoise_utils.tire.tasselli" in closure
    assert set(module_closure({type(model).__module__})) <= set(closure)


def test_the_footprint_partitions_its_contact_nodes_and_balances_the_load(model):
    footprint = model.load(model.case("flat"))
    t = footprint.tasselli
    assert isinstance(footprint, ru.Footprint) and footprint.load == model.default_load
    assert t.node_tassello.min() == 0 and np.all(np.bincount(t.node_tassello) > 0)  # each node in one tassello
    np.testing.assert_allclose(np.bincount(t.node_tassello, weights=t.node_weight), 1.0, rtol=0, atol=1e-12)
    assert np.all(t.node_weight >= 0) and footprint.node_pressure.shape == t.node_x.shape
    assert np.all(footprint.node_pressure >= 0) and footprint.node_pressure.max() > 0
    assert abs(footprint.hub_force / footprint.load - 1) < HUB_TOLERANCE  # the hub carries the load
    assert footprint.vertical_stiffness > 0 and 0.05 < footprint.footprint_length < 0.3


def test_the_fixed_hub_frfs_add_up_and_start_at_the_static_stiffness(model):
    case = model.case("flat")
    footprint, frfs = model.load(case), model.fixed_hub_frfs(case)
    n = frfs.freqs.size
    assert frfs.H.shape == (footprint.tasselli.n, n) and frfs.H_tot.shape == (n,)
    assert np.max(np.abs(frfs.H_sum - frfs.H_tot) / np.abs(frfs.H_tot)) < SUPERPOSITION_TOLERANCE
    assert frfs.freqs[0] == 0.0
    assert abs(frfs.H_tot[0].real / footprint.vertical_stiffness - 1) < STATIC_TOLERANCE
    if model.has("hub_transfer"):
        assert abs(-frfs.G_H[0].real / footprint.vertical_stiffness - 1) < STATIC_TOLERANCE
    some = model.fixed_hub_frfs(case, frfs.freqs[[0, 80, 250]])
    np.testing.assert_allclose(some.H_tot, frfs.H_tot[[0, 80, 250]], rtol=1e-13)


def test_the_files_round_trip_exactly(model, tmp_path):
    """Written as a tire from files (binary UFF 58, 17-digit CSV) and read back: the same footprint and FRFs."""
    case = model.case("flat")
    back = ru.tire_model(ru.export_frf_files(model, tmp_path, [case], "round_trip"))
    original, again = model.load(case), back.load(back.case("flat"))
    for name in ("node_x", "node_y", "node_dx_minus", "node_dx_plus", "widths", "node_weight", "centre_x", "area"):
        np.testing.assert_array_equal(getattr(again.tasselli, name), getattr(original.tasselli, name))
    np.testing.assert_array_equal(again.node_pressure, original.node_pressure)
    assert again.vertical_stiffness == original.vertical_stiffness and back.rim_side_mass() == model.rim_side_mass()
    frfs, read = model.fixed_hub_frfs(case), back.fixed_hub_frfs(back.case("flat"))
    for name in ("freqs", "H", "H_tot", "G_H"):
        np.testing.assert_array_equal(getattr(read, name), getattr(frfs, name))


def test_a_capability_works_or_says_not_applicable_by_name(model):
    for capability in CAPABILITIES:
        if not model.has(capability):
            with pytest.raises(NotApplicable, match=f"not applicable: {capability}"):
                model.require(capability)
    with pytest.raises(ValueError, match="valid values are"):
        model.has("telepathy")


#: Each optional capability -> a call of the method that needs it.
CAPABILITY_CALLS = {
    "fe_mesh": lambda m: m.equivalent_dof(),
    "cavity_shape": lambda m: m.air_cavity(),
    "one_sided_cleat": lambda m: m.one_sided_setup(ru.experiments.one_sided_conditions()),
    "released_hub": lambda m: m.released_hub(m.case("flat"), np.array([10.0]), 30.0, 2e4, 1e3),
    "rolling_cavity": lambda m: m.rolling_cavity_frfs(m.case("flat"), np.array([10.0]), 1.0),
}


@pytest.mark.parametrize("capability", sorted(CAPABILITY_CALLS))
def test_a_method_of_a_capability_the_model_lacks_says_so_by_name(model, capability):
    """The method itself (not only :meth:`require`) refuses with the capability's name; a model that has
    it answers the cheap ones (its mesh size, its air cavity)."""
    call = CAPABILITY_CALLS[capability]
    if not model.has(capability):
        with pytest.raises(NotApplicable, match=f"not applicable: {capability}"):
            call(model)
    elif capability == "fe_mesh":
        assert call(model) > 1000
    elif capability == "cavity_shape":
        assert call(model).area > 0 and call(model).mean_radius > 0


def test_the_replace_of_a_sweep_gives_the_same_model_kind(model):
    variant = model.replace(name="variant")
    assert type(variant) is type(model) and variant.name == "variant" and variant.kind == model.kind


def test_a_tire_file_of_an_unknown_model_is_refused_naming_the_registered_ones(tmp_path):
    path = tmp_path / "x.toml"
    path.write_text('[tire]\nmodel = "shell"\nname = "x"\n')
    with pytest.raises(
        ValueError,
        match=r"\[tire\] model = 'shell': valid values are \['cross-section', 'frf-file', 'loaded-fe', 'ring'\]",
    ):
        ru.load_tire(path)
    path.write_text('[tire]\nname = "x"\n')
    with pytest.raises(ValueError, match=r"\[tire\] model is missing"):
        ru.tire_model(path)
