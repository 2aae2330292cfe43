"""Elastic constants of the cross-section tire's layers: rubber, cord-rubber plies, rotations.

Each layer of the cross-section model (:mod:`~roadnoise_utils.tire.cross_section`) is a linear elastic solid whose
6x6 stiffness ``C`` (engineering Voigt notation) is scaled by its compound law
:math:`g_c(\\omega)` (:mod:`.rubber`). Rubber is isotropic. A cord-rubber ply is transversely
isotropic about its cords, its constants from the cord and matrix moduli by the rule of
mixtures (along the cords) and the Halpin-Tsai equations (across them): Halpin & Kardos,
"The Halpin-Tsai equations: a review", Polym. Eng. Sci. 16 (1976); for tire cord-rubber
composites, Walter, "Cord-rubber tire composites: theory and applications", Rubber Chem.
Technol. 51 (1978), and Clark, *Mechanics of Pneumatic Tires* (1981), ch. 1.

Axes. Local layer axes are ``(n, theta, s)``: the normal to the layer, the circumferential
direction and the meridian tangent. The model's axes are ``(r, theta, y)``. Voigt order is
``[11, 22, 33, 23, 13, 12]`` in either frame, so ``[nn, tt, ss, ts, ns, nt]`` locally and
``[rr, tt, yy, ty, ry, rt]`` globally.

A ply at cord angle ``+beta`` alone couples normal strains to the in-plane shear
``gamma_ts``; the belt's plies come in ``+beta / -beta`` pairs, so each angled ply is given the
balanced (``+beta`` and ``-beta`` averaged) stiffness. This keeps the membrane stiffness of the
pair exact and neglects its extension-twist coupling (B16, B26 of the antisymmetric
``[+beta / -beta]`` pair; its D16 is zero), which lets the symmetric and antisymmetric
circumferential harmonics decouple (:mod:`roadnoise_utils.tire.cross_section.waveguide`).
"""

from __future__ import annotations

import numpy as np

#: Voigt index pairs ``[11, 22, 33, 23, 13, 12]``.
VOIGT = ((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))


def isotropic(youngs_modulus: float, poisson: float) -> np.ndarray:
    """6x6 stiffness (Pa) of an isotropic solid, engineering shear strains."""
    e, nu = youngs_modulus, poisson
    lam = e * nu / ((1 + nu) * (1 - 2 * nu))
    mu = e / (2 * (1 + nu))
    c = np.zeros((6, 6))
    c[:3, :3] = lam
    c[np.arange(3), np.arange(3)] += 2 * mu
    c[np.arange(3, 6), np.arange(3, 6)] = mu
    return c


def halpin_tsai(fibre: float, matrix: float, volume_fraction: float, xi: float) -> float:
    """Halpin-Tsai estimate of a transverse or shear modulus of a fibre composite (Pa).

    :math:`M = M_m (1 + \\xi \\eta V_f) / (1 - \\eta V_f)`,
    :math:`\\eta = (M_f/M_m - 1)/(M_f/M_m + \\xi)`; ``xi = 2`` for the transverse modulus of
    round fibres, ``xi = 1`` for the longitudinal shear modulus (Halpin & Kardos 1976).
    """
    ratio = fibre / matrix
    eta = (ratio - 1.0) / (ratio + xi)
    return matrix * (1.0 + xi * eta * volume_fraction) / (1.0 - eta * volume_fraction)


def cord_ply_constants(
    cord_modulus: float,
    matrix_modulus: float,
    volume_fraction: float,
    cord_poisson: float = 0.3,
    matrix_poisson: float = 0.49,
) -> dict[str, float]:
    """Engineering constants of a unidirectional cord-rubber ply (Pa, -).

    ``E_L`` and ``nu_LT`` by the rule of mixtures, ``E_T`` and ``G_LT`` by Halpin-Tsai; the
    transverse plane (across the cords) takes the matrix's Poisson ratio.
    """
    vf, vm = volume_fraction, 1.0 - volume_fraction
    g_cord = cord_modulus / (2 * (1 + cord_poisson))
    g_matrix = matrix_modulus / (2 * (1 + matrix_poisson))
    e_t = halpin_tsai(cord_modulus, matrix_modulus, vf, 2.0)
    nu_tt = matrix_poisson
    return {
        "E_L": cord_modulus * vf + matrix_modulus * vm,
        "E_T": e_t,
        "nu_LT": cord_poisson * vf + matrix_poisson * vm,
        "G_LT": halpin_tsai(g_cord, g_matrix, vf, 1.0),
        "nu_TT": nu_tt,
        "G_TT": e_t / (2 * (1 + nu_tt)),
    }


def transversely_isotropic(constants: dict[str, float]) -> np.ndarray:
    """6x6 stiffness (Pa) with the fibre along axis 1 (Voigt ``[11, 22, 33, 23, 13, 12]``)."""
    el, et, nu_lt, glt, nu_tt, gtt = (constants[k] for k in ("E_L", "E_T", "nu_LT", "G_LT", "nu_TT", "G_TT"))
    s = np.zeros((6, 6))
    s[0, 0] = 1 / el
    s[1, 1] = s[2, 2] = 1 / et
    s[0, 1] = s[1, 0] = s[0, 2] = s[2, 0] = -nu_lt / el
    s[1, 2] = s[2, 1] = -nu_tt / et
    s[3, 3] = 1 / gtt
    s[4, 4] = s[5, 5] = 1 / glt
    return np.linalg.inv(s)


def bond(rotation: np.ndarray) -> np.ndarray:
    """6x6 Bond matrix ``T`` with ``C' = T C T^T`` for axes rotated by ``rotation``.

    ``rotation[..., i, j]`` is the cosine between new axis ``i`` and old axis ``j`` (leading
    axes: a batch of rotations, e.g. one per point); engineering shear strains (Bond 1943; Auld,
    *Acoustic Fields and Waves in Solids*, ch. 3).
    """
    a = np.asarray(rotation, float)
    t = np.zeros(a.shape[:-2] + (6, 6))
    for row, (i, j) in enumerate(VOIGT):
        for col, (k, m) in enumerate(VOIGT):
            if col < 3:
                t[..., row, col] = a[..., i, k] * a[..., j, m]
            else:
                t[..., row, col] = a[..., i, k] * a[..., j, m] + a[..., i, m] * a[..., j, k]
    return t


def rotate(c: np.ndarray, rotation: np.ndarray) -> np.ndarray:
    """Stiffness ``c`` expressed in axes rotated by ``rotation`` (see :func:`bond`; both may be batched)."""
    t = bond(rotation)
    return t @ c @ np.swapaxes(t, -1, -2)


def cord_layer(constants: dict[str, float], cord_angle_deg: float) -> np.ndarray:
    """Balanced stiffness of a ply in its local ``(n, theta, s)`` axes (Pa).

    ``cord_angle_deg`` is measured from the circumferential direction ``theta`` towards the
    meridian ``s`` (0 for a cap ply, ~20-25 for steel belts, 90 for a radial carcass). The
    ``+beta`` and ``-beta`` stiffnesses are averaged (see the module notes).
    """
    c_fibre = transversely_isotropic(constants)  # axes (L, T, T')
    out = np.zeros((6, 6))
    for sign in (1.0, -1.0):
        beta = np.radians(sign * cord_angle_deg)
        # old axes (L, T, n); new axes (n, theta, s): theta = cos b L - sin b T, s = sin b L + cos b T
        rot = np.array([[0.0, 0.0, 1.0], [np.cos(beta), -np.sin(beta), 0.0], [np.sin(beta), np.cos(beta), 0.0]])
        out += 0.5 * rotate(c_fibre, rot)
    # the balanced average has no normal-shear coupling left; remove round-off
    out[:3, 3:5] = out[3:5, :3] = 0.0
    out[:3, 5] = out[5, :3] = 0.0
    out[3:5, 5] = out[5, 3:5] = 0.0
    return out


def to_model_axes(c_local: np.ndarray, tangent_r: np.ndarray, tangent_y: np.ndarray) -> np.ndarray:
    """Layer stiffness in the model axes ``(r, theta, y)`` at points with meridian tangents.

    Parameters
    ----------
    c_local : ndarray (6, 6)
        Stiffness in the layer axes ``(n, theta, s)``.
    tangent_r, tangent_y : ndarray (m,)
        Unit meridian tangent ``s = (s_r, s_y)`` at each point.

    Returns
    -------
    ndarray (m, 6, 6)
    """
    sr, sy = np.broadcast_arrays(np.asarray(tangent_r, float), np.asarray(tangent_y, float))
    out = np.empty(sr.shape + (6, 6))
    for idx in np.ndindex(sr.shape):
        # old axes (n, theta, s) with n = (s_y, -s_r) in (r, y); new axes (r, theta, y)
        rot = np.array([[sy[idx], 0.0, sr[idx]], [0.0, 1.0, 0.0], [-sr[idx], 0.0, sy[idx]]])
        out[idx] = rotate(c_local, rot)
    return out
