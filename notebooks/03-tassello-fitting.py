# ---
# jupyter:
#   jupytext:
#     formats: ipynb,py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#       format_version: '1.3'
#       jupytext_version: 1.19.7
#   kernelspec:
#     display_name: Python 3 (ipykernel)
#     language: python
#     name: python3
# ---

# %% [markdown]
# # 03 — Per-tassello rational fits and the state-space tire
#
# **Paper stages 6-7** (section *System Identification*, Eq. 1-4, Fig. 6).
#
# The RM model lives in the time domain so it can be coupled with vehicle models. For each
# tassello the paper fits "the ratio between two polynomials",
#
# $$G_i(s) = \frac{h_i(s)}{d_i(s)}, \tag{1}$$
#
# "a transfer function with eight poles and eight zeros has been found to be suitable to
# reproduce the dynamic behavior of the tasselli in the 0-250 Hz frequency range" (MATLAB's
# Frequency Domain Identification Toolbox; Fig. 6: the fit "cannot be appreciated" from the
# target). Each fit becomes an 8-state model (Eq. 2), and all are stacked block-diagonally
# into the fixed-hub tire (Eq. 3-4):
#
# $$\dot x_F = A_F x_F + B_F u_F, \qquad F_F = C_F x_F + D_F u_F .$$
#
# We fit the same biproper model in **pole-residue form** by **relaxed vector fitting**
# (Gustavsen & Semlyen 1999; Gustavsen 2006) — stable poles, real coefficients, the DC value
# imposed — realise it straight from poles and residues (never through ill-conditioned
# degree-8 polynomials), and check the result against two peer libraries, scikit-rf and
# pyvectorfit.

# %%
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

import roadnoise_utils as ru

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): tire file, road of the static state, fitted band (Hz), error target
tire_name = "165_65R14"
road = "flat"
f_max = 250.0
tolerance = 0.01

# %%
# The parameters above, checked before anything runs: a wrong one is refused naming it and its valid values
ru.experiments.check_parameters(tire_name=tire_name, road=road, f_max=f_max, tolerance=tolerance)

# %%
# NBVAL_IGNORE_OUTPUT
# The local FRFs of notebook 02 (cached): direct (FETvisco) and modal
tire = ru.load_tire(tire_name)
surface = {"road": road, "drum_radius": ru.experiments.cleat_conditions().drum_radius if road == "drum" else None}
static = ru.stages.solve_static(tire, **surface)
visco = ru.stages.frf_visco(tire, **surface)
frf_sets = {"direct FRFs": visco}
if ru.experiments.applicable(tire, "modal_reduction"):
    frf_sets["modal FRFs"] = ru.stages.modal_reduction(tire, **surface).frf
band = visco.freqs <= f_max

# %% [markdown]
# ## 1. Which FRFs to fit, and how many poles
#
# The paper fits the modal local FRFs. Our frozen complex modal model has a constant complex
# stiffness — hysteretic damping, which is not causal: each mode $1/(\lambda_r - \omega^2)$
# has a mirror pole in the right half plane, which no stable rational model reproduces. The
# direct viscoelastic FRFs (fractional Zener rubber) are causal and cheap to compute (one
# adjoint solve per frequency, notebook 02), so we fit those; the modal ones are shown alongside.

# %%
# NBVAL_CHECK_OUTPUT
# Error of the fits against the model order, direct and modal FRFs (0-250 Hz)
orders = range(8, 17)
scans = {label: ru.rm.order_scan(frfs.freqs, frfs.H, orders, f_max=f_max) for label, frfs in frf_sets.items()}
both = scans["direct FRFs"].drop(columns="time (s)")
if "modal FRFs" in scans:
    both = both.join(scans["modal FRFs"].drop(columns="time (s)").add_suffix(" (modal)"))
print(both.to_string(float_format=lambda v: f"{v:.3f}"))

# %%
# Order scan: the paper's 8 poles and our 1 % target
ru.figures.tassello_fitting.plot_order_scan(scans, tolerance)
plt.show()

# %% [markdown]
# **Eight poles are not enough for our tire.** Its local FRFs have *five* vertical resonances
# in 0-250 Hz (80, 108, 148, 195 and 247 Hz, notebook 02), which need at least ten poles; with
# eight, one resonance is missing and the error is ~40 %. The paper's tire presumably had four
# (its Fig. 14 shows "the first four vertical modes" below 220 Hz). We use the lowest order at
# which *every* tassello is fitted within 1 % (the table above; printed below).

# %%
# NBVAL_CHECK_OUTPUT
# The fits used by the later stages (cached): lowest order with every tassello within 1 %
fits = ru.stages.fit_tasselli(tire, **surface)
table = fits.table()
print(
    f"{len(fits)} tasselli, {fits.n_poles} poles and {fits.n_poles} zeros each, band "
    f"{fits.band[0]:.0f}-{fits.band[1]:.0f} Hz"
)
print(f"relative RMS error: max {table['rms error'].max():.4f}, median {table['rms error'].median():.4f}")
print(
    f"every pole stable: {bool((table['max Re(p) (1/s)'] < 0).all())}; "
    f"DC imposed: max DC error {ru.analysis.format_small(table['DC error'].max(), 1e-10)}"
)
assert table["rms error"].max() < tolerance and (table["max Re(p) (1/s)"] < 0).all()

# %%
# Relative RMS error of each tassello's fit on the footprint
ax = ru.figures.common.plot_tassello_map(
    static, 100 * table["rms error"].to_numpy(), "rms error (%)", cmap="viridis", symmetric=False
)
ax.set_title(f"Fit error per tassello, {fits.n_poles} poles")
plt.show()

# %% [markdown]
# ## 2. Fig. 6: target and identified FRF of a tassello near the centre of the footprint

# %%
# Fig. 6 analogue: target (FEA) vs identified modulus and phase, central tassello
centre = int(np.argmin(np.hypot(static.tasselli.centre_x, static.tasselli.centre_y)))
f = visco.freqs[band]
ru.figures.tassello_fitting.plot_fit(
    f,
    visco.H[centre, band],
    fits[centre](f),
    f"Fig. 6 analogue: tassello {centre + 1} (footprint centre), {fits.n_poles} poles / zeros",
)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Its fit error, and the one with the largest error
worst = ru.analysis.argmax_all(table["rms error"].to_numpy())  # mirror-image tasselli fit alike: name them all
print(
    f"tassello {centre + 1} (centre): rms error {fits[centre].rms_error:.4f}, largest deviation "
    f"{fits[centre].max_error:.4f} of its peak"
)
print(
    f"{'tasselli' if worst.size > 1 else 'tassello'} {', '.join(str(k + 1) for k in worst)} (worst):  rms error {fits[worst[0]].rms_error:.4f}"
)

# %% [markdown]
# ## 3. State space: Eq. 2 for one tassello, Eq. 3-4 for the tire
#
# Each fit is realised from poles and residues: a 2x2 block per conjugate pair, a 1x1 block
# per real pole. Stacking them gives the fixed-hub tire, a python-control `StateSpace`.

# %%
# One tassello (Eq. 2) and the assembled fixed-hub tire (Eq. 3-4)
tassello = ru.realize(fits[centre])
tire_F = ru.assemble_fixed_hub(fits)
print(
    f"tassello {centre + 1}: {tassello.nstates} states; A block diagonal: "
    f"{np.count_nonzero(tassello.A)} non-zeros of {tassello.A.size}"
)

# %%
# NBVAL_CHECK_OUTPUT
# Size, stability and DC gains of the fixed-hub tire
poles = np.linalg.eigvals(tire_F.A)
dc = np.ravel(tire_F.dcgain())
static_influence = visco.H[:, 0].real
print(f"(A_F, B_F, C_F, D_F): {tire_F.nstates} states, {tire_F.ninputs} inputs (tasselli), {tire_F.noutputs} output")
print(
    f"slowest pole: Re = {poles.real.max():.2f} 1/s (stable); fastest: |p| = {np.abs(poles).max() / (2 * np.pi):.0f} Hz"
)
print(
    f"DC gains vs the static influence H_i(0): max relative difference "
    f"{ru.analysis.format_small(np.max(np.abs(dc / static_influence - 1)), 1e-10)}"
)
print(f"sum of DC gains {dc.sum() / 1e3:.2f} N/mm = H_tot(0) {visco.H_tot[0].real / 1e3:.2f} N/mm")

# %% [markdown]
# ### Verification: the assembled model is the sum of the fits
#
# python-control evaluates the assembled model (a dense solve per frequency, independent of
# the block structure) at a few frequencies; it must equal the fitted FRFs to round-off.

# %%
# NBVAL_CHECK_OUTPUT
# Assembled model (python-control) vs the fitted FRFs, at 12 frequencies
check_freqs = np.linspace(0.0, f_max, 12)
assembled = ru.rm.frequency_response(tire_F, check_freqs)
fitted = fits.responses(check_freqs)
assembly_error = np.max(np.abs(assembled - fitted)) / np.max(np.abs(fitted))
print(f"max |assembled - fitted| / max |fitted|: {ru.analysis.format_small(assembly_error, 1e-10)}")
assert assembly_error < 1e-10

# %%
# The fitted sum against sum_i H_i (direct) and H_tot (forward), 0-250 Hz
fitted_sum = fits.responses(f).sum(axis=0)
fig, ax = plt.subplots(figsize=(8, 4.5))
ax.plot(f, np.abs(visco.H_tot[band]) / 1e3, "k", lw=2.5, label="H_tot (forward solve, SISO)")
ax.plot(f, np.abs(visco.H_sum[band]) / 1e3, color="tab:orange", lw=1.5, label="Σ H_i (direct, MIMO)")
ax.plot(f, np.abs(fitted_sum) / 1e3, "--", color="tab:red", label=f"Σ G_i (fitted, {fits.n_poles} poles each)")
ax.set_xlabel("Frequency (Hz)")
ax.set_ylabel("|H| (N/mm)")
ax.set_title("The fitted tasselli's sum against the FE model's, 0-250 Hz")
ax.legend()
plt.show()

# %% [markdown]
# ## 4. The hub FRF $G_H$ for the moving hub

# %%
# NBVAL_CHECK_OUTPUT
# Fit of G_H (the same 1 % rule)
if ru.experiments.applicable(tire, "hub_transfer"):
    hub = ru.stages.fit_hub(tire, **surface)
    print(
        f"G_H: {hub.n_poles} poles, relative RMS error {hub[0].rms_error:.4f}, G_H(0) = {hub[0].dc_gain / 1e3:.2f} N/mm"
    )

# %% [markdown]
# ## 5. Peer check: scikit-rf's `VectorFitting` and pyvectorfit's `fit` on the same FRFs
#
# The same model (the same order, constant term) fitted with two independent implementations of
# the same algorithm, on the same data. Vector fitting relocates poles from a starting set to a
# local optimum, and which start reaches the better one differs from tassello to tassello. Ours
# starts from lightly damped pairs spread evenly over the band; from a second set as well, spread
# evenly on a log scale as pyvectorfit starts (`starting_poles=("linear", "log")`), each tassello
# keeps the better fit. The pipeline keeps the first alone: the log start's relocations amplify
# round-off in the data (a change of 1e-15 moves some fits by 1e-6 of the response at 14-17 poles
# and 5e-4 at 20, against at most 6e-9 from the linear start), enough for two processes to print
# different digits. Poles the band cannot pin down are
# held to what it supports: above the band, at least 0.5 % damping; none slower than the grid
# resolves.

# %%
# NBVAL_IGNORE_OUTPUT
# Side by side: errors and wall time (timings vary run to run)
peer_errors, peer_seconds = ru.rm.fitting_peer.skrf_vector_fit(visco.freqs, visco.H, fits.n_poles, f_max)
pyvf_errors, pyvf_seconds = ru.rm.fitting_peer.pyvectorfit_fit(visco.freqs, visco.H, fits.n_poles, f_max)
pd.concat(
    [
        ru.rm.fitting_peer.fit_comparison(fits.rms_errors, fits.seconds, peer_errors, peer_seconds),
        ru.rm.fitting_peer.fit_comparison(
            fits.rms_errors, fits.seconds, pyvf_errors, pyvf_seconds, peer="pyvectorfit fit"
        ).iloc[1:],
    ]
)

# %%
# NBVAL_CHECK_OUTPUT
# Ours is at least as good as scikit-rf's on every tassello; from both starts, within 1.2x of the better peer
better_peer = np.minimum(peer_errors, pyvf_errors)
both = ru.fit_tasselli(visco.freqs, visco.H, n_poles=fits.n_poles, f_max=f_max, starting_poles=("linear", "log"))
print(f"ours <= scikit-rf on {np.sum(fits.rms_errors <= peer_errors)} of {len(fits)} tasselli")
print(f"from both starts, within 1.2x of the better peer on {np.sum(both.rms_errors <= 1.2 * better_peer)} of {len(fits)}")
assert np.all(fits.rms_errors <= peer_errors) and np.all(both.rms_errors <= 1.2 * better_peer)

# %% [markdown]
# ## 6. Paper vs ours
#
# The claims, the paper's values and our tolerances are in `data/paper/claims.toml`;
# `ru.claims` computes our side on the paper's tire (whatever this notebook's parameters).

# %%
# The paper's claims shown by this notebook, our values and the verdicts
claims = ru.claims.report(notebook="03-tassello-fitting.ipynb")
claims.drop(columns="notebook")

# %%
# NBVAL_CHECK_OUTPUT
# Verdicts; every claim passes or is a documented deviation
print(ru.claims.verdicts(claims))
ru.claims.check(claims)

# %% [markdown]
# The one claim we do not reproduce is the order: our tire has a fifth vertical mode at the
# top of the band, so its tasselli need more poles than 8 (the order printed above). Everything
# downstream uses that model; the procedure is unchanged. The block-diagonal structure of
# Eq. 3-4 is as in the paper, with that many states per tassello instead of 8.
#
# ## Explore: the fit of any tassello at any order

# %%
# NBVAL_IGNORE_OUTPUT
# Widget: fit one tassello with a chosen number of poles
from ipywidgets import IntSlider, interact


def show_fit(tassello=37, n_poles=14):
    fit = ru.vector_fit(f, visco.H[tassello - 1, band], n_poles=n_poles)
    ru.figures.tassello_fitting.plot_fit(
        f, visco.H[tassello - 1, band], fit(f), f"tassello {tassello}, {n_poles} poles: rms error {fit.rms_error:.2%}"
    )
    plt.show()


_ = interact(
    show_fit,
    tassello=IntSlider(value=centre + 1, min=1, max=len(fits), continuous_update=False),
    n_poles=IntSlider(value=fits.n_poles, min=4, max=20, continuous_update=False),
)

# %% [markdown]
# **Next:** notebook 04 drives this fixed-hub tire with a cleat on the 1.25 m drum (paper
# Fig. 8-9) and compares the time-domain result with the full FE model.
