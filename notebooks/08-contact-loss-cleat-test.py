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
# # 08 — Beyond the paper: contact loss in the cleat test
#
# **Beyond the paper** (section *Validation of the Model for Fixed Hub*, Fig. 8-9).
#
# The paper's RM model is linear: every tread point of the static footprint stays tied to the
# road. The authors compare it with a drum test (165/65 R14, 2.3 bar, 4512 N, drum R = 1.25 m,
# triangular cleat 15 mm × 15 mm) and find the simulated quasi-static peak, 1200 N, above the
# measured 850 N — which they attribute to a nonlinearity their model cannot show: "the
# contact between tire and obstacle is lost" next to the cleat. The cleat is 15 mm high
# against a static deflection of about 28 mm, so the tread on either side of it lifts off.
#
# Here the FE tire itself (not the RM chain) meets the drum through **one-sided** tread
# contact, and the results are judged against the paper's *measurement*; the linear chain of
# notebook 04 stays judged against the paper's *simulation*:
#
# * **quasi-static run** — a sequence of exact contact solves (active set on the static
#   compliance condensed onto the tread points) while the cleat moves, hub held;
# * **dynamic run** — implicit Newmark stepping (average acceleration) of every belt DOF with
#   the frequency-dependent rubber and layer laws in their Prony form (one auxiliary state per
#   Maxwell branch: the *same* viscoelastic model as the frequency domain, not a modal damping
#   frozen at one frequency), lift-off and re-contact at every step.
#
# Contact is vertical and frictionless, as in the static solve; the paper's own check (our
# notebook 02) finds the longitudinal footprint motion insignificant for the vertical hub force.

# %%
import matplotlib.pyplot as plt
import numpy as np

import roadnoise_utils as ru

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): tire file; None takes data/conditions/cleat_test.toml ([cleat], [speeds], [one_sided])
tire_name = "165_65R14"
n_elements = None

# %% [markdown]
# ## 1. The refined tire on the drum
#
# Contact loss happens over a few millimetres, so the one-sided runs use the tire with its
# circumference refined (``[one_sided] n_elements``); everything else is the tire file of
# notebook 01. The mesh study in section 5 shows why.

# %%
# NBVAL_IGNORE_OUTPUT
# Both one-sided runs (cached stages): quasi-static contact solves and the dynamic run at 30 km/h
conditions = ru.experiments.one_sided_conditions(n_elements=n_elements)
test = ru.experiments.one_sided_cleat_test(tire_name, conditions=conditions)
linear = ru.experiments.cleat_test(tire_name, conditions=conditions.cleat)
cleat = conditions.cleat

# %%
# NBVAL_CHECK_OUTPUT
# The refined tire and its static state on the drum
drum = test.static
print(
    f"{test.tire.name}: {test.tire.mesh.n_elements} elements, contact points "
    f"{2 * np.pi * test.tire.geometry.outer_radius / test.tire.mesh.n_elements * 1e3:.1f} mm apart"
)
print(
    f"on the drum: deflection {drum.deflection * 1e3:.1f} mm, footprint {drum.footprint_length * 1e3:.0f} mm long, "
    f"{int(drum.contact.sum())} tread points in contact; cleat {cleat.height * 1e3:.0f} mm high"
)

# %% [markdown]
# ## 2. The measured test, simulated with contact loss (Fig. 8 analogue)
#
# Solid: one-sided contact; dashed: the linear RM chain of notebook 04 (tied footprint). The
# paper's measured quasi-static peak and the measured dynamic peak (≈ 2.2 × 850 N) are drawn as
# reference lines.

# %%
# Fig. 8 analogue: quasi-static and 30 km/h, one-sided contact vs the linear chain, with the measured peaks
measured = {
    "paper: measured quasi-static peak": ru.claims.paper_value("contact_quasi_static"),
    "paper: measured dynamic peak (≈ 2.2 x 850 N)": ru.claims.paper_value("contact_dynamic"),
}
ru.figures.contact_loss.plot_contact_runs(
    {"one-sided, quasi-static": test.quasi_static, f"one-sided, {cleat.dynamic_kmh:.0f} km/h": test.dynamic},
    {"linear chain, quasi-static": linear.quasi_static, f"linear chain, {cleat.dynamic_kmh:.0f} km/h": linear.dynamic},
    title="Fig. 8 analogue: hub force over the cleat with contact loss",
    paper=measured,
)
plt.xlim(-0.15, 0.4)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The measured test's quantities: one-sided contact against the linear chain
table = test.to_frame()
table["linear chain"] = linear.to_frame()["ours"].reindex(table.index)
print(table.to_string(float_format=lambda v: f"{v:.3f}"))
print("two largest peaks at 30 km/h (one-sided):\n" + test.peaks.to_string(float_format=lambda v: f"{v:.3f}"))

# %% [markdown]
# The tread lifting off next to the cleat removes the tension the tied footprint of the linear
# model puts on either side of it, so the force the cleat sends to the hub roughly doubles.
# The cleat also meets the tread well *ahead* of the static footprint (the tread rises only
# slowly off the drum): the one-sided force starts about 0.1 m before the axle.

# %%
# Tread points in contact while the cleat passes
ru.figures.contact_loss.plot_contact_points(
    {"quasi-static": test.quasi_static, f"{cleat.dynamic_kmh:.0f} km/h": test.dynamic}, int(drum.contact.sum())
)
plt.xlim(-0.15, 0.2)
plt.show()

# %% [markdown]
# ## 3. Peak against speed
#
# The linear chain and the one-sided FE run side by side from 15 to 60 km/h (the passage only).

# %%
# NBVAL_CHECK_OUTPUT
# Peak hub force against speed (N)
sweep = ru.experiments.speed_sweep(tire_name, conditions=conditions)
print(sweep.to_string(float_format=lambda v: f"{v:.0f}"))

# %%
# The speed sweep with the measured peaks
ax = ru.figures.contact_loss.plot_speed_sweep(sweep, paper=measured)
ax.set_title(
    f"{ru.load_tire(tire_name).name}: the peak hub force against speed, one-sided contact and the linear chain"
)
plt.show()

# %% [markdown]
# ## 4. Verification
#
# **Frozen contact = the linear FE model.** With every static contact point bilateral (no
# lift-off) the time-stepped run is linear and must equal the frequency-domain FE response of
# the same point inputs (notebook 04's second method, here per tread point and with the
# footprint free to slide, as the frictionless contact). Both are band-limited to 250 Hz the
# same way; on the tire file's own mesh.

# %%
# NBVAL_CHECK_OUTPUT
# Frozen-contact time stepping vs the FE frequency domain
frozen = ru.experiments.frozen_check(tire_name, conditions=conditions)
print(
    f"peak: time domain {frozen.time_domain.max():.1f} N, frequency domain {frozen.frequency_domain.max():.1f} N, "
    f"difference {frozen.peak_difference:+.2%}; RMS difference {frozen.rms_difference:.2%}"
)
assert abs(frozen.peak_difference) < 0.02 and frozen.rms_difference < 0.02

# %% [markdown]
# **Contact conditions and force balance.** No tread point out of contact is penetrated, every
# contact force is compressive, and in the quasi-static run the hub reaction equals the sum of
# the contact forces at every step.

# %%
# NBVAL_CHECK_OUTPUT
# Penetration, force balance, active-set iterations
for name, run in {"quasi-static": test.quasi_static, f"{cleat.dynamic_kmh:.0f} km/h": test.dynamic}.items():
    balance = "-" if np.isnan(run.force_balance) else ru.analysis.format_small(run.force_balance, 1e-9)
    print(
        f"{name:13s} largest penetration out of contact {ru.analysis.format_small(run.max_penetration, 1e-12)} m; "
        f"|hub reaction - contact forces| / load {balance}; at most {run.iterations} active-set iterations"
    )
assert test.quasi_static.force_balance < 1e-9 and test.dynamic.max_penetration < 1e-12

# %% [markdown]
# ## 5. Mesh and time step
#
# The quasi-static and the dynamic peak on the tire file's mesh and on the refined one, and the
# dynamic peak at two time steps on the tire file's mesh (cached runs). Refining once more
# (1200 elements) moves the quasi-static peak by under 2 % (the comment in
# `data/conditions/cleat_test.toml` keeps the numbers).

# %%
# NBVAL_CHECK_OUTPUT
# Mesh convergence (N)
study = ru.experiments.one_sided_cleat.convergence(tire_name, conditions=conditions)
for elements, peak in study.quasi_static_peaks.items():
    print(f"{elements:5d} elements: quasi-static peak {peak:6.0f} N")
(coarse_n, coarse_peak), (fine_n, fine_peak) = study.dynamic_peaks.items()
print(f"{cleat.dynamic_kmh:.0f} km/h peak: {coarse_peak:.0f} N at {coarse_n} elements, {fine_peak:.0f} N at {fine_n}")

# %%
# NBVAL_CHECK_OUTPUT
# Time-step convergence of the dynamic peak on the tire file's mesh
(dt, peak), (half_dt, half_peak) = study.step_peaks.items()
print(
    f"dt = {dt * 1e6:.0f} us: {peak:.1f} N; dt = {half_dt * 1e6:.0f} us: {half_peak:.1f} N ({half_peak / peak - 1:+.2%})"
)

# %% [markdown]
# **Vanishing speed.** As the speed goes to zero the dynamic run must tend to the quasi-static
# one. It does so slowly: the fractional rubber laws stiffen like $(\omega\tau)^\alpha$ even
# at a few hertz, and every lift-off is a small impact.

# %%
# NBVAL_CHECK_OUTPUT
# Dynamic runs at the paper's base-curve speed (0.36 km/h) and slower vs the quasi-static run, tire file's mesh
for speed, peak in study.slow_peaks.items():
    quasi_static = study.slow_quasi_static
    print(
        f"{speed * 3.6:.2f} km/h: peak {peak:.1f} N, quasi-static {quasi_static:.1f} N ({peak / quasi_static - 1:+.2%})"
    )

# %% [markdown]
# ## 6. The same test on the tire built from its cross-section
#
# The tire built from its cross-section (notebook 09) has one-sided contact in its static solve
# (active set on the harmonic-sum compliance of its contact grid). Holding the deflection
# instead of the load and moving the cleat under the footprint step by step gives its
# quasi-static base curve (`ru.tire.cross_section.one_sided`): every point of the grid free to
# lift off, frictionless.
#
# Its 30 km/h run steps the tire's dynamics at the contact grid in time
# (`ru.tire.cross_section.stepping`): the tire is axisymmetric, so each of its 401 harmonics is an
# independent small system (its Ritz basis of the frequency domain, ~60-130 coordinates) until
# the contact couples them; every compound keeps its Prony series, as in the ring's run. Two
# things differ from the ring's run, both forced by the model:
#
# * **Passivity.** The linear inflation leaves the belt plies' edges in hoop compression, and
#   harmonics above ~190 (wavelengths under 9 mm) have a direction of *negative* static
#   stiffness, a shoulder-local wrinkle of the smeared ply. The frequency domain sees only a
#   negative compliance term (the contact points barely feel it: the largest effect is at the
#   harmonic where that stiffness crosses zero, 0.3 % of the edge column's compliance); in time
#   it is a real pole that grows e-fold in about 60 µs. The stepped model leaves those
#   directions out of its bases (the static shapes reach them only next to the crossing), and
#   keeps the carcass law (which also scales the indefinite pneumatic stiffness) on the
#   positive part only.
# * **Time integration.** The contact sits directly on the tread's nodes, a constrained
#   system: the trapezoidal rule leaves a non-decaying oscillation at the Nyquist frequency in
#   the contact forces, and with lift-off a chatter that pumps energy in: the footprint never
#   settles after the cleat. The generalised-α scheme (spectral radius 0.5 at infinite
#   frequency, `ru.tire.cross_section.stepping.SPECTRAL_RADIUS`) damps it, with little damping in the
#   band (the frozen check below measures what is left).
#
# The frozen check below measures both changes against the frequency-domain footprint solve.
# The cleat's impact also rings the tread at kHz in the raw hub force (the ring's massless tread
# springs do not ring); the paper's model and its measurement are 0-250 Hz, so the run is
# compared band-limited to 250 Hz, as printed below. The step is 1/6000 s, 24 samples per period
# at 250 Hz: halving it moves that peak by less than 0.5 % (a test holds it there) for twice the work.

# %%
# NBVAL_IGNORE_OUTPUT
# The cross-section tire's runs (cached stages; about a minute on a fresh checkout)
section_tire_name = f"{tire_name}_cross_section"
section = ru.experiments.one_sided_cleat_test(section_tire_name, conditions=conditions)
section_raw = ru.experiments.one_sided_cleat.raw_dynamic(section_tire_name, conditions=conditions)
section_frozen = ru.experiments.frozen_check(section_tire_name, conditions=conditions)
section_stepper = ru.tire.cross_section.stepping.HarmonicStepper(
    ru.section_stages.section_tire(section_tire_name),
    section_raw.dt,
    ru.section_stages.harmonic_reductions(section_tire_name),
)

# %%
# NBVAL_CHECK_OUTPUT
# The stepped model: harmonics, left-out directions, and the frozen check against the frequency domain
dropped = section_stepper.dropped
print(
    f"harmonics 0-{len(section_stepper.cos[0]) - 1}, with their modes up to {section_stepper.n_dynamic}; "
    f"directions of negative static stiffness in the stepped bases, left out: {sum(dropped.values())} "
    f"(harmonics {', '.join(str(n) for n in dropped)})"
)
print(
    f"contact frozen, 30 km/h, 0-250 Hz: peak {section_frozen.peak_difference:+.2%}, "
    f"RMS {section_frozen.rms_difference:.2%} against the frequency-domain footprint solve"
)

# %%
# The cleat test with contact loss on both tire models, with the measured peaks
ru.figures.contact_loss.plot_contact_runs(
    {
        f"ring tire ({ru.load_tire(tire_name).name}), quasi-static": test.quasi_static,
        f"ring tire, {cleat.dynamic_kmh:.0f} km/h": test.dynamic,
        "cross-section tire, quasi-static": section.quasi_static,
        f"cross-section tire, {cleat.dynamic_kmh:.0f} km/h (0-250 Hz)": section.dynamic,
    },
    {},
    title="one-sided contact on both tire models",
    paper=measured,
    raw={"cross-section tire, raw": section_raw},
    x_range=(-0.15, 0.4),
)
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The measured test's quantities on both tire models
both = test.to_frame().rename(columns={"one-sided contact": "ring tire"})
both["cross-section tire"] = section.to_frame()["one-sided contact"]
print(both.to_string(float_format=lambda v: f"{v:.3f}"))
print("two largest peaks at 30 km/h (cross-section):\n" + section.peaks.to_string(float_format=lambda v: f"{v:.3f}"))
print(
    f"raw peak {section_raw.peak_force:.0f} N; largest penetration out of contact "
    f"{ru.analysis.format_small(section_raw.max_penetration, 1e-12)} m (quasi-static "
    f"{ru.analysis.format_small(section.quasi_static.max_penetration, 1e-12)} m); hub force off the cleat "
    f"against the load {ru.analysis.format_small(section.quasi_static.force_balance)}"
)

# %% [markdown]
# Contact loss lifts the cross-section tire's base curve far above its linear peak (notebook 13,
# section 4), to about the measured level, like the ring's: the peak is set by what the tread
# lifting off the drum around the cleat hands over to it, not by the row influences of the
# tied footprint. At 30 km/h the cross-section tire goes further than the ring: nearly the whole
# footprint lifts off while the cleat is under the axle (the fewest points in contact, printed
# above), the tire rides on the cleat, and its two peaks come close to the measured dynamic
# peak, with a dynamic amplification close to the measured 2.2 (the ring stays near the 1.56
# of the paper's own simulation). The decay after the cleat is the first vertical mode at
# ~82 Hz with ~6 % damping, as measured.

# %% [markdown]
# ## 7. Paper vs ours

# %%
# The measured-test claims, judged on the one-sided runs
claims = ru.claims.report(notebook="08-contact-loss-cleat-test.ipynb")
claims.drop(columns="notebook")

# %%
# NBVAL_CHECK_OUTPUT
# Verdicts; every claim passes or is a documented deviation
print(ru.claims.verdicts(claims))
ru.claims.check(claims)

# %% [markdown]
# ## Explore: speed and cleat height
#
# The callback runs the one-sided passage on the tire file's own mesh (a few seconds).

# %%
# NBVAL_IGNORE_OUTPUT
# Widget: one-sided passage at any speed and cleat height
from ipywidgets import FloatSlider, interact


def show_contact(speed_kmh, height_mm):
    spec = ru.stages.load_tire(tire_name)
    run = ru.stages.one_sided_run(
        spec, speed_kmh / 3.6, height_mm / 1e3, cleat.base, cleat.shape, cleat.drum_radius, conditions.sweep_distance
    )
    ru.figures.contact_loss.plot_contact_runs({f"{speed_kmh:.0f} km/h": run}, {}, title=f"peak {run.peak_force:.0f} N")
    plt.show()


_ = interact(
    show_contact,
    speed_kmh=FloatSlider(value=cleat.dynamic_kmh, min=5.0, max=80.0, step=5.0, continuous_update=False),
    height_mm=FloatSlider(value=cleat.height * 1e3, min=2.0, max=25.0, step=1.0, continuous_update=False),
)

# %% [markdown]
# **Next:** notebook 09 builds the second FE tire from its cross-section, whose one-sided runs
# this chapter drew beside the ring's; notebook 00's report judges both against the measured test.
