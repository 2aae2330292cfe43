"""Designs of a sweep: names and values checked before any work, outputs as the stages compute them."""

from __future__ import annotations

import pickle

import numpy as np
import pandas as pd
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import design

PRESSURE = "operating.inflation_pressure"
TREAD = "tread.normal_stiffness_per_area"


def test_the_sweepable_parameters_are_the_tire_files_keys_with_their_ranges():
    ring = design.sweep_parameters("165_65R14")
    assert {PRESSURE, TREAD, "belt.bending_stiffness", "operating.vertical_load", "compounds.tread.order"} <= set(
        ring.index
    )
    assert ring.loc[PRESSURE, "value"] == 2.3e5 and ring.loc[PRESSURE, "unit"] == "Pa"
    assert (ring.loc[PRESSURE, "low"], ring.loc[PRESSURE, "high"]) == (0.5e5, 5.0e5)
    assert ring.loc["mesh.n_elements", "integer"] and "cavity.enabled" not in ring.index  # booleans are not swept
    section = design.sweep_parameters("165_65R14_cross_section")
    assert {PRESSURE, "operating.vertical_load", "layers.tread.youngs_modulus"} <= set(section.index)
    assert "layers.tread.compound" not in section.index  # names are not numbers


def test_a_grid_is_every_combination_the_last_name_fastest():
    rows = design.design_rows({PRESSURE: [2.0e5, 2.6e5], TREAD: [0.9e9, 1.2e9, 1.5e9]})
    assert len(rows) == 6 and rows[1] == {PRESSURE: 2.0e5, TREAD: 1.2e9} and rows[3] == {PRESSURE: 2.6e5, TREAD: 0.9e9}
    frame = pd.DataFrame({PRESSURE: [2.0e5, 2.4e5]})
    assert design.design_rows(frame) == [{PRESSURE: 2.0e5}, {PRESSURE: 2.4e5}]


def test_each_design_is_the_tire_file_with_its_overrides():
    designs = design.make_designs("165_65R14", {PRESSURE: [2.0e5], "mesh.n_elements": [240]})
    spec = designs[0].spec
    assert spec.operating.inflation_pressure == 2.0e5 and spec.mesh.n_elements == 240
    assert spec.geometry == ru.load_tire("165_65R14").geometry
    assert designs[0].describe() == f"design 0 ({PRESSURE} = 200000, mesh.n_elements = 240)"


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"tread.stiffness": [1e9]}, r"unknown parameter\(s\) \['tread.stiffness'\].*tread.normal_stiffness_per_area"),
        (
            {PRESSURE: [2.0e5, 9.0e5]},
            r"design 1: operating.inflation_pressure = 900000.0: valid range is \[50000, 500000\] Pa",
        ),
        ({PRESSURE: ["2 bar"]}, r"design 0: operating.inflation_pressure = '2 bar' must be a number"),
        ({PRESSURE: [float("nan")]}, r"valid range is \[50000, 500000\] Pa"),
        ({"mesh.n_elements": [300.5]}, r"design 0: mesh.n_elements = 300.5: valid range is integers in \[24, 2000\]"),
        ({PRESSURE: []}, r"parameters\['operating.inflation_pressure'\] is empty"),
        ({PRESSURE: 2.0e5}, r"give a list of values"),
        ({}, r"no design"),
        ({"geometry.belt_width": [0.2]}, r"design 0 \(geometry.belt_width = 0.2\): .*must not exceed section_width"),
    ],
)
def test_bad_parameters_are_refused_naming_the_design_parameter_and_range(parameters, message):
    with pytest.raises(ValueError, match=message):
        design.make_designs("165_65R14", parameters)


def test_bad_outputs_are_refused_with_the_valid_ones():
    with pytest.raises(ValueError, match=r"outputs = \['Kv'\]: valid outputs are \['K_v', 'footprint'"):
        design.check_outputs(["Kv"])
    with pytest.raises(ValueError, match="at least one"):
        design.check_outputs([])
    assert design.check_outputs(["f1", "K_v"]) == ("K_v", "f1")  # table order
    assert design.output_columns("cleat") == ["cleat_quasi_static_peak (N)", "cleat_dynamic_peak (N)"]


def test_sweep_conditions_are_resolved_once_and_keyed_by_what_the_outputs_use():
    conditions = design.sweep_conditions()
    assert conditions.cleat == ru.experiments.cleat_conditions() and conditions.texture == "rough"
    assert conditions.road.textures == ("rough",) and conditions.hub_band == design.HUB_BAND
    assert conditions.used_by(["K_v", "f1"]) == {}  # a cheap sweep's key ignores the cleat and the road
    assert set(conditions.used_by(["cleat", "hub_acceleration"])) == {"cleat", "road", "vehicle", "texture", "hub_band"}
    with pytest.raises(ValueError, match="hub_band"):
        design.sweep_conditions(hub_band=(220.0, 40.0))


def test_a_designs_outputs_are_the_stages_values_and_pickle(tire):
    spec = tire.replace(**{PRESSURE: 2.1e5})
    result = design.evaluate_design(spec, ["K_v", "footprint"], design.sweep_conditions(), cache=False)
    static = ru.stages.solve_static(spec)
    assert result.values == {
        "K_v (N/m)": static.vertical_stiffness,
        "footprint_length (m)": static.footprint_length,
        "footprint_width (m)": static.footprint_width,
    }
    assert result.computed and result.warnings == ()
    back = pickle.loads(pickle.dumps(result))
    assert back == result and all(isinstance(v, float) for v in back.values.values())
    assert np.isfinite(list(result.values.values())).all()


def test_a_grid_listing_a_value_twice_warns_which_designs_repeat():
    from roadnoise_utils.guards import RoadnoiseWarning

    with pytest.warns(RoadnoiseWarning, match=r"1 design\(s\) repeat another \(design 2 = design 0\)"):
        designs = ru.experiments.design.make_designs(
            "165_65R14", {"operating.inflation_pressure": [2.3e5, 2.4e5, 2.3e5]}
        )
    assert len(designs) == 3


def test_a_sweep_over_a_switched_off_sub_model_warns():
    from roadnoise_utils.guards import RoadnoiseWarning

    assert ru.load_tire("165_65R14").cavity.enabled is False
    with pytest.warns(
        RoadnoiseWarning, match=r"\['cavity.temperature'\] belong to a sub-model the tire file switches off"
    ):
        ru.experiments.design.make_designs("165_65R14", {"cavity.temperature": [10.0, 30.0]})


def test_the_swept_parameters_of_a_grid_and_a_misspelt_name_among_them():
    table = ru.experiments.design.sweep_parameters("165_65R14", ["operating.inflation_pressure"])
    assert (
        list(table.index) == ["operating.inflation_pressure"]
        and table.loc["operating.inflation_pressure", "unit"] == "Pa"
    )
    with pytest.raises(ValueError, match=r"unknown parameter\(s\) \['operating.inflation_presure'\]"):
        ru.experiments.design.sweep_parameters("165_65R14", {"operating.inflation_presure": [2.3e5]})
