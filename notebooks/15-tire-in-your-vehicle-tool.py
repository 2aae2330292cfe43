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
# # 15 — The tire in your vehicle tool: an FMU of the RM tire
#
# **Beyond the paper**, but its whole point (section *Simulation of Wheel-Road Interaction*): the
# state-space tire "can be implemented in a car model", and the paper couples it to a quarter
# car (Eq. 8) and names multibody codes as the target. Vehicle models live in Simcenter,
# Dymola/OpenModelica, Simulink, CarMaker or in-house MBS codes, and those tools exchange
# dynamic models as **FMUs** (the Functional Mock-up Interface, FMI 2.0). This chapter exports
# the moving-hub RM tire of Eq. 7,
#
# $$F_M = F_F + F_H = \sum_i G_i(s)\,u_i + G_H(s)\,u_H, \tag{5-7}$$
#
# as a co-simulation FMU, checks it with a standard FMU runner (fmpy) against our own
# simulation, and drives a quarter car with it the way a vehicle tool would.
#
# **What the FMU contains.** One small C program, the same for every tire, reads the tire's
# numbers from `resources/tire.bin` when it is instantiated: the modal sections of Eq. 7
# (each pole pair with its exact first-order-hold recursion, as `ru.simulate` steps it) and the
# footprint's road taps. It is compiled with the machine's C compiler at export, and the source
# and the FMI headers travel inside, so another platform's tool can build it. No Python runs
# inside.
#
# **How the road enters.** A vehicle tool's road model gives heights at points. The FMU takes,
# at every step, the road height at the footprint's *leading edge* (`leading_edge_x` ahead of
# the footprint centre), one per lateral strip of the tread for a 3-D road (`road_height[k]` at
# `road_y[k]`), or one for a road uniform across the width. At a speed $V$ and step $\Delta t$
# the road advances $V\Delta t$ a step, so the road under the footprint is the last few
# leading-edge heights: the FMU keeps them, and each tassello's displacement is a fixed
# weighted sum of them — the paper's "weighted average of all the physical displacements of
# the points inside the area of the tassello" (notebook 06) for a road linear between the
# samples. A road table baked into the FMU would tie it to one road; heights at the leading
# edge work with any road the tool has.

# %%
import tempfile
import time
from pathlib import Path

import control
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from fmpy import read_model_description
from fmpy.validation import validate_fmu

import roadnoise_utils as ru
from roadnoise_utils.fmu.drive import TireSlave, run_fmu
from roadnoise_utils.fmu.statespace_files import read_statespace_mat, write_statespace_mat
from roadnoise_utils.rm.aggregated import road_hub_force
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.vehicle.spectra import psd

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): the tire exported for the cleat (Fig. 9's tire) and its speed (km/h; None: the paper's
# 30 km/h of data/conditions/cleat_test.toml); the car of the co-simulation (its tire is the vehicle file's), on the
# paper's road test (data/conditions/road_test.toml)
tire_name = "165_65R14"
speed_kmh = None
vehicle_name = "midsize_195_65R15"

# %%
# The parameters above, checked before anything runs: a wrong one is refused naming it and its valid values
ru.experiments.check_parameters(tire_name=tire_name, vehicle_name=vehicle_name)
cleat = ru.experiments.cleat_conditions(dynamic_kmh=speed_kmh)  # the paper's cleat, the speed checked there
speed = cleat.dynamic_kmh / 3.6
folder = Path(tempfile.mkdtemp(prefix="roadnoise-fmu-"))  # the FMUs of this chapter

# %% [markdown]
# ## 1. Export
#
# `ru.export_fmu` asks the tire-model interface for the loaded footprint and the fits (the cached
# stages of notebooks 01-05), so every tire model — the ring, the cross-section tire, a tire from
# your own FRF files (notebook 13) — exports the same way.

# %%
# NBVAL_IGNORE_OUTPUT
# The paper's cleat tire as an FMU for a road uniform across the width (one road input), and its variables
started = time.perf_counter()
fmu_path = ru.export_fmu(tire_name, folder / "tire.fmu", speed, lateral=False)
export_seconds = time.perf_counter() - started
description = read_model_description(str(fmu_path))
variables = pd.DataFrame(
    [
        {"name": v.name, "causality": v.causality, "variability": v.variability, "unit": v.unit,
         "start": v.start, "description": v.description}
        for v in description.modelVariables
    ]
)  # fmt: skip
print(f"{fmu_path.name}: {fmu_path.stat().st_size / 1e3:.0f} kB, exported in {export_seconds:.1f} s")
variables

# %%
# NBVAL_CHECK_OUTPUT
# What the FMU is: FMI 2.0 co-simulation, its step, and what fmpy's validator finds to fix
tables = ru.experiments.fmu_export.fmu_tables(tire_name, speed, lateral=False)
print(f"FMI {description.fmiVersion}, co-simulation: {description.coSimulation is not None}")
print(
    f"step {tables.dt * 1e6:.2f} us ({1 / tables.dt:.0f} Hz) at {tables.speed * 3.6:.0f} km/h: {tables.speed * tables.dt * 1e3:.2f} mm of road a step"
)
print(
    f"{tables.n_tasselli} tasselli, {tables.n_states} states, {tables.taps.shape[1]} road samples under the footprint"
)
print(f"fmpy.validation.validate_fmu: {validate_fmu(str(fmu_path)) or 'nothing to fix'}")

# %% [markdown]
# ## 2. The FMU against our simulation
#
# A master loop drives the FMU at each communication point $t_k$: set the inputs at $t_k$, read
# the outputs at $t_k$, step. The outputs depend on the inputs set at $t_k$ (direct
# feedthrough: the exact first-order hold needs them), which is how every co-simulation master
# can call an FMU.
#
# **The cleat with the hub held** (paper Fig. 9's test, on the flat road here): the FMU is fed
# the cleat's heights at the leading edge; our reference is `road_hub_force` (the aggregated
# simulation of notebook 06) on the road linear between the same samples. Two codes, one model:
# they must agree to round-off.

# %%
# The cleat flowing through the footprint, FMU against ours
start, end = cleat.dynamic_distance  # the travel: from before the cleat reaches the footprint to its free decay
fits, hub = ru.stages.fit_tasselli(tire_name), ru.stages.fit_hub(tire_name)
static = ru.stages.solve_static(tire_name)
knots = tables.leading_edge + start + speed * tables.dt * np.arange(int((end - start) / (speed * tables.dt)) + 2)
heights = cleat_profile(cleat.height, cleat.base, cleat.shape)(knots)
ours = road_hub_force(ru.assemble_fixed_hub(fits), static, lambda s: np.interp(s, knots, heights), speed,
                      (start, end), 1 / tables.dt)  # fmt: skip
run = run_fmu(fmu_path, heights[: ours.t.size])  # the same samples, one per step
ru.figures.vehicle_tools.plot_fmu_against_ours(run.t, ours.force, run.F_F, "F_F, hub held")
plt.title(f"The {tire_name} FMU on the paper's cleat at {cleat.dynamic_kmh:g} km/h against ru.road_hub_force")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# The cleat: peak force and the FMU's largest difference from ours
cleat_error = np.max(np.abs(run.F_F - ours.force)) / np.max(np.abs(ours.force))
print(f"peak F_F {np.max(np.abs(ours.force)):.0f} N; FMU - ours below 1e-9 of the peak: {cleat_error < 1e-9}")

# %% [markdown]
# **The hub moving on a level road**: $F_H$ is $G_H$ (Eq. 6) driven by the hub displacement,
# against `ru.simulate` of $G_H$'s state space.

# %%
# NBVAL_CHECK_OUTPUT
# The hub's path: a random hub motion, FMU against ru.simulate of G_H
hub_motion = np.cumsum(np.random.default_rng(15).normal(size=2000)) * 1e-6
hub_motion -= hub_motion[0]  # from the static state, where the FMU and ru.simulate both start (see below)
hub_run = run_fmu(fmu_path, np.zeros(hub_motion.size), hub_motion)
hub_input = ru.RoadInput(t=tables.dt * np.arange(hub_motion.size), distance=speed * tables.dt * np.arange(hub_motion.size),
                         u=hub_motion[None, :], speed=speed, description="hub displacement")  # fmt: skip
hub_ours = ru.simulate(ru.rm.hub_statespace(hub), hub_input).force
hub_error = np.max(np.abs(hub_run.F_H - hub_ours)) / np.max(np.abs(hub_ours))
print(f"F_H: FMU - ours below 1e-9 of the peak: {hub_error < 1e-9}; F_F stays 0: {not np.any(hub_run.F_F)}")

# %% [markdown]
# **The start.** A vehicle tool starts its car on the road as it is, not at zero. The FMU starts
# in the steady state of the inputs set at its first point: the road behind the leading edge
# level with the first height and every modal section at its steady state under it,
# $x = (b_0 + b_1)\,v / (1 - e)$, the exact discrete counterpart of the continuous
# $-g\,v/p$. Inputs held constant then give the static force from the first step, with no
# start-up kick; `ru.simulate` starts at rest, so the two agree when the inputs start at zero
# (as above). The static force against the continuous models' DC gain (python-control):

# %%
# NBVAL_CHECK_OUTPUT
# Road raised 1 mm and hub raised 0.5 mm from the first step: the FMU's forces against the DC gains
held = run_fmu(fmu_path, np.full(200, 1e-3), np.full(200, 5e-4))
road_static = float(np.sum(control.dcgain(ru.assemble_fixed_hub(fits)))) * 1e-3
hub_static = float(np.squeeze(control.dcgain(ru.rm.hub_statespace(hub)))) * 5e-4
print(f"F_F: {held.F_F[0]:.0f} N at the first step, DC gain x 1 mm = {road_static:.0f} N, "
      f"constant to 1e-9: {bool(np.allclose(held.F_F, road_static, rtol=1e-9))}")
print(f"F_H: {held.F_H[0]:.0f} N at the first step, DC gain x 0.5 mm = {hub_static:.0f} N, "
      f"constant to 1e-9: {bool(np.allclose(held.F_H, hub_static, rtol=1e-9))}")  # fmt: skip

# %% [markdown]
# ## 3. A quarter car co-simulated with the FMU
#
# The paper's road test (Fig. 11-14): the 195/65 R15 car at 120 km/h on the rough texture. A
# master loop in Python over fmpy's `FMU2Slave` plays the vehicle tool: at each step it reads the
# car's hub displacement, gives it and the road heights (one per tread strip: the road is 3-D)
# to the FMU, reads $F_M$, and advances the car's own discrete state space with that force held
# over the step. Ours is `ru.experiments.quarter_car`'s: the car closed through $G_H$ in
# continuous time (Eq. 8), driven by $F_F$.

# %%
# NBVAL_IGNORE_OUTPUT
# The co-simulation on the road test (its first texture, the whole record), beside ours
started = time.perf_counter()
car = ru.experiments.fmu_quarter_car(folder, vehicle_name)
car_seconds = time.perf_counter() - started
steps = car.ours.t.size
print(f"{steps} steps of {1e6 / car.ours.sample_rate:.0f} us ({steps / car.ours.sample_rate:.0f} s of driving) in {car_seconds:.1f} s, "
      f"both runs and the export")  # fmt: skip

# %%
# Hub acceleration: ASD of both runs and the per-octave RMS ratio of both outputs
ru.figures.vehicle_tools.plot_cosimulated_car(
    psd(car.ours.outputs["a_hub"], car.ours.sample_rate),
    psd(car.cosimulated.outputs["a_hub"], car.cosimulated.sample_rate),
    car.octaves,
    "a_hub",
)
plt.suptitle(f"The {car.setup.tire.name} FMU in a co-simulated quarter car, rough road at 120 km/h, against ours")
plt.show()

# %%
# NBVAL_CHECK_OUTPUT
# Per octave, 20-250 Hz: the co-simulated car against ours
print(car.octaves.assign(**{"ratio - 1": car.octaves["ratio - 1"].map("{:+.2%}".format)})
      .drop(columns=["ours", "FMU co-simulation"]).to_string(index=False))  # fmt: skip
print(f"every octave within 1 %: {bool(np.max(np.abs(car.octaves['ratio - 1'])) < 0.01)}")

# %% [markdown]
# The co-simulation holds $F_M$ over each step while the hub moves: a coupling error of the
# first order in the step, which the master could remove (it knows the FMU's feedthrough) but a
# vehicle tool's generic master does not. Halving the step halves it, the error of a coupling
# and not of the tire:

# %%
# NBVAL_CHECK_OUTPUT
# The coupling error against the step: RMS of the hub acceleration's difference from ours (after 0.5 s)
errors = {rate: ru.experiments.coupling_error(car.setup, folder, rate) for rate in (10000.0, 20000.0)}
print(f"10 kHz: {errors[10000.0]:.1%} of the RMS, 20 kHz: {errors[20000.0]:.1%}; "
      f"ratio {errors[10000.0] / errors[20000.0]:.1f} (first order: 2)")  # fmt: skip

# %% [markdown]
# ## 4. The state space for Simulink, and what the FMU costs
#
# For Simulink's State-Space block the fixed-hub (Eq. 3-4) and moving-hub (Eq. 7) matrices go
# to a MATLAB file (`load tire.mat` gives `A_M`, `B_M`, `C_M`, `D_M`, the tasselli's positions
# and a description); the road then enters as the tassello displacements the user's road model
# computes. A Modelica model with the matrices written out would be ~10⁶ literals for a
# 1000-state tire: the FMU is the way into Modelica tools.

# %%
# NBVAL_CHECK_OUTPUT
# The .mat file read back: its moving-hub model's response is the fits' own (pole-residue form)
mat = read_statespace_mat(write_statespace_mat(folder / "tire.mat", fits, hub, static, tire_name))
moving = ru.rm.assemble_moving_hub(fits, hub)
check_freqs = np.array([10.0, 80.0, 160.0, 240.0])
file_model = control.ss(mat["A_M"], mat["B_M"], mat["C_M"], mat["D_M"])
from_file = np.asarray(file_model(2j * np.pi * check_freqs, squeeze=False))[0]
expected = np.vstack([fits.responses(check_freqs), hub[0](check_freqs)[None, :]])
print(f"A_M {mat['A_M'].shape}, B_M {mat['B_M'].shape}: {moving.nstates} states, {moving.ninputs} inputs")
print(
    f"response of the file's model = the fits' to 1e-8: {np.allclose(from_file, expected, rtol=1e-8, atol=1e-8 * np.abs(expected).max())}"
)

# %%
# NBVAL_IGNORE_OUTPUT
# The FMU's cost per step through fmpy (set, get, step: ctypes calls included) against real time
with TireSlave(fmu_path) as slave:
    road_row = np.zeros(1)
    started = time.perf_counter()
    for k in range(20000):
        road_row[0] = heights[k % heights.size]
        slave.set(road_row, 0.0)
        slave.outputs()
        slave.step()
    per_step = (time.perf_counter() - started) / 20000
print(f"{tables.n_states} states: {per_step * 1e6:.1f} us per step through fmpy, {tables.dt / per_step:.1f}x real time "
      f"at {1 / tables.dt:.0f} Hz on one core")  # fmt: skip

# %% [markdown]
# ## 5. Paper vs ours, and the limits
#
# The paper has no FMU; what it asks of the tire is that the car sees the same force. The checks:

# %%
# NBVAL_CHECK_OUTPUT
# The FMU's checks: what each compares and whether it holds
pd.DataFrame(
    [
        {"check": "cleat, hub held: FMU F_F vs road_hub_force (same road samples)", "tolerance": "1e-9 of the peak",
         "holds": bool(cleat_error < 1e-9)},
        {"check": "level road, hub moving: FMU F_H vs ru.simulate of G_H", "tolerance": "1e-9 of the peak",
         "holds": bool(hub_error < 1e-9)},
        {"check": "quarter car co-simulated, rough road 120 km/h: RMS per octave 20-250 Hz vs ours",
         "tolerance": "1 %", "holds": bool(np.max(np.abs(car.octaves["ratio - 1"])) < 0.01)},
        {"check": "coupling error halves with the step (10 -> 20 kHz)", "tolerance": "ratio 1.8-2.2",
         "holds": bool(1.8 < errors[10000.0] / errors[20000.0] < 2.2)},
    ]
)  # fmt: skip

# %% [markdown]
# **Limits of the FMU**, each refused with a message through the FMU's logger (`fmi2Error`) or
# at export rather than answered with a wrong number:
#
# * **one speed and one step**: the road's advance through the footprint and the exact
#   discretisation are built for them; a communication step more than 1e-6 of itself from
#   `time_step` (more than a tool's round-off), or setting the constant `speed` to another
#   value, is an error. Export one FMU per speed (about a second each).
# * **the band**: the fits cover 0-250 Hz (or 0-400 Hz, notebook 10); above it the tire is
#   whatever the rational functions do.
# * **a linear tire**: the footprint never leaves the road (contact loss is notebook 08's
#   time-stepped FE tire, not the RM model's); the hub force is relative to the static preload.
# * **the start**: the FMU starts in the steady state of its first inputs (the road behind the
#   leading edge level with the first height, every mode at rest under it), so inputs held
#   constant give the static force from the first step; our simulation starts at rest, so the
#   two agree when the inputs start at zero. The car co-simulated above starts at rest on a
#   road that is not (a start-up transient in both runs: skip the first 0.5 s as the spectra do).
# * **the road**: heights at the leading edge, linear between steps. A non-finite height is an
#   error, never a NaN force.
# * **an unstable fit or repeated poles**: refused at export, naming the tassello.
