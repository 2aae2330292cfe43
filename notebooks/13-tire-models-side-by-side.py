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
# # 13 — The tire models side by side: the ring, the cross-section and a tire from files
#
# The RM method is a pipeline from *any* finite-element tire's footprint FRFs to a time-domain
# tire (paper Fig. 1 and 4): "the local FRFs ... are computed on the FET model" and everything
# after them — the fits (Eq. 1), the state space (Eq. 2-4), the moving hub (Eq. 5-7), the car
# (Eq. 8) — uses nothing else. Every stage of the collection asks the tire through one interface,
# `ru.TireModel` (`tire/model.py`): `load(case)` gives the loaded footprint (its tasselli, their
# FE weights, the pressure map, $K_v$), `fixed_hub_frfs(case)` the local FRFs $H_i$, $H_{tot}$ and
# $G_H$; the rest are optional capabilities a model may lack. Three models implement it:
#
# * **ring** (notebook 01): a ring on springs, tread points on the belt — the paper's FET at
#   its own size;
# * **cross-section** (notebook 09): layered solid elements from bead to tread, every
#   circumferential harmonic a small problem, the footprint coupling them;
# * **frf-file**: *your* FE tire — the footprint FRFs as UFF 58, the footprint as a CSV, a
#   tire file naming them with the load and the rim-side mass.
#
# Here the third is the cross-section tire written to such files (`ru.experiments.tire_as_files`),
# exactly what an FE code would hand over, so that it must give back the cross-section's numbers.
# The paper's Fig. 2, 5, 9 and 14 follow on every model.

# %%
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

import roadnoise_utils as ru
from roadnoise_utils.experiments import tire_models, whole_car

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): the paper's tire (Fig. 2-9) and the car's tire (Fig. 14), each as a ring
# and from its cross-section; the files are written from the cross-section model
tire_size = "165_65R14"
car_tire_size = "195_65R15"

# %%
# The parameters above, checked before anything runs: a wrong one is refused naming it and its valid values
ru.experiments.check_parameters(tire_size=tire_size, car_tire_size=car_tire_size)

# %%
# The three models of each tire: our two FE tires and the cross-section one written as files
conditions = ru.experiments.cleat_conditions()
section_name = f"{tire_size}_cross_section"
files = tire_models.tire_as_files(section_name, ("flat", "drum"), conditions.drum_radius)
tires = {"ring": tire_size, "cross-section": section_name, "from files": files}

# %% [markdown]
# ## 1. One interface, three models
#
# What each model can do beyond the interface's core. A stage whose capability a model lacks
# refuses it with `ru.NotApplicable`, naming the capability; a chapter prints
# "not applicable: ..." and goes on, and a paper claim is reported "n/a" with the reason.

# %%
# NBVAL_CHECK_OUTPUT
# The optional capabilities of each model
print(tire_models.capability_table(tires).to_string())

# %% [markdown]
# ## 2. Fig. 2 on every model: the footprint and its tasselli
#
# The same load on a flat road; one colour scale for the three maps.

# %%
# Fig. 2 analogue: pressure map and tasselli of every model, one colour scale
footprints = {label: ru.stages.solve_static(tire) for label, tire in tires.items()}
p_max = max(f.node_pressure.max() for f in footprints.values()) / 1e6
fig, axes = plt.subplots(1, 3, figsize=(16, 4.2))
for ax, (label, footprint) in zip(axes, footprints.items()):
    ru.figures.fe_tire_model.plot_footprint(footprint, ax, numbers="some", vmax=p_max)
    ax.set_title(f"{label}: {footprint.tasselli.n} tasselli")
fig.suptitle("Fig. 2 analogue: contact pressure and tasselli, flat road")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The footprint of every model
for label, f in footprints.items():
    print(f"{label:13s}: {f.footprint_length * 1e3:5.1f} x {f.footprint_width * 1e3:5.1f} mm, {f.tasselli.n:3d} tasselli, "
          f"K_v {f.vertical_stiffness / 1e3:6.1f} N/mm, deflection {f.deflection * 1e3:5.2f} mm")  # fmt: skip

# %% [markdown]
# ## 3. Fig. 5 on every model: the sum of the local FRFs against the whole footprint
#
# The paper's procedure (Fig. 4) builds the local FRFs from a modal reduction of the loaded FE
# tire; notebook 02 runs it on the ring. The cross-section tire builds its modal reduction by a
# component-mode synthesis (MacNeal 1971; Craig & Kurdila, *Fundamentals of Structural
# Dynamics*, ch. 19; notebook 09, section 7): the free modes of every harmonic, the residual
# flexibility of the rest at the contact points, the footprint held by point forces — the
# result has the ring's form, so steps 1-3 of Fig. 4 run unchanged (it has no separate solve of
# the loaded eigenmodes, hence `loaded_modes` above). A tire from files has
# FRFs and no FE model to reduce: its $\sum_i H_i$ is checked against its $H_{tot}$ directly.

# %%
# NBVAL_IGNORE_OUTPUT
# Direct FRFs of every model and the paper's modal reduction where the model has one (cached stages)
visco = {label: ru.stages.frf_visco(tire) for label, tire in tires.items()}
default = "frozen complex + identified damping (default)"
variants = {
    label: {
        "paper: storage moduli + identified damping": ru.stages.modal_reduction(tire, frozen="storage"),
        default: ru.stages.modal_reduction(tire),
    }
    for label, tire in tires.items()
    if ru.experiments.applicable(tire, "modal_reduction")
}
f_frozen = ru.claims.paper_value("freezing_frequency")  # data/paper/claims.toml

# %%
# Fig. 5 analogue on every model: |H_tot| (direct) vs |sum_i H_i| of the modal models (or of the files)
fig, axes = plt.subplots(1, 3, figsize=(17, 4.5), sharey=True)
for ax, (label, frf) in zip(axes, visco.items()):
    sums = {k: v.frf for k, v in variants[label].items()} if label in variants else {"sum of the files' H_i": frf}
    ours = {"ours: freezing frequency": variants[label][default].reference_frequency} if label in variants else {}
    lines = {"paper: freezing frequency": f_frozen, **ours}
    ru.figures.superposition.plot_superposition(frf, sums, f_max=300, ax=ax, paper=lines)
    ax.set_title(f"{label}: {ru.load_tire(tires[label]).name}")
fig.suptitle("Fig. 5 analogue on every model: H_tot (direct) against the sum of the H_i")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Relative error of sum_i H_i (modal) against H_tot (direct) per band, and the files' own superposition
bands = ((0.0, 100.0), (100.0, 150.0), (150.0, 250.0))
for label, by_variant in variants.items():
    for name, variant in by_variant.items():
        errors = ru.analysis.band_errors(visco[label].freqs, visco[label].H_tot, variant.frf.H_sum, bands)
        print(
            f"{label}, {name}: complex relative RMS "
            + ", ".join(f"{b} {e:.3f}" for b, e in errors["complex rel. RMS"].items())
        )
own = visco["from files"]
print(
    f"from files: max |sum_i H_i - H_tot| / |H_tot| {ru.analysis.format_small(np.max(np.abs(own.H_sum - own.H_tot) / np.abs(own.H_tot)))}"
)

# %% [markdown]
# The complex-frozen model follows both FE tires within a few per cent below 100 Hz. The
# paper's procedure as written does not on the cross-section tire: freezing only the storage
# moduli takes the rubber loss out of the loaded modes and out of the footprint's residual
# flexibility — on this tire the road reaches the modes through the tread rubber itself — so
# its resonance comes out with too much phase lag; with the complex moduli frozen and the same
# identified damping the error drops close to the ring's. The frozen cross-section tire also
# underestimates its higher modes by several times the ring's shift (notebook 02, section 4;
# notebook 09, section 7):
# in the ring most of the stiffness is the inflation pressure, which does not depend on
# frequency; here the rubber's share is larger.

# %% [markdown]
# ## 4. Fig. 9 on every model: the cleat test
#
# The same drum, cleat and speeds (notebook 04) on every model: drum footprint, tasselli, direct
# FRFs, fits, state space, the two runs. The FE check (the force straight from the FE model,
# capability `direct_response`) runs where the model has it.

# %%
# NBVAL_IGNORE_OUTPUT
# The paper's cleat test on every model (cached stages)
tests = {
    label: ru.experiments.cleat_test(tire, conditions=conditions, fe_reference=ru.tire_model(tire).has("direct_response"))
    for label, tire in tires.items()
}  # fmt: skip
paper = {  # data/paper/claims.toml
    "paper: measured quasi-static peak": ru.claims.paper_value("cleat_quasi_static", "measured"),
    "paper: simulated quasi-static peak": ru.claims.paper_value("cleat_quasi_static"),
    "paper: dynamic peak (≈ 2.2 x measured)": ru.claims.paper_value("cleat_dynamic"),
}

# %%
# Fig. 9 analogue on every model, with the paper's peaks
fig, axes = plt.subplots(1, 3, figsize=(17, 4.5), sharey=True)
for ax, (label, run) in zip(axes, tests.items()):
    ru.figures.cleat_test.plot_cleat_runs(
        {f"base curve ({conditions.quasi_static_kmh} km/h)": run.quasi_static, f"{conditions.dynamic_kmh:.0f} km/h": run.dynamic},
        ax=ax, title=f"{label}: {run.system.nstates} states, {run.static.tasselli.n} tasselli", paper=paper,
    )  # fmt: skip
fig.suptitle("Fig. 9 analogue on every model: the cleat test with the paper's peaks")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The cleat test on every model against the paper's simulation (1200 N, 1870 N)
table = pd.concat({label: run.to_frame()["ours"] for label, run in tests.items()}, axis=1)
print(table.to_string(float_format=lambda v: f"{v:.3f}"))
for label, run in tests.items():
    q, d = run.quasi_static.peak_force, run.dynamic.peak_force
    fe = "no FE model" if run.fe_reference is None else (
        f"RM vs FE peak {run.fe_reference.peak_difference:+.2%}, RMS {run.fe_reference.rms_difference:.2%}")  # fmt: skip
    print(f"{label}: quasi-static {q / paper['paper: simulated quasi-static peak'] - 1:+.0%} of the paper's 1200 N, "
          f"30 km/h {d / paper['paper: dynamic peak (≈ 2.2 x measured)'] - 1:+.0%} of its 1870 N; {fe}")  # fmt: skip
same = np.abs(tests["from files"].dynamic.result.force - tests["cross-section"].dynamic.result.force).max()
same /= np.abs(tests["cross-section"].dynamic.result.force).max()
print(f"from files vs cross-section, 30 km/h: largest difference {ru.analysis.format_small(same)} of the peak")
assert same < 1e-9

# %%
# Row influences H(0) along the drum footprint on every model
fig, axes = plt.subplots(1, 3, figsize=(17, 3.8), sharey=True)
rows = {}
for ax, (label, tire) in zip(axes, tires.items()):
    rows[label], k_v = tire_models.drum_rows(tire, conditions.drum_radius)
    ru.figures.cleat_test.plot_row_influence(rows[label], tests[label].static, conditions.base, ax=ax)
    ax.set_title(f"{label}: K_v = {k_v / 1e3:.0f} N/mm on the drum")
fig.suptitle("Static influence H(0) of each row along the drum footprint, every model")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The entry row, and the share of K_v in the two outer rows at each end
for label, row in rows.items():
    h = row["H(0) of the row (N/mm)"]
    print(
        f"{label:13s}: entry row {h.iloc[0]:5.1f} N/mm ({h.iloc[0] / h.sum():.0%} of K_v), "
        f"two outer rows each end {ru.experiments.cleat.edge_share(row):.0%} of K_v, {len(h)} rows"
    )

# %% [markdown]
# Both FE tires reproduce the *shape* of the paper's simulation — two peaks, then a decay (led
# by the first vertical mode, 82 Hz, on the cross-section tire; by its 107 Hz mode on the ring) — and the RM chain follows each FE solve within the fit error.
# Neither reproduces the *size*: the peak is about the entry row's $H(0)$ times the cleat's mean
# height over a row (~8 mm), so the paper's 1200 N needs an entry row of ~150 N/mm — well over
# half of $K_v$ — where ours carry the shares printed above. Both share a push at the footprint
# edge between the entry row and its neighbours: the cross-section tire through its belt's
# bending and shear, the ring through a beam on springs (notebook 04). The cross-section tire rings more (its dynamic /
# quasi-static ratio, against the paper's 1870 / 1200 = 1.56). The tire from files gives the
# cross-section's forces to round-off: the RM chain needs nothing but the files. What the linear
# models cannot do — lose contact next to the cleat — notebook 08 adds.
#
# ## 5. Fig. 14 on every model: the car's tire in the hub acceleration
#
# The quarter car of notebook 07 at 120 km/h on the rough texture, its tire the 195/65 R15 as a
# ring, from its cross-section and from the cross-section's files; the hub acceleration from the
# frequency-domain prediction (checked against the time domain in notebook 07).

# %%
# NBVAL_IGNORE_OUTPUT
# The corner on every model of the car's tire (cached stages; the cross-section's shoulder tasselli may warn that no fit order reaches 1 %)
road_test = ru.experiments.road_test_conditions()
shown = road_test.textures[0]  # the rough texture of the paper's test
car = ru.vehicle.load_vehicle(f"midsize_{car_tire_size}")
car_section = f"{car_tire_size}_cross_section"
car_tires = {"ring": car_tire_size, "cross-section": car_section, "from files": tire_models.tire_as_files(car_section)}
f_check = np.arange(2.0, 251.0, 1.0)
setups = {label: ru.experiments.corner_setup(car, tire=tire) for label, tire in car_tires.items()}
by_model = {
    label: s.predicted(f_check, road_test.spectra()[shown], road_test.speed)["a_hub"] for label, s in setups.items()
}
car_visco = {label: ru.stages.frf_visco(tire) for label, tire in car_tires.items()}
modes = {label: ru.response.modal_reduction.identify_modes(f.freqs, f.H_tot) for label, f in car_visco.items()}

# %%
# Fig. 14 analogue on every model: hub acceleration 40-220 Hz (frequency domain, 2-D rough road)
in_band = (f_check >= 40) & (f_check <= 220)
hub_peaks = {
    label: ru.analysis.resonance_peaks(f_check[in_band], np.sqrt(psd[in_band]), min_ratio=0.0)[0]
    for label, psd in by_model.items()
}
ax = ru.figures.quarter_car.plot_spectra(
    f_check[in_band], {k: v[in_band] for k, v in by_model.items()}, "hub acceleration ASD ((m/s²)/√Hz)",
    (40.0, 220.0), log=True, styles=("-", "-", "--"),  # the files' curve dashed: it lies on the cross-section's
    peaks=hub_peaks,
)  # fmt: skip
ax.set_title(f"Fig. 14 analogue, every model: {road_test.speed_kmh:.0f} km/h, {shown} texture, peaks marked")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Peaks of the hub acceleration 40-220 Hz on each model, and the tire's identified vertical modes
for label, found in hub_peaks.items():
    print(f"{label:13s}: hub peaks at " + ", ".join(f"{fp:.0f}" for fp in found) + " Hz; vertical modes in H_tot "
          + ", ".join(f"{fm:.0f}" for fm in modes[label].freqs) + " Hz")  # fmt: skip

# %% [markdown]
# The cross-section tire's $H_{tot}$ has one strong resonance — its higher vertical modes nearly
# cancel when the whole footprint moves together — yet the hub shows a row of peaks above it.
# The rolling road does not move the footprint together: each row of tasselli sees the road
# later than the one before, and those phase differences drive the modes the uniform push
# cancels. The tasselli's own FRFs carry them (notebook 03), so the RM chain does too. They are
# broad: this tire's rubber damps its modes several times more than the ring's (notebook 09).
#
# ## 6. The whole car on every model
#
# The car of notebook 11 on each model of its tire (fits and $G_H$ at every corner),
# frequency domain, 2-D road at 120 km/h.

# %%
# NBVAL_IGNORE_OUTPUT
# The whole car on every model (cached stages)
car_test = whole_car.whole_car_conditions()
f_car = np.arange(0.5, 250.0, 0.5)
car_setups = {label: whole_car.whole_car_setup(car_test.car, tire=tire) for label, tire in car_tires.items()}
car_psd = whole_car.predicted_2d(car_setups, car_test.spectrum, car_test.speed_kmh / 3.6, f_car)

# %%
# Front hub and body heave on every model (frequency domain, 2-D road)
fig = ru.figures.whole_car.plot_hub_and_heave(
    f_car, car_psd, ("tab:red", "tab:blue", "tab:green"), (0.0, 250.0), styles=("-", "-", "--")
)
fig.suptitle(f"every tire model under the whole car, {car_test.speed_kmh:.0f} km/h, 2-D {car_test.texture} road")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# RMS 2-250 Hz on every model (frequency domain)
for label, psd in car_psd.items():
    hub = ru.vehicle.spectra.band_rms((f_car, psd["a_hub_FL"]))
    heave = ru.vehicle.spectra.band_rms((f_car, psd["a_heave"]))
    print(f"{label:13s}: front-left hub {hub:.2f} m/s^2, heave {heave:.3f} m/s^2 RMS")

# %% [markdown]
# ## Your own tire
#
# An FE code that computes footprint FRFs writes the same three files: for each load case a
# UFF 58 file (`ru.response.uff.write_uff58` shows the sets: $H_i$ per tassello, $H_{tot}$ and,
# optionally, $G_H$) and a footprint CSV (`ru.tire.footprint_file`: each tassello's nodes with
# their FE weights and outlines), and a tire file naming them with the load, $K_v$ and the
# rim-side mass (the one written above is at `files`). Any chapter then takes the tire file's
# path as its `tire_name`; without $G_H$ the moving hub, the quarter car and the whole car are
# "not applicable".

# %%
# NBVAL_IGNORE_OUTPUT
# The tire file written above
print(files.read_text())

# %% [markdown]
# **Next:** notebook 14 adds the air cavity to the tire models.
