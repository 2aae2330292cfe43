"""UFF 58 files of the FRF sets: written and read back to the format's precision, files written by
pyuff's own API read correctly, bad input refused, nothing half-written."""

from __future__ import annotations

import re

import numpy as np
import pytest
import pyuff

import roadnoise_utils as ru
from roadnoise_utils.response import uff
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.footprint import footprint_frf
from roadnoise_utils.tire.ring.frf import FRFResult

#: ASCII values are printed with 12 significant digits (%20.11e): each real and imaginary part comes
#: back within half a unit of the 12th digit, 5e-12 of itself (plus the parse's 1e-16).
ASCII_RTOL = 5e-12 + 1e-15


def _synthetic(freqs: np.ndarray, n_tasselli: int = 5, n_points: int = 3, seed: int = 0) -> FRFResult:
    """FRFs whose parts span four decades (1e2-1e6 N/m), none zero, the sums consistent."""
    rng = np.random.default_rng(seed)
    size = (n_points, freqs.size)
    points = 10 ** rng.uniform(2, 6, size) * np.exp(1j * rng.uniform(0.1, 1.4, size)) * rng.choice([-1, 1], size)
    H = np.array([points.sum(axis=0) * (k + 1) / n_tasselli for k in range(n_tasselli)])
    G_H = -2.0e5 * (1 + 0.05j) + (2 * np.pi * freqs) ** 2 * 9.0 + 1.0
    return FRFResult(freqs=freqs, H=H, H_tot=H.sum(axis=0) + 7.0, G_H=G_H, H_points=points, method="synthetic")


def _assert_close_parts(got: np.ndarray, want: np.ndarray) -> None:
    for part in (np.real, np.imag):
        err = np.abs(part(got) - part(want))
        assert np.all(err <= ASCII_RTOL * np.abs(part(want))), float(np.max(err / np.abs(part(want))))


def test_ascii_round_trip_to_the_printed_precision(tmp_path):
    frfs = _synthetic(np.arange(0.0, 250.0 + 0.5, 1.0))
    back = ru.read_uff58(ru.write_uff58(tmp_path / "frfs.uff", frfs, points=True, label="165/65 R14"))
    np.testing.assert_array_equal(back.freqs, frfs.freqs)  # even grid: start and step exact in E13.5
    for name in ("H", "H_tot", "G_H", "H_points"):
        _assert_close_parts(getattr(back, name), getattr(frfs, name))
    assert not np.array_equal(back.H, frfs.H)  # the file really is ASCII (12 digits, not 17)
    assert back.method == "read from UFF 58 file frfs.uff (synthetic)"


def test_binary_round_trip_is_exact_and_its_byte_counts_right(tmp_path):
    frfs = _synthetic(np.arange(0.0, 40.0, 0.25), n_points=0)
    path = ru.write_uff58(tmp_path / "frfs.uff", frfs, binary=True)
    back = ru.read_uff58(path)
    for name in ("freqs", "H", "H_tot", "G_H"):
        np.testing.assert_array_equal(getattr(back, name), getattr(frfs, name))
    assert back.H_points.shape == (0, frfs.freqs.size)
    # every binary header's byte count (field 4 of its line 2) is the data that follows its 13 text lines
    raw = path.read_bytes()
    heads = [m.start() for m in re.finditer(rb"    -1\n    58b", raw)]
    assert len(heads) == 2 + frfs.H.shape[0]
    for start in heads:
        lines = raw[start:].split(b"\n", 13)  # "-1", the binary header, 11 text records, then the data
        count = int(lines[1][31:43])
        assert lines[13][count : count + 7] == b"    -1\n" and count == 16 * frfs.freqs.size


def test_sets_carry_nodes_directions_and_units(tmp_path):
    """Read with pyuff itself: one SI units set, then FRFs of hub Fz per +Z displacement, N/m."""
    frfs = _synthetic(np.arange(0.0, 10.0), n_tasselli=3, n_points=0)
    sets = pyuff.UFF(str(ru.write_uff58(tmp_path / "frfs.uff", frfs))).read_sets()
    assert sets[0]["type"] == 164 and sets[0]["units_code"] == 1 and sets[0]["length"] == sets[0]["force"] == 1.0
    assert [s["ref_node"] for s in sets[1:]] == [1000, 1, 1001, 1002, 1003]
    for s in sets[1:]:
        assert (s["func_type"], s["rsp_node"], s["rsp_dir"], s["ref_dir"]) == (4, 1, 3, 3)
        assert (s["abscissa_spec_data_type"], s["ordinate_spec_data_type"], s["orddenom_spec_data_type"]) == (18, 9, 8)
        assert (s["ordinate_axis_units_lab"], s["orddenom_axis_units_lab"]) == ("N", "m")


def test_uneven_frequencies(tmp_path):
    # 6 significant digits hold these: ASCII gives them back exactly, as the x-value of every point
    coarse = np.array([0.0, 0.5, 1.0, 2.5, 10.0, 31.25, 80.0, 123.45, 250.0])
    back = ru.read_uff58(ru.write_uff58(tmp_path / "a.uff", _synthetic(coarse)))
    np.testing.assert_array_equal(back.freqs, coarse)
    # these need 17: binary keeps them, ASCII rounds them to 6 digits and says so
    fine = np.geomspace(1.0, 400.0, 37)
    np.testing.assert_array_equal(
        ru.read_uff58(ru.write_uff58(tmp_path / "b.uff", _synthetic(fine), binary=True)).freqs, fine
    )
    with pytest.warns(ru.guards.RoadnoiseWarning, match="6 significant digits"):
        rounded = ru.read_uff58(ru.write_uff58(tmp_path / "c.uff", _synthetic(fine))).freqs
    np.testing.assert_allclose(rounded, fine, rtol=5e-6, atol=0)
    assert not np.array_equal(rounded, fine)


def test_ring_tire_frfs_round_trip(flat, fet, tmp_path):
    visco = ru.frf_visco(fet, flat, np.array([0.0, 20.0, 80.0, 160.0]), progress=False)
    back = ru.read_uff58(ru.write_uff58(tmp_path / "ring.uff", visco))
    assert back.H.shape == (flat.tasselli.n, 4)
    for name in ("H", "H_tot", "G_H"):
        _assert_close_parts(getattr(back, name), getattr(visco, name))
    assert back.G_H[0].real < 0  # -K_v at rest, the sign convention kept


def test_cross_section_footprint_frfs_round_trip(tmp_path):
    name = "165_65R14_cross_section"
    static = ru.stages.solve_static(name, "flat")
    frfs = footprint_frf(section_stages.section_tire(name), static, np.array([0.0, 80.0]))
    back = ru.read_uff58(ru.write_uff58(tmp_path / "section.uff", frfs.to_frf_result(), binary=True, points=True))
    np.testing.assert_array_equal(back.H, frfs.H_tasselli().T)
    np.testing.assert_array_equal(back.H_tot, frfs.H_tot)
    np.testing.assert_array_equal(back.G_H, frfs.G_H)
    np.testing.assert_array_equal(back.H_points, frfs.hub.T)


def _sdof(freqs: np.ndarray) -> dict[str, np.ndarray]:
    """A known dynamic stiffness (N/m): a mass on a damped spring, and a footprint that shares it."""
    w = 2 * np.pi * freqs
    k, m, c = 2.0e5, 9.0, 60.0
    g_h = -(k - m * w**2 + 1j * c * w)
    h_tot = k * k / (k - 3.0 * w**2 + 1j * c * w)
    return {"G_H": g_h, "H_tot": h_tot, "H": np.array([0.25 * h_tot, 0.75 * h_tot])}


def test_a_file_written_by_pyuff_is_read(tmp_path):
    """Independent reference: sets written through pyuff's own API, in N/mm (units set 164 with a
    length factor 1000: SI = file value x 1000 / 1), uneven frequencies; ours returns N/m."""
    freqs = np.array([0.0, 1.0, 5.0, 20.0, 50.0, 80.0, 120.0, 250.0])
    known = _sdof(freqs)
    units = pyuff.prepare_164(
        units_code=9, units_description="mm N s", temp_mode=2, length=1000.0, force=1.0, temp=1.0, temp_offset=273.15
    )
    sets = [units]
    for node, data in [(1000, known["H_tot"]), (1, known["G_H"]), (1001, known["H"][0]), (1002, known["H"][1])]:
        sets.append(
            pyuff.prepare_58(
                func_type=4, rsp_node=1, rsp_dir=3, ref_node=node, ref_dir=3, abscissa_spacing=0, x=freqs,
                data=data / 1000.0, abscissa_spec_data_type=18, ordinate_spec_data_type=13, orddenom_spec_data_type=8,
            )
        )  # fmt: skip
    pyuff.UFF(str(tmp_path / "peer.uff")).write_sets(sets, mode="add")
    back = ru.read_uff58(tmp_path / "peer.uff")
    np.testing.assert_array_equal(back.freqs, freqs)
    for name in ("H", "H_tot", "G_H"):
        np.testing.assert_allclose(getattr(back, name), known[name], rtol=1e-11)
    assert back.G_H[0] == pytest.approx(-2.0e5, rel=1e-11)


def _bad(frfs: FRFResult, **changes) -> FRFResult:
    fields = {f: getattr(frfs, f) for f in ("freqs", "H", "H_tot", "G_H", "H_points", "method")}
    return FRFResult(**{**fields, **changes})


GOOD = _synthetic(np.arange(0.0, 10.0), n_tasselli=3)


@pytest.mark.parametrize(
    ("frfs", "error", "message"),
    [
        (_bad(GOOD, H=np.where(np.arange(10) == 4, np.nan, GOOD.H)), ValueError, r"frfs.H \(tassello 0\) is NaN"),
        (_bad(GOOD, G_H=GOOD.G_H + np.where(np.arange(10) == 2, np.inf, 0)), ValueError, "frfs.G_H is NaN or inf"),
        (_bad(GOOD, H_tot=GOOD.H_tot[:-1]), ValueError, r"frfs.H_tot has shape \(9,\): valid is \(10,\)"),
        (_bad(GOOD, H=GOOD.H[:, :-1]), ValueError, r"frfs.H has shape \(3, 9\)"),
        (_bad(GOOD, freqs=GOOD.freqs[::-1]), ValueError, "strictly increasing"),
        (_bad(GOOD, freqs=GOOD.freqs[:1], H=GOOD.H[:, :1]), ValueError, "at least 2 frequencies"),
        (GOOD.H, TypeError, "frfs must be an FRFResult"),
    ],
)
def test_bad_frfs_are_refused_and_nothing_is_written(tmp_path, frfs, error, message):
    with pytest.raises(error, match=message):
        ru.write_uff58(tmp_path / "bad.uff", frfs)
    assert list(tmp_path.iterdir()) == []


def test_an_existing_file_is_kept_unless_overwrite(tmp_path, monkeypatch):
    path = tmp_path / "frfs.uff"
    path.write_text("keep me")
    with pytest.raises(FileExistsError, match="overwrite=True"):
        ru.write_uff58(path, GOOD)

    # a writer failing half-way leaves the old file and no temporary one
    def fail(self, sets, mode="add"):
        open(self._filename, "a").write("    -1\n    58\npartial")
        raise RuntimeError("disk full")

    monkeypatch.setattr(pyuff.UFF, "write_sets", fail)
    with pytest.raises(RuntimeError, match="disk full"):
        ru.write_uff58(path, GOOD, overwrite=True)
    assert path.read_text() == "keep me" and list(tmp_path.iterdir()) == [path]


def test_foreign_or_incomplete_files_are_refused(tmp_path):
    freqs = np.array([0.0, 10.0, 20.0])
    accel = pyuff.prepare_58(
        func_type=4, rsp_node=1, rsp_dir=3, ref_node=1000, ref_dir=3, abscissa_spacing=1, x=freqs, data=freqs + 1j,
        abscissa_spec_data_type=18, ordinate_spec_data_type=12, orddenom_spec_data_type=13,
    )  # fmt: skip
    pyuff.UFF(str(tmp_path / "accel.uff")).write_sets([accel], mode="add")
    with pytest.raises(ValueError, match="ordinate acceleration per excitation force, expected force per displacement"):
        ru.read_uff58(tmp_path / "accel.uff")
    sets = pyuff.UFF(str(ru.write_uff58(tmp_path / "frfs.uff", GOOD))).read_sets()
    pyuff.UFF(str(tmp_path / "no_hub.uff")).write_sets([s for s in sets if s.get("ref_node") != 1], mode="add")
    no_hub = ru.read_uff58(tmp_path / "no_hub.uff")  # data without a hub transfer: G_H is None, the rest as written
    assert no_hub.G_H is None and np.abs(no_hub.H_tot - GOOD.H_tot).max() <= 1e-11 * np.abs(GOOD.H_tot).max()
    again = ru.read_uff58(ru.write_uff58(tmp_path / "again.uff", no_hub, binary=True))
    assert again.G_H is None and np.array_equal(again.H, no_hub.H)
    pyuff.UFF(str(tmp_path / "no_footprint.uff")).write_sets([s for s in sets if s.get("ref_node") != 1000], mode="add")
    with pytest.raises(ValueError, match="no set for H_tot"):
        ru.read_uff58(tmp_path / "no_footprint.uff")
    pyuff.UFF(str(tmp_path / "gap.uff")).write_sets([s for s in sets if s.get("ref_node") != 1002], mode="add")
    with pytest.raises(ValueError, match=r"tassello node\(s\) \[1002\]"):
        ru.read_uff58(tmp_path / "gap.uff")
    (tmp_path / "text.uff").write_text("not a universal file\n")
    with pytest.raises(ValueError, match="no UFF 58 data set"):
        ru.read_uff58(tmp_path / "text.uff")
    with pytest.raises(FileNotFoundError, match="does not exist"):
        ru.read_uff58(tmp_path / "missing.uff")


def test_node_layout_constants_are_consistent():
    assert uff.TASSELLO_NODE + uff.MAX_TASSELLI == uff.POINT_NODE and uff.FOOTPRINT_NODE < uff.TASSELLO_NODE
