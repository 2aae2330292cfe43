"""Hyperelastic layers of the loaded tire, consistent with the cross-section tire's small-strain moduli.

Every integration point carries the stiffness ``C`` of its ply (:mod:`~roadnoise_utils.tire.cross_section.laminate`:
isotropic rubber, transversely isotropic cord-rubber plies, the smeared tread blocks). For large
deformations it is split into the layer's rubber, a compressible neo-Hookean solid with the
rubber's Lamé constants (a cord ply's ``lambda`` lowered where the ply is softer in bulk than its
skim rubber, so that the remainder below has no negative direction: :meth:`PointMaterials.from_stiffness`),

.. math:: W_r = \\tfrac{\\mu}{2}(I_1 - 3) - \\mu\\ln J + \\tfrac{\\lambda}{2}(\\ln J)^2,

and what the cords (or the tread's block geometry) add, ``C_f = C - C_rubber``, a
Saint Venant-Kirchhoff term :math:`W_f = \\tfrac12 E:C_f:E` in the Green-Lagrange strain ``E``
(Holzapfel, *Nonlinear Solid Mechanics*, 2000, sec. 6.4 and 6.5; fibre-reinforced rubber as a
matrix plus a fibre energy: Holzapfel, Gasser & Ogden, J. Elasticity 61, 2000). At zero strain
the tangent is exactly ``C``, so the linearised tire about the round, unloaded state is the
cross-section tire; the cords stretch little, so their quadratic energy is where it is accurate,
while the rubber takes the large strains.

Cords in compression. A quadratic fibre energy carries compression as stiffly as tension, and a
ply compressed along its cords by more than its shear stiffness loses strong ellipticity (Rosen's
micro-buckling: the compressive strength of a fibre composite is its shear modulus, Rosen, *Fibre
Composite Materials*, ASM 1965, ch. 3): the tread's belts and carcass under the footprint edge
reach that at a few millimetres of deflection, where the discrete tangent then turns indefinite
at loads that depend on the mesh. Tire cords buckle in compression (textile cords at once, steel
cords by their strands), and netting analyses of the tire let them carry tension only (Purdy,
*Mathematics Underlying the Design of Pneumatic Tyres*, 1963). So each of a ply's two cord families (``+beta`` and ``-beta``, the balanced
ply's halves) carries, along its own Green strain :math:`e = a\\cdot E a`, the quadratic energy in
tension and a stress that levels off in compression,

.. math:: \\sigma(e) = k\\,e \\;(e \\ge 0), \\qquad \\sigma(e) = k\\,e_c \\tanh(e / e_c) \\;(e < 0),
          \\qquad k\\,e_c = \\sigma_c = \\tfrac12 \\mu,

at most half the skim rubber's shear modulus per family (:data:`CORD_BUCKLING_FRACTION`), so that
both families together stay below the ply's shear stiffness and the compressed ply stays strongly
elliptic up to large compressions (what the buckled cords keep, :data:`CORD_SHARE`, still grows
with the strain: the 165/65 R14 file's belts lose it at 9.2 % compression along their cords and
6.9 % in both in-plane directions, the carcass and the cap beyond 20 %). ``k`` is nearly all the stiffness the ply has along its cords beyond its rubber
(:data:`CORD_SHARE`; for the 165/65 R14 file's plies within 0.2 % of the rule of mixtures'
:math:`V_f E_{cord} / 2` per family): buckled cords leave the ply its skim's stiffness. The law is :math:`C^2` in the stress at ``e = 0``: at
zero and tensile cord strain it is the quadratic law above, its tangent exactly ``C``.

Voigt order ``[11, 22, 33, 23, 13, 12]`` with engineering shear strains, as the laminate.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..cross_section.laminate import VOIGT
from ..cross_section.spec import CordLayer, RubberLayer, TreadLayer

#: Poisson ratio of the skim rubber of a cord ply (the laminate's own Halpin-Tsai assumption).
MATRIX_POISSON = 0.49

#: Compressive stress a cord family carries at most, as a fraction of its skim rubber's shear
#: modulus: two families at one half stay below the ply's shear stiffness (Rosen's limit, whose
#: in-plane shear modulus ``G_LT`` exceeds the skim's), so the compressed ply stays elliptic.
CORD_BUCKLING_FRACTION = 0.5

#: Share of the largest stiffness along the cords that a cord family gives up when it buckles: the
#: largest leaves the remainder singular, and the rubber's ``lambda`` would have to drop to zero;
#: 0.999 keeps it within 1 % of its value without cords' compression (a 165/65 R14 belt keeps
#: 0.1 % of its cords' stiffness when buckled, 15 MPa, the order of its skim rubber's 8 MPa).
CORD_SHARE = 0.999


def rubber_lame(layer: RubberLayer | CordLayer | TreadLayer) -> tuple[float, float]:
    """Lamé constants ``(lambda, mu)`` (Pa) of the rubber of a construction layer.

    Rubber: its own modulus and Poisson ratio. Cord ply: the skim rubber (``matrix_modulus``,
    Poisson ratio :data:`MATRIX_POISSON`). Tread: the blocks' shear modulus ``E (1 - void) / 3``
    and no Lamé coupling (the smeared blocks' stiffness is diagonal: grooves let them bulge).
    """
    if isinstance(layer, RubberLayer):
        e, nu = layer.youngs_modulus, layer.poisson
    elif isinstance(layer, CordLayer):
        e, nu = layer.matrix_modulus, MATRIX_POISSON
    elif isinstance(layer, TreadLayer):
        return 0.0, layer.youngs_modulus * (1.0 - layer.void_ratio) / 3.0
    else:
        raise TypeError(f"layer of type {type(layer).__name__}: expected a rubber, cord or tread layer")
    return e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))


@dataclass(frozen=True, eq=False)
class PointMaterials:
    r"""The hyperelastic law at a set of points (arrays over any leading shape ``...``).

    Attributes
    ----------
    lam, mu : ndarray (...)
        Lamé constants of the neo-Hookean rubber (Pa).
    fibre : ndarray (..., 6, 6)
        The Saint Venant-Kirchhoff remainder ``C - C_rubber`` in the global axes (Pa).

    cords : ndarray (..., 2, 6) or None
        Voigt vectors :math:`a \otimes a` of the two cord families' reference directions (shears
        ``a_i a_j``): the cord strain is ``cords @ E``. None: no cords.
    cord_stiffness, cord_buckling : ndarray (...) or None
        Each family's stiffness ``k`` along its cords and its compressive stress limit
        :math:`\sigma_c` (Pa); zero stiffness where a point has no cords.
    """

    lam: np.ndarray
    mu: np.ndarray
    fibre: np.ndarray
    cords: np.ndarray | None = None
    cord_stiffness: np.ndarray | None = None
    cord_buckling: np.ndarray | None = None

    @classmethod
    def from_stiffness(
        cls,
        stiffness: np.ndarray,
        lam: np.ndarray,
        mu: np.ndarray,
        cords: np.ndarray | None = None,
    ) -> PointMaterials:
        r"""Split the small-strain ``stiffness`` (..., 6, 6) into the rubber of ``lam, mu`` and the rest.

        The remainder must be positive semi-definite: a Saint Venant-Kirchhoff energy with a negative
        direction has no stable large-strain response, and a cord ply's own transverse bulk stiffness
        (the laminate's) is lower than its skim rubber's at Poisson ratio 0.49 (-131 MPa and -201 MPa
        along one direction of the carcass and the belts). Where it would not be, ``lam`` is lowered
        to the largest value that keeps it so, :math:`\lambda = 1 / (m^T A^{+} m)` with
        :math:`A = C - 2\mu I` and :math:`m = [1, 1, 1, 0, 0, 0]`; the sum, and so the small-strain
        stiffness, is unchanged.

        ``cords`` (..., 2, 3): the unit reference directions of each point's two cord families
        (equal for a radial ply; zero vectors where a point has none). Each family gets the
        compression law of the module notes, with ``k`` the share :data:`CORD_SHARE` of the largest
        stiffness along the cords that the layer holds beyond its rubber's shear (so that fully
        buckled cords leave a semi-definite remainder), and ``lam`` is lowered for that too.
        """
        lam, mu = np.asarray(lam, float), np.asarray(mu, float)
        if cords is None:
            lam = np.minimum(lam, _largest_lambda(stiffness, mu))
            return cls(lam=lam, mu=mu, fibre=stiffness - _isotropic(lam, mu, stiffness.shape))
        vectors = cord_vectors(cords)
        shear_part = stiffness - _isotropic(np.zeros_like(mu), mu, stiffness.shape)
        k = CORD_SHARE * _largest_cord_stiffness(shear_part, vectors)
        buckled = stiffness - np.einsum("...,...fi,...fj->...ij", k, vectors, vectors)
        lam = np.minimum(lam, _largest_lambda(buckled, mu))
        return cls(
            lam=lam,
            mu=mu,
            fibre=stiffness - _isotropic(lam, mu, stiffness.shape),
            cords=vectors,
            cord_stiffness=k,
            cord_buckling=np.where(k > 0.0, CORD_BUCKLING_FRACTION * mu, 0.0),
        )


def cord_vectors(directions: np.ndarray) -> np.ndarray:
    r"""Voigt vectors (..., 6) of :math:`a \otimes a` for directions (..., 3): ``[a1^2, a2^2, a3^2, a2 a3, a1 a3, a1 a2]``.

    With engineering shear strains, the strain along ``a`` is the dot product with ``E`` (Voigt).
    """
    a = np.asarray(directions, float)
    return np.stack([a[..., i] * a[..., j] for i, j in VOIGT], axis=-1)


def _largest_cord_stiffness(stiffness: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """The largest ``k`` (Pa) with ``stiffness - k (v_1 v_1^T + v_2 v_2^T)`` positive semi-definite.

    ``1 / lambda_max(V^T stiffness^+ V)`` with ``V = [v_1, v_2]`` (the cords' Voigt vectors). Zero
    where the vectors are zero (no cords) or leave the stiffness's range (nothing to take out).
    """
    values, basis = np.linalg.eigh(stiffness)
    floor = 1e-9 * np.maximum(np.abs(values).max(axis=-1, keepdims=True), 1e-300)
    kept = values > floor
    inverse = np.where(kept, 1.0 / np.where(kept, values, 1.0), 0.0)
    along = np.einsum("...ji,...fj->...if", basis, vectors)  # (..., eigenvector, family)
    outside = np.einsum("...if,...i->...", along**2, np.where(kept, 0.0, 1.0)) > 1e-12
    gram = np.einsum("...if,...i,...ig->...fg", along, inverse, along)
    largest = np.linalg.eigvalsh(gram)[..., -1]
    has_cords = (largest > 0.0) & ~outside
    return np.where(has_cords, 1.0 / np.where(has_cords, largest, 1.0), 0.0)


def _cord_law(strain: np.ndarray, stiffness: np.ndarray, buckling: np.ndarray) -> tuple[np.ndarray, ...]:
    r"""Each family's energy, stress and tangent (Pa) less the quadratic ``k e^2 / 2``: zero in tension.

    In compression :math:`\sigma = k e_c \tanh(e / e_c)` with :math:`e_c = \sigma_c / k`, whose
    energy is :math:`k e_c^2 \ln\cosh(e / e_c)`.
    """
    limit = np.where(stiffness > 0.0, buckling / np.where(stiffness > 0.0, stiffness, 1.0), 1.0)
    x = np.minimum(strain, 0.0) / limit
    tanh = np.tanh(x)
    log_cosh = -x + np.log1p(np.exp(2.0 * x)) - np.log(2.0)  # x <= 0: no overflow
    k = stiffness
    e = np.minimum(strain, 0.0)
    energy = k * (limit**2 * log_cosh - 0.5 * e**2)
    stress = k * (limit * tanh - e)
    tangent = k * ((1.0 - tanh**2) - 1.0)
    return energy, stress, tangent


def _isotropic(lam: np.ndarray, mu: np.ndarray, shape: tuple) -> np.ndarray:
    """Isotropic stiffness (..., 6, 6) of Lamé constants ``lam, mu``, Voigt with engineering shears."""
    rubber = np.zeros(shape)
    rubber[..., :3, :3] = lam[..., None, None]
    idx = np.arange(6)
    rubber[..., idx, idx] += np.where(idx < 3, 2.0, 1.0) * mu[..., None]
    return rubber


def _largest_lambda(stiffness: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """The largest ``lam`` with ``stiffness - C_iso(lam, mu)`` positive semi-definite (Pa): ``1 / (m^T A^+ m)``.

    ``A`` (the stiffness less the rubber's shear part) is semi-definite, singular for a rubber
    layer (``A = lam m m^T``), so its pseudo-inverse on the eigenvalues above round-off; where
    ``m`` has a part in ``A``'s null space no positive ``lam`` keeps the remainder so: 0.
    """
    shear_part = stiffness - _isotropic(np.zeros_like(mu), mu, stiffness.shape)
    values, vectors = np.linalg.eigh(shear_part)
    floor = 1e-9 * np.abs(values).max(axis=-1, keepdims=True)
    if np.any(values < -floor):
        raise ValueError("the rubber's shear modulus exceeds what the layer's stiffness holds in some direction")
    along = vectors[..., :3, :].sum(axis=-2)  # m^T v for every eigenvector v
    kept = values > floor
    inverse = np.where(kept, 1.0 / np.where(kept, values, 1.0), 0.0)
    in_null_space = np.sum(np.where(kept, 0.0, along**2), axis=-1) > 1e-12
    reciprocal = np.sum(along**2 * inverse, axis=-1)
    return np.where(in_null_space, 0.0, 1.0 / np.where(in_null_space, 1.0, reciprocal))


def tensor(voigt: np.ndarray, shear_factor: float) -> np.ndarray:
    """Symmetric 3x3 tensors (..., 3, 3) from Voigt vectors (..., 6); shears divided by ``shear_factor``."""
    t = np.empty(voigt.shape[:-1] + (3, 3))
    for col, (i, j) in enumerate(VOIGT):
        value = voigt[..., col] / (shear_factor if i != j else 1.0)
        t[..., i, j] = value
        t[..., j, i] = value
    return t


def voigt(t: np.ndarray) -> np.ndarray:
    """Voigt vectors (..., 6) of symmetric tensors (..., 3, 3), no shear factor (stresses)."""
    return np.stack([t[..., i, j] for i, j in VOIGT], axis=-1)


def stress_and_tangent(green: np.ndarray, m: PointMaterials) -> tuple[np.ndarray, np.ndarray]:
    """Second Piola-Kirchhoff stress and its tangent at Green-Lagrange strains.

    Parameters
    ----------
    green : ndarray (..., 6)
        Green-Lagrange strain, Voigt with engineering shears.
    m : PointMaterials

    Returns
    -------
    stress : ndarray (..., 6)
        ``S`` (Pa), Voigt.
    tangent : ndarray (..., 6, 6)
        :math:`\\partial S / \\partial E` (Pa), symmetric: ``C`` at zero strain.
    """
    c = np.eye(3) + 2.0 * tensor(green, 2.0)  # right Cauchy-Green tensor
    inv = np.linalg.inv(c)
    det = np.linalg.det(c)
    if np.any(det <= 0.0):
        raise FloatingPointError("a point of the mesh is inverted (det C <= 0): the load step is too large")
    log_j = 0.5 * np.log(det)
    s = m.mu[..., None, None] * (np.eye(3) - inv) + (m.lam * log_j)[..., None, None] * inv
    stress = voigt(s) + np.einsum("...ij,...j->...i", m.fibre, green)
    # D_ijkl = lam Ci_ij Ci_kl + (mu - lam ln J)(Ci_ik Ci_jl + Ci_il Ci_jk), Voigt pairs (i, j) and (k, l)
    a = np.array([i for i, _ in VOIGT])
    b = np.array([j for _, j in VOIGT])
    inv_ik = inv[..., a[:, None], a[None, :]]
    inv_jl = inv[..., b[:, None], b[None, :]]
    inv_il = inv[..., a[:, None], b[None, :]]
    inv_jk = inv[..., b[:, None], a[None, :]]
    inv_ij = inv[..., a, b]
    factor = (m.mu - m.lam * log_j)[..., None, None]
    tangent = (
        m.lam[..., None, None] * inv_ij[..., :, None] * inv_ij[..., None, :]
        + factor * (inv_ik * inv_jl + inv_il * inv_jk)
        + m.fibre
    )
    if m.cords is not None:
        _, cord_stress, cord_tangent = _cord_law(
            np.einsum("...fi,...i->...f", m.cords, green), m.cord_stiffness[..., None], m.cord_buckling[..., None]
        )
        stress = stress + np.einsum("...f,...fi->...i", cord_stress, m.cords)
        tangent = tangent + np.einsum("...f,...fi,...fj->...ij", cord_tangent, m.cords, m.cords)
    return stress, tangent


def green_strain(f: np.ndarray) -> np.ndarray:
    """Green-Lagrange strain, Voigt with engineering shears (..., 6), of deformation gradients (..., 3, 3)."""
    c = np.matmul(np.swapaxes(f, -1, -2), f)
    return np.stack([(c[..., i, j] - (i == j)) * (0.5 if i == j else 1.0) for i, j in VOIGT], axis=-1)


def energy(green: np.ndarray, m: PointMaterials) -> np.ndarray:
    """Strain energy density (J/m^3) at Green-Lagrange strains (..., 6): the potential of :func:`stress_and_tangent`."""
    c = np.eye(3) + 2.0 * tensor(green, 2.0)
    log_j = 0.5 * np.log(np.linalg.det(c))
    rubber = 0.5 * m.mu * (np.trace(c, axis1=-2, axis2=-1) - 3.0) - m.mu * log_j + 0.5 * m.lam * log_j**2
    fibre = 0.5 * np.einsum("...i,...ij,...j->...", green, m.fibre, green)
    if m.cords is not None:
        cord_energy, _, _ = _cord_law(
            np.einsum("...fi,...i->...f", m.cords, green), m.cord_stiffness[..., None], m.cord_buckling[..., None]
        )
        fibre = fibre + cord_energy.sum(axis=-1)
    return rubber + fibre


def half_sphere(count: int) -> np.ndarray:
    """``count`` unit vectors spread evenly over a half sphere (a Fibonacci lattice): the directions of
    :func:`least_acoustic_eigenvalue` (``N`` and ``-N`` give one acoustic tensor)."""
    k = np.arange(count) + 0.5
    z = k / count  # 0..1: the upper half
    phi = np.pi * (1.0 + np.sqrt(5.0)) * k
    r = np.sqrt(1.0 - z**2)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=-1)


def least_acoustic_eigenvalue(f: np.ndarray, m: PointMaterials, directions: np.ndarray) -> np.ndarray:
    r"""Least eigenvalue (Pa) over ``directions`` of the acoustic tensor at deformation gradients ``f`` (..., 3, 3).

    :math:`Q_{ik}(N) = A_{iJkL} N_J N_L` with the first elasticity tensor
    :math:`A_{iJkL} = F_{iI} F_{kK} D_{IJKL} + \delta_{ik} S_{JL}` (Holzapfel 2000, sec. 6.9). The law
    is strongly elliptic where it is positive for every ``N``: a negative value is a point that
    can buckle at no length of its own (a cord ply compressed along its cords beyond its shear
    stiffness: Rosen's micro-buckling), and a solution that depends on the mesh.
    """
    stress, d = stress_and_tangent(green_strain(f), m)
    pair = np.zeros((3, 3), int)
    for a, (i, j) in enumerate(VOIGT):
        pair[i, j] = pair[j, i] = a
    directions = np.asarray(directions, float)
    d_full = d[..., pair[:, :, None, None], pair[None, None, :, :]]  # D_IJKL
    d_nn = np.einsum("...IJKL,nJ,nL->...nIK", d_full, directions, directions)
    s_nn = np.einsum("...JL,nJ,nL->...n", stress[..., pair], directions, directions)
    q = np.einsum("...iI,...nIK,...kK->...nik", f, d_nn, f) + s_nn[..., None, None] * np.eye(3)
    return np.linalg.eigvalsh(q)[..., 0].min(axis=-1)
