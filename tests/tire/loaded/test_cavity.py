"""The loaded FE tire's air cavity, on the model's test mesh.

Checked by a second method each: the rings' volumes integrated round the wheel change under
inflation and load as the statics' own cavity volume does (a surface integral over the solids'
faces); the round tire's volume per radian of every ring equals the waveguide's section (the
sweep and the rings' indexing: the same formula on the same section); inflated and
unloaded on equal arcs the tire repeats arc by arc, so its Webster area is the same at every angle; loaded, the
footprint takes area from the cavity under it, the first doublet splits, and more load splits it more.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.cavity import webster_modes
from roadnoise_utils.tire.cross_section.cavity import section_area
from roadnoise_utils.tire.cross_section.static import build_section_tire
from roadnoise_utils.tire.loaded import cavity, pressure, statics
from roadnoise_utils.tire.model import NotApplicable


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


def test_its_frfs_refuse_a_cavity_they_do_not_couple(small_loaded):
    with_air = small_loaded.replace(**{"cavity.enabled": True})
    with pytest.raises(NotApplicable, match="not applicable: cavity"):
        with_air.fixed_hub_frfs(with_air.case(), np.array([0.0]))
