"""Where the collection keeps its data, cache and figures: the settings that name them."""

from __future__ import annotations

import pytest

from roadnoise_utils.repro import paths


@pytest.mark.parametrize("variable", ["ROADNOISE_CACHE_DIR", "ROADNOISE_FIGURE_DIR", "ROADNOISE_DATA_DIR"])
def test_an_empty_folder_setting_is_refused_rather_than_taken_as_the_working_folder(monkeypatch, variable):
    monkeypatch.setenv(variable, "")
    with pytest.raises(ValueError, match=f"{variable} is set but empty"):
        {"ROADNOISE_CACHE_DIR": paths.cache_dir, "ROADNOISE_FIGURE_DIR": paths.figure_dir}.get(
            variable, paths.data_dir
        )()


def test_a_relative_folder_is_taken_from_the_repository_root_whatever_the_working_folder(monkeypatch, tmp_path):
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", "my-cache")
    at_root = paths.cache_dir()
    monkeypatch.chdir(tmp_path)  # a notebook runs in notebooks/, the reproduction at the root
    assert paths.cache_dir() == at_root == paths.REPO_ROOT / "my-cache"


def test_a_data_folder_without_tires_is_refused_naming_the_setting(monkeypatch, tmp_path):
    monkeypatch.setenv("ROADNOISE_DATA_DIR", str(tmp_path))
    with pytest.raises(FileNotFoundError, match="ROADNOISE_DATA_DIR = .* has no tires/ folder"):
        paths.data_file("165_65R14", "tires", "tire file")
