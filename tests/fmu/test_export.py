"""The FMU file: FMI 2.0 valid by fmpy's validator, its parts in place, source-only without a compiler."""

from __future__ import annotations

import subprocess
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
import pytest
from fmpy.validation import validate_fmu

from roadnoise_utils.fmu import export
from roadnoise_utils.fmu.export import MODEL_IDENTIFIER, compile_binary, platform_folder, write_fmu
from roadnoise_utils.guards import RoadnoiseWarning


def test_fmpy_finds_nothing_to_fix(tire_2d, tire_3d):
    assert validate_fmu(str(tire_2d.path)) == []
    assert validate_fmu(str(tire_3d.path)) == []


def test_the_archive_holds_description_resources_sources_and_binary(tire_3d):
    names = set(zipfile.ZipFile(tire_3d.path).namelist())
    suffix = {"linux": ".so", "darwin": ".dylib", "win": ".dll"}[platform_folder()[:-2]]
    assert {
        "modelDescription.xml",
        "resources/tire.bin",
        f"sources/{MODEL_IDENTIFIER}.c",
        f"sources/{MODEL_IDENTIFIER}.h",
        "sources/fmi2_unsupported.c",
        "sources/fmi2Functions.h",
        "sources/fmi2FunctionTypes.h",
        "sources/fmi2TypesPlatform.h",
        f"binaries/{platform_folder()}/{MODEL_IDENTIFIER}{suffix}",
    } <= names
    root = ET.fromstring(zipfile.ZipFile(tire_3d.path).read("modelDescription.xml"))
    listed = {file.get("name") for file in root.iter("File")}  # what a tool compiles: every C source shipped
    assert listed == {
        name.removeprefix("sources/") for name in names if name.startswith("sources/") and name.endswith(".c")
    }


def test_the_description_names_each_input_and_output_with_its_unit(tire_3d):
    root = ET.fromstring(zipfile.ZipFile(tire_3d.path).read("modelDescription.xml"))
    variables = {v.get("name"): v for v in root.iter("ScalarVariable")}
    tables = tire_3d.tables
    for name in ("F_M", "F_F", "F_H"):
        assert (variables[name].get("causality"), variables[name].find("Real").get("unit")) == ("output", "N")
    roads = [name for name in variables if name.startswith("road_height[")]
    assert len(roads) == tables.n_strips > 1
    assert all(variables[name].get("causality") == "input" for name in roads + ["hub_displacement"])
    constants = ["speed", "time_step", "leading_edge_x"] + [f"road_y[{k + 1}]" for k in range(tables.n_strips)]
    for name in constants:  # what the FMU was built for: read by a master, never written
        assert (variables[name].get("causality"), variables[name].get("variability")) == ("output", "constant")
    assert float(variables["speed"].find("Real").get("start")) == tables.speed
    assert float(variables["time_step"].find("Real").get("start")) == tables.dt
    assert float(root.find("DefaultExperiment").get("stepSize")) == tables.dt
    y = [float(variables[f"road_y[{k + 1}]"].find("Real").get("start")) for k in range(tables.n_strips)]
    np.testing.assert_array_equal(y, tables.strip_y)


def test_without_a_compiler_the_fmu_is_source_only_with_a_warning(tire_2d, tmp_path, monkeypatch):
    monkeypatch.setattr(export, "compiler", lambda: None)
    with pytest.warns(RoadnoiseWarning, match="source-only.*no C compiler"):
        path = write_fmu(tire_2d.tables, tmp_path / "source_only.fmu")
    names = zipfile.ZipFile(path).namelist()
    assert not any(name.startswith("binaries/") for name in names)
    assert validate_fmu(str(path)) == []


def test_the_sources_inside_build_on_their_own(tire_2d, tmp_path):
    """What a tool on another platform does: compile sources/ as shipped, with its own headers only."""
    path = write_fmu(tire_2d.tables, tmp_path / "sources.fmu", binary=False)
    zipfile.ZipFile(path).extractall(tmp_path / "unzipped")
    sources = tmp_path / "unzipped" / "sources"
    assert compile_binary(sources, tmp_path / "built.so") is None
    symbols = subprocess.run(["nm", "-D", str(tmp_path / "built.so")], capture_output=True, text=True).stdout
    for function in (
        "fmi2Instantiate",
        "fmi2DoStep",
        "fmi2GetReal",
        "fmi2SetReal",
        "fmi2FreeInstance",
        "fmi2GetStatus",
    ):
        assert function in symbols


def test_a_compiler_error_leaves_a_source_only_fmu(tire_2d, tmp_path, monkeypatch):
    monkeypatch.setattr(export, "compile_binary", lambda sources, target: "cc failed: error: something")
    with pytest.warns(RoadnoiseWarning, match="cc failed"):
        path = write_fmu(tire_2d.tables, tmp_path / "broken.fmu")
    assert not any(name.startswith("binaries/") for name in zipfile.ZipFile(path).namelist())


@pytest.mark.parametrize(
    ("where", "message"), [("tire.zip", "must end in .fmu"), ("missing/tire.fmu", "does not exist")]
)
def test_a_path_that_cannot_be_written_is_refused_up_front(tire_2d, tmp_path, where, message):
    with pytest.raises(ValueError, match=message):
        write_fmu(tire_2d.tables, tmp_path / where)
    assert list(tmp_path.iterdir()) == []  # nothing written half-way


def test_wrong_arguments_are_refused(tire_2d, tmp_path):
    with pytest.raises(TypeError, match="tables"):
        write_fmu({"dt": 1e-4}, tmp_path / "x.fmu")
    with pytest.raises(ValueError, match="binary"):
        write_fmu(tire_2d.tables, tmp_path / "x.fmu", binary="no")
