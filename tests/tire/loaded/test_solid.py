"""The loaded tire's swept mesh, hyperelastic layers and total Lagrangian solids, on a small test tire.

Properties that hold on any mesh: the swept volume converges to the solid of revolution, the
stress is the energy's gradient and the tangent the stress's, a rigid motion strains nothing,
a linear field gives its uniform strain (patch test), and linearised about the round tire the
solids are the waveguide tire of the same file (its modes' Rayleigh quotients converge to its
frequencies at the fourth power of the arc length).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import scipy.linalg as sl
import scipy.sparse.linalg as sla

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section.geometry import section_mesh
from roadnoise_utils.tire.cross_section.laminate import rotate
from roadnoise_utils.tire.cross_section.operators import harmonic_operators
from roadnoise_utils.tire.cross_section.spec import CordLayer
from roadnoise_utils.tire.cross_section.waveguide import harmonic_weight, point_geometry
from roadnoise_utils.tire.loaded import material, solid
from roadnoise_utils.tire.loaded.mesh import GROWTH, graded_arcs, sweep

#: A small cross-section: 4 crown and 2 x 2 sidewall elements (85 nodes per ring).
SMALL = {"mesh.crown_elements": 4, "mesh.sidewall_elements": 2}


@pytest.fixture(scope="module")
def small():
    spec = ru.load_tire("165_65R14_cross_section").replace(**SMALL)
    section, _ = section_mesh(spec)
    return spec, section


def uniform(n_arcs: int) -> np.ndarray:
    return np.linspace(-np.pi, np.pi, n_arcs + 1)


def swept(small, n_arcs: int, arc_points: int = solid.ARC_POINTS):
    spec, section = small
    mesh = sweep(section, uniform(n_arcs))
    return mesh, solid.element_groups(mesh, spec, arc_points)


def test_graded_arcs_are_fine_over_the_footprint_sector_and_grow_gently():
    radius, fine, half, coarse = 0.29, 0.005, 0.3, 0.04
    edges = graded_arcs(radius, fine, half, coarse)
    lengths = np.diff(edges) * radius
    mid = 0.5 * (edges[1:] + edges[:-1])
    assert edges[0] == -np.pi and edges[-1] == np.pi and 0.0 in edges
    np.testing.assert_allclose(lengths, lengths[::-1], rtol=1e-12)  # symmetric about the bottom
    assert lengths[np.abs(mid) < half].max() <= fine * (1 + 1e-12)
    assert lengths.max() <= coarse * (1 + 1e-12)
    ratio = lengths[1:] / lengths[:-1]
    assert np.all(ratio <= GROWTH * (1 + 1e-12)) and np.all(1 / ratio <= GROWTH * (1 + 1e-12))
    with pytest.raises(ValueError, match="fine_length"):
        graded_arcs(radius, 0.05, half, coarse)


def test_the_swept_volume_and_mass_converge_to_the_solid_of_revolution_at_the_fourth_power(small):
    spec, section = small
    geo = point_geometry(section.r, section.y, section.elements, section.points)
    exact_volume = 2 * np.pi * geo.volume.sum()
    exact_mass = 2 * np.pi * (geo.volume * section.points.density).sum()
    errors = []
    for n_arcs in (12, 24):
        _, groups = swept(small, n_arcs, arc_points=3)
        volume = sum(g.volume.sum() for g in groups)
        mass = sum((g.volume * g.density).sum() for g in groups)
        errors.append(abs(volume / exact_volume - 1))
        np.testing.assert_allclose(mass / exact_mass - 1, volume / exact_volume - 1, rtol=1e-6, atol=1e-14)
    assert errors[1] < 2e-5
    assert 12.0 < errors[0] / errors[1] < 20.0  # quadratic arcs: error ~ h^4


def _materials_of_every_kind(small):
    """Laws at the points of one arc: rubber, cord plies rotated into the global axes, tread."""
    spec, _ = small
    _, groups = swept(small, 6)
    return [g.materials for g in groups[:2]]


@pytest.mark.parametrize("scale", [0.02, 0.15])
def test_the_stress_is_the_energy_s_gradient_and_the_tangent_the_stress_s(small, scale):
    rng = np.random.default_rng(1)
    for laws in _materials_of_every_kind(small):
        laws = material.PointMaterials(laws.lam[0, :8], laws.mu[0, :8], laws.fibre[0, :8])
        green = scale * rng.uniform(-1, 1, (8, 6))
        stress, tangent = material.stress_and_tangent(green, laws)
        np.testing.assert_allclose(tangent, np.swapaxes(tangent, -1, -2), rtol=1e-12, atol=1e-6)
        h = 1e-6 * scale
        for k in range(6):
            step = np.zeros(6)
            step[k] = h
            up, down = material.energy(green + step, laws), material.energy(green - step, laws)
            np.testing.assert_allclose((up - down) / (2 * h), stress[:, k], rtol=1e-6, atol=1e-6 * np.abs(stress).max())
            s_up = material.stress_and_tangent(green + step, laws)[0]
            s_down = material.stress_and_tangent(green - step, laws)[0]
            np.testing.assert_allclose(
                (s_up - s_down) / (2 * h), tangent[:, :, k], rtol=1e-6, atol=1e-7 * np.abs(tangent).max()
            )


def test_at_zero_strain_the_tangent_is_the_layer_s_small_strain_stiffness(small):
    spec, section = small
    mesh, groups = swept(small, 6)
    for e, group in enumerate(groups):
        stress, tangent = material.stress_and_tangent(np.zeros(group.materials.lam.shape + (6,)), group.materials)
        assert np.all(stress == 0.0)
        sel = section.points.element == e
        position = np.einsum("qa,maj->mqj", group.shape, mesh.coordinates[mesh.elements[group.elements]])
        theta = np.arctan2(position[..., 0], -position[..., 2])
        local = rotate(tangent, np.swapaxes(solid._model_to_global(theta), -1, -2))
        expected = np.repeat(section.points.stiffness[sel], group.arc_points, axis=0)
        np.testing.assert_allclose(local, np.broadcast_to(expected, local.shape), rtol=0, atol=1e-9 * expected.max())


def test_each_layer_s_remainder_beside_its_rubber_is_positive_semi_definite(small):
    """The Saint Venant-Kirchhoff remainder ``C - C_rubber`` has no negative direction at any point (a
    negative one gives the large-strain law a spurious instability: the cord plies' skim rubber at
    Poisson ratio 0.49 is stiffer in bulk than the ply), and only the cord plies' rubber is softened."""
    spec, _ = small
    _, groups = swept(small, 6)
    for group in groups:
        m = group.materials
        smallest = np.linalg.eigvalsh(m.fibre)[..., 0]
        assert np.all(smallest >= -1e-9 * (m.lam + 2 * m.mu)), smallest.min()
    lowered = {layer: 0 for layer in spec.layers}
    points = section_mesh(spec)[0].points
    for e, group in enumerate(groups):
        names = np.repeat(np.asarray(points.layers)[points.layer[points.element == e]], group.arc_points)
        nominal = np.array([material.rubber_lame(spec.layers[name])[0] for name in names])
        for name in names[np.any(group.materials.lam < nominal * (1 - 1e-12), axis=0)]:
            lowered[name] += 1
    assert {name for name, n in lowered.items() if n} == {
        name for name, layer in spec.layers.items() if isinstance(layer, CordLayer)
    }


def test_the_rubber_s_lambda_is_capped_where_the_layer_is_softer_in_bulk():
    """Closed forms: an isotropic layer keeps its rubber whole; a layer with no bulk coupling beyond the
    rubber's shear keeps none of its lambda; any other split leaves a singular semi-definite remainder."""
    mu = np.full(2, 1e6)
    isotropic = np.zeros((2, 6, 6))
    isotropic[:, :3, :3] = 5e7
    isotropic[:, np.arange(6), np.arange(6)] += np.array([2, 2, 2, 1, 1, 1]) * 1e6
    whole = material.PointMaterials.from_stiffness(isotropic, np.full(2, 5e7), mu)
    np.testing.assert_allclose(whole.lam, 5e7, rtol=1e-12)
    assert np.abs(whole.fibre).max() < 1e-6 * 5e7
    diagonal = np.broadcast_to(np.diag([2e6, 2e6, 2e6, 1e6, 1e6, 1e6]), (2, 6, 6))
    assert np.all(material.PointMaterials.from_stiffness(diagonal, np.full(2, 5e7), mu).lam == 0.0)
    rng = np.random.default_rng(0)
    a = rng.standard_normal((2, 6, 6)) * 1e4
    capped = material.PointMaterials.from_stiffness(a @ np.swapaxes(a, 1, 2) + isotropic, np.full(2, 1e9), mu)
    assert np.all(capped.lam < 1e9)
    smallest = np.linalg.eigvalsh(capped.fibre)[:, :2]
    assert np.all(np.abs(smallest[:, 0]) < 1e-6 * smallest[:, 1])  # singular: lambda is as large as it can be


def test_the_tangent_is_the_derivative_of_the_internal_force(small):
    mesh, groups = swept(small, 6)
    rng = np.random.default_rng(2)
    u = 1e-5 * rng.standard_normal(mesh.n_dof)  # random nodes in plies 1 mm thin: strains up to ~5 %
    assert 0.01 < max(np.abs(solid.green_strain(solid.deformation_gradient(g, u))).max() for g in groups) < 0.2
    v = rng.standard_normal(mesh.n_dof)
    _, k = solid.assemble(groups, u, mesh.n_dof)
    h = 1e-9
    fd = (solid.internal_force(groups, u + h * v, mesh.n_dof) - solid.internal_force(groups, u - h * v, mesh.n_dof)) / (
        2 * h
    )
    assert np.linalg.norm(k @ v - fd) / np.linalg.norm(k @ v) < 1e-6
    assert abs(sl.norm((k - k.T).toarray(), 1)) <= 1e-9 * sl.norm(k.toarray(), 1)


def _linear_field(mesh, matrix, offset):
    return (mesh.coordinates @ matrix.T + offset).ravel()


def test_a_rigid_motion_strains_nothing_and_loads_no_node(small):
    mesh, groups = swept(small, 6)
    angle = np.radians(30.0)
    about_axle = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]])
    u = _linear_field(mesh, about_axle - np.eye(3), np.array([0.01, -0.02, 0.03]))
    for group in groups:
        assert np.abs(solid.green_strain(solid.deformation_gradient(group, u))).max() < 1e-13
    stiffness = solid.assemble(groups, np.zeros(mesh.n_dof), mesh.n_dof)[1]
    reference = np.abs(stiffness @ (1e-3 * np.random.default_rng(3).standard_normal(mesh.n_dof))).max()
    assert np.abs(solid.internal_force(groups, u, mesh.n_dof)).max() < 1e-12 * reference


def test_a_linear_field_gives_its_uniform_strain_and_no_interior_force_in_a_uniform_solid(small):
    """The patch test: distorted, curved 27-node elements reproduce a homogeneous deformation exactly."""
    spec, section = small
    mesh, groups = swept(small, 6)
    gradient = np.array([[0.02, 0.01, -0.005], [0.0, -0.01, 0.004], [0.003, 0.0, 0.015]])
    u = _linear_field(mesh, gradient, np.zeros(3))
    expected = solid.green_strain(np.eye(3) + gradient)
    for group in groups:
        np.testing.assert_allclose(
            solid.green_strain(solid.deformation_gradient(group, u)),
            np.broadcast_to(expected, group.volume.shape + (6,)),
            rtol=0,
            atol=1e-13,
        )
    one_rubber = [
        dataclasses.replace(
            g,
            materials=material.PointMaterials(
                np.full(g.volume.shape, 1e7), np.full(g.volume.shape, 2e6), np.zeros(g.volume.shape + (6, 6))
            ),
        )
        for g in groups
    ]
    force = solid.internal_force(one_rubber, u, mesh.n_dof).reshape(-1, 3)
    stations, rows = np.meshgrid(np.arange(1, section.n_stations - 1), np.arange(1, section.n_rows - 1), indexing="ij")
    inner = mesh.node(np.arange(mesh.theta.size)[:, None], section.node(stations, rows).ravel()[None, :]).ravel()
    assert np.abs(force[inner]).max() < 1e-10 * np.abs(force).max()


def _waveguide_mode(ops, free, n: int, k: int):
    stiffness = sum(ops.elastic[c][0] + n * ops.elastic[c][1] + n * n * ops.elastic[c][2] for c in ops.elastic)
    values, vectors = sl.eigh(
        (harmonic_weight(n) * stiffness)[free][:, free].toarray(),
        (harmonic_weight(n) * ops.mass)[free][:, free].toarray(),
    )
    amplitudes = np.zeros(ops.n_dof)
    amplitudes[free] = vectors[:, k]
    return values[k], amplitudes.reshape(-1, 3)


def test_linearised_about_the_round_tire_the_solids_are_the_waveguide_tire(small):
    """Each harmonic's modes of the waveguide tire (same file, same section mesh, elastic layers only),
    interpolated on the 3-D mesh: their Rayleigh quotients converge to its frequencies at h^4."""
    spec, section = small
    ops = harmonic_operators(section, spec.laws(), spec.operating.inflation_pressure)
    errors = {}
    for n_arcs in (12, 24):
        mesh, groups = swept(small, n_arcs)
        force, k = solid.assemble(groups, np.zeros(mesh.n_dof), mesh.n_dof)
        assert np.all(force == 0.0)
        m = solid.mass_matrix(solid.element_groups(mesh, spec, arc_points=3), mesh.n_dof)
        theta = mesh.theta[:, None]
        for n, mode in ((0, 0), (0, 1), (1, 0), (2, 0)):
            value, a = _waveguide_mode(ops, ops.free, n, mode)
            u_r, u_y = a[:, 0] * np.cos(n * theta), a[:, 2] * np.cos(n * theta)
            u_t = a[:, 1] * (np.sin(n * theta) if n else np.ones_like(theta))
            u = np.stack(
                [u_r * np.sin(theta) + u_t * np.cos(theta), u_y, -u_r * np.cos(theta) + u_t * np.sin(theta)], -1
            )
            u = u.ravel()
            errors.setdefault((n, mode), []).append((u @ (k @ u)) / (u @ (m @ u)) / value - 1)
    for (n, mode), (coarse, fine) in errors.items():
        assert abs(fine) < {0: 1e-5, 1: 1e-4, 2: 3e-2}[n], (n, mode, fine)
        if abs(coarse) > 1e-9:
            assert coarse / fine > 12.0, (n, mode, coarse, fine)  # h^4


def test_no_deformation_escapes_the_stiffness_and_the_mass_refuses_a_reduced_integration(small):
    """On 6 arcs of 60 degrees the lowest frequency (beads clamped) is still above the waveguide tire's
    lowest, its n = 1 mode: no spurious mode; two points around the arc (the mass's integrand is of
    degree four) are refused by the mass."""
    spec, section = small
    mesh, groups = swept(small, 6)
    _, k = solid.assemble(groups, np.zeros(mesh.n_dof), mesh.n_dof)
    m = solid.mass_matrix(groups, mesh.n_dof)
    free = np.setdiff1d(np.arange(mesh.n_dof), (3 * mesh.bead_nodes[:, None] + np.arange(3)).ravel())
    lowest = sla.eigsh(k[free][:, free].tocsc(), 1, m[free][:, free].tocsc(), sigma=0, return_eigenvectors=False)[0]
    ops = harmonic_operators(section, spec.laws(), spec.operating.inflation_pressure)
    waveguide = min(_waveguide_mode(ops, ops.free, n, 0)[0] for n in range(4))
    assert lowest > 0.99 * waveguide
    with pytest.raises(ValueError, match="3 Gauss points"):
        solid.mass_matrix(solid.element_groups(mesh, spec, arc_points=2), mesh.n_dof)


def test_the_acoustic_tensor_s_least_eigenvalue_is_the_shear_modulus_and_rosen_s_limit():
    """Unstrained isotropic rubber: mu over every direction (the shear wave). A fibre along x of
    modulus E_f in rubber of shear modulus mu (lambda = 0), stretched ``s`` along it: along x the
    transverse wave's modulus is mu + S_11 = mu + E_f (s^2 - 1) / 2, negative once the fibre's
    compression exceeds mu (Rosen's micro-buckling of a composite)."""
    rubber = material.PointMaterials(lam=np.array(3e6), mu=np.array(1e6), fibre=np.zeros((6, 6)))
    least = material.least_acoustic_eigenvalue(np.eye(3), rubber, material.half_sphere(300))
    assert abs(least / 1e6 - 1) < 1e-12
    fibre = np.zeros((6, 6))
    fibre[0, 0] = 1e9
    ply = material.PointMaterials(lam=np.array(0.0), mu=np.array(1e6), fibre=fibre)
    for stretch in (1.0, 0.9995, 0.998):
        value = material.least_acoustic_eigenvalue(np.diag([stretch, 1.0, 1.0]), ply, np.array([[1.0, 0.0, 0.0]]))
        assert abs(value - (1e6 + 1e9 * (stretch**2 - 1) / 2)) < 1e-6 * 1e6
    directions = material.half_sphere(50)
    np.testing.assert_allclose(np.linalg.norm(directions, axis=1), 1.0, rtol=1e-14)
    assert np.all(directions[:, 2] > 0)  # one of each pair N, -N


def _ply_along_x(k_cords: float = 1e9, mu: float = 1e6) -> tuple[np.ndarray, np.ndarray]:
    """A layer of neo-Hookean rubber (lambda 3 mu) with cords of stiffness ``k_cords`` along x and a shear
    modulus along them twice the rubber's (a ply's G_LT: 2.1 mu in the file's carcass, 1.5 mu in its
    belts): its small-strain stiffness and cord directions (both families along x, a radial ply's)."""
    stiffness = np.zeros((6, 6))
    stiffness[:3, :3] = 3 * mu
    stiffness[np.arange(6), np.arange(6)] += np.array([2, 2, 2, 1, 2, 2]) * mu
    stiffness[0, 0] += k_cords
    return stiffness, np.array([[1.0, 0.0, 0.0], [1.0, 0.0, 0.0]])


def test_cords_carry_compression_up_to_their_buckling_stress_and_the_ply_stays_elliptic():
    """Closed forms on a ply with cords along x. In tension, the quadratic law exactly; in
    compression the cords' stress levels off at sigma_c = mu / 2 per family, so where the quadratic
    law loses strong ellipticity (its axial stress beyond the ply's shear modulus along the cords:
    Rosen), the ply keeps it: that shear modulus less the cords' limited stress and the rubber's own."""
    stiffness, cords = _ply_along_x()
    quadratic = material.PointMaterials.from_stiffness(stiffness, np.array(3e6), np.array(1e6))
    ply = material.PointMaterials.from_stiffness(stiffness, np.array(3e6), np.array(1e6), cords)
    assert abs(2 * ply.cord_stiffness / 1e9 - material.CORD_SHARE) < 1e-9  # the two families share it
    np.testing.assert_allclose(ply.cord_buckling, material.CORD_BUCKLING_FRACTION * 1e6)
    stretched = material.green_strain(np.diag([1.01, 1.0, 1.0]))
    np.testing.assert_allclose(
        material.stress_and_tangent(stretched, ply)[0], material.stress_and_tangent(stretched, quadratic)[0], rtol=1e-12
    )
    squeezed = np.diag([0.95, 1.0, 1.0])
    rubber_only = material.PointMaterials(lam=ply.lam, mu=ply.mu, fibre=ply.fibre - 1e9 * np.outer(*[np.eye(6)[0]] * 2))
    cord_stress = (
        material.stress_and_tangent(material.green_strain(squeezed), ply)[0][0]
        - (material.stress_and_tangent(material.green_strain(squeezed), rubber_only)[0][0])
    )
    strain = (0.95**2 - 1) / 2
    residual = (1 - material.CORD_SHARE) * 1e9 * strain  # what the buckled cords keep, quadratic
    assert abs(cord_stress - residual - (-2 * material.CORD_BUCKLING_FRACTION * 1e6)) < 1e-9 * 1e6
    along_x = np.array([[1.0, 0.0, 0.0]])
    assert material.least_acoustic_eigenvalue(squeezed, quadratic, along_x) < -1e7  # Rosen: buckled
    assert material.least_acoustic_eigenvalue(squeezed, ply, material.half_sphere(200)) > 0.0


def test_the_cords_stiffness_is_the_rule_of_mixtures_and_its_compression_law_is_consistent(small):
    """Each family's ``k`` of the file's cord plies is V_f E_cord / 2 (the laminate's rule of mixtures
    for E_L) to 0.3 %, computed from the layer's stiffness alone; and in compression the energy's
    gradient is the stress and the stress's the tangent (central differences)."""
    spec, section = small
    mesh, groups = swept(small, 6)
    pts = section.points
    for e, group in enumerate(groups):
        layer = np.repeat(pts.layer[pts.element == e], group.arc_points)
        for index in np.unique(layer):
            ply = spec.layers[pts.layers[index]]
            k = group.materials.cord_stiffness[:, layer == index]
            if isinstance(ply, CordLayer):
                np.testing.assert_allclose(k, ply.cord_volume_fraction * ply.cord_modulus / 2, rtol=3e-3)
            else:
                assert np.all(k == 0.0)
    stiffness, cords = _ply_along_x()
    ply = material.PointMaterials.from_stiffness(stiffness, np.array(3e6), np.array(1e6), cords)
    rng = np.random.default_rng(5)
    for strain in [
        np.array([-4e-4, 1e-3, 0.0, 2e-4, 0.0, -1e-4]),
        2e-3 * rng.standard_normal(6) - [3e-3, 0, 0, 0, 0, 0],
    ]:
        stress, tangent = material.stress_and_tangent(strain, ply)
        h = 1e-8
        for i in range(6):
            step = np.eye(6)[i] * h
            energy = (material.energy(strain + step, ply) - material.energy(strain - step, ply)) / (2 * h)
            assert abs(energy - stress[i]) < 1e-5 * np.abs(stress).max()
            column = (
                material.stress_and_tangent(strain + step, ply)[0] - material.stress_and_tangent(strain - step, ply)[0]
            ) / (2 * h)
            np.testing.assert_allclose(column, tangent[:, i], rtol=0, atol=1e-5 * np.abs(tangent).max())


def test_the_tire_s_laws_are_strongly_elliptic_unstrained(small):
    """At zero strain every layer's stiffness is positive definite, so every acoustic tensor is too."""
    mesh, groups = swept(small, 6)
    assert min(v.min() for v in solid.ellipticity(groups, np.zeros(mesh.n_dof), directions=60)) > 0.0


def test_a_rubber_stiffer_than_its_layer_is_refused_naming_the_layers(small, monkeypatch):
    """A skim rubber whose shear modulus exceeds what its ply holds leaves no positive fibre remainder."""
    spec, section = small
    monkeypatch.setattr(solid, "rubber_lame", lambda layer: (0.0, 1e12))
    with pytest.raises(ValueError, match=r"\[layers\] .*liner.*shear modulus exceeds"):
        solid.element_groups(sweep(section, uniform(6)), spec)
