"""The loaded FE tire's chapter: its experiments' properties, and the chapter run alone on the test mesh.

The chapter (notebooks/16-loaded-fe-tire.ipynb) computes the production mesh's stages, 10 CPU-minutes
that do not fit the suite; nbval does not collect it (the root conftest.py). Here papermill runs it
on the test mesh written as tire files, as a user runs it on their own: every cell must execute.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import loaded_tire
from roadnoise_utils.repro.cache import cache_key
from roadnoise_utils.repro.paths import REPO_ROOT
from roadnoise_utils.repro.reproduce import INLINE_BACKEND
from roadnoise_utils.tire.loaded import stages
from roadnoise_utils.tire.loaded.statics import StaticState
from tests.conftest import SMALL_LOADED

CHAPTER = REPO_ROOT / "notebooks" / "16-loaded-fe-tire.ipynb"
#: The kernel's environment: matplotlib's inline backend, as the reproduction's kernels (a headless run's
#: ``MPLBACKEND=Agg`` would draw no figure into the notebook).
INLINE_FIGURES = {**os.environ, "MPLBACKEND": INLINE_BACKEND}
#: The chapter's loads on the test mesh (N): two, the file's last, one loading shared with the curve's test.
CHAPTER_LOADS = [600.0, SMALL_LOADED["operating.vertical_load"]]


@pytest.fixture(scope="module")
def test_mesh_files(tmp_path_factory, small_loaded):
    """The test mesh as a user's tire files: the construction at the test load and a loaded FE file
    sweeping it (the same spec as ``small_loaded``, so the two share their cached stages)."""
    folder = tmp_path_factory.mktemp("small_loaded")
    text = (REPO_ROOT / "data" / "tires" / "165_65R14_cross_section.toml").read_text()
    load = SMALL_LOADED["operating.vertical_load"]
    assert "vertical_load = 4512.0" in text
    (folder / "construction.toml").write_text(text.replace("vertical_load = 4512.0", f"vertical_load = {load}"))
    mesh = "\n".join(
        f"{key.removeprefix('solid_mesh.')} = {value}"
        for key, value in SMALL_LOADED.items()
        if key.startswith("solid_mesh.")
    )
    path = folder / "small_loaded.toml"
    path.write_text(
        f'[tire]\nname = "{small_loaded.spec.name}"\nmodel = "loaded-fe"\n\n'
        f'[construction]\nfile = "construction.toml"\n\n[solid_mesh]\n{mesh}\n'
    )
    same = [cache_key("loaded_state", {"tire": spec}, "") for spec in (ru.load_tire(path), small_loaded.spec)]
    assert same[0] == same[1]  # only the files' names differ, which no stage reads
    return path


def _history_state(history: list) -> StaticState:
    return StaticState(u=np.zeros(3), pressure=2e5, history=history)


def test_newton_order_is_two_for_quadratic_and_one_for_linear_residuals():
    quadratic = [1e-1, 1e-2, 1e-4, 1e-8, 1e-16]  # r_{k+1} = r_k^2, the last at round-off
    linear = [1e-1, 1e-2, 1e-3, 1e-4]
    steps = loaded_tire.newton_steps(_history_state([[quadratic], [[0.5, 1e-3], linear]]))
    assert list(steps.index) == ["inflation", "road step 1"]
    assert steps.loc["inflation", "order of the last iterations"] == pytest.approx(2.0)
    assert steps.loc["road step 1", "order of the last iterations"] == pytest.approx(1.0)
    assert steps.loc["road step 1", "contact sets"] == 2
    assert steps.loc["road step 1", "residuals evaluated"] == 6
    assert steps.loc["inflation", "last residual"] == 1e-16


def test_newton_order_is_nan_with_fewer_than_three_residuals_above_round_off():
    steps = loaded_tire.newton_steps(_history_state([[[1e-3, 1e-7, 1e-14]]]))
    assert np.isnan(steps.loc["inflation", "order of the last iterations"])


def test_newton_steps_of_the_test_mesh_converge_superlinearly(small_loaded):
    steps = loaded_tire.newton_steps(stages.loaded_state(small_loaded.spec, small_loaded.case()))
    orders = steps["order of the last iterations"].dropna()
    assert orders.size >= 2 and (orders > 1.6).all()
    assert (steps["last residual"] < 1e-8).all()


def test_mesh_summary_counts_agree(small_loaded):
    summary = loaded_tire.mesh_summary(small_loaded)
    mesh = SMALL_LOADED
    assert summary["degrees of freedom"] == 3 * summary["nodes"]
    assert summary["27-node solid elements"] == summary["arcs around the wheel"] * summary["section elements (swept)"]
    assert summary["tread nodes across the crown"] == 2 * mesh["solid_mesh.crown_elements"] + 1
    # the footprint's arcs at most the file's (equal arcs over its sector); none longer than the coarse arc
    assert 0.5 * mesh["solid_mesh.footprint_arc"] < summary["shortest arc at the tread (mm)"] / 1e3
    assert summary["shortest arc at the tread (mm)"] <= 1e3 * mesh["solid_mesh.footprint_arc"] * 1.0001
    assert summary["longest arc at the tread (mm)"] <= 1e3 * mesh["solid_mesh.coarse_arc"] * 1.0001


def test_loaded_model_refuses_another_model():
    with pytest.raises(ValueError, match="'ring' tire; this needs a 'loaded-fe' tire file"):
        loaded_tire.loaded_model("165_65R14")


def test_load_curve_at_the_file_s_load_is_the_loaded_state(small_loaded):
    """One loading through several loads and the file's own loading reach the same equilibrium."""
    load = small_loaded.default_load
    curves = loaded_tire.load_curves({"loaded FE": small_loaded}, CHAPTER_LOADS[::-1])  # sorted by the function
    assert list(curves["load (kN)"]) == pytest.approx([x / 1e3 for x in CHAPTER_LOADS])
    assert CHAPTER_LOADS[-1] == load
    at_load = curves.iloc[-1]
    direct = small_loaded.load(small_loaded.case())
    assert at_load["deflection (mm)"] == pytest.approx(1e3 * direct.deflection, rel=1e-6)
    assert at_load["K_v (N/mm)"] == pytest.approx(direct.vertical_stiffness / 1e3, rel=1e-6)
    assert np.all(np.diff(curves["deflection (mm)"]) > 0)  # a heavier load deflects the tire more


def test_the_chapter_runs_alone_on_the_test_mesh(test_mesh_files, tmp_path):
    out = tmp_path / "chapter.ipynb"
    parameters = {"beside": {"ring": "165_65R14"}, "loads": CHAPTER_LOADS}
    result = subprocess.run(
        [sys.executable, "-m", "papermill", str(CHAPTER), str(out), "--cwd", str(CHAPTER.parent),
         "-p", "loaded_name", str(test_mesh_files), "-y", json.dumps(parameters)],
        capture_output=True, text=True, timeout=600, env=INLINE_FIGURES,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr[-3000:]
    cells = json.loads(out.read_text())["cells"]
    text = "".join("".join(o.get("text", "")) for c in cells if c["cell_type"] == "code" for o in c.get("outputs", []))
    images = sum("image/png" in o.get("data", {}) for c in cells if c["cell_type"] == "code" for o in c["outputs"])
    # the side view, the footprints, the curves against load, the cavity split and FRFs, the rows, the
    # one-sided cleat test and its run with the air, Fig. 5
    assert images == 9
    assert "with its air" in text and "the air's first order" in text  # the air in the cleat runs and the modes
    assert "loaded FE" in text and "a minimum of the potential: True" in text
    assert "loaded FE, contact frozen, 30 km/h" in text  # the one-sided cleat test's table
    assert "paper: storage moduli, identified damping" in text  # the modal reduction's table


def test_modal_variants_are_the_model_s_reductions_and_their_errors_against_the_direct_frfs(small_loaded):
    reductions, table = loaded_tire.modal_variants(small_loaded)
    assert list(reductions) == list(loaded_tire.MODAL_VARIANTS) == list(table.index[1:])
    direct = small_loaded.fixed_hub_frfs(small_loaded.case())
    low = direct.freqs <= 100.0
    for label, reduction in reductions.items():
        miss = np.linalg.norm(reduction.frf.H_tot[low] - direct.H_tot[low]) / np.linalg.norm(direct.H_tot[low])
        assert table.loc[label, "error 0-100 Hz"] == pytest.approx(miss, rel=1e-12)
    assert table.loc["complex moduli, the model's own loss", "error 0-100 Hz"] < 0.05
    peak = table.attrs["peak (Hz)"]
    assert table.loc["direct", "phase at the peak (deg)"] == pytest.approx(
        np.degrees(np.angle(direct.H_tot[direct.freqs == peak][0]))
    )


def test_chapter_parameters_are_checked():
    with pytest.raises(ValueError, match="strictly increasing"):
        ru.experiments.check_parameters(loads=[3000.0, 1500.0])
    with pytest.raises(ValueError, match=r"loads\[0\] = 100.0: valid range"):
        ru.experiments.check_parameters(loads=[100.0])
    with pytest.raises(TypeError, match="a list of one or more loads"):
        ru.experiments.check_parameters(loads="4500")
    with pytest.raises(FileNotFoundError, match=r"beside\['ring'\] = 'no_such_tire'"):
        ru.experiments.check_parameters(beside={"ring": "no_such_tire"})
    with pytest.raises(TypeError, match="a dict of labels"):
        ru.experiments.check_parameters(beside=["165_65R14"])
