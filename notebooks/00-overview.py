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
# # 00 — Overview: the road-noise (RM) model and a map of this collection
#
# Belluzzo, Mancosu, Sangalli, Cheli and Bruni, *New Predictive Model for the Study of
# Vertical Forces (up to 250 Hz) Induced on the Tire Hub by Road Irregularities*, Tire Science
# and Technology 30(1), 2002, pp. 2-18.
#
# The RM model predicts the **vertical force on the tire hub, 0-250 Hz**, caused by road
# irregularities with wavelengths above 5 cm (pavement megatexture). Its idea (paper Fig. 1):
#
# 1. take a detailed finite-element tire (FET, ~8000 DOF, viscoelastic rubber) and load it
#    on the road;
# 2. divide the footprint into ~71 blocks, the *tasselli*, and compute the frequency response
#    $H_i(\omega)$ from the vertical displacement of each tassello to the hub force —
#    fast, through a modal model frozen at ~70 Hz with damping identified from the full
#    viscoelastic model; check the superposition $\sum_i H_i = H_{tot}$ (the paper's Eq. i,
#    Fig. 5);
# 3. fit each $H_i$ with an 8-pole/8-zero transfer function (Eq. 1, Fig. 6) and stack the
#    state-space models into one time-domain tire (Eq. 2-4);
# 4. drive it with the road flowing through the footprint: a cleat on a drum with the hub
#    fixed (Fig. 8-9), or, with a moving hub (Eq. 5-7), a vehicle model on rough and
#    smooth textures (Fig. 10-14).
#
# Each stage is a notebook; all logic lives in the `roadnoise_utils` package and every number
# is computed. Each notebook runs alone: earlier stages come from a cache keyed by their inputs
# and by the code they run.

# %%
import matplotlib.pyplot as plt
from IPython.display import Markdown

import roadnoise_utils as ru

ru.set_style()

# %% tags=["parameters"]
# Parameters (papermill): the claims to evaluate (ids of data/paper/claims.toml; None = all)
claim_ids = None

# %%
# Fig. 1 analogue: the RM pipeline and the notebook of each stage
ru.figures.overview.plot_rm_pipeline(ru.collection.stages())
plt.show()

# %% [markdown]
# ## Map of the collection
#
# Generated from `data/collection.toml`, the same source as the README's table; the links open
# each stage's notebook.

# %%
# The notebooks, the paper section and figures each reproduces
Markdown(ru.collection.markdown_table(link_prefix=""))

# %% [markdown]
# ## The reproduction report
#
# Every claim of the paper that a number can check, our value and the verdict on **both tire
# models** — the ring on springs (notebook 01) and the tire built from its cross-section
# (notebook 09) — computed live (on a fresh checkout this runs every stage once, a few minutes;
# later the stage cache answers). The claims, the paper's values with their section or figure,
# and the tolerances are in `data/paper/claims.toml`; a claim a model does not reproduce carries
# the reason, and so does a claim that does not apply to a model. The reproduction command
# (`python -m roadnoise_utils`) writes the same table to `figures/reproduction-report.md` and
# `.csv`, with a third column: the loaded FE tire (notebook 16), the paper's own kind of FE tire,
# whose production stages take some ten CPU-minutes — this chapter, which the test suite runs,
# leaves it to the reproduction (`data/paper/report.toml`).

# %%
# The report: one row per claim, a value and a verdict per tire model
claims = ru.claims.select_claims(claim_ids)  # a misspelt id is an error listing the valid ones
report = ru.claims.report(claims=claims, models=ru.claims.OVERVIEW_MODELS)
report.drop(columns=[c for c in report.columns if c.startswith("deviation")])

# %%
# NBVAL_CHECK_OUTPUT
# How many claims each tire model reproduces
print(ru.claims.summary(report))

# %%
# NBVAL_CHECK_OUTPUT
# Verdicts; every claim passes or is a documented deviation
print(ru.claims.verdicts(report))
ru.claims.check(report)

# %%
# The documented deviations, and the claims a model does not apply to, and why
Markdown(
    "\n".join(
        f"- **{model}: {cid}** ({row[f'verdict ({model})']}): {row[f'deviation ({model})']}"
        for model in ru.claims.models_of(report)
        for cid, row in report.iterrows()
        if row[f"deviation ({model})"]
    )
)

# %% [markdown]
# ## Public entry points and where the code lives
#
# ```python
# import roadnoise_utils as ru
# tire   = ru.load_tire("165_65R14")            # validated TireSpec from data/tires/*.toml
# fet    = ru.build_fet(tire)                   # FETModel: sparse M, K(ω) parts, DOF maps
# static = ru.solve_static(fet, road="flat")    # or road="drum": footprint, pressures, tasselli
# visco  = ru.frf_visco(fet, static, freqs)     # direct FRFs: H_tot, H_i, G_H (fixed hub)
# test   = ru.experiments.cleat_test("165_65R14")  # the paper's cleat test, conditions resolved once
# ```
#
# The package has one folder per stage, in the order the data flows: `tire/` (spec, the ring
# FE model, statics, tasselli) → `response/` (direct FRFs, modes, modal reduction, FE reference
# solves) → `rm/` (fits, state space, simulation) → `road/` (tassello inputs) → `vehicle/`
# (quarter car, corner, spectra); `experiments/` runs the paper's tests from their
# `data/conditions` files, `figures/` holds one module per notebook, `repro/` the cache, the
# claims and the reproduce command. The notebooks get earlier stages from `ru.stages`, whose
# functions carry the names of the stage functions they cache (`ru.stages.solve_static`,
# `ru.stages.frf_visco`, `ru.stages.fit_tasselli`, ...) and take a tire name instead of the
# earlier results.

# %%
# NBVAL_CHECK_OUTPUT
# The tires available in data/tires and their size
for name in ("165_65R14", "195_65R15"):
    spec = ru.load_tire(name)
    print(
        f"{name}: {spec.name}, {spec.operating.inflation_pressure / 1e5:.1f} bar, "
        f"{spec.operating.vertical_load:.0f} N, outer radius {spec.geometry.outer_radius * 1e3:.1f} mm"
    )
