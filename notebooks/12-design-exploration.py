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
# # 12 — Beyond the paper: design exploration, sweeps of the tire file on dask
#
# **Abstract and Conclusions of the paper.** Because the RM model is identified from finite-element
# calculations and not from measurements, the authors note that it "can be used to predict the
# dynamical characteristics of tires which haven't been built yet, speeding up the optimization
# process of tires under development" (abstract), "from the earliest stage of its design"
# (Conclusions). This chapter does that: it changes parameters of the tire file — inflation
# pressure, tread stiffness, belt bending stiffness, load — and runs, for every design, the
# chain of the earlier chapters:
#
# * the vertical stiffness $K_v$ and the footprint (notebook 01),
# * the first vertical resonance $f_1$ of the fixed-hub tire and its damping ratio $\zeta_1$
#   (notebooks 01-02),
# * the peak hub force of the paper's cleat test with the linear RM chain (Fig. 9, notebook 04)
#   and, optionally, with one-sided contact of the FE tire (notebook 08),
# * the hub acceleration of the quarter car on the rough road, 40-220 Hz (Fig. 14, notebook 07).
#
# `ru.experiments.sweep` runs the designs on a local dask cluster (one single-threaded process
# per core), or on a cluster whose address you give, or one after the other in this process
# (`scheduler="serial"`). Each design's result is cached, so an interrupted sweep resumes where
# it stopped. The table it returns has one row per design, SI units in its column names.

# %%
import matplotlib.pyplot as plt
import numpy as np

import roadnoise_utils as ru

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): the tire file, the grid (dotted tire-file names -> values, SI units), the
# outputs and where to run (None: a local dask cluster; "serial"; or a scheduler address).
# A small grid (4 designs, the tire file's own values among them); enlarge it freely,
# e.g. "operating.inflation_pressure": [2.0e5, 2.15e5, 2.3e5, 2.45e5, 2.6e5], "belt.bending_stiffness": [2.5, 5.0, 10.0].
tire_name = "165_65R14"
grid = {
    "operating.inflation_pressure": [2.3e5, 2.6e5],  # Pa
    "tread.normal_stiffness_per_area": [1.2e9, 1.8e9],  # N/m^3
}
outputs = ["K_v", "footprint", "f1", "zeta1", "cleat", "hub_acceleration"]  # the figures use all but footprint
scheduler = None
n_workers = None

# %% [markdown]
# ## 1. What can be swept
#
# A design is the tire file with some of its values overridden, each named by its dotted key in
# the file (`[operating] inflation_pressure` is `"operating.inflation_pressure"`). The names and
# values are checked before anything runs: an unknown name is refused with the list of valid
# ones, a value outside its physical range with the range.

# %%
# NBVAL_CHECK_OUTPUT
# The swept parameters of the tire file: value, unit and valid range
swept = ru.experiments.design.sweep_parameters(tire_name, grid)  # a misspelt name: an error listing the valid ones
print(swept[["value", "unit", "low", "high"]].to_string(float_format=lambda v: f"{v:.4g}"))
print(f"{len(ru.experiments.design.sweep_parameters(tire_name))} parameters can be swept on this tire file")

# %%
# NBVAL_CHECK_OUTPUT
# A bad name or value stops the sweep before any work, naming the design, the parameter and its range
try:
    ru.experiments.sweep({"operating.inflation_pressure": [2.3e5, 6.0e5]}, ["K_v"], tire=tire_name)
except ValueError as error:
    print(error)

# %% [markdown]
# ## 2. The sweep
#
# The full grid of the parameters above; every design runs the experiments of the earlier
# chapters with the paper's conditions (`data/conditions/`), resolved once for all designs.

# %%
# NBVAL_IGNORE_OUTPUT
# Run the grid (a progress bar over the designs; a rerun reads every design from the cache)
table = ru.experiments.sweep(grid, outputs, tire=tire_name, scheduler=scheduler, n_workers=n_workers)
print(
    f"{len(table)} designs on {table.attrs['scheduler']}: {table.attrs['computed']} computed, "
    f"{table.attrs['from_cache']} from the cache, {table.attrs['seconds']:.1f} s"
)

# %%
# NBVAL_CHECK_OUTPUT
# The table: parameters and outputs in the paper's units
shown = ru.figures.design_exploration.in_paper_units(table)
print(shown.to_string(float_format=lambda v: f"{v:.3g}"))

# %%
# NBVAL_IGNORE_OUTPUT
# What each design's computation warned about (kept with its cached result)
for index, warned in table["warnings"].items():
    print(f"design {index}: {warned or '-'}")

# %% [markdown]
# ## 3. The trade-offs
#
# Each point is a design (its number in the table), the circled one the tire file as it is. Left: the
# cleat's dynamic peak against the vertical stiffness, coloured by the first resonance; right:
# the hub acceleration on the rough road against the first resonance, coloured by the damping
# ratio. The shaded bands are the calibration targets of the paper's tire
# (`data/calibration/165_65R14.toml`).

# %%
# The tire file as it is (a design of the grid when its own values are on it)
own = [swept.loc[name, "value"] for name in grid]
on_grid = (table[table.attrs["parameters"]] == own).all(axis=1)
baseline = table[on_grid].iloc[0] if on_grid.any() else None
targets = ru.experiments.calibration.calibration_targets(tire_name)
k_target, f_target = (targets.get(q) for q in ("vertical_stiffness", "first_vertical_resonance"))

# %%
# Trade-offs: cleat peak against K_v (colour f1), hub acceleration against f1 (colour zeta1)
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
plot = ru.figures.design_exploration.plot_trade_off
plot(
    table, "K_v (N/m)", "cleat_dynamic_peak (N)", "f1 (Hz)", ax=left, baseline=baseline,
    target=(k_target["low"] * 1e3, k_target["high"] * 1e3) if k_target else None, target_label="K_v target",
)  # fmt: skip
plot(
    table, "f1 (Hz)", "a_hub_rms (m/s^2)", "zeta1 (-)", ax=right, baseline=baseline,
    target=(f_target["low"], f_target["high"]) if f_target else None, target_label="f1 target",
)  # fmt: skip
fig.suptitle(f"Design trade-offs of the {ru.load_tire(tire_name).name}: the cleat, the road and the first mode")
plt.show()

# %% [markdown]
# ## 4. What moves what
#
# The sensitivities of the grid (relative change of each output over the parameter's range,
# the other parameters held): finite differences of the table, nothing fitted.

# %%
# NBVAL_CHECK_OUTPUT
# Relative change of each output across each parameter's range, the other parameter held (mean of the pairs)
effects = ru.experiments.design_sweep.effects(table)
print(effects.to_string(float_format=lambda v: f"{v:+.1%}"))

# %% [markdown]
# In this grid (the table above), pressure stiffens the tire ($K_v$), raises its first mode and, on
# the rough road, the hub acceleration: the classic comfort/handling trade-off. The tread's
# normal stiffness barely moves $K_v$ or $f_1$ (the tread is in series with a much softer
# carcass and air spring) but raises the cleat's dynamic peak: the cleat's edge pushes on the
# edge rows of the footprint, which carry most of its stiffness in a zone $1/\beta$ deep,
# $\beta = (k_{tread}/4EI)^{1/4}$ (a beam on an elastic foundation; notebook 04), and a stiffer
# tread concentrates it there.
#
# ## 5. Where it fails: the footprint moves in steps of the mesh
#
# The footprint's edge lies on a node of the belt mesh, so a design that lengthens or shortens
# the footprint moves it by whole elements (one at each end), and the outputs that live at the edge — the linear
# chain's quasi-static cleat peak above all — jump with it rather than follow the parameter
# smoothly. Compare the footprint lengths of the designs with the element length:

# %%
# NBVAL_CHECK_OUTPUT
# The designs' footprint lengths and their steps, in element lengths of the belt mesh
spec = ru.load_tire(tire_name)
element = 2 * np.pi * spec.geometry.belt_radius / spec.mesh.n_elements
lengths = np.unique(table["footprint_length (m)"].round(9))
print(f"element length {element * 1e3:.2f} mm; footprint lengths over the designs (mm):", end=" ")
print(", ".join(f"{v * 1e3:.1f}" for v in lengths))
print("steps between them (elements):", ", ".join(f"{d:.1f}" for d in np.diff(lengths) / element) or "-")

# %% [markdown]
# A sweep of a parameter that moves the footprint's edge wants a finer mesh along the
# circumference (`"mesh.n_elements"` is a sweep parameter too, e.g. 600 as the one-sided runs of
# notebook 08 use) or a trend read across several such steps, not from two neighbouring designs.
#
# ## 6. Your sweep
#
# * **A bigger grid or a sample.** Enlarge `grid` above, or pass a Latin-hypercube sample:
#   `ru.experiments.sample({"operating.inflation_pressure": (2.0e5, 2.6e5), "belt.bending_stiffness": (2.5, 10.0)}, 20, seed=0)`.
# * **Contact loss.** Add `"one_sided"` to `outputs` for the one-sided cleat peaks of notebook 08
#   (about 20 s a ring design on one core).
# * **Your cluster.** `scheduler="tcp://host:8786"` (or a `distributed.Client`) runs the same
#   sweep there; its workers need this package and, to share the per-design cache, the same
#   `ROADNOISE_CACHE_DIR`.
# * **The cross-section tire.** `tire="165_65R14_cross_section"` sweeps its own keys
#   (`"layers.tread.youngs_modulus"`, `"operating.inflation_pressure"`, ...; about 10x the cost of
#   a ring design).
# * **Interrupted?** Run the same call again: finished designs come from the cache.

# %% [markdown]
# **Next:** notebook 13 runs the chain on every tire model side by side, a tire read from files
# among them.
