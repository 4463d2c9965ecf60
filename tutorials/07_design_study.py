# %% [markdown]
# # Tutorial 7 — a design study: the LS-1 valve train over speed and geometry
#
# The same Analysis over many designs and operating points, as one tidy table:
#
# 1. roller follower: cam speed 500–3000 rpm × roller radius → smallest film over the cycle, peak
#    Hertz pressure, jump margin (the smallest contact force over the cycle); the feasible region;
# 2. flat-faced follower: speed × base radius → peak Hertz pressure, sliding friction power, jump
#    margin — and the base radii the lift law cannot have (undercut), kept in the table as errors;
# 3. the same sweep on a process pool (and on Dask when the `[dask]` extra is installed) gives the
#    identical table; exports to CSV, Parquet and a unit-carrying pint-pandas frame.
#
# The design limits are illustrative assumptions: Lambda >= 1.5 (h_min / composite roughness),
# p_h <= 1.0 GPa, jump margin > 100 N.

# %%
from concurrent.futures import ProcessPoolExecutor

import attrs
import matplotlib.pyplot as plt
import numpy as np

import camcontact as cc
from camcontact.report_export import to_pint_frame, write_csv, write_parquet
from camcontact.scene_file import load_scene

scene = load_scene()  # the LS-1 roller valve train of Tsuha (2015), the main job's scene
roller = attrs.evolve(scene.component, angle_step="2 deg", max_speed=None)
sigma = float(np.hypot(0.2e-6, 0.2e-6))  # cam and roller roughness 0.2 um RMS each
speeds = [f"{n} rpm" for n in (500, 1000, 1500, 2000, 2500, 3000)]
radii = ["6 mm", "8 mm", "10 mm", "12 mm", "14 mm"]
analysis = cc.Analysis(roller, outputs=["h_min_cycle", "p_h_max", "jump_margin", "jump"], models=scene.models)
study = analysis.sweep({"speed": speeds, "follower.roller_radius": radii}, progress=False)
print(study.to_string(index=False, float_format=lambda v: f"{v:.4g}"))

# %% [markdown]
# A larger roller spreads the load (lower pressure, thicker film); speed thickens the film but eats
# the jump margin (inertia ~ speed²). The feasible region is where all three limits hold: its designs are
# the white dots, the infeasible side is hatched.

# %%
def grid(frame, column, rows, cols):
    return frame.pivot(index=rows, columns=cols, values=column).to_numpy(dtype=float)


rows, cols = "follower.roller_radius [mm]", "speed [rpm]"
X, Y = np.meshgrid(sorted(study[cols].unique()), sorted(study[rows].unique()))
film = grid(study, "h_min_cycle [µm]", rows, cols) * 1e-6 / sigma
pressure = grid(study, "p_h_max [MPa]", rows, cols)
margin = grid(study, "jump_margin [N]", rows, cols)
feasible = (film >= 1.5) & (pressure <= 1000.0) & (margin > 100.0)
fig, axes = plt.subplots(1, 3, figsize=(14, 4.4), layout="constrained")
for ax, (values, label) in zip(axes, ((film, "Lambda = h_min / sigma [-]"), (pressure, "peak p_h [MPa]"),
                                      (margin, "jump margin [N]"))):
    contour = ax.contourf(X, Y, values, levels=12)
    fig.colorbar(contour, ax=ax, label=label)
    if feasible.any() and not feasible.all():  # the boundary, and the infeasible side hatched
        ax.contour(X, Y, feasible.astype(float), levels=[0.5], colors="w", linewidths=2)
    ax.contourf(X, Y, feasible.astype(float), levels=[-0.5, 0.5], colors="none", hatches=["//"])
    ax.plot(X[feasible], Y[feasible], "o", mfc="w", mec="k", ms=5)
    ax.set(xlabel="cam speed [rpm]", ylabel="roller radius [mm]", title=label)
fig.legend(handles=[plt.Line2D([], [], color="w", marker="o", mec="k", ls="", label="feasible design"),
                    plt.Line2D([], [], color="k", lw=2, label="feasible boundary (white)"),
                    plt.matplotlib.patches.Patch(facecolor="none", edgecolor="k", hatch="//",
                                                 label="infeasible: Lambda < 1.5, p_h > 1 GPa or jump margin < 100 N")],
           loc="outside lower center", ncol=3, fontsize=8)
fig.savefig("design_study_roller.png", dpi=80)
print("feasible designs (roller radius [mm] x speed [rpm]):")
print(np.where(feasible, "ok", "--"))

# %% [markdown]
# ## 2. Flat-faced follower: sliding friction and undercut
# A flat face slides over the cam (Coulomb friction, mu = 0.05): friction power grows with speed and
# with the base radius (longer sliding path). Base radii too small for the lift law undercut; those
# cases keep their parameters and the error text in the table instead of stopping the study.

# %%
flat = attrs.evolve(roller, follower=cc.Follower.flat(material=roller.follower.material),
                    cam=attrs.evolve(roller.cam, base_radius="50 mm"))
flat_analysis = cc.Analysis(flat, outputs=["p_h_max", "friction_power_mean", "jump_margin"], models=scene.models)
flat_study = flat_analysis.sweep({"speed": speeds[::2], "cam.base_radius": ["10 mm", "20 mm", "30 mm", "45 mm", "60 mm"]},
                                 progress=False)
print(flat_study.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
undercut = flat_study[flat_study["error"] != ""]
print(f"\n{len(undercut)} cases failed, e.g.: {undercut['error'].iloc[0][:160]}..." if len(undercut) else "")

# %% [markdown]
# ## 3. Executors and exports
# The same sweep on a local process pool gives the identical table (on a Dask cluster:
# `executor=client.get_executor()`); the table exports to CSV, Parquet and pint-pandas.

# %%
with ProcessPoolExecutor(max_workers=2) as pool:
    pooled = analysis.sweep({"speed": speeds, "follower.roller_radius": radii}, executor=pool, progress=False)
print("process pool gives the same table:", pooled.equals(study))
write_csv(study, "design_study.csv")
try:
    write_parquet(study, "design_study.parquet")
    print("Parquet written")
except cc.InputError as exc:  # without the [parquet] extra
    print(exc)
try:
    typed = to_pint_frame(study)
    print(typed.dtypes.to_string())
except cc.InputError as exc:  # without the [pint] extra
    print(exc)
