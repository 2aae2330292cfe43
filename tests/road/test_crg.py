"""OpenCRG roads: written and read back, the modifiers applied only when asked (no false static
offset from the C loader's defaults), a hand-written file read as the format says, bad roads refused."""

from __future__ import annotations

import numpy as np
import pycrg
import pytest

import roadnoise_utils as ru

#: The OpenCRG C library keeps heights in single precision, whatever the file's format.
FLOAT32 = 2.0**-24
#: LRFI prints 10 characters per value: 7 decimals for a negative height below 0.1 m.
LRFI_ABS = 5e-8


@pytest.fixture(scope="module")
def field():
    spectrum = ru.textures.load_texture("rough")
    with pytest.warns(ru.guards.RoadnoiseWarning, match="shorter than the spectrum's longest wavelength"):
        return ru.textures.generate_field(spectrum, 2.56, 0.005, np.array([-0.06, -0.02, 0.02, 0.06]), seed=3)


@pytest.mark.parametrize("fmt", ["KDBI", "KRBI", "LDFI", "LRFI"])
def test_round_trip_every_format(tmp_path, field, fmt):
    path = ru.road.save_crg(tmp_path / "road.crg", field, fmt=fmt)
    assert ru.road.crg_modifiers(path) == {}  # an empty block: readers keep the road where it is
    back = ru.road.load_crg(path)
    np.testing.assert_array_equal(back.s, field.s)
    np.testing.assert_allclose(back.y, field.y, rtol=0, atol=1e-15)
    bound = FLOAT32 * np.abs(field.z) + (LRFI_ABS if fmt == "LRFI" else 0.0)
    assert np.all(np.abs(back.z - field.z) <= bound)
    assert not back.periodic and back.spectrum is None


def test_a_2d_profile_round_trips_as_two_equal_long_sections(tmp_path):
    s = np.arange(0.0, 1.0, 0.004)
    profile = ru.road.RoadProfile(
        s=s, y=np.zeros(1), z=1e-3 * np.sin(2 * np.pi * s / 0.3)[None], spectrum=None, seed=None, periodic=False
    )
    back = ru.road.load_crg(ru.road.save_crg(tmp_path / "p.crg", profile))
    np.testing.assert_allclose(back.y, [-0.15, 0.15])
    assert np.all(np.abs(back.z - profile.z) <= FLOAT32 * np.abs(profile.z))


def _plateau_road(path, mods):
    """A road whose first 0.5 m stands 14.24 mm up, then flat with a 15 mm cleat; v = -0.1..0.1 m."""
    du = 0.005
    u = np.arange(0.0, 3.0 + du / 2, du)
    v = np.linspace(-0.1, 0.1, 5)
    cleat = np.clip(0.015 * (1 - np.abs(u - 1.5) / 0.0075), 0.0, None)
    z = (0.01424 * (u < 0.5) + cleat)[:, None] + 0.0 * v
    pycrg.write(path, z, du, v, mods=mods)
    return z.T


def test_a_file_without_modifiers_gets_no_static_offset(tmp_path):
    """The C loader's defaults move the start of the reference line to z = 0: the whole road shifts by
    minus its height there (the OpenCRG specification's default reference point). Ours only when asked."""
    path = tmp_path / "no_mods.crg"
    z = _plateau_road(path, mods=None)
    assert ru.road.crg_modifiers(path) is None
    for modifiers in ("file", "none"):
        road = ru.road.load_crg(path, modifiers=modifiers)
        assert np.all(np.abs(road.z - z) <= FLOAT32 * np.abs(z))
        assert np.median(road.z) == 0.0
    with pytest.warns(ru.guards.RoadnoiseWarning, match=r"median height is -14.24 mm.*OpenCRG's defaults"):
        shifted = ru.road.load_crg(path, modifiers="opencrg")
    shift = shifted.z - z
    np.testing.assert_allclose(shift, -z[2, 0], rtol=0, atol=2e-9)  # the height at (u start, v = 0)


def test_the_files_own_modifiers_apply_with_file_not_with_none(tmp_path):
    path = tmp_path / "mods.crg"
    z = _plateau_road(path, mods={"scale_z_grid": 2.0, "refline_offset_z": 0.001})
    as_stored = ru.road.load_crg(path, modifiers="none")
    assert np.all(np.abs(as_stored.z - z) <= FLOAT32 * np.abs(z))
    for modifiers in ("file", "opencrg"):  # a block replaces the defaults: the same road
        road = ru.road.load_crg(path, modifiers=modifiers)
        np.testing.assert_allclose(road.z, 2.0 * z + 0.001, rtol=0, atol=1e-9)


def test_a_hand_written_text_file_is_read_as_the_format_says(tmp_path):
    """Independent of pycrg's writer: an LDFI file typed from the OpenCRG format (header sections,
    one line of values per cross section, u from the U channel's start and step, v right to left)."""
    du, u0, v = 0.01, 2.0, np.array([-0.05, 0.0, 0.05])
    u = u0 + du * np.arange(41)
    z = 0.002 * np.sin(2 * np.pi * (u - u0) / 0.2)[:, None] + 0.001 * v[None, :] / 0.05 + 0.01424
    header = [
        "$CT",
        "hand-written test road, no modifier block",
        "$",
        "$ROAD_CRG",
        f"reference_line_start_u   = {u0}",
        f"reference_line_end_u     = {u[-1]:.2f}",
        f"reference_line_increment = {du}",
        "long_section_v_right     = -0.05",
        "long_section_v_left      = 0.05",
        "long_section_v_increment = 0.05",
        "$",
        "$KD_DEFINITION",
        "#:LDFI",
        f"U:reference line u,m,{u0},{du}",
        *[f"D:long section {k + 1},m" for k in range(3)],
        "$",
        "$" * 72,
    ]
    rows = ["".join(f"{x:20.15f}" for x in row) for row in z]
    path = tmp_path / "hand.crg"
    path.write_text("\n".join(header + rows) + "\n")
    with pytest.warns(ru.guards.RoadnoiseWarning, match="median height is 14.24 mm"):  # genuinely raised
        road = ru.road.load_crg(path)
    np.testing.assert_allclose(road.s, u, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(road.y, v)
    assert np.all(np.abs(road.z - z.T) <= FLOAT32 * np.abs(z.T))


def test_track_and_half_width_pick_the_long_sections(tmp_path, field):
    path = ru.road.save_crg(tmp_path / "road.crg", field)
    right = ru.road.load_crg(path, track=-0.04, half_width=0.025)
    np.testing.assert_allclose(right.y, [-0.02, 0.02], atol=1e-15)
    np.testing.assert_array_equal(right.z, ru.road.load_crg(path).z[:2])


def test_a_crg_road_drives_the_tasselli(tmp_path, field, flat):
    road = ru.road.load_crg(ru.road.save_crg(tmp_path / "road.crg", field))
    u = ru.road.profile_input(flat, road.as_3d(), speed=60 / 3.6, distance=(0.2, 1.2))
    direct = ru.road.profile_input(flat, field.as_3d(), speed=60 / 3.6, distance=(0.2, 1.2))
    assert np.max(np.abs(u.u - direct.u)) <= 1e-7 * np.max(np.abs(direct.u))


def test_bad_crg_input_is_refused(tmp_path, field):
    path = ru.road.save_crg(tmp_path / "road.crg", field)
    with pytest.raises(ValueError, match="modifiers = 'default': valid values are 'file', 'none', 'opencrg'"):
        ru.road.load_crg(path, modifiers="default")
    with pytest.raises(ValueError, match=r"track = 0.5 m: valid range is the road's width, \[-0.06, 0.06\] m"):
        ru.road.load_crg(path, track=0.5)
    with pytest.raises(ValueError, match="half_width = 0.01 m: no long section"):
        ru.road.load_crg(path, track=0.0, half_width=0.01)
    with pytest.raises(FileExistsError, match="overwrite=True"):
        ru.road.save_crg(path, field)
    with pytest.raises(ValueError, match="fmt = 'CSV'"):
        ru.road.save_crg(tmp_path / "x.crg", field, fmt="CSV")
    with pytest.raises(FileNotFoundError, match="does not exist"):
        ru.road.load_crg(tmp_path / "missing.crg")
    coarse = tmp_path / "coarse.crg"
    pycrg.write(coarse, np.zeros((50, 3)), 0.02, np.array([-0.1, 0.0, 0.1]), mods={})
    with pytest.raises(ValueError, match="step 20.0 mm is too coarse"):
        ru.road.load_crg(coarse)
    border = tmp_path / "border.crg"
    z = np.zeros((50, 3))
    z[:, 0] = np.nan  # no data at the right border
    pycrg.write(border, z, 0.005, np.array([-0.1, 0.0, 0.1]), mods={})
    with pytest.raises(ValueError, match=r"NaN heights in the long sections at v = \[-0.1\] m"):
        ru.road.load_crg(border)
    assert ru.road.load_crg(border, half_width=0.1, track=0.05).y.tolist() == [-0.05, 0.05]
    (tmp_path / "text.crg").write_text("not a road\n")
    with pytest.raises(ValueError, match="OpenCRG cannot load it"):
        ru.road.load_crg(tmp_path / "text.crg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["border.crg", "coarse.crg", "road.crg", "text.crg"]


def _ldfi_lines(
    rows: np.ndarray, road: dict | None = None, mods: list[str] | None = None, channels: int = 3
) -> list[str]:
    """An LDFI file typed from the OpenCRG format: u from 2.0 m every 0.01 m, v = -0.05, 0, 0.05 m."""
    header = {
        "reference_line_start_u": 2.0,
        "reference_line_end_u": 2.4,
        "reference_line_increment": 0.01,
        "long_section_v_right": -0.05,
        "long_section_v_left": 0.05,
        "long_section_v_increment": 0.05,
        **(road or {}),
    }
    lines = ["$CT", "test road", "$", "$ROAD_CRG", *[f"{k} = {v}" for k, v in header.items()], "$"]
    if mods is not None:
        lines += ["$ROAD_CRG_MODS", *mods, "$"]
    lines += ["$KD_DEFINITION", "#:LDFI", "U:reference line u,m,2.0,0.01"]
    lines += [f"D:long section {k + 1},m" for k in range(channels)] + ["$", "$" * 72]
    return lines + ["".join(f"{x:20.15f}" for x in row) for row in rows]


ROWS = 0.002 * np.sin(np.linspace(0.0, 12.0, 41))[:, None] * np.ones(3)


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        (
            _ldfi_lines(ROWS, {"reference_line_end_u": 2.8}),
            r"2 .. 2.8 m every 0.01 m make 81 cross sections \(u\); the data has 41",
        ),
        (
            _ldfi_lines(ROWS)[:-1] + ["".join(f"{x:20.15f}" for x in ROWS[-1, :2])],
            "make 41 cross sections .*the data has 40",
        ),
        (_ldfi_lines(ROWS, {"long_section_v_increment": 0.04}), r"make 3.5 long sections \(v\); the data has 3"),
        (_ldfi_lines(ROWS, {"long_section_v_increment": 0.0}), "long_section_v_increment = 0.0: valid range is > 0 m"),
        (_ldfi_lines(ROWS[:, :2], channels=2), r"make 3 long sections \(v\); the data has 2"),
        (_ldfi_lines(ROWS, mods=["scale_z = abc"]), r"a header line OpenCRG cannot parse \(.*line 13"),
        (_ldfi_lines(ROWS, mods=["scale_zz = 2.0"]), r"a header line OpenCRG cannot parse \(.*scale_zz"),
    ],
    ids=[
        "end beyond the data",
        "last line cut",
        "v step",
        "zero v step",
        "a long section missing",
        "bad value",
        "bad name",
    ],
)
def test_an_inconsistent_crg_file_is_refused_naming_what_was_expected(tmp_path, lines, message):
    """OpenCRG's loader reads each of these (skipping the line it cannot parse, or as many sections as the
    data holds) and gives a road; the header and the data must agree."""
    path = tmp_path / "road.crg"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=f"road.crg: .*{message}"):
        ru.road.load_crg(path)


def test_the_consistent_hand_written_file_of_the_inconsistency_tests_loads(tmp_path):
    path = tmp_path / "road.crg"
    path.write_text("\n".join(_ldfi_lines(ROWS)) + "\n")
    road = ru.road.load_crg(path)
    assert road.z.shape == (3, 41) and np.allclose(road.z, ROWS.T, atol=1e-9)


@pytest.mark.parametrize("mods", [None, {}], ids=["no modifier block", "an empty block"])
def test_a_road_at_its_geographic_elevation_is_read_relative_to_the_wheel_s_path(tmp_path, mods):
    """A surveyed road 350 m up, on a 2 % grade and a 1 % bank: refused as it is (with the way to read
    it), read with modifiers='path' as its roughness, to the library's single precision."""
    u = np.arange(400) * 0.005
    v = np.array([-0.1, 0.0, 0.1])
    roughness = 1e-3 * np.random.default_rng(5).standard_normal((u.size, v.size))
    path = tmp_path / "surveyed.crg"
    pycrg.write(path, roughness, 0.005, v, z0=350.0, slope=0.02, banking=0.01, fmt="KDBI", mods=mods)
    with pytest.raises(
        ValueError, match=r"heights up to 350 m .*modifiers='path' reads it relative to its reference line"
    ):
        ru.road.load_crg(path, modifiers="none", half_width=0.1)
    road = ru.road.load_crg(path, modifiers="path", half_width=0.1)
    np.testing.assert_array_equal(road.y, v)
    assert np.abs(road.z - roughness.T).max() <= 2 * FLOAT32 * np.abs(roughness).max()
