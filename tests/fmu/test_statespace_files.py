"""The state-space .mat files: read back identical, and their responses are the fits' own (Eq. 1-4, 7)."""

from __future__ import annotations

import control
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fmu.statespace_files import read_statespace_mat, write_statespace_mat


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    tire = "165_65R14"
    static, fits, hub = ru.stages.solve_static(tire), ru.stages.fit_tasselli(tire), ru.stages.fit_hub(tire)
    path = write_statespace_mat(tmp_path_factory.mktemp("mat") / "tire.mat", fits, hub, static)
    return path, static, fits, hub


def test_the_matrices_read_back_as_assembled(written):
    path, static, fits, hub = written
    data = read_statespace_mat(path)
    fixed, moving = ru.assemble_fixed_hub(fits), ru.rm.assemble_moving_hub(fits, hub)
    for m in "ABCD":
        np.testing.assert_array_equal(data[f"{m}_F"], np.asarray(getattr(fixed, m)))
        np.testing.assert_array_equal(data[f"{m}_M"], np.asarray(getattr(moving, m)))
    np.testing.assert_array_equal(data["tassello_x"], static.tasselli.centre_x)


def test_the_loaded_moving_hub_model_has_the_fits_responses(written):
    """Second method: the pole-residue fits evaluated directly against C (sI - A)^-1 B + D of the loaded file."""
    path, _, fits, hub = written
    data = read_statespace_mat(path)
    system = control.ss(data["A_M"], data["B_M"], data["C_M"], data["D_M"])
    freqs = np.array([5.0, 40.0, 110.0, 230.0])
    response = np.asarray(system(2j * np.pi * freqs, squeeze=False))[0]  # (inputs, freqs)
    expected = np.vstack([fits.responses(freqs), hub[0](freqs)[None, :]])
    np.testing.assert_allclose(response, expected, rtol=1e-8, atol=1e-8 * np.abs(expected).max())


def test_bad_paths_and_files_are_refused(written, tmp_path):
    _, static, fits, hub = written
    with pytest.raises(ValueError, match="must end in .mat"):
        write_statespace_mat(tmp_path / "tire.txt", fits, hub, static)
    with pytest.raises(ValueError, match="does not exist"):
        write_statespace_mat(tmp_path / "no" / "tire.mat", fits, hub, static)
    with pytest.raises(TypeError, match="static"):
        write_statespace_mat(tmp_path / "tire.mat", fits, hub, None)
    import scipy.io

    scipy.io.savemat(tmp_path / "other.mat", {"A": np.eye(2)})
    with pytest.raises(ValueError, match="not a roadnoise state-space file"):
        read_statespace_mat(tmp_path / "other.mat")
