"""The tire models side by side (notebook 13): capabilities, any model written as files, the drum rows.

And the RM chapters on any tire file: the coarse ring written as a tire from files stands in for a
user's FE tire; notebooks 03 and 04 must run to their end on it, printing ``not applicable:
<capability>`` where the files lack one (the modal reduction, the FE check of the cleat).
"""

from __future__ import annotations

import jupytext
import nbformat
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import tire_models
from roadnoise_utils.repro.paths import REPO_ROOT, file_digest
from roadnoise_utils.repro.reproduce import execute_notebook
from roadnoise_utils.tire.model import CAPABILITIES

COARSE_RING = {"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1}


@pytest.fixture(scope="module")
def coarse_ring():
    return ru.load_tire("165_65R14").replace(**COARSE_RING)


@pytest.fixture(scope="module")
def drum_radius():
    return ru.experiments.cleat_conditions().drum_radius


@pytest.fixture(scope="module")
def ring_files(coarse_ring, drum_radius):
    return tire_models.tire_as_files(coarse_ring, ("flat", "drum"), drum_radius)


def test_the_capability_table_has_a_row_per_capability_and_a_column_per_tire(coarse_ring, ring_files):
    table = tire_models.capability_table({"ring": coarse_ring, "files": ring_files})
    assert list(table.index) == list(CAPABILITIES) and list(table.columns) == ["ring", "files"]
    ring, files = ru.tire_model(coarse_ring), ru.tire_model(ring_files)
    for capability in CAPABILITIES:
        assert (table.loc[capability, "ring"] == "yes") == ring.has(capability)
        assert (table.loc[capability, "files"] == "yes") == files.has(capability)
    assert table.loc["hub_transfer", "files"] == "yes" and table.loc["modal_reduction", "files"] == "not applicable"


def test_a_tire_written_as_files_gives_back_its_footprint_and_frfs(coarse_ring, ring_files, drum_radius):
    """The files hold the source's load cases exactly (binary UFF 58): K_v, tasselli and H_i."""
    for road, radius in (("flat", None), ("drum", drum_radius)):
        source = ru.stages.solve_static(coarse_ring, road, drum_radius=radius)
        read = ru.stages.solve_static(ring_files, road, drum_radius=radius)
        assert read.tasselli.n == source.tasselli.n
        assert read.vertical_stiffness == pytest.approx(source.vertical_stiffness, rel=1e-12)
        a = ru.stages.frf_visco(coarse_ring, road, drum_radius=radius)
        b = ru.stages.frf_visco(ring_files, road, drum_radius=radius)
        assert np.array_equal(a.freqs, b.freqs) and np.abs(b.H - a.H).max() <= 1e-12 * np.abs(a.H).max()


def test_asking_again_keeps_the_files_and_a_variant_gets_its_own_folder(coarse_ring, ring_files, drum_radius):
    folder = ring_files.parent
    before = {p.name: file_digest(p) for p in folder.iterdir()}
    again = tire_models.tire_as_files(coarse_ring, ("flat", "drum"), drum_radius)
    assert again == ring_files and {p.name: file_digest(p) for p in folder.iterdir()} == before
    stiffer = coarse_ring.replace(**{"belt.bending_stiffness": 2 * coarse_ring.belt.bending_stiffness})
    assert tire_models.tire_as_files(stiffer).parent != folder


@pytest.mark.parametrize(
    "roads, drum_radius, message",
    [(("drum",), None, "drum_radius"), ((), None, "roads"), ("drum", 1.25, "roads"), (("flat", "flat"), None, "roads"),
     (("flat", "wet"), None, "roads"), (("drum",), 0.1, "drum_radius")],
)  # fmt: skip
def test_bad_load_cases_are_refused_naming_the_parameter(coarse_ring, roads, drum_radius, message):
    with pytest.raises(ValueError, match=message):
        tire_models.tire_as_files(coarse_ring, roads, drum_radius)


def test_applicable_says_which_capability_a_model_lacks(coarse_ring, ring_files, capsys):
    assert tire_models.applicable(coarse_ring, "modal_reduction")
    assert capsys.readouterr().out == ""
    assert not tire_models.applicable(ring_files, "modal_reduction")
    assert "not applicable: modal_reduction" in capsys.readouterr().out
    with pytest.raises(ValueError, match="capability"):
        tire_models.applicable(coarse_ring, "flying")


def test_the_drum_rows_sum_to_the_drum_stiffness(coarse_ring, drum_radius):
    rows, k_v = tire_models.drum_rows(coarse_ring, drum_radius)
    h_tot = ru.stages.frf_visco(coarse_ring, "drum", drum_radius=drum_radius).H_tot[0].real
    assert rows["H(0) of the row (N/mm)"].sum() * 1e3 == pytest.approx(k_v, rel=1e-12)
    assert k_v == pytest.approx(h_tot, rel=1e-9)  # superposition at 0 Hz, Eq. (i)


def _run_chapter(stem: str, tire_file, folder) -> str:
    """Execute ``notebooks/<stem>.py`` with ``tire_name`` set to ``tire_file``; return its printed text."""
    notebook = jupytext.read(REPO_ROOT / "notebooks" / f"{stem}.py")
    (parameters,) = [c for c in notebook.cells if "parameters" in c.metadata.get("tags", [])]
    parameters.source += f"\ntire_name = {str(tire_file)!r}"
    path = REPO_ROOT / "notebooks" / f"_test_{stem}_{folder.name}.ipynb"  # the notebook's own folder: its paths
    nbformat.write(notebook, path)
    try:
        executed = execute_notebook(path)
    finally:
        path.unlink()
    return "\n".join(
        "".join(output.get("text", ""))
        for cell in executed.cells
        for output in cell.get("outputs", [])
        if output.get("output_type") == "stream"
    )


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize(
    "stem, lacking",
    [("03-tassello-fitting", ["modal_reduction"]), ("04-cleat-test", ["direct_response", "the ring's parameters"])],
)
def test_an_rm_chapter_runs_on_a_tire_from_files(stem, lacking, ring_files, tmp_path):
    """The chapter runs to its end on the files and names each capability it skips."""
    printed = _run_chapter(stem, ring_files, tmp_path)
    for capability in lacking:
        assert f"not applicable: {capability}" in printed
