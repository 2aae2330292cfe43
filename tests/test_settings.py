"""The environment settings: one table, read in one module, every value checked."""

from __future__ import annotations

import ast
import re
import warnings

import pytest

from roadnoise_utils import guards, settings
from roadnoise_utils.repro.paths import REPO_ROOT
from tests.test_layout import PACKAGE_DIR

ENVIRON_READERS = {("os", "getenv"), ("environ", "get")}


def _environment_reads(tree: ast.AST) -> list[str]:
    """String constants passed to ``os.environ.get``/``os.getenv`` or used as ``os.environ[...]`` keys."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.args:
            owner = node.func.value
            owner_name = owner.attr if isinstance(owner, ast.Attribute) else getattr(owner, "id", "")
            if (owner_name, node.func.attr) in ENVIRON_READERS and isinstance(node.args[0], ast.Constant):
                found.append(str(node.args[0].value))
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) and node.value.attr == "environ":
            if isinstance(node.slice, ast.Constant):
                found.append(str(node.slice.value))
    return found


def test_only_the_settings_module_reads_a_setting():
    for path in sorted(PACKAGE_DIR.rglob("*.py")):
        if path.name == "settings.py" and path.parent == PACKAGE_DIR:
            continue
        reads = [name for name in _environment_reads(ast.parse(path.read_text())) if name.startswith("ROADNOISE_")]
        assert not reads, (
            f"{path.relative_to(PACKAGE_DIR)} reads {reads} itself: read it through roadnoise_utils.settings"
        )


def test_every_setting_named_in_the_package_is_in_the_table():
    """A ROADNOISE_* name in a string anywhere in the package is a setting of the table (a misspelt one is not)."""
    for path in sorted(PACKAGE_DIR.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                for name in re.findall(r"ROADNOISE_[A-Z_]*[A-Z]", node.value):
                    assert name in settings.SETTINGS, (path.name, name)


def test_every_setting_is_documented_in_the_book():
    page = (REPO_ROOT / "book" / "reference" / "layout.md").read_text()
    for name, setting in settings.SETTINGS.items():
        assert f"`{name}`" in page and setting.valid in page, name


def test_an_unknown_roadnoise_variable_warns_naming_it(monkeypatch):
    monkeypatch.setenv("ROADNOISE_CACHEDIR", "/tmp/x")
    settings._warn_unknown.cache_clear()
    with pytest.warns(guards.RoadnoiseWarning, match="ROADNOISE_CACHEDIR: not a roadnoise setting"):
        settings.flag("ROADNOISE_CACHE", True)
    settings._warn_unknown.cache_clear()


def test_reading_a_name_that_is_not_a_setting_is_a_programming_error():
    with pytest.raises(KeyError, match="ROADNOISE_CACHEDIR is not a roadnoise setting"):
        settings.raw("ROADNOISE_CACHEDIR")


@pytest.mark.parametrize(
    "name, value, read",
    [
        ("ROADNOISE_CACHE", "maybe", lambda: settings.flag("ROADNOISE_CACHE", True)),
        ("ROADNOISE_THREADS", "3", lambda: settings.choice("ROADNOISE_THREADS", ("1", "2"))),
        ("ROADNOISE_MAX_BYTES", "-1", lambda: settings.positive_number("ROADNOISE_MAX_BYTES", 1.0)),
        ("ROADNOISE_MAX_BYTES", "lots", lambda: settings.positive_number("ROADNOISE_MAX_BYTES", 1.0)),
        ("ROADNOISE_CACHE_DIR", " ", lambda: settings.path("ROADNOISE_CACHE_DIR", None)),
    ],
)
def test_a_bad_value_names_the_setting_and_its_valid_values(monkeypatch, name, value, read):
    monkeypatch.setenv(name, value)
    with pytest.raises(ValueError) as caught:
        read()
    assert name in str(caught.value) and settings.SETTINGS[name].valid in str(caught.value)


def test_paths_are_taken_from_the_repository_root_and_a_blank_log_is_no_log(monkeypatch):
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", "some/cache")
    assert settings.path("ROADNOISE_CACHE_DIR", None) == REPO_ROOT / "some" / "cache"
    monkeypatch.setenv("ROADNOISE_STAGE_LOG", "  ")
    assert settings.path("ROADNOISE_STAGE_LOG", None) is None
    monkeypatch.setenv("ROADNOISE_CACHE", " OFF ")
    assert settings.flag("ROADNOISE_CACHE", True) is False


def test_unset_settings_take_their_defaults(monkeypatch):
    for name in settings.SETTINGS:
        monkeypatch.delenv(name, raising=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert settings.flag("ROADNOISE_CACHE", True) is True
        assert settings.choice("ROADNOISE_THREADS", ("1", "2")) is None
        assert settings.positive_number("ROADNOISE_MAX_BYTES", 4.0) == 4.0
        assert settings.path("ROADNOISE_FIGURE_DIR", REPO_ROOT / "figures") == REPO_ROOT / "figures"
