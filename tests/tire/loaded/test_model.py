"""The loaded FE tire through the tire-model interface (``[tire] model = "loaded-fe"``), on the test mesh.

Its load case is carried exactly by a minimum of the potential reached the same whichever path the
load takes; a load it cannot carry, a drum and sticking contact are refused by name; its tire file
is validated like every other; and the RM chain runs on it: the quarter car built on the model is
the one built on its FRFs written to files and read back.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.loaded import loading, road_contact, stages
from roadnoise_utils.tire.loaded.spec import from_dict
from roadnoise_utils.tire.model import NotApplicable


def test_the_load_case_is_carried_by_a_minimum_reached_again_pressed_further_and_lifted_back(
    small_loaded, model_tire, model_inflated, model_state
):
    """The model's state (one 7 mm road step from the inflated tire, then Brent's method) carries its load
    at a minimum; pressed a tenth further and lifted back, the same equilibrium: its contact set and
    every displacement (the load steps' own path independence: the statics' tests)."""
    tire, loaded = model_tire, model_state
    footprint = small_loaded.load(small_loaded.case())
    assert abs(loaded.road_force / small_loaded.default_load - 1) < loading.LOAD_TOLERANCE and loaded.stable
    assert footprint.force_balance() < 1e-9 and footprint.deflection == loaded.road_lift
    further = road_contact.press_on_road(tire, model_inflated, 1.1 * loaded.road_lift, steps=1, start=loaded)
    back = road_contact.press_on_road(tire, model_inflated, loaded.road_lift, steps=1, start=further)
    assert np.array_equal(back.contact, loaded.contact)
    assert np.abs(back.u - loaded.u).max() < 1e-8 * np.abs(loaded.u).max()
    assert np.abs(further.u - loaded.u).max() > 0.05 * np.abs(loaded.u).max()  # a path of its own
    with pytest.raises(ValueError, match="start carries"):
        loading.load_on_road(tire, model_inflated, 500.0, 0.001, start=loaded)


def test_a_load_sweep_continues_each_load_from_the_last(monkeypatch):
    """Each load of a sweep starts from the state of the one before (the first from ``start``)."""
    starts = []

    def landed(tire, inflated, load, road_step, road, start):
        starts.append(start)
        return f"state at {load:g} N"

    monkeypatch.setattr(loading, "load_on_road", landed)
    states = loading.load_sweep(None, None, [1000.0, 2000.0, 3000.0], 0.005, start="start")
    assert states == ["state at 1000 N", "state at 2000 N", "state at 3000 N"]
    assert starts == ["start", "state at 1000 N", "state at 2000 N"]
    for loads in ([1000.0, 900.0], [], [1000.0, 1000.0]):
        with pytest.raises(ValueError, match="increasing"):
            loading.load_sweep(None, None, loads, 0.001)


def test_a_cached_sweep_takes_its_first_load_from_the_load_case_and_continues_from_it(small_loaded, monkeypatch):
    """The sweep's first leg (inflated tire to its first load, flat road) is the same loading as the load case
    at that load: it is taken from that cached stage, the rest continued from it."""
    cases, sweeps = [], []
    monkeypatch.setattr(stages, "cached", lambda stage, inputs, compute, runs=(): compute())
    monkeypatch.setattr(stages, "built_tire", lambda spec: "tire")
    monkeypatch.setattr(stages, "inflated_state", lambda spec: "inflated")
    monkeypatch.setattr(stages, "loaded_state", lambda spec, case: cases.append(case) or f"case at {case.load:g} N")
    monkeypatch.setattr(
        loading, "load_sweep", lambda tire, inflated, loads, step, start: sweeps.append((loads, start)) or loads
    )
    assert stages.swept_states(small_loaded.spec, (600.0, 800.0, 1000.0)) == ["case at 600 N", 800.0, 1000.0]
    assert [(c.road.kind, c.load) for c in cases] == [("flat", 600.0)]
    assert sweeps == [([800.0, 1000.0], "case at 600 N")]
    assert stages.swept_states(small_loaded.spec, (1000.0,)) == ["case at 1000 N"] and len(sweeps) == 1
    with pytest.raises(ValueError, match="increasing"):
        stages.swept_states(small_loaded.spec, (1000.0, 600.0))


def test_a_load_the_tire_cannot_carry_or_a_step_newton_cannot_follow_is_refused_naming_it(tire, inflated, monkeypatch):
    """The statics' refusals (the road reaching the rim, Newton not converging: both tested with the
    statics) restated for the load case: the load and the most the tire carried, or the road step."""
    press = road_contact.press_on_road

    def bottoms_beyond(limit: float, error: Exception):
        def pressed(tire, inflated, lift, road, **options):
            if lift > limit:
                raise error
            return press(tire, inflated, lift, road, **options)

        return pressed

    bottoms = road_contact.TireBottoms("lift = 0.002 m: valid range is (0, 0.0015) m; the road would reach the rim")
    monkeypatch.setattr(road_contact, "press_on_road", bottoms_beyond(0.0015, bottoms))
    with pytest.raises(ValueError, match=r"load = 5000 N: the tire carries at most \d+ N before the road reaches"):
        loading.load_on_road(tire, inflated, 5000.0, 0.001)
    monkeypatch.setattr(road_contact, "press_on_road", bottoms_beyond(0.0015, RuntimeError("did not converge")))
    with pytest.raises(  # 1 -> 2 mm refused, 1 -> 1.5 mm taken; 1.5 -> 2.5, 2 and 1.75 mm refused
        ValueError, match=r"road_step = 0.001 m: the static solve did not follow the road from 1.50 to 1.75 mm"
    ):
        loading.load_on_road(tire, inflated, 5000.0, 0.001)
    monkeypatch.undo()
    for load, step, name in ((1000.0, 0.0, "road_step"), (100.0, 0.001, "load"), (np.nan, 0.001, "load")):
        with pytest.raises(ValueError, match=name):
            loading.load_on_road(tire, inflated, load, step)


def test_a_road_step_newton_does_not_follow_is_halved_and_the_load_still_carried(tire, inflated, monkeypatch):
    """Newton made to fail on any road step longer than 0.6 of ``road_step``: the first step is halved,
    the next goes as far as the secant stiffness asks (a little past the load), and the load is carried
    (that the state does not depend on the steps is tested with the load case's paths)."""
    press = road_contact.press_on_road
    pressed = []

    def follows_half_steps(tire, inflated, lift, road, start, **options):
        if lift - start.road_lift > 0.6 * 0.004:
            raise RuntimeError("did not converge")
        state = press(tire, inflated, lift, road, start=start, **options)
        pressed.append((lift, state.road_force))
        return state

    monkeypatch.setattr(road_contact, "press_on_road", follows_half_steps)
    halved = loading.load_on_road(tire, inflated, 600.0, 0.004)
    monkeypatch.undo()
    (first, carried), (second, passed) = pressed[:2]
    assert first == pytest.approx(0.002, abs=1e-15)  # 4 mm refused, 2 mm taken
    assert second - first == pytest.approx(loading.SECANT_OVERSHOOT * (600.0 - carried) * first / carried, rel=1e-12)
    assert carried < 600.0 < passed < 1.1 * 600.0  # the secant's step passes the load, close to it
    assert abs(halved.road_force - 600.0) < 1e-7 and halved.stable


@pytest.mark.parametrize("exponent", [0.5, 0.25, 0.15])
def test_where_the_tire_softens_the_secant_s_step_falls_short_once_then_road_steps_reach_the_load(
    monkeypatch, exponent
):
    """A force growing like a power of the lift below one (softening: a secant step falls short): one
    secant step, then road steps, no more solves than road steps alone would take plus one. Each step's
    Newton starts on the line through the last two states (here displacements equal to the lift: exact)."""
    lifts, guesses = [], []

    def force(lift: float) -> float:
        return 1000.0 * (lift / 0.01) ** exponent

    def pressed(tire, inflated, lift, start, load, road_step, road, guess):
        lifts.append(lift)
        guesses.append(guess)
        assert len(lifts) < 50, "the steps never pass the load"
        return SimpleNamespace(road_lift=lift, road_force=force(lift), u=np.array([lift]))

    monkeypatch.setattr(loading, "_pressed", pressed)
    monkeypatch.setattr(loading, "_land", lambda tire, inflated, load, below, above, *rest: (below, above))
    inflated = SimpleNamespace(road_lift=0.0, road_force=0.0, u=np.zeros(1))
    below, above = loading.load_on_road(None, inflated, 1500.0, 0.004)
    assert guesses[0] is None  # from the inflated tire: one state known
    assert all(guess == pytest.approx([lift], rel=1e-12) for guess, lift in zip(guesses[1:], lifts[1:]))
    assert below.road_force < 1500.0 <= above.road_force
    steps = np.diff([0.0, *lifts])
    (short,) = np.nonzero(np.abs(steps - 0.004) > 1e-12)[0]  # one step sized by the secant, the others road steps
    before = SimpleNamespace(road_lift=lifts[short - 1], road_force=force(lifts[short - 1]))
    assert steps[short] == pytest.approx(loading._secant_step(before, 1500.0), rel=1e-12) and steps[short] < 0.004
    road_steps_alone = int(np.ceil(0.01 * (1500.0 / 1000.0) ** (1 / exponent) / 0.004))
    assert len(lifts) <= road_steps_alone + 1


def test_sticking_contact_and_what_it_lacks_are_refused_by_name(small_loaded, model_tire):
    with pytest.raises(ValueError, match="stick = True"):
        small_loaded.fixed_hub_frfs(small_loaded.case(), stick=True)
    assert small_loaded.has("modal_reduction") and small_loaded.has("cavity") and small_loaded.has("one_sided_cleat")
    assert not small_loaded.has("released_hub")
    with pytest.raises(NotApplicable, match="released_hub"):
        small_loaded.require("released_hub")
    assert small_loaded.equivalent_dof() == model_tire.n_dof == 4080


@pytest.mark.parametrize(
    "edit, message",
    [
        (lambda d: d["solid_mesh"].update(footprint_arc=0.5), r"footprint_arc = 0.5 m is outside"),
        (lambda d: d["solid_mesh"].update(arcs=6), r"unknown parameter\(s\) \['arcs'\]"),
        (lambda d: d["solid_mesh"].update(crown_elements=3), "crown_elements = 3 must be even"),
        (lambda d: d["construction"].update(file="165_65R14.toml"), "is a 'ring' tire file"),
        (lambda d: d["construction"].update(file="nowhere.toml"), "no such file"),
        (lambda d: d.pop("solid_mesh"), r"missing section\(s\) \['\[solid_mesh\]'\]"),
    ],
)
def test_a_bad_tire_file_is_refused_naming_the_value(edit, message):
    path = ru.repro.paths.data_file("165_65R14_loaded", "tires", "tire file")
    data = ru.repro.paths.read_toml(path)
    edit(data)
    with pytest.raises(ValueError, match=message):
        from_dict(data, source=path.name, folder=path.parent)


def test_replace_reaches_the_construction_and_the_solid_mesh(small_loaded):
    spec = small_loaded.spec.replace(**{"layers.tread.youngs_modulus": 6e6, "solid_mesh.road_step": 0.001})
    assert spec.construction.layers["tread"].youngs_modulus == 6e6 and spec.solid_mesh.road_step == 0.001
    assert spec.construction.mesh.crown_elements == spec.solid_mesh.crown_elements == 4
    with pytest.raises(KeyError, match="solid_mesh.arcs"):
        small_loaded.spec.replace(**{"solid_mesh.arcs": 6})


def test_the_quarter_car_runs_on_it_and_on_its_frfs_written_to_files(small_loaded, tmp_path):
    """The chain's fits, state space and corner on the model, and on its FRFs and footprint written
    as a tire from files and read back (binary UFF 58: exact): the same spectra to 1e-9."""
    files = ru.export_frf_files(small_loaded, tmp_path, [small_loaded.case()], "loaded")
    on_model = ru.experiments.corner_setup(tire=small_loaded)
    on_files = ru.experiments.corner_setup(tire=str(files))
    frfs = small_loaded.fixed_hub_frfs(small_loaded.case())
    band = (frfs.freqs > 0) & (frfs.freqs <= 250.0)  # the fits' band (Eq. 1, the paper's 0-250 Hz)
    fitted = on_model.fits.responses(frfs.freqs[band]).sum(axis=0)
    assert np.abs(fitted - frfs.H_tot[band]).max() < 0.02 * np.abs(frfs.H_tot[band]).max()
    freqs = np.linspace(2.0, 250.0, 125)
    spectrum, speed = ru.textures.load_texture("rough"), 120 / 3.6
    a, b = on_model.predicted(freqs, spectrum, speed), on_files.predicted(freqs, spectrum, speed)
    for name in a:
        assert np.all(np.isfinite(a[name])) and a[name].max() > 0
        assert np.abs(b[name] - a[name]).max() <= 1e-9 * np.abs(a[name]).max(), name
