"""The FMU run by fmpy against our own simulation of the same tire on the same road samples."""

from __future__ import annotations

import subprocess
import zipfile

import control
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fmu.drive import FmuError, TireSlave, run_fmu
from roadnoise_utils.fmu.export import SOURCE_DIR, compiler
from roadnoise_utils.rm.aggregated import road_hub_force
from roadnoise_utils.road.cleat import cleat_profile

from .conftest import SPEED, knots


def cleat_heights(tables, n: int) -> np.ndarray:
    """The paper's cleat (triangle, 15 x 15 mm) at the leading edge, the travel starting 0.1 m before it."""
    return cleat_profile(0.015, 0.015)(knots(tables, n))


def reference(exported, profile, n: int) -> np.ndarray:
    """Our force on the same road: the road linear between the FMU's samples, through the fixed-hub tire."""
    grid = SPEED * exported.tables.dt
    system = ru.assemble_fixed_hub(exported.fits)
    distance = (-0.1, -0.1 + grid * (n - 0.5))  # n samples, whatever the round-off of the travel's length
    force = road_hub_force(system, exported.static, profile, SPEED, distance, 1 / exported.tables.dt).force
    assert force.size == n
    return force


def test_cleat_with_the_hub_held_is_our_simulation(tire_2d):
    """Eq. 3-4 by two codes: the FMU's delay line, taps and FOH sections in C against road_hub_force (the
    aggregated per-track convolution) on the road linear between the same samples; round-off apart."""
    n = int(0.6 / (SPEED * tire_2d.tables.dt))
    heights = cleat_heights(tire_2d.tables, n)
    s = knots(tire_2d.tables, n)
    expected = reference(tire_2d, lambda x: np.interp(x, s, heights), n)
    run = run_fmu(tire_2d.path, heights)
    peak = np.max(np.abs(expected))
    assert peak > 300.0  # the cleat's force peak, hundreds of N
    assert np.max(np.abs(run.F_F - expected)) <= 1e-9 * peak
    np.testing.assert_array_equal(run.F_H, 0.0)
    np.testing.assert_array_equal(run.F_M, run.F_F)


def test_a_laterally_varying_road_is_our_simulation(tire_3d):
    """A 3-D road, each strip with its own heights, against road_hub_force with profile(s, y)."""
    tables = tire_3d.tables
    n = 600
    rng = np.random.default_rng(7)
    heights = np.cumsum(rng.normal(size=(tables.n_strips, n)), axis=1) * 2e-5
    heights -= heights[:, :1]  # from zero, where the FMU's steady start and ours at rest agree
    s = knots(tables, n)

    def profile(x, y):
        return np.interp(x, s, heights[int(np.argmin(np.abs(tables.strip_y - y)))])

    expected = reference(tire_3d, profile, n)
    run = run_fmu(tire_3d.path, heights)
    assert np.max(np.abs(run.F_F - expected)) <= 1e-9 * np.max(np.abs(expected))


def test_hub_motion_on_a_level_road_is_g_h(tire_2d):
    """Eq. 6: with the road level, F_H is G_H's state space simulated by ru.simulate."""
    tables = tire_2d.tables
    n = 2000
    hub = np.concatenate([[0.0], np.cumsum(np.random.default_rng(1).normal(size=n - 1)) * 1e-6])
    run = run_fmu(tire_2d.path, np.zeros(n), hub)
    road = ru.RoadInput(t=tables.dt * np.arange(n), distance=SPEED * tables.dt * np.arange(n), u=hub[None, :],
                        speed=SPEED, description="hub displacement")  # fmt: skip
    expected = ru.simulate(ru.rm.hub_statespace(tire_2d.hub), road).force
    assert np.max(np.abs(run.F_H - expected)) <= 1e-9 * np.max(np.abs(expected))
    np.testing.assert_array_equal(run.F_F, 0.0)


def test_road_and_hub_superpose(tire_2d):
    """Eq. 5: F_M of both inputs at once is the sum of the two runs (the tire is linear)."""
    n = 500
    heights = cleat_heights(tire_2d.tables, n)
    hub = 1e-3 * np.sin(np.arange(n) * 0.05)
    both = run_fmu(tire_2d.path, heights, hub)
    road_only, hub_only = run_fmu(tire_2d.path, heights), run_fmu(tire_2d.path, np.zeros(n), hub)
    scale = np.max(np.abs(both.F_M))
    assert np.max(np.abs(both.F_M - road_only.F_M - hub_only.F_M)) <= 1e-12 * scale
    assert np.max(np.abs(both.F_M - both.F_F - both.F_H)) <= 1e-12 * scale


def static_gains(exported) -> tuple[float, float]:
    """The continuous models' DC gains (python-control): F_F per metre of level road, F_H per metre of hub."""
    road = float(np.sum(control.dcgain(ru.assemble_fixed_hub(exported.fits))))
    return road, float(np.squeeze(control.dcgain(ru.rm.hub_statespace(exported.hub))))


def test_constant_inputs_give_the_static_force_from_the_first_point(tire_2d):
    """The FMU starts in the steady state of its first inputs: no start-up kick. The static force is the
    continuous state spaces' DC gain (a level road moves every tassello by its height), against the C's
    discrete steady state of each FOH section."""
    road_gain, hub_gain = static_gains(tire_2d)
    assert road_gain > 1e5 and hub_gain < -1e5  # N/m: a road pushed up compresses the tire, a hub raised relieves it
    run = run_fmu(tire_2d.path, np.full(300, 1e-3), np.full(300, 5e-4))
    np.testing.assert_allclose(run.F_F, road_gain * 1e-3, rtol=1e-9)
    np.testing.assert_allclose(run.F_H, hub_gain * 5e-4, rtol=1e-9)


def test_inputs_starting_away_from_zero_are_the_rest_response_plus_the_static_force(tire_2d):
    """Linearity: starting in the steady state of u0 is ru.simulate's rest response to u - u0 plus the static
    force of u0."""
    tables = tire_2d.tables
    n = 1500
    hub = 2e-4 + np.cumsum(np.random.default_rng(5).normal(size=n)) * 1e-6
    run = run_fmu(tire_2d.path, np.zeros(n), hub)
    road = ru.RoadInput(t=tables.dt * np.arange(n), distance=SPEED * tables.dt * np.arange(n),
                        u=(hub - hub[0])[None, :], speed=SPEED, description="hub displacement")  # fmt: skip
    expected = ru.simulate(ru.rm.hub_statespace(tire_2d.hub), road).force + static_gains(tire_2d)[1] * hub[0]
    assert np.max(np.abs(run.F_H - expected)) <= 1e-9 * np.max(np.abs(expected))


def test_another_step_is_refused_with_the_fmus_message(tire_2d):
    with TireSlave(tire_2d.path) as slave, pytest.raises(FmuError, match="communication step .* steps .* exactly"):
        slave.set([0.0], 0.0)
        slave.step(2 * slave.dt)
    with TireSlave(tire_2d.path) as slave, pytest.raises(FmuError, match="communication step nan"):
        slave.set([0.0], 0.0)
        slave.step(np.nan)


def test_a_step_off_by_a_tools_round_off_is_taken(tire_2d):
    """A tool's accumulated or printed step may differ from the FMU's in the last digits: taken (1e-6 of it)."""
    n = 100
    heights = cleat_heights(tire_2d.tables, n)
    exact = run_fmu(tire_2d.path, heights)
    with TireSlave(tire_2d.path) as slave:
        forces = []
        for k in range(n):
            slave.set(heights[[k]], 0.0)
            forces.append(slave.outputs()[0])
            slave.step(slave.dt * (1 + 1e-7 * (-1) ** k))
    np.testing.assert_array_equal(forces, exact.F_M)
    with TireSlave(tire_2d.path) as slave, pytest.raises(FmuError, match="communication step"):
        slave.set([0.0], 0.0)
        slave.step(slave.dt * (1 + 1e-5))


@pytest.mark.parametrize("value", [20.0, np.nan])
def test_another_speed_is_refused(tire_2d, value):
    with TireSlave(tire_2d.path) as slave, pytest.raises(FmuError, match="exported for 8.33333 m/s only"):
        slave._call(slave.slave.setReal, [4], [value])


@pytest.mark.parametrize(("name", "message"), [("time_step", "steps .* exactly"), ("leading_edge_x", "fixed at"),
                                               ("road_y[1]", "fixed at")])  # fmt: skip
def test_the_other_constants_refuse_another_value_and_nan(tire_2d, name, message):
    with TireSlave(tire_2d.path) as slave:
        reference = slave.variables[name].valueReference
        own = float(slave.variables[name].start)
        slave._call(slave.slave.setReal, [reference], [own])  # its own value: taken
        for value in (own + 1e-3, np.nan):
            with pytest.raises(FmuError, match=message):
                slave._call(slave.slave.setReal, [reference], [value])


def test_a_step_before_initialisation_is_refused(tire_2d):
    with TireSlave(tire_2d.path) as slave:
        slave.slave.reset()
        with pytest.raises(FmuError, match="before fmi2ExitInitializationMode"):
            slave.step()


def test_a_status_the_fmu_does_not_keep_is_discarded_and_the_last_time_is_kept(tire_2d):
    from fmpy.fmi2 import fmi2DoStepStatus, fmi2LastSuccessfulTime

    with TireSlave(tire_2d.path) as slave:
        slave.set([0.0], 0.0)
        slave.step()
        assert slave.slave.getRealStatus(fmi2LastSuccessfulTime) == slave.dt
        with pytest.raises(Exception, match=r"status 2 \(discard\)"):
            slave.slave.getStatus(fmi2DoStepStatus)
        assert slave.messages[-1] == "fmi2GetStatus: this FMU keeps no such status"


@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_a_road_that_is_not_finite_is_an_error_not_a_nan(tire_2d, value):
    with TireSlave(tire_2d.path) as slave:
        slave.set([0.0], 0.0)
        slave.outputs()
        slave.step()
        slave.set([value], 0.0)
        with pytest.raises(FmuError, match=r"road_height\[1\] = .* must be finite"):
            slave.outputs()


def test_a_non_finite_hub_is_an_error(tire_2d):
    with TireSlave(tire_2d.path) as slave, pytest.raises(FmuError, match="hub_displacement = nan"):
        slave.set([0.0], np.nan)
        slave.step()


def test_a_damaged_resource_file_fails_instantiation_with_its_reason(tire_2d, tmp_path):
    damaged = tmp_path / "damaged.fmu"
    with zipfile.ZipFile(tire_2d.path) as source, zipfile.ZipFile(damaged, "w") as target:
        for item in source.infolist():
            data = source.read(item)
            target.writestr(item, data[:-100] if item.filename == "resources/tire.bin" else data)
    with pytest.raises(FmuError, match="truncated or damaged"):
        TireSlave(damaged)


def test_reset_starts_again_as_instantiated(tire_2d):
    n = 300
    heights = cleat_heights(tire_2d.tables, n)
    with TireSlave(tire_2d.path) as slave:
        first = []
        for k in range(n):
            slave.set(heights[[k]], 0.0)
            first.append(slave.outputs()[0])
            slave.step()
        slave.slave.reset()
        slave.slave.setupExperiment(startTime=0.0)
        slave.slave.enterInitializationMode()
        slave.slave.exitInitializationMode()
        slave.time = 0.0
        again = []
        for k in range(n):
            slave.set(heights[[k]], 0.0)
            again.append(slave.outputs()[0])
            slave.step()
        slave.set([1e-3], 5e-4)  # inputs away from their start values when the reset comes
        slave.slave.reset()  # the inputs back at their start values (0): outputs at rest without setting them
        slave.slave.setupExperiment(startTime=0.0)
        slave.slave.enterInitializationMode()
        slave.slave.exitInitializationMode()
        np.testing.assert_array_equal(slave.outputs(), 0.0)
    np.testing.assert_array_equal(again, first)


def test_input_histories_of_the_wrong_shape_are_refused(tire_2d):
    with pytest.raises(ValueError, match="road must be"):
        run_fmu(tire_2d.path, np.zeros((3, 10)))
    with pytest.raises(ValueError, match="hub must have one value per road sample"):
        run_fmu(tire_2d.path, np.zeros(10), np.zeros(9))


def rewrite_resources(source, target, change) -> None:
    """Copy the FMU ``source`` to ``target`` with ``change(bytes) -> bytes`` applied to resources/tire.bin."""
    with zipfile.ZipFile(source) as original, zipfile.ZipFile(target, "w") as copy:
        for item in original.infolist():
            data = original.read(item)
            copy.writestr(item, change(data) if item.filename == "resources/tire.bin" else data)


@pytest.mark.parametrize(
    ("field", "value", "message"),
    [(3, 999_999, "its length is not what its header announces"), (3, 2_000_000, "sizes out of range"),
     (5, -1, "sizes out of range"), (0, 1, "another format version")],
)  # fmt: skip
def test_a_header_out_of_range_or_disagreeing_with_the_file_is_refused(tire_2d, tmp_path, field, value, message):
    """Sizes that would ask for gigabytes, or that the file cannot hold, are refused before any allocation."""

    def change(data: bytes) -> bytes:
        header = np.frombuffer(data, "<i4", 6, 8).copy()
        header[field] = value
        return data[:8] + header.tobytes() + data[32:]

    rewrite_resources(tire_2d.path, tmp_path / "bad.fmu", change)
    with pytest.raises(FmuError, match=message):
        TireSlave(tmp_path / "bad.fmu")


def test_resources_of_another_fmu_are_refused(tire_2d, tire_3d, tmp_path):
    with zipfile.ZipFile(tire_3d.path) as other:
        foreign = other.read("resources/tire.bin")
    rewrite_resources(tire_2d.path, tmp_path / "swapped.fmu", lambda data: foreign)
    with pytest.raises(FmuError, match="belongs to another FMU"):
        TireSlave(tmp_path / "swapped.fmu")


URI_PROBE = r"""
#include "roadnoise_rm_tire.c"
int main(int argc, char **argv) {
    char path[256];
    int k;
    for (k = 1; k < argc; k++) printf("%s\n", uri_to_path(argv[k], path, sizeof path) ? path : "(too long)");
    return 0;
}
"""


def uri_paths(folder, uris: list[str], drive_letters: bool) -> list[str]:
    """``uri_to_path`` of the C source on ``uris``, compiled with the Windows rule or the POSIX one."""
    (folder / "probe.c").write_text(URI_PROBE)
    probe = folder / f"probe_{int(drive_letters)}"
    built = subprocess.run([compiler(), "-std=c99", f"-DROADNOISE_DRIVE_LETTERS={int(drive_letters)}",
                            f"-I{SOURCE_DIR}", f"-I{SOURCE_DIR / 'fmi2'}", "-o", str(probe), str(folder / "probe.c"),
                            "-lm"], capture_output=True, text=True)  # fmt: skip
    assert built.returncode == 0, built.stderr
    return subprocess.run([str(probe), *uris], capture_output=True, text=True, check=True).stdout.splitlines()


@pytest.mark.skipif(compiler() is None, reason="needs a C compiler")
def test_resource_uris_become_paths_on_every_platform(tmp_path):
    """FMI 2.0 passes the resources as a file URI (RFC 8089): POSIX paths, escapes, and on Windows drive
    letters; a path too long for the buffer is refused, not cut."""
    both = {
        "file:///home/a%20b/resources": "/home/a b/resources",
        "file:/home/x/resources": "/home/x/resources",
        "file://localhost/tmp/r": "/tmp/r",
        "file:///tmp/100%zz/r%2": "/tmp/100%zz/r%2",
        "file:///" + "a" * 300: "(too long)",
    }
    windows = {
        "file:///C:/Users/a%20b/resources": "C:/Users/a b/resources",
        "file://localhost/D:/fmu/resources": "D:/fmu/resources",
        "file:///C%3A/fmu": "C:/fmu",
        "file://C:/fmu": "C:/fmu",
    }
    posix = {"file:///a:b/x": "/a:b/x", "file:///a%3Ab/x": "/a:b/x"}
    assert uri_paths(tmp_path, [*both, *windows], True) == [*both.values(), *windows.values()]
    assert uri_paths(tmp_path, [*both, *posix], False) == [*both.values(), *posix.values()]


def test_a_road_input_that_drives_no_tassello_is_refused(tire_3d, tmp_path):
    """Every strip has a tap row: the delay line (16 n_strips n_taps bytes) then stays within twice the file."""

    def change(data: bytes) -> bytes:
        header = np.frombuffer(data, "<i4", 6, 8)
        rows_at = 32 + 64 + 24 + 8 * header[1] + 8 * (header[2] + 1)
        row_strip = np.frombuffer(data, "<i4", header[5], rows_at).copy()
        row_strip[row_strip == 1] = 0  # strip 2's rows moved to strip 1: strip 2 drives nothing
        return data[:rows_at] + row_strip.tobytes() + data[rows_at + row_strip.nbytes :]

    rewrite_resources(tire_3d.path, tmp_path / "bad.fmu", change)
    with pytest.raises(FmuError, match="drives no tassello"):
        TireSlave(tmp_path / "bad.fmu")
