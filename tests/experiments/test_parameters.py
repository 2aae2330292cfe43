"""The notebooks' parameters reach the package's checks before anything uses them."""

from __future__ import annotations

import re

import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments.parameters import CHECKS
from roadnoise_utils.repro.paths import REPO_ROOT

#: The package functions a notebook hands its parameters to first: each checks them up front.
CHECKERS = (
    "check_parameters",
    "load_tire",
    "load_vehicle",
    "select_claims",
    "cleat_test",
    "cleat_conditions",
    "applicable",
    "suspension_conditions",
    "road_test_conditions",
    "one_sided_conditions",
    "whole_car_conditions",
    "band_extension",
    "sweep_parameters",
)
NOTEBOOKS = sorted((REPO_ROOT / "notebooks").glob("[0-9][0-9]-*.py"))


def _parameters(source: str) -> tuple[dict[str, str], str]:
    """A notebook's parameter cell (name -> value source) and the code after it (markdown dropped)."""
    found = re.search(r'# %% tags=\["parameters"\]\n(.*?)\n(?=# %%)', source, re.S)
    assert found, "no parameters cell"
    names = dict(re.findall(r"^([a-z_]+)\s*=\s*(.+?)(?:\s+#.*)?$", found.group(1), re.M))
    cells = re.split(r"^# %%.*$", source[found.end() :], flags=re.M)
    code = [cell for cell in cells if not cell.lstrip().startswith("# ##") and "[markdown]" not in cell]
    body = "\n".join(line for cell in code for line in cell.splitlines() if not line.lstrip().startswith("#"))
    return names, body


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem[:2])
def test_every_parameter_goes_to_a_check_first(notebook):
    names, body = _parameters(notebook.read_text())
    for name in names:
        first = next(line for line in body.splitlines() if re.search(rf"\b{name}\b", line))
        context = body[max(0, body.index(first) - 300) : body.index(first) + len(first)]
        assert any(f"{checker}(" in context for checker in CHECKERS), (notebook.name, name, first)


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem[:2])
def test_each_notebooks_own_values_pass(notebook):
    names, _ = _parameters(notebook.read_text())
    ours = {name: eval(value) for name, value in names.items() if name in CHECKS}  # noqa: S307 - our literals
    ru.experiments.check_parameters(**ours)


@pytest.mark.parametrize(
    "name, value, error",
    [
        ("tire_name", "175_70R13", FileNotFoundError),
        ("ring_name", 165, TypeError),
        ("vehicle_name", "sedan", FileNotFoundError),
        ("tire_size", "195_65R15x", FileNotFoundError),
        ("car_tire_size", "165_65R14", FileNotFoundError),
        ("road", "gravel", ValueError),
        ("f_band", 0.0, ValueError),
        ("f_max", 1e4, ValueError),
        ("band", 1.0, ValueError),
        ("tolerance", 1.5, ValueError),
        ("n_modes", 2.5, ValueError),
        ("length", float("nan"), ValueError),
    ],
)
def test_a_bad_value_is_refused_naming_the_parameter(name, value, error):
    with pytest.raises(error, match=rf"^{name} = "):
        ru.experiments.check_parameters(**{name: value})


def test_an_unknown_parameter_is_refused_with_the_known_ones():
    with pytest.raises(ValueError, match="not a notebook parameter"):
        ru.experiments.check_parameters(tire="165_65R14")
