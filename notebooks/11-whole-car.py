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
# # 11 — Beyond the paper: the whole car on four RM tires
#
# **Paper Eq. 8, and its future work.** The paper writes the equations of the whole vehicle —
# "a vector $x_T$ collecting the state variables of all the tires of the vehicle model and a
# vector $u_R$ of the displacements impressed by the road to all tasselli in the four tires",
# the hub forces $F_V$ and displacements $u_V$ — but runs only "an elementary 'quarter of
# vehicle' model (see Fig. 13)", and closes with "future developments will be addressed to the
# implementation of the RD model in a complete vehicle model".
#
# This chapter builds that complete vehicle: a rigid body in heave, pitch and roll on the four
# corners of notebook 07 (each with its strut, top mount and damper rod), every corner on its own
# moving-hub RM tire ($F_M = F_F + G_H u_H$, Eq. 5-7), all four wheels on one 3-D road whose
# left and right tracks are coherent as an isotropic surface's, the rear wheels running the
# front's road a wheelbase later. What a quarter car cannot show appears here: the **wheelbase
# filtering** of heave and pitch, the **body's** spectra, and how coherent the left and right
# road forces are.
#
# As in notebook 07 the fixed-hub road forces $F_F$ are simulated per tire (the fast modal
# simulation of Eq. 3) and only the small closed car is driven by them: the chain is linear, so
# this equals integrating Eq. 8's whole state vector.
#
# Notebook 13 puts the car on every tire model; notebook 14 adds the tire's air cavity.

# %%
import matplotlib.pyplot as plt
import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.experiments import whole_car
from roadnoise_utils.vehicle import full_car

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): speed (km/h), texture, duration (s), seed; None takes data/conditions/whole_car.toml
speed_kmh = None
texture = None
duration = None
seed = None

# %%
# The parameters left at None take the whole-car road test (data/conditions/whole_car.toml)
test = whole_car.whole_car_conditions(speed_kmh, texture, duration, seed)
speed_kmh, texture, duration, seed = test.speed_kmh, test.texture, test.duration, test.seed

# %% [markdown]
# ## 1. The car
#
# `data/vehicles/midsize_195_65R15_car.toml`: the sprung body (mass and inertias with their
# sources), the wheelbase, the centre of mass and the tracks, and the front and rear corner
# files. The front corner is notebook 07's (its strut reproduces the paper's Fig. 10); the rear
# is scaled from it with its reasons (the paper has no rear data). Every wheel carries the same
# tire, the 195/65 R15 of the paper's road test, with its cached RM stages.

# %%
# NBVAL_IGNORE_OUTPUT
# The car on the ring tire of its vehicle files (cached tire stages)
setup = whole_car.whole_car_setup(test.car)
car = setup.car
static = setup.tire.static

# %%
# The car from above, with the road tracks its belt strips run on
ru.figures.whole_car.plot_car_layout(car, ru.road.two_track.wheel_tracks(static, car.positions))
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The body and the geometry
b = car.body
print(
    f"sprung body: {b.mass:.0f} kg, pitch inertia {b.pitch_inertia:.0f} kg m^2, roll inertia {b.roll_inertia:.0f} kg m^2"
)
print(f"wheelbase {car.wheelbase:.2f} m, centre of mass {car.cg_to_front:.2f} m behind the front axle, "
      f"tracks {car.track_front:.2f} / {car.track_rear:.2f} m")  # fmt: skip
print(f"tracks of the 3-D road: {ru.road.two_track.wheel_tracks(static, car.positions).size}")

# %% [markdown]
# The car's modes on its tires, from the closed model (python-control, `setup.model`: the four
# $F_F$ in, 18 outputs): the body's heave, pitch and roll near 1.5 Hz, each corner's wheel hop
# near 14 Hz. The corner dampers are the quarter car's, so the body modes are well damped. The
# car is symmetric left to right: in each wheel-hop mode both wheels of an axle carry the same
# kinetic energy (in phase or in opposition), so both are named.

# %%
# NBVAL_CHECK_OUTPUT
# Modes below 30 Hz: frequency, damping ratio and the DOF that carries most of the kinetic energy
modes = full_car.car_modes(car, setup.model, setup.tire.tire_hub_mass)
for _, m in modes.iterrows():
    print(f"{m['frequency (Hz)']:6.2f} Hz  zeta {m['damping ratio']:.2f}  {m['dominant DOF']}")
print(f"closed car stable: {bool(np.max(setup.model.poles().real) < 0)} ({setup.model.nstates} states)")

# %% [markdown]
# ## 2. The road test: every corner and the body
#
# The paper's road test (120 km/h, the rough texture, 10 s) under the whole car. One 3-D road
# carries a track for every belt strip of all four wheels (`road.two_track.two_track_road`),
# jointly Gaussian with the isotropic surface's coherence (Kropáč & Múčka 2009, notebook 06);
# each wheel's tasselli see their own lateral positions, the front axle a wheelbase ahead.

# %%
# NBVAL_IGNORE_OUTPUT
# Road -> four wheels' tassello inputs -> four fixed-hub forces -> the closed car -> spectra
result = whole_car.whole_car_run(setup, test.spectrum, test.speed_kmh / 3.6, test.duration, test.seed)
spectra = result.spectra
print(f"{result.run.t.size} samples x 4 wheels, road to all spectra in {result.seconds:.2f} s")

# %%
# Hub and top-mount accelerations at every corner (the Fig. 11-12 analogues for all four)
fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
ru.figures.whole_car.plot_corner_spectra(spectra.freqs, spectra.psd, "a_hub", (0.0, 250.0), ax=top)
ru.figures.whole_car.plot_corner_spectra(spectra.freqs, spectra.psd, "a_mount", (0.0, 250.0), ax=bottom)
top.set_title(f"every corner at {speed_kmh:.0f} km/h on the {texture} texture (3-D road)")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# RMS 2-250 Hz per corner (m/s^2)
for corner in full_car.CORNERS:
    hub = ru.vehicle.spectra.band_rms((spectra.freqs, spectra.psd[f"a_hub_{corner}"]))
    mount = ru.vehicle.spectra.band_rms((spectra.freqs, spectra.psd[f"a_mount_{corner}"]))
    print(f"{corner}: hub {hub:.2f}, top mount {mount:.2f} m/s^2 RMS")

# %% [markdown]
# The body sees the suspension's forces summed: its heave, pitch and roll accelerations fall
# from the body modes, with the wheel hops' bump near 14 Hz, and carry the tire's modes above
# 80 Hz only as far as the struts pass them (notebook 07, Fig. 10).

# %%
# The body: heave, pitch and roll accelerations
fig = ru.figures.whole_car.plot_body_spectra(spectra.freqs, spectra.psd, (0.0, 250.0))
fig.suptitle(f"the body at {speed_kmh:.0f} km/h on the {texture} texture")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Body RMS 2-250 Hz and 0.5-20 Hz
for name, unit in (("a_heave", "m/s^2"), ("a_pitch", "rad/s^2"), ("a_roll", "rad/s^2")):
    full = ru.vehicle.spectra.band_rms((spectra.freqs, spectra.psd[name]))
    low = ru.vehicle.spectra.band_rms((spectra.freqs, spectra.psd[name]), band=(0.5, 20.0))
    print(f"{name[2:]}: {full:.3f} {unit} RMS in 2-250 Hz, {low:.3f} in 0.5-20 Hz")

# %% [markdown]
# ## 3. The wheelbase filtering, and the check of the time domain
#
# On a road uniform across the width both wheels of an axle see one force, and the front axle
# sees the rear's a time $L/V$ earlier: $F_{front}(f) = F_{rear}(f)\,e^{i 2\pi f L/V}$, so
#
# $$y(f) = \big[(H_{FL} + H_{FR})\,e^{i 2\pi f L/V} + H_{RL} + H_{RR}\big]\,F_{rear}(f).$$
#
# On a car symmetric front to rear the pitch cancels at $f = kV/L$ and the heave at
# $f = (k + \tfrac12) V/L$: the **wheelbase filtering**. Our car is not symmetric (60 % of its
# weight on the front), so its notches are dips, not zeros; the closed form is checked on its
# symmetric variant (the same front corner at both axles, the centre of mass mid-way).
#
# At the check's speed (`[wheelbase_check]`) the notches are $V/L$ apart; the sample rate puts
# the delay on a whole number of samples, and the time domain is compared octave by octave with
# the frequency domain *as the Welch estimate sees it* (`vehicle.spectra.expected_psd`: the
# predicted PSD through the Hann window's spectral kernel). Compared with the raw PSD instead,
# the steep body spectra of 20-40 Hz read 0.68-0.80: the window's leakage and the rectangle sums
# of a steep spectrum, not the model.

# %%
# NBVAL_IGNORE_OUTPUT
# The 2-D road at the check's speed (cached run) and the frequency domain of Eq. 8 with the delay
check = whole_car.wheelbase_check(setup, test)
notches = whole_car.notch_frequencies(check.speed, check.wheelbase, 100.0)

# %%
# The wheelbase filtering: heave and pitch, time and frequency domain, the symmetric car's notches
ru.figures.whole_car.plot_wheelbase_filtering(check, notches, (0.5, 100.0))
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Octave band power, time domain over the Welch expectation of the frequency domain
print(f"{check.speed * 3.6:.0f} km/h, notches {check.speed / check.wheelbase:.2f} Hz apart")
print(check.ratios.to_string(float_format=lambda v: f"{v:.2f}"))
print(f"largest |ratio - 1|: {float((check.ratios - 1).abs().to_numpy().max()):.2f}")

# %%
# NBVAL_CHECK_OUTPUT
# The closed form: on the symmetric car, pitch at k V/L and heave at (k + 1/2) V/L (20 m/s)
depth = whole_car.notch_depth(setup, 20.0)
for name, row in depth.iterrows():
    print(f"{name[2:]}: {row['notches']:.0f} notches from {row['first (Hz)']:.2f} Hz, "
          f"largest at a notch / peak < 1e-12: {bool(row['largest at a notch / peak'] < 1e-12)}")  # fmt: skip
print(
    f"heavy body (x 1e9) vs the quarter car: largest difference < 1e-7: {whole_car.heavy_body_difference(car) < 1e-7}"
)

# %% [markdown]
# ## 4. Left and right: the coherence of the road forces
#
# Two wheel tracks $b$ apart on an isotropic road have the coherence $\gamma^2(n, b)$ of
# notebook 06: near 1 for wavelengths much longer than $b$, near 0 for shorter ones. A wheel's
# force averages its own footprint (0.15 m wide), much narrower than the track (1.48 m), so the
# left and right road forces of an axle should be exactly as coherent as the road tracks a
# track apart (`vehicle.car_spectra`: the strips' shares $A_s$ of $F_F$ summed over every strip
# pair). A slower, longer run of the front axle alone on a 3-D road of its two wheels' tracks
# (`[coherence]`) estimates it in the time domain.

# %%
# NBVAL_IGNORE_OUTPUT
# The coherence run (3-D road, cached) and the frequency domain
coh = whole_car.axle_coherence(setup, test)

# %%
# Coherence of the front axle's left and right road forces
ax = ru.figures.whole_car.plot_axle_coherence(coh)
ax.set_title(
    f"front axle at {test.coherence_speed_kmh:.0f} km/h, {test.coherence_duration:.0f} s of the {texture} texture"
)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Predicted force coherence vs the road's, and the time-domain estimate where the coherence is strong
strong = coh.predicted > 0.3
z = (coh.estimated - coh.predicted) / coh.deviation
print(f"largest |force - road| coherence, 0-15 Hz: {np.abs(coh.predicted - coh.road).max():.3f}")
print(f"where it exceeds 0.3 ({coh.freqs[strong].min():.1f}-{coh.freqs[strong].max():.1f} Hz): "
      f"estimate within {np.abs(z[strong]).max():.1f} standard deviations of the prediction")  # fmt: skip
print(f"above 10 Hz: predicted below {coh.predicted[coh.freqs > 10].max():.3f}")

# %% [markdown]
# Above a few hertz at 60 km/h the two wheels of an axle are driven independently; the estimate
# scatters around the prediction by the Welch estimate's own noise: ~60 windows, a standard
# deviation of $\sqrt{2}(1 - \gamma^2)|\gamma|/\sqrt{n_d}$ (Bendat & Piersol, *Random Data*,
# Eq. 9.82; 0.07 at $\gamma^2 = 0.45$) and a bias near $1/n_d$ where the coherence is small.
#
# ## 5. Paper vs ours
#
# The paper has no whole-car result to compare with: these are checks *beyond the
# paper*, each against its closed form, its independent computation or the cited measurements
# (`data/paper/claims.toml`, marked `beyond`), evaluated on both tire models and counted apart
# from the paper's claims.

# %%
# The checks of this chapter, our values and the verdicts
claims = ru.claims.report(notebook="11-whole-car.ipynb")
claims.drop(columns="notebook")

# %%
# NBVAL_CHECK_OUTPUT
# Verdicts; every check passes or is a documented deviation
print(ru.claims.verdicts(claims))
ru.claims.check(claims)

# %% [markdown]
# ## Explore: speed and texture
#
# The callback runs the whole chain on a 2-D road (4 s; the package's `whole_car_run`) and shows
# the front hub, the rear top mount and the heave.

# %%
# NBVAL_IGNORE_OUTPUT
# Widget: the whole car's spectra for any speed and texture
from ipywidgets import Dropdown, FloatSlider, interact


def show_whole_car(speed_kmh, texture):
    run = whole_car.whole_car_run(
        setup, ru.textures.load_texture(texture), speed_kmh / 3.6, 4.0, test.seed, lateral=False
    )
    psd = run.spectra.psd
    curves = {"front-left hub": psd["a_hub_FL"], "rear-right top mount": psd["a_mount_RR"], "heave": psd["a_heave"]}
    ax = ru.figures.quarter_car.plot_spectra(
        run.spectra.freqs, curves, "acceleration ASD ((m/s²)/√Hz)", (0.0, 250.0), log=True
    )
    ax.set_title(f"the whole car at {speed_kmh:.0f} km/h on the 2-D {texture} road")
    plt.show()


_ = interact(
    show_whole_car,
    speed_kmh=FloatSlider(value=speed_kmh, min=30.0, max=160.0, step=10.0, continuous_update=False),
    texture=Dropdown(options=["rough", "smooth"], value=texture),
)

# %% [markdown]
# **Next:** notebook 12 sweeps the tire file's design parameters; notebook 13 runs the chain on
# every tire model, notebook 14 adds the air cavity.
