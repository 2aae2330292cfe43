# ---
# jupyter:
#   jupytext:
#     formats: ipynb,py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#       format_version: '1.3'
#       jupytext_version: 1.19.6
#   kernelspec:
#     display_name: Python 3 (ipykernel)
#     language: python
#     name: python3
# ---

# %% [markdown]
# # 04 — The cleat test on the drum, hub fixed
#
# **Paper stage 8** (section *Validation of the Model for Fixed Hub*, Fig. 8 and 9; section
# *Simulation of Wheel-Road Interaction* for the road input).
#
# The paper validates the fixed-hub model (Eq. 3) against an indoor cleat test: the 165/65 R14
# on a 4J rim at 2.3 bar and 4512 N rolls over a drum of radius 1.25 m carrying a triangular
# cleat 15 mm long and 15 mm high, once quasi-statically ("base curve") and once at 30 km/h
# ("dynamic curve"). It reports:
#
# * two force peaks while the cleat crosses the footprint, in both runs;
# * measured: the dynamic maximum "about 2.2 times" the quasi-static one (850 N);
# * simulated: quasi-static maximum 1200 N (above the measured 850 N, which the authors put
#   down to contact loss, a nonlinearity the linear model cannot show), dynamic maximum "very
#   close to the measured one";
# * after the cleat has left the footprint, a decay dominated by the 80 Hz first vertical mode.
#
# Here the road flows through the footprint (each tassello's displacement is the
# shape-function-weighted average of the drum surface under it), the state-space tire of
# notebook 03 — fitted on the drum footprint — is simulated in the time domain, and the same
# response is computed a second way, straight from the viscoelastic FE model in the frequency
# domain.

# %%
import matplotlib.pyplot as plt
import numpy as np

import roadnoise_utils as ru

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): tire file, speeds (km/h), cleat (m); None takes the paper's test
# from data/conditions/cleat_test.toml (resolved by ru.experiments.cleat_conditions)
tire_name = "165_65R14"
speed_kmh = None
quasi_static_kmh = None
cleat_height = None
cleat_base = None

# %% [markdown]
# ## 1. The tire on the drum
#
# The footprint on the 1.25 m drum is shorter than on a flat road (notebook 01); its tasselli,
# direct FRFs, fits and state-space model are computed for this footprint (cached stages).

# %%
# NBVAL_IGNORE_OUTPUT
# The paper's test (data/conditions/cleat_test.toml; the parameters above override it), run on the
# tire: the drum footprint, its fixed-hub state-space tire, both runs and the FE check (cached stages)
conditions = ru.experiments.cleat_conditions(
    height=cleat_height, base=cleat_base, dynamic_kmh=speed_kmh, quasi_static_kmh=quasi_static_kmh
)
fe_check = ru.experiments.applicable(tire_name, "direct_response")  # the FE check needs the FE model
test = ru.experiments.cleat_test(tire_name, conditions=conditions, fe_reference=fe_check)
tire, drum, tire_F = test.tire, test.static, test.system
height, base = conditions.height, conditions.base
speed_kmh, quasi_static_kmh = conditions.dynamic_kmh, conditions.quasi_static_kmh

# %%
# NBVAL_CHECK_OUTPUT
# The test
print(
    f"{tire.name}: drum R = {drum.road.drum_radius:.2f} m, footprint {drum.footprint_length * 1e3:.0f} mm long, "
    f"{drum.tasselli.n} tasselli; state-space tire: {tire_F.nstates} states, {tire_F.ninputs} inputs"
)
print(f"cleat: {conditions.shape}, base {base * 1e3:.0f} mm, height {height * 1e3:.0f} mm")

# %% [markdown]
# ## 2. The road flowing through the footprint
#
# At distance $d$ the footprint point at $x$ sees the drum surface at $x + d$; each tassello's
# displacement is the correlation of the cleat profile with the tassello's shape-function
# kernel. The sample rate follows from the band (20 samples per period of 250 Hz) and the speed
# (at most 3.5 mm of road per sample, about half the spacing of the tread points).

# %%
# Tassello displacements at 30 km/h, the centre column, leading, middle and trailing rows
dynamic_road = test.dynamic.result.road
last_row = int(drum.tasselli.row.max())
ru.figures.cleat_test.plot_tassello_inputs(dynamic_road, drum, [0, last_row // 2, last_row])
plt.xlim(-0.1, 0.15)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Sampling of the two runs
print(
    f"{speed_kmh:.0f} km/h: {dynamic_road.sample_rate:.0f} Hz, {dynamic_road.u.shape[1]} samples of {dynamic_road.u.shape[0]} inputs"
)
quasi_road = test.quasi_static.result.road
print(f"{quasi_static_kmh} km/h: {quasi_road.sample_rate:.0f} Hz, {quasi_road.u.shape[1]} samples")

# %% [markdown]
# ## 3. The simulation (Fig. 8-9 analogue)
#
# The fixed-hub tire is a set of independent pole pairs, each driven by one tassello: every
# pair is discretised exactly for an input linear between samples (first-order hold) and run
# as a second-order IIR filter (`scipy.signal.lfilter`). No loop over time steps in Python.
# The hub force is then band-limited to the fits' 0-250 Hz (zero phase), and the peaks are read
# from it, as section 5 compares it with the FE model: above the band the fitted poles follow
# nothing of the tire, and the cleat at 30 km/h reaches them.

# %%
# Fig. 9 analogue: quasi-static (base curve) and 30 km/h (dynamic curve) runs, with the paper's peaks
quasi, dynamic = test.quasi_static, test.dynamic
paper = {  # data/paper/claims.toml
    "paper: measured quasi-static peak": ru.claims.paper_value("cleat_quasi_static", "measured"),
    "paper: simulated quasi-static peak": ru.claims.paper_value("cleat_quasi_static"),
    "paper: dynamic peak (≈ 2.2 x measured)": ru.claims.paper_value("cleat_dynamic"),
}
ax = ru.figures.cleat_test.plot_cleat_runs(
    {f"base curve ({quasi_static_kmh} km/h)": quasi, f"dynamic curve ({speed_kmh:.0f} km/h)": dynamic},
    title="Fig. 9 analogue: simulated hub force during a cleat test",
    paper=paper,
)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The two peaks of each run while the cleat crosses the footprint
print("quasi-static:\n" + quasi.peaks.to_string(float_format=lambda v: f"{v:.3f}"))
print(f"{speed_kmh:.0f} km/h:\n" + dynamic.peaks.to_string(float_format=lambda v: f"{v:.3f}"))

# %% [markdown]
# Two peaks in both runs, as in the paper: one as the cleat enters the footprint, one as it
# leaves. At 30 km/h the cleat crosses the ~100 mm footprint in 12 ms, about one period of the
# first vertical mode: the dynamics raise the entry peak and lower the exit one. The chain is
# linear and the footprint symmetric, so the exit push alone would give the entry's peak; the
# ringing left by the entry is out of phase with it when the cleat leaves, and takes the
# difference off (notebook 08 sweeps the speed).
#
# ### The free decay
#
# After the cleat has left the footprint, the force is a sum of damped sinusoids; the matrix
# pencil method (Hua & Sarkar 1990) extracts them from the signal alone — not from a mode
# table.

# %%
# NBVAL_CHECK_OUTPUT
# Damped components of the decay after the cleat has left (largest first)
print(dynamic.decay.head(4).to_string(float_format=lambda v: f"{v:.3f}"))

# %% [markdown]
# ## 4. Paper vs ours
#
# The paper's cleat-test numbers. The claims, the paper's values (with their source) and our
# tolerances are in `data/paper/claims.toml`; `ru.claims` computes our side on the paper's tire
# (whatever this notebook's parameters).

# %%
# The paper's claims shown by this notebook, our values and the verdicts
claims = ru.claims.report(notebook="04-cleat-test.ipynb")
claims.drop(columns="notebook")

# %%
# NBVAL_CHECK_OUTPUT
# Verdicts; every claim passes or is a documented deviation
print(ru.claims.verdicts(claims))
ru.claims.check(claims)

# %% [markdown]
# **What we reproduce:** the shape — two peaks while crossing, then a decay carried by the
# first two vertical modes (80 and 108 Hz).
#
# **What we do not:** the size. The linear chain's quasi-static peak is under half the paper's
# simulated 1200 N, and its dynamic amplification is ~1.1, so the 30 km/h peak is a third of
# the measured one. The measured test (Fig. 8: 850 N, ratio 2.2, 80 Hz decay) involves the tread
# lifting off the drum next to the cleat, which no linear model shows; notebook 08 runs it with
# one-sided contact and judges *that* against the measurement.
#
# Why the linear peak is low: the force a cleat sends to the hub is set by the *static
# influence* $H_i(0)$ of the rows it crosses. Our ring puts nearly all of $K_v$ at the footprint's
# ends, but shares it between the entry row and its neighbour: the belt on the tread springs is
# a beam on an elastic foundation, whose response to an edge load decays as
# $e^{-\beta s}\cos\beta s$ with $\beta = (k_{tread}\,b / 4EI)^{1/4}$, so $K_v$ sits in an
# edge zone $1/\beta$ deep, two rows at each end (computed below). The paper's 1200 N needs an
# entry row of about $0.75\,K_v$ *alone*, the
# leading and trailing rows together well above $K_v$ and the interior negative — which a solid
# tread on a shell carcass (the paper's 3D FE tire) gives and a ring on springs cannot. The
# next cells show the influence profile and that no plausible change of the ring's parameters
# closes the gap — it is the model family, not a calibration error, so we keep the calibration
# of notebook 01 and record the deviation.

# %%
# Static influence of each row along the drum footprint: where the two peaks come from
visco_drum = ru.stages.frf_visco(tire, road="drum", drum_radius=conditions.drum_radius)
static_influence = visco_drum.H[:, 0].real
rows = ru.experiments.cleat.row_influence(drum, static_influence)
ax = ru.figures.cleat_test.plot_row_influence(rows, drum, base)
ax.set_title("Static influence H_i(0) of each row: the cleat meets the large rows at entry and exit")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Row influences, and the quasi-static force straight from them (no dynamics at all)
print((rows.round(1) + 0.0).to_string(float_format=lambda v: f"{v:.1f}"))  # + 0.0: no "-0.0"
direct_quasi = ru.experiments.cleat.quasi_static_force(static_influence, quasi_road)
ring_tire = ru.tire_model(tire).kind == "ring"  # the beam on springs and its parameters are the ring's
if ring_tire:
    beta = ru.tire.ring.closed_form.edge_zone_wavenumber(tire)
    print(f"edge zone 1/beta = {1e3 / beta:.1f} mm (beta = (k_tread b / 4 EI)^(1/4) = {beta:.1f} /m); ", end="")
print(f"two outer rows each side: {ru.experiments.cleat.edge_share(rows):.0%} of K_v")
print(
    f"peak of sum_i H_i(0) u_i: {direct_quasi.max():.1f} N; simulated at {quasi_static_kmh} km/h: "
    f"{quasi.peak_force:.1f} N"
)

# %%
# NBVAL_CHECK_OUTPUT
# Sensitivity of the quasi-static peak to the ring tire's parameters (each row: one change, all else as calibrated)
if ring_tire:
    variants = {
        "as calibrated": {},
        "belt bending stiffness x 3": {"belt.bending_stiffness": 3 * tire.belt.bending_stiffness},
        "tread 3 x stiffer": {"tread.normal_stiffness_per_area": 3 * tire.tread.normal_stiffness_per_area},
        "sidewall rubber x 3 (radial)": {"foundation.radial_rubber": 3 * tire.foundation.radial_rubber},
        "sidewalls 3 x stiffer at the edges": {"foundation.edge_factor": 3 * tire.foundation.edge_factor},
    }
    peaks = ru.experiments.cleat.peak_sensitivity(
        tire, variants, height, base, conditions.shape, conditions.drum_radius
    )
    for name, peak in peaks.items():
        print(f"{name:36s} quasi-static peak {peak:6.0f} N")
else:
    print(f"{tire.name}: not applicable: the ring's parameters (its belt, tread springs and sidewalls)")

# %% [markdown]
# Tripling any one of the stiffnesses that shape the footprint moves the peak by well under a
# factor of two, and the stiff-tread variant would break the footprint calibration — none
# reaches the paper's simulated 1200 N.
# Notebook 13 runs the same test on the tire built from its cross-section — layered solid
# elements, no springs — and on a tire read from files.
#
# ## 5. Second method: the RM chain against the full FE model
#
# The same dynamic passage computed in the frequency domain straight from the viscoelastic FE
# model, $F(\omega) = \sum_i H_i(\omega) U_i(\omega)$ with the direct $H_i$ at every FFT bin —
# no modal reduction, no fitting, no time stepping. Both methods see the same 1 s record (the
# road padded with zeros, so the free decay ends inside it) and both forces are band-limited
# to the RM model's 250 Hz the same way (zero phase).

# %%
# RM chain vs FE model
# (the FE frequency-domain response and the RM chain on the same road, band-limited to 250 Hz)
if fe_check:
    road, fe_force, rm_force = test.fe_reference.road, test.fe_reference.fe_force, test.fe_reference.rm_force
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(road.distance, fe_force, "k", lw=2.5, label="FE model, frequency domain (direct H_i)")
    ax.plot(road.distance, rm_force, "--", color="tab:red", label="RM chain: fitted state space, time domain")
    ax.set_xlabel("distance travelled (m)")
    ax.set_ylabel("hub force, 0-250 Hz (N)")
    ax.set_title(f"{tire.name}: the RM chain against the FE model on the {speed_kmh:.0f} km/h passage")
    ax.legend()
    plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Peak and RMS differences between the RM chain and the FE model
if fe_check:
    peak_difference = test.fe_reference.peak_difference
    rms_difference = test.fe_reference.rms_difference
    print(f"peak: FE {fe_force.max():.1f} N, RM {rm_force.max():.1f} N, difference {peak_difference:+.2%}")
    print(f"RMS of the difference / RMS of the FE force: {rms_difference:.2%}")
    assert abs(peak_difference) < 0.02 and rms_difference < 0.02

# %% [markdown]
# The whole chain — tasselli, fits, realisation, discretisation, simulation — reproduces the
# FE model to within the fit error: what separates us from the paper's numbers is the tire,
# not the method.
#
# ## 6. The simulation against python-control
#
# The fast simulation must equal python-control's `forced_response` (dense, same FOH
# assumption) on the same model and input.

# %%
# NBVAL_CHECK_OUTPUT
# Fast block-diagonal simulation vs control.forced_response on (up to) 300 samples of the dynamic run
import control

short = dynamic_road.excerpt(0, 300)
reference = control.forced_response(tire_F, T=short.t, U=short.u).outputs
fast = ru.simulate(test.sections, short).force
agreement = np.max(np.abs(fast - reference)) / np.max(np.abs(reference))
print(f"max |ours - python-control| / max |python-control|: {ru.analysis.format_small(agreement, 1e-9)}")
assert agreement < 1e-9

# %% [markdown]
# ## Explore: speed and cleat
#
# The callback builds the cleat input and runs the simulation with the package functions.

# %%
# NBVAL_IGNORE_OUTPUT
# Widget: cleat test at any speed and cleat size
from ipywidgets import FloatSlider, interact


def show_cleat(speed_kmh, height_mm, base_mm):
    run = ru.experiments.cleat.run_cleat(
        test.sections,
        drum,
        speed_kmh / 3.6,
        height_mm / 1e3,
        base_mm / 1e3,
        conditions.shape,
        distance=conditions.dynamic_distance,
        dynamic=False,
    )
    ru.figures.cleat_test.plot_cleat_runs({f"{speed_kmh:.0f} km/h": run}, title=f"peak {run.peak_force:.0f} N")
    plt.show()


_ = interact(
    show_cleat,
    speed_kmh=FloatSlider(value=speed_kmh, min=5.0, max=120.0, step=5.0, continuous_update=False),
    height_mm=FloatSlider(value=height * 1e3, min=2.0, max=30.0, step=1.0, continuous_update=False),
    base_mm=FloatSlider(value=base * 1e3, min=5.0, max=60.0, step=5.0, continuous_update=False),
)

# %% [markdown]
# **Next:** notebook 05 frees the hub (Eq. 5-7) so the tire can be coupled to a vehicle.
