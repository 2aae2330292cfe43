"""The cross-section tire's air cavity: its section, its wall's volume change and the loaded split."""

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import cavity as cavity_test
from roadnoise_utils.tire.cross_section import cavity as section_cavity
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.static import loaded_displacement, solve_section_static, solve_section_statics
from roadnoise_utils.tire.cross_section.waveguide import lagrange3, pressure_operators

TIRE = "165_65R14_cross_section"


@pytest.fixture(scope="module")
def tire():
    return section_stages.section_tire(TIRE)


def _section_polygon(tire, displacement=None, samples=200):
    """The cavity's section as a dense polygon (r, y): the inner face's quadratic lines sampled, moved
    by ``displacement`` (n_nodes, 3) if given, then the rim's closing at the bead-seat radius."""
    mesh = tire.mesh
    r, y = mesh.r.copy(), mesh.y.copy()
    if displacement is not None:
        r, y = r + displacement[:, 0], y + displacement[:, 2]
    shape, _ = lagrange3(np.linspace(-1.0, 1.0, samples))
    lines = mesh.face_lines(0)
    points = np.concatenate([np.stack([shape.T @ r[line], shape.T @ y[line]], axis=1)[:-1] for line in lines])
    points = np.vstack([points, [r[lines[-1, -1]], y[lines[-1, -1]]]])
    base = tire.spec.geometry.rim_radius
    return np.vstack([points, [base, points[-1, 1]], [base, points[0, 1]]])


def _area_and_volume(polygon):
    """Area and volume per radian (the integral of r dA) of a closed polygon (r, y), by its edges."""
    r1, y1 = polygon[:, 0], polygon[:, 1]
    r2, y2 = np.roll(r1, -1), np.roll(y1, -1)
    area = 0.5 * np.sum(r1 * y2 - r2 * y1)
    volume = np.sum((y2 - y1) * (r1**2 + r1 * r2 + r2**2)) / 6.0
    return abs(area), abs(volume)


def test_the_section_is_the_contour_closed_by_the_rim(tire):
    area, volume = section_cavity.section_area(tire)
    polygon_area, polygon_volume = _area_and_volume(_section_polygon(tire))
    assert abs(area / polygon_area - 1.0) < 1e-6
    assert abs(volume / polygon_volume - 1.0) < 1e-6
    cavity = section_cavity.section_cavity(tire).cavity
    assert cavity.area == pytest.approx(area, rel=1e-12)
    assert cavity.mean_radius == pytest.approx(volume / area, rel=1e-12)
    assert 2e-2 > cavity.volume > 1e-2  # m^3: a 165/65 R14 holds ~17 L


def test_the_wall_vector_is_the_first_variation_of_the_cavity_volume(tire):
    """The Eulerian volume change of the wall equals the pressure load's first variation
    (:func:`roadnoise_utils.tire.cross_section.waveguide.pressure_operators`, the divergence form) on every DOF off the beads:
    two derivations, the same vector; and it carries no circumferential DOF."""
    mesh = tire.mesh
    wall = section_cavity.wall_volume(tire)
    first, _, _ = pressure_operators(mesh.r, mesh.y, mesh.face_lines(0), mesh.n_dof)
    free = tire.ops.free
    assert np.abs(wall[free] - first[free]).max() < 1e-12 * np.abs(first).max()
    assert np.all(wall[1::3] == 0.0)


def test_the_loaded_area_is_the_deformed_section(tire):
    """The harmonic sum of the wall's volume change against the section deformed by the loaded
    displacement (:func:`roadnoise_utils.tire.cross_section.static.loaded_displacement`) and measured as a polygon,
    at the footprint, beside it and at the top (the displacement scaled down: the linear change)."""
    static = ru.stages.solve_static(TIRE, "flat")
    cavity = section_cavity.section_cavity(tire)
    area = section_cavity.loaded_area(tire, static, cavity=cavity)
    nodes = np.array([0, 24, 360])  # of 720: theta = 0, 12 deg, 180 deg
    theta = 2.0 * np.pi * nodes / area.size
    displacement = loaded_displacement(tire, static, theta)
    _, reference = _area_and_volume(_section_polygon(tire))
    scale = 1e-4
    for k, node in enumerate(nodes):
        _, moved = _area_and_volume(_section_polygon(tire, scale * displacement[k]))
        expected = (moved - reference) / scale / cavity.cavity.mean_radius
        assert abs((area[node] - cavity.cavity.area) - expected) < 1e-4 * abs(area[0] - cavity.cavity.area)
    assert area[0] < cavity.cavity.area  # the footprint takes air out of the section


def test_several_loads_share_one_compliance(tire):
    states = solve_section_statics(tire, "flat", (3000.0, 5000.0))
    alone = solve_section_static(tire, "flat", 5000.0)
    np.testing.assert_array_equal(states[1].contact_force, alone.contact_force)
    assert states[1].deflection == alone.deflection
    both = section_cavity.loaded_areas(tire, states)
    np.testing.assert_allclose(both[1], section_cavity.loaded_area(tire, alone), rtol=1e-13)


def test_the_loaded_doublet_splits_as_measured():
    """At the 195/65 R15's 4000 N the fore-aft mode sits below the vertical one, apart by the measured
    2-14 Hz of passenger tires (Choi & Bolton 2020, 2026); the split grows with the load, nearly in
    proportion (a linear tire), and the first-order formula of :mod:`.tire.cavity` follows it."""
    table = cavity_test.split_against_load(cavity_test.cavity_conditions("195_65R15_cross_section"))
    rated = table.set_index("load (N)").loc[4000.0]
    assert rated["fore-aft (Hz)"] < rated["vertical (Hz)"]
    assert 2.0 < rated["split (Hz)"] < 14.0
    assert np.all(np.diff(table["split (Hz)"]) > 0)
    assert 0.9 < cavity_test.load_exponent(table) < 1.1
    np.testing.assert_allclose(table["first-order split (Hz)"], table["split (Hz)"], rtol=0.06)


def test_a_bad_cavity_table_is_refused():
    spec = section_stages.load_section_tire(TIRE)
    with pytest.raises(ValueError, match="damping_ratio"):
        spec.replace(**{"cavity.damping_ratio": -0.1})


def test_the_stages_that_do_not_carry_the_cavity_refuse_it():
    spec = section_stages.load_section_tire(TIRE).replace(**{"cavity.enabled": True})
    with pytest.raises(ValueError, match="enabled = false"):
        section_stages.harmonic_reductions(spec)  # the time stepping
    with pytest.raises(ValueError, match="enabled = false"):
        section_stages.section_modal(spec, section_stages.nominal_case(spec))
