"""The tire from files (``[tire] model = "frf-file"``): a user's FE tire run through the whole RM chain.

The worked example: the cross-section 165/65 R14, written as UFF 58 FRFs and footprint CSVs
(binary: exact) and read back, gives the same cleat test and quarter car to 1e-9; with 1 %
noise on its FRFs the chain still runs, warns where a fit misses, and stays stable. Bad files
are refused naming the file and the value.
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.guards import RoadnoiseWarning
from roadnoise_utils.tire.footprint_file import read_footprint_csv
from roadnoise_utils.tire.model import NotApplicable

CROSS_SECTION = "165_65R14_cross_section"
COARSE_RING = {"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1}


@pytest.fixture(scope="module")
def drum_radius():
    return ru.experiments.cleat_conditions().drum_radius


@pytest.fixture(scope="module")
def cross_section_files(tmp_path_factory, drum_radius):
    model = ru.tire_model(CROSS_SECTION)
    folder = tmp_path_factory.mktemp("cross_section_files")
    return ru.export_frf_files(model, folder, [model.case("flat"), model.case("drum", drum_radius=drum_radius)], "cs")


@pytest.fixture(scope="module")
def ring_files(tmp_path_factory, drum_radius):
    ring = ru.tire_model(ru.load_tire("165_65R14").replace(**COARSE_RING))
    folder = tmp_path_factory.mktemp("ring_files")
    return ru.export_frf_files(ring, folder, [ring.case("flat"), ring.case("drum", drum_radius=drum_radius)], "ring")


@pytest.mark.filterwarnings("ignore:decay components above the 250 Hz band")  # the tire's own 293 Hz component
def test_the_cross_section_tire_from_its_files_gives_the_same_cleat_test(cross_section_files):
    """The cleat test of notebook 04 on the files: the same forces, peaks and decay to 1e-9."""
    original = ru.experiments.cleat_test(CROSS_SECTION)
    from_files = ru.experiments.cleat_test(str(cross_section_files))
    for run in ("quasi_static", "dynamic"):
        a, b = getattr(original, run).result.force, getattr(from_files, run).result.force
        assert a.shape == b.shape and np.abs(b - a).max() <= 1e-9 * np.abs(a).max()
    assert abs(from_files.ratio / original.ratio - 1) < 1e-9
    assert from_files.system.nstates == original.system.nstates


def test_the_cross_section_tire_from_its_files_gives_the_same_quarter_car(cross_section_files):
    """The corner of notebook 07 on the files' flat-road case: the same G_H fit and spectra to 1e-9."""
    original = ru.experiments.corner_setup(tire=CROSS_SECTION)
    from_files = ru.experiments.corner_setup(tire=str(cross_section_files))
    assert from_files.hub.n_poles == original.hub.n_poles and from_files.tire_hub_mass == original.tire_hub_mass
    freqs = np.linspace(2.0, 250.0, 125)
    spectrum, speed = ru.textures.load_texture("rough"), 120 / 3.6
    a, b = original.predicted(freqs, spectrum, speed), from_files.predicted(freqs, spectrum, speed)
    for name in a:
        assert np.abs(b[name] - a[name]).max() <= 1e-9 * np.abs(a[name]).max(), name


@pytest.mark.filterwarnings("ignore:decay components above the 250 Hz band")
def test_the_cleat_chain_is_checked_against_the_files_frfs_in_the_frequency_domain(cross_section_files):
    """With no FE model of its own, the cleat test's second method is the passage from its FRFs on their
    1 Hz grid: the files hold the cross-section tire's FRFs, so it is that tire's direct passage (its
    harmonic solve at the same bins) to round-off, and the chain follows it as on that tire."""
    from_files = ru.experiments.cleat_test(str(cross_section_files), fe_reference=True).fe_reference
    original = ru.experiments.cleat_test(CROSS_SECTION, fe_reference=True).fe_reference
    assert np.abs(from_files.fe_force - original.fe_force).max() <= 1e-9 * np.abs(original.fe_force).max()
    assert abs(from_files.peak_difference) < 0.01 and from_files.rms_difference < 0.02


@pytest.mark.filterwarnings("ignore:decay components above the 250 Hz band")
def test_what_the_files_cannot_give_is_not_applicable(cross_section_files, drum_radius):
    """No modal reduction, no FE solve of its own, only the files' load cases and frequencies."""
    model = ru.tire_model(cross_section_files)
    assert model.has("hub_transfer") and not model.has("modal_reduction")
    with pytest.raises(NotApplicable, match="not applicable: modal_reduction"):
        ru.stages.modal_reduction(model)
    assert not model.has("direct_response")
    with pytest.raises(ValueError, match="no load case 4512 N on a drum of R = 2.00 m"):
        ru.stages.solve_static(model, "drum", drum_radius=2.0)
    with pytest.raises(ValueError, match="not frequencies of the file's FRFs"):
        ru.stages.frf_visco(model, freqs=[10.5])


def test_with_noise_on_its_frfs_the_chain_runs_warns_and_stays_stable(ring_files, tmp_path):
    """1 % multiplicative noise on every FRF (seeded): the read warns that the tasselli no longer add up
    to H_tot, the fits warn that no order reaches 1 %, and every pole of the state space is stable."""
    noisy = tmp_path / "noisy"
    shutil.copytree(ring_files.parent, noisy)
    rng = np.random.default_rng(1)
    for uff in noisy.glob("*.uff"):
        frfs = ru.read_uff58(uff)

        def noise(values):
            return values * (1 + 0.01 * (rng.standard_normal(values.shape) + 1j * rng.standard_normal(values.shape)))

        changed = ru.FRFResult(frfs.freqs, noise(frfs.H), noise(frfs.H_tot), noise(frfs.G_H), None, "with 1 % noise")
        ru.write_uff58(uff, changed, binary=True, overwrite=True)
    with pytest.warns(RoadnoiseWarning, match="sum to H_tot within"):
        model = ru.tire_model(noisy / ring_files.name)
    with pytest.warns(RoadnoiseWarning):
        test = ru.experiments.cleat_test(model.spec)
    assert np.all(np.linalg.eigvals(test.system.A).real < 0)
    assert np.isfinite(test.dynamic.peak_force) and test.dynamic.peak_force > 0


def test_frfs_off_zero_and_on_an_uneven_grid_take_k_v_from_the_file(ring_files, tmp_path):
    folder = tmp_path / "uneven"
    shutil.copytree(ring_files.parent, folder)
    frfs = ru.read_uff58(folder / "ring-1.uff")
    keep = np.r_[1:60, 60:401:3]  # from 1 Hz, every 1 Hz then every 3 Hz
    part = ru.FRFResult(frfs.freqs[keep], frfs.H[:, keep], frfs.H_tot[keep], frfs.G_H[keep], None, "part")
    ru.write_uff58(folder / "ring-1.uff", part, binary=True, overwrite=True)
    model = ru.tire_model(folder / "ring.toml")
    stiffness = model.load(model.case("flat")).vertical_stiffness
    assert stiffness == ru.tire_model(ring_files).load(model.case("flat")).vertical_stiffness  # the file's K_v
    fits = ru.stages.fit_tasselli(model)
    assert fits.band[0] == pytest.approx(1.0) and np.all(fits.rms_errors < 0.05)
    lines = (folder / "ring.toml").read_text().splitlines()
    first = next(k for k, line in enumerate(lines) if line.startswith("vertical_stiffness"))  # the flat road's
    (folder / "ring.toml").write_text("\n".join(lines[:first] + lines[first + 1 :]) + "\n")
    with pytest.raises(ValueError, match="start at 1 Hz, not at 0 Hz: give vertical_stiffness"):
        ru.tire_model(folder / "ring.toml")


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda t: t.replace('road = "flat"', 'road = "sand"'), "road = 'sand': valid values are 'flat' and 'drum'"),
        (
            lambda t: t.replace("rim_side_mass = ", "rim_side_mass = -"),
            r"rim_side_mass = -[0-9.]+ kg is outside its valid range",
        ),
        (lambda t: t.replace('frfs = "ring-1.uff"', 'frfs = "missing.uff"'), "does not exist"),
        (lambda t: t.replace('footprint = "ring-1.csv"', 'footprint = "ring-2.csv"'), "they must be the same tasselli"),
        (lambda t: t + "colour = 1\n", r"unknown key\(s\) \['colour'\]"),
        (lambda t: t.replace("[hub]", "[hubs]"), r"missing section\(s\) \['\[hub\]'\]"),
    ],
)
def test_a_bad_tire_file_is_refused_naming_the_value(ring_files, tmp_path, edit, message):
    folder = tmp_path / "bad"
    shutil.copytree(ring_files.parent, folder)
    (folder / "ring.toml").write_text(edit((folder / "ring.toml").read_text()))
    with pytest.raises((ValueError, FileNotFoundError), match=message):
        ru.tire_model(folder / "ring.toml")


@pytest.mark.parametrize(
    ("column", "value", "message"),
    [
        ("weight", 0.5, r"the weights of tassello \d+ sum to 0.5"),
        ("dx_plus_m", -0.001, r"column 'dx_plus_m', data row 1: -0.001 m; valid range is \(0"),
        ("x_m", "abc", r"column 'x_m', data row 1: 'abc' is not a finite number"),
        ("tassello", 2.5, "valid values are integers >= 1"),
    ],
)
def test_a_bad_footprint_file_is_refused_naming_the_row(ring_files, tmp_path, column, value, message):
    import pandas as pd

    table = pd.read_csv(ring_files.parent / "ring-1.csv")
    table[column] = table[column].astype(object)
    table.loc[0, column] = value
    table.to_csv(tmp_path / "bad.csv", index=False)
    with pytest.raises(ValueError, match=message):
        read_footprint_csv(tmp_path / "bad.csv")
    table = pd.read_csv(ring_files.parent / "ring-1.csv").drop(columns="pressure_Pa")
    table.to_csv(tmp_path / "short.csv", index=False)
    with pytest.raises(ValueError, match="a footprint file has exactly"):
        read_footprint_csv(tmp_path / "short.csv")
