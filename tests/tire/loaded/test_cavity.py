"""The loaded FE tire's air cavity, on the model's test mesh.

Checked by a second method each: the rings' volumes integrated round the wheel change under
inflation and load as the statics' own cavity volume does (a surface integral over the solids'
faces); the round tire's volume per radian of every ring equals the waveguide's section (the
sweep and the rings' indexing: the same formula on the same section); inflated and
unloaded on equal arcs the tire repeats arc by arc, so its Webster area is the same at every angle; loaded, the
footprint takes area from the cavity under it, the first doublet splits, and more load splits it more.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from roadnoise_utils.repro.cache import cache_key
from roadnoise_utils.tire.cavity import RollingFlow, webster_modes
from roadnoise_utils.tire.cross_section.cavity import section_area
from roadnoise_utils.tire.cross_section.static import build_section_tire
from roadnoise_utils.tire.loaded import cavity, dynamics, pressure, stages, statics
from roadnoise_utils.tire.loaded.direct import footprint_frf_direct


def _total_volume(tire, u) -> float:
    """The rings' volume per radian integrated round the wheel (Simpson on each quadratic arc), the rim's
    base added back: the volume between the axle and the inner surface, as the statics measure it."""
    angle, volume = cavity.ring_volumes(tire, u)
    angle, volume = np.append(angle, angle[0] + 2.0 * np.pi), np.append(volume, volume[0])
    simpson = sum(
        (angle[i + 2] - angle[i]) / 6.0 * (volume[i] + 4.0 * volume[i + 1] + volume[i + 2])
        for i in range(0, angle.size - 2, 2)
    )
    section = tire.mesh.section
    ends = section.face_lines(0)[[0, -1], [0, -1]]
    base = tire.spec.geometry.rim_radius
    return simpson + np.pi * base**2 * abs(section.y[ends[1]] - section.y[ends[0]])


def test_the_rings_volume_changes_are_the_statics_cavity_volume_s(model_tire, model_inflated, model_state):
    """Second method: the statics' own cavity volume (a surface integral over the quadratic faces,
    :func:`.pressure.cavity_volume`) changes by the same amount under inflation and under load (within
    2 %; the test mesh's 377 mm arcs make its round torus 0.46 % small, which cancels in the changes)."""
    states = [np.zeros(model_tire.n_dof), model_inflated.u, model_state.u]
    rings = np.array([_total_volume(model_tire, u) for u in states])
    solids = np.array([pressure.cavity_volume(model_tire.mesh, model_tire.surface, u) for u in states])
    assert np.abs(np.diff(rings) / np.diff(solids) - 1.0).max() < 0.02
    assert np.diff(solids)[0] > 0 > np.diff(solids)[1]  # inflation grows the cavity, the footprint takes from it


def test_the_round_rings_hold_the_waveguide_section_s_volume(model_tire):
    angle, volume = cavity.ring_volumes(model_tire, np.zeros(model_tire.n_dof))
    reference = section_area(build_section_tire(model_tire.spec))[1]
    assert np.abs(volume / reference - 1.0).max() < 1e-12
    assert np.all(np.diff(angle) > 0)  # the rings in their order round the wheel
    assert np.allclose(angle, np.sort(model_tire.mesh.theta), atol=1e-12)


def test_inflated_the_area_is_the_same_all_round_up_to_the_arcs_discretisation(tire, inflated):
    """Inflated and unloaded the tire is axisymmetric: its Webster area varies round the wheel only by
    the quadratic arcs' error (end and mid rings of an arc), which halving the arcs cuts by more than
    16x (measured: 33x from 6 to 12 equal arcs); the pressure pushes the inner surface outward."""
    finer = statics.build_loaded_tire(tire.spec, np.linspace(-np.pi, np.pi, 13))
    variation = []
    for model, state in ((tire, inflated), (finer, statics.inflate(finer))):
        area = cavity.webster_area(model, state)
        assert area.min() > cavity.air_cavity(model.spec).area
        variation.append(np.ptp(area) / area.mean())
    assert variation[0] < 1e-4 and variation[1] < variation[0] / 16


def test_loaded_the_footprint_takes_area_and_splits_the_doublet(small_loaded):
    loads = (600.0, small_loaded.default_load)
    footprints, areas = small_loaded.loaded_cavity_areas(loads)
    air = small_loaded.air_cavity()
    assert [f.load for f in footprints] == list(loads)
    assert np.all(np.argmin(areas, axis=1) == 0)  # the least area under the footprint's centre
    splits = [np.subtract(*webster_modes(air, a).split()[::-1]) for a in areas]
    assert 0.0 < splits[0] < splits[1]


# ---------------------------------------------------------------- the air coupled into the FRFs


@pytest.fixture(scope="module")
def coupling(model_tire, model_state):
    return cavity.loaded_coupling(model_tire, model_state)


@pytest.fixture(scope="module")
def linearised(model_tire, model_state):
    return dynamics.linearise(model_tire, model_state)


def test_the_wall_is_the_derivative_of_the_cavity_s_volume(model_tire, model_state, coupling):
    """Second method: the statics' exact cavity volume (:func:`.pressure.cavity_volume`) differentiated
    by central differences along a random motion of the free nodes: the wall's rows sum to it."""
    motion = np.random.default_rng(0).standard_normal(model_tire.n_dof)
    motion[model_tire.fixed] = 0.0
    step = 1e-6  # m: the volume's third-order terms below 1e-8 of the derivative, its round-off below 1e-8
    volume = [
        pressure.cavity_volume(model_tire.mesh, model_tire.surface, model_state.u + e * motion) for e in (-step, step)
    ]
    derivative = (volume[1] - volume[0]) / (2.0 * step)
    assert (coupling.wall @ motion).sum() == pytest.approx(derivative, rel=1e-6)


def test_a_rigid_translation_keeps_the_volume_and_moves_the_air_as_the_area_says(model_tire, coupling):
    """A vertical translation of the whole wheel (every node, the rim's base with it) leaves the cavity's
    volume unchanged: the uniform mode feels nothing (the surface's and the rim's shares each vanish
    over the circle). Seen from the fixed angles it shifts the section: by the divergence theorem the
    volume change per radian is :math:`-(A\\cos\\phi + A'\\sin\\phi)`, so the first even mode's value
    is the area's projection (within 2 %: the test mesh's 45-degree arcs sample the surface at 24
    angles; measured 0.8 %). That weighs the rim's share against the surface's: without the rim the
    value would be 2.5 times the projection, with its sign turned 4 times."""
    translation = np.zeros(model_tire.n_dof)
    translation[2::3] = 1.0
    modal = coupling.volume.T @ translation
    scale = np.abs(coupling.volume).sum(axis=0)
    assert abs(modal[0]) < 1e-12 * scale[0]  # the volume, unchanged
    step = 2.0 * np.pi / coupling.area.size
    phi = step * np.arange(coupling.area.size)
    area = coupling.area
    shift = -(area * np.cos(phi) + np.gradient(area, step) * np.sin(phi)) * step
    even = 1 if coupling.modes.parity[1] > 0 else 2  # the first doublet's vertical (even) mode
    assert coupling.modes.parity[even] == 1 and coupling.modes.parity[3 - even] == -1
    assert modal[even] == pytest.approx(coupling.modes.shapes[even] @ shift, rel=0.02)
    assert abs(modal[3 - even]) < 1e-9 * abs(modal[even])  # the odd (fore-aft) mode: no vertical share


def test_reduced_coupled_frfs_equal_the_direct_coupled_solve(linearised, coupling):
    """Second method: every DOF solved with the air by Woodbury's identity on the sparse factor, against
    the reduced basis that carries the air's static load: within 1e-3 of the largest transfer at each
    frequency, through the doublet (measured 4.5e-4, as the reduction without air)."""
    split = coupling.modes.freqs[1:3]
    freqs = np.array([0.0, 50.0, 150.0, split[0] - 1.0, split.mean(), split[1] + 1.0, 400.0])
    direct = footprint_frf_direct(linearised, freqs, cavity=coupling)
    reduced = dynamics.footprint_frf(linearised, freqs, cavity=coupling)
    scale = np.abs(direct.hub).max(axis=1)
    assert np.all(np.abs(reduced.hub - direct.hub).max(axis=1) < 1e-3 * scale)
    assert np.all(np.abs(reduced.G_H - direct.G_H) < 1e-3 * np.abs(direct.G_H))


def test_streaming_air_is_refused_by_name(linearised, coupling):
    """The loaded tire's solves use the modes' gains at rest: a coupling whose air streams is refused."""
    modes = coupling.omegas.size
    flow = RollingFlow(1.0, np.zeros((modes, modes)), np.zeros_like(coupling.volume), np.zeros_like(coupling.volume))
    streaming = replace(coupling, flow=flow)
    for solve in (footprint_frf_direct, dynamics.footprint_frf):
        with pytest.raises(ValueError, match="cavity.flow: the loaded FE tire's air is at rest"):
            solve(linearised, np.array([10.0]), cavity=streaming)


def test_at_rest_the_air_stiffens_the_tire_by_its_compressibility(model_tire, model_state, linearised, coupling):
    """Closed form at rest: only the uniform pressure is left, :math:`p = -\\kappa\\,\\Delta V`,
    :math:`\\kappa = \\rho c^2 / V_0` (:math:`V_0` the waveguide's volume), so the hub feels
    :math:`-\\kappa s^2 / (1 + \\kappa Q)` more, :math:`s` the volume change per unit hub motion with
    the footprint held (central differences of the statics' exact volume along the static shape,
    the rim held: a translation changes nothing) and :math:`Q` the wall's compliance to pressure."""
    reduced = dynamics.reduce(linearised, 10.0, keep_basis=True)
    hub_shape = reduced.basis[:, reduced.n_boundary - 1]
    translation = np.zeros(model_tire.n_dof)
    translation[2::3] = 1.0
    motion = (hub_shape - translation) * 1e-4
    volume = [pressure.cavity_volume(model_tire.mesh, model_tire.surface, model_state.u + e * motion) for e in (-1, 1)]
    s = (volume[1] - volume[0]) / 2e-4
    wall = np.asarray(coupling.wall.sum(axis=0)).ravel()[linearised.free]
    stiffness = linearised.stiffness(0.0).real.tocsc()[linearised.free][:, linearised.free]
    q = wall @ spla.spsolve(stiffness, wall)
    air = cavity.air_cavity(model_tire.spec)
    kappa = (
        air.density * air.sound_speed**2 / (air.mean_radius * coupling.area.sum() * 2.0 * np.pi / coupling.area.size)
    )
    plain = footprint_frf_direct(linearised, np.array([0.0]))
    coupled = footprint_frf_direct(linearised, np.array([0.0]), cavity=coupling)
    assert (coupled.G_H - plain.G_H)[0].real == pytest.approx(-kappa * s**2 / (1.0 + kappa * q), rel=1e-6)
    assert 0.0 < kappa * s**2 < 0.01 * abs(plain.G_H[0])  # stiffer, by a fraction of a per cent on this mesh


def test_the_model_couples_the_air_where_its_file_enables_it(small_loaded, coupling):
    """The model's FRFs with ``[cavity] enabled`` (on the static state of the tire without its air): the
    air's stiffness at rest, the cavity's resonance in the total transfer between the loaded doublet's
    modes."""
    with_air = small_loaded.replace(**{"cavity.enabled": True})
    keys = [cache_key("loaded_state", {"tire": stages.without_air(m.spec)}, "") for m in (small_loaded, with_air)]
    assert keys[0] == keys[1]  # the air does not touch the statics: one static state for both
    freqs = np.arange(0.0, 301.0)
    plain, coupled = (model.fixed_hub_frfs(model.case(), freqs) for model in (small_loaded, with_air))
    assert coupled.G_H[0].real < plain.G_H[0].real < 0.0
    band = (freqs > 200.0) & (freqs < 280.0)
    gain = np.abs(coupled.H_tot[band]) / np.abs(plain.H_tot[band])
    peak = freqs[band][np.argmax(gain)]
    low, high = coupling.modes.freqs[1:3]
    assert low - 3.0 <= peak <= high + 3.0 and gain.max() > 2.0
