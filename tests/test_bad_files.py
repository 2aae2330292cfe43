"""Damaged data files: every reader refuses a mutated valid file with a clear error, never a raw one.

Each valid file the collection reads (tire, vehicle, road texture, conditions, road height field,
OpenCRG, UFF 58, footprint) is mutated by hypothesis: a line deleted, duplicated or cut short, a
value replaced by a non-number, NaN, an infinity, a negative or a huge number, the file truncated.
The reader may accept a harmless mutation (a comment edited, a value still in range); otherwise it
must raise ``ValueError``/``TypeError``/``KeyError``/``FileNotFoundError`` naming the file, not an
``IndexError`` or ``AttributeError`` from inside a library, nor a message without the file's name.
"""

from __future__ import annotations

import re
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import roadnoise_utils as ru
from roadnoise_utils.experiments.conditions import load_conditions
from roadnoise_utils.repro.paths import REPO_ROOT
from roadnoise_utils.tire.footprint_file import read_footprint_csv, write_footprint_csv

#: Errors a reader may raise for a damaged file (with the file's name in the message).
CLEAR = (ValueError, TypeError, KeyError, FileNotFoundError)
#: Values a mutation writes in place of a number.
TOKENS = ["nan", "inf", "-inf", "-1", "0", "1e400", "1e30", "abc", '""', "[]", "true", "-0.0", "1,5", ""]
FUZZ = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")


@st.composite
def mutations(draw, text: str) -> str:
    """``text`` with one damage: a number replaced, a line deleted/duplicated/cut, or the file truncated."""
    lines = text.splitlines()
    kind = draw(st.sampled_from(["number", "number", "delete", "duplicate", "cut", "truncate"]))
    if kind == "number":
        spans = [m.span() for m in NUMBER.finditer(text)]
        start, end = draw(st.sampled_from(spans))
        return text[:start] + draw(st.sampled_from(TOKENS)) + text[end:]
    if kind == "truncate":
        return text[: draw(st.integers(0, len(text) - 1))]
    k = draw(st.integers(0, len(lines) - 1))
    if kind == "delete":
        lines.pop(k)
    elif kind == "duplicate":
        lines.insert(k, lines[k])
    else:
        lines[k] = lines[k][: draw(st.integers(0, max(len(lines[k]) - 1, 0)))]
    return "\n".join(lines) + "\n"


def _read_clearly(reader, path: Path) -> None:
    """Call ``reader(path)``: success, or a clear error naming the file."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a doubtful but valid file may warn
        try:
            reader(path)
        except CLEAR as exc:
            assert path.name in str(exc) or path.stem in str(exc) or "path" in str(exc), (
                f"{type(exc).__name__} without the file's name: {exc}"
            )


def _source(relative: str) -> str:
    return (REPO_ROOT / "data" / relative).read_text(encoding="utf-8")


# the text files as shipped, each with its reader
READERS = {
    "tire (ring)": ("tires/165_65R14.toml", "tire.toml", ru.load_tire),
    "tire (cross-section)": ("tires/165_65R14_cross_section.toml", "tire.toml", ru.load_tire),
    "vehicle": ("vehicles/midsize_195_65R15.toml", "car.toml", ru.vehicle.load_vehicle),
    "road texture": ("roads/rough.toml", "rough.toml", ru.road.textures.load_texture),
    "conditions": ("conditions/cleat_test.toml", "cleat_test.toml", load_conditions),
    "road height field": ("roads/example_height_field.csv", "field.csv", ru.road.load_road_file),
}


@pytest.mark.parametrize("kind", list(READERS))
@FUZZ
@given(data=st.data())
def test_a_damaged_data_file_is_refused_naming_the_file(tmp_path, kind, data):
    source, name, reader = READERS[kind]
    path = tmp_path / name
    path.write_text(data.draw(mutations(_source(source))), encoding="utf-8")
    _read_clearly(reader, path)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """An OpenCRG text file, a UFF 58 file and a footprint file written by the package."""
    folder = tmp_path_factory.mktemp("written")
    rng = np.random.default_rng(0)
    s = np.arange(200) * 0.005
    road = ru.road.textures.RoadProfile(
        s=s,
        y=np.array([-0.05, 0.0, 0.05]),
        z=1e-3 * rng.standard_normal((3, s.size)),
        spectrum=None,
        seed=None,
        periodic=False,
    )
    crg = ru.road.save_crg(folder / "road.crg", road, fmt="LDFI")
    visco = ru.stages.frf_visco("165_65R14")
    uff = ru.response.uff.write_uff58(folder / "frfs.uff", visco)
    static = ru.stages.solve_static("165_65R14")
    footprint = write_footprint_csv(folder / "footprint.csv", static.tasselli, static.node_pressure)
    return {"crg": crg, "uff": uff, "footprint": footprint}


WRITTEN_READERS = {
    "crg": ru.road.load_crg,
    "uff": ru.response.uff.read_uff58,
    "footprint": read_footprint_csv,
}


@pytest.mark.parametrize("kind", list(WRITTEN_READERS))
@FUZZ
@given(data=st.data())
def test_a_damaged_written_file_is_refused_naming_the_file(tmp_path, written, kind, data):
    path = tmp_path / written[kind].name
    text = written[kind].read_text(encoding="utf-8", errors="replace")
    path.write_text(data.draw(mutations(text)), encoding="utf-8")
    _read_clearly(WRITTEN_READERS[kind], path)


def test_the_fuzzed_files_are_read_when_undamaged(tmp_path, written):
    """The mutations start from files every reader accepts."""
    for source, name, reader in READERS.values():
        shutil.copy(REPO_ROOT / "data" / source, tmp_path / name)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            reader(tmp_path / name)
    for kind, reader in WRITTEN_READERS.items():
        reader(written[kind])
