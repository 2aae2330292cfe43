"""Cross-section tire files: the model key, the construction, and every kind of bad input named."""

from __future__ import annotations

import copy
import tomllib

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.guards import ResourceLimitError
from roadnoise_utils.repro.paths import data_dir
from roadnoise_utils.tire.cross_section import laminate
from roadnoise_utils.tire.cross_section import spec as cross_section
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.spec import CrossSectionSpec

NAME = "165_65R14_cross_section"


def _raw(name=NAME):
    with open(data_dir() / "tires" / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)


@pytest.mark.parametrize("name", [NAME, "195_65R15_cross_section"])
def test_model_key_selects_the_tire_model(name):
    spec = ru.load_tire(name)
    assert isinstance(spec, CrossSectionSpec) and spec.model == "cross-section"
    assert ru.load_tire(name.removesuffix("_cross_section")).model == "ring"
    assert cross_section.to_dict(cross_section.from_dict(cross_section.to_dict(spec))) == cross_section.to_dict(spec)


def test_cord_ply_constants_follow_the_rule_of_mixtures_and_halpin_tsai():
    c = laminate.cord_ply_constants(150e9, 8e6, 0.2)
    assert c["E_L"] == pytest.approx(0.2 * 150e9 + 0.8 * 8e6)
    # Halpin-Tsai with xi = 2 lies between the series (Reuss) and parallel (Voigt) bounds
    reuss = 1 / (0.2 / 150e9 + 0.8 / 8e6)
    assert reuss < c["E_T"] < c["E_L"]
    # a balanced +/-beta ply has no normal-shear coupling, and beta = 0 puts E_L along theta
    ply = laminate.cord_layer(c, 22.0)
    assert abs(ply[1, 3]) < 1e-9 * ply[1, 1]
    along = laminate.cord_layer(c, 0.0)
    compliance = np.linalg.inv(along)  # the compliance's theta-theta entry is 1 / E_theta
    assert 1 / compliance[1, 1] == pytest.approx(c["E_L"], rel=1e-9)


def _edit(path, value):
    data = copy.deepcopy(_raw())
    node = data
    *parents, leaf = path
    for part in parents:
        node = node[part]
    if value is None:
        del node[leaf]
    else:
        node[leaf] = value
    return data


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        (("tire", "model"), "shell", r"\[tire\] model = 'shell' where a 'cross-section' tire file is expected"),
        (("layers", "belt_1", "kind"), "steel", r"\[layers.belt_1\] kind = 'steel': valid kinds"),
        (("layers", "cap", "compound"), "nylon", r"\[layers.cap\] compound = 'nylon' names no \[compounds"),
        (("layers", "tread", "void_ratio"), 0.95, r"\[layers.tread\] void_ratio = 0.95 - is outside its valid range"),
        (("layers", "carcass", "cord_angle"), None, r"\[layers.carcass\] is missing 'cord_angle'"),
        (("construction", "crown"), ["liner", "kevlar"], r"\[construction\] crown = .* must be a non-empty list"),
        (("mesh", "crown_elements"), 15, r"crown_elements = 15 must be even"),
        (("geometry", "bead_radius"), 0.3, r"need rim radius .* < bead_radius 0.3"),
        (("mesh", "contact_spacing"), 0.05, r"\[mesh\] contact_spacing = 0.05 m is outside its valid range"),
    ],
)
def test_bad_construction_is_named(path, value, message):
    with pytest.raises(ValueError, match=message):
        cross_section.from_dict(_edit(path, value), "x.toml")


def test_each_model_refuses_the_other_models_file():
    with pytest.raises(TypeError, match="model = 'cross-section'"):
        ru.build_fet(ru.load_tire(NAME))
    with pytest.raises(ValueError, match="is a 'ring' tire file"):
        section_stages.section_tire("165_65R14")


def test_a_contact_grid_too_fine_for_memory_is_refused_before_the_solve(monkeypatch):
    monkeypatch.setenv("ROADNOISE_MAX_BYTES", "1e8")
    tire = section_stages.section_tire(ru.load_tire(NAME).replace(**{"mesh.contact_spacing": 0.001}))
    from roadnoise_utils.tire.cross_section.static import solve_section_static

    with pytest.raises(ResourceLimitError, match=r"\[mesh\] contact_spacing: the contact compliance of \d+ points"):
        solve_section_static(tire)


def test_footprint_frf_refuses_bad_frequencies_and_another_tires_state():
    from roadnoise_utils.tire.cross_section.footprint import footprint_frf

    tire = section_stages.section_tire(NAME)
    flat = ru.stages.solve_static(NAME)
    for bad in ([], [0.0, np.nan], [-1.0, 10.0], [10.0, 5.0]):
        with pytest.raises(ValueError, match="freqs must"):
            footprint_frf(tire, flat, np.array(bad))
    other = section_stages.section_tire(ru.load_tire(NAME).replace(**{"layers.tread.youngs_modulus": 6e6}))
    with pytest.raises(ValueError, match="another tire"):
        footprint_frf(other, flat, np.array([0.0, 10.0]))
