"""The reduced harmonics' receptance: condensed on the contact DOF and split by the left-right mirror."""

from dataclasses import replace

import numpy as np
import pytest

from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.dynamics import (
    ReducedHarmonic,
    direct_receptance,
    lateral_mirror,
    reduce_harmonic,
)
from roadnoise_utils.tire.cross_section.waveguide import harmonic_weight

TIRE = "165_65R14_cross_section"


@pytest.fixture(scope="module")
def tire():
    return section_stages.section_tire(TIRE)


@pytest.mark.parametrize("n, cutoff", [(1, 1000.0), (12, 1000.0), (150, None)])
def test_the_mirror_split_receptance_is_the_whole_basis_one(tire, n, cutoff):
    """Symmetric and antisymmetric halves solved apart (the dynamic stiffness does not couple them)
    give the receptance of the whole basis; both follow the direct sparse solve at 0 and 200 Hz."""
    mirror = lateral_mirror(tire.ops)
    split = reduce_harmonic(tire.ops, tire.grid.dofs, n, 400.0, cutoff, mirror=mirror)
    assert split.mirror is not None  # the paper's tire is left-right symmetric
    whole = ReducedHarmonic(split.n, split.projected, split.n_modes)
    omegas = 2 * np.pi * np.array([0.0, 200.0])
    a, b = split.receptance(tire.ops.laws, omegas), whole.receptance(tire.ops.laws, omegas)
    assert np.abs(a - b).max() < 1e-9 * np.abs(b).max()
    direct = direct_receptance(tire.ops, tire.grid.dofs, n, omegas[1])
    assert np.abs(a[1] - direct).max() < 2e-3 * np.abs(direct).max()


def test_an_asymmetric_section_has_no_mirror(tire):
    mesh = tire.ops.mesh
    y = mesh.y.copy()
    y[np.argmax(y)] += 1e-3  # one node moved: no mirror image
    moved = replace(tire.ops, mesh=replace(mesh, y=y))
    assert lateral_mirror(moved) is None
    assert lateral_mirror(tire.ops) is not None


def test_the_shared_pattern_gives_the_operators_exactly(tire):
    """Harmonic matrices from the aligned entries equal the sparse sums they replace; the free block
    equals slicing the full matrix."""
    ops, free = tire.ops, tire.ops.free
    for n in (0, 1, 37):
        direct = harmonic_weight(n) * (ops.mass.tocsr())
        assert abs(ops.mass_matrix(n) - direct).max() == 0.0
        k0, k1, k2 = ops.elastic["tread"]
        layers = k0 + n * k1 + n * n * k2
        assert abs(ops.layers("tread", n) - layers).max() <= 1e-12 * abs(layers).max()
        full = ops.stiffness(n, 2 * np.pi * 80.0)
        assert abs(ops.free_stiffness(n, 2 * np.pi * 80.0) - full[free][:, free]).max() == 0.0


def test_the_shared_pattern_ignores_explicitly_stored_zeros():
    """A base matrix may store zeros the union (a sum) drops; even one beyond the union's last entry."""
    import scipy.sparse as sp

    from roadnoise_utils.tire.cross_section.operators import _SharedPattern

    diagonal = sp.csr_matrix(np.diag([1.0, 2.0, 0.0]))
    stored_zero = sp.csr_matrix((np.array([3.0, 0.0]), np.array([0, 2]), np.array([0, 1, 1, 2])), shape=(3, 3))
    pattern = _SharedPattern({"a": diagonal, "b": stored_zero}, np.arange(3))
    assert np.array_equal(pattern.matrix(pattern.data["b"]).toarray(), stored_zero.toarray())
    assert np.array_equal(pattern.free_matrix(pattern.data["a"]).toarray(), diagonal.toarray())


def test_a_harmonic_reduces_to_the_same_bits_every_time(tire):
    """The modes come from ARPACK with a fixed starting vector (its default is random): two reductions of a
    harmonic, and so every FRF of the tire, agree to the last bit, within a process and across processes."""
    mirror = lateral_mirror(tire.ops)
    first, second = (reduce_harmonic(tire.ops, tire.grid.dofs, 1, 400.0, 1000.0, mirror=mirror) for _ in range(2))
    omegas = 2 * np.pi * np.array([0.0, 80.0, 200.0])
    assert np.array_equal(first.receptance(tire.ops.laws, omegas), second.receptance(tire.ops.laws, omegas))
