# %% [markdown]
# # Tutorial 4 — a cam–follower valve train from motion law to film, friction and wear
#
# The LS-1 push-rod valve train of Tsuha (2015), the case of camcontact's main job: an offset roller
# follower (R_f = 10 mm, offset 5 mm) on a cam with a 40 mm base circle, 20 mm lift by the
# 8th-degree polynomials P-1 (rise, 0–90°) and P-2 (return, 90–180°), dwell to 360°, at 1000 rpm.
#
# 1. the motion program and its continuity;
# 2. kinematics: SVAJ, pressure angle, radius of curvature, entrainment; the cam profile;
# 3. dynamics: the 1-DOF force and its parts, jump and the minimum spring stiffness;
# 4. contact and film over the cycle — formulas at every degree, and the numerical (multigrid) film
#    at the thesis's 15° angles in both speed conventions (Table 6.4);
# 5. the flat-faced follower, whose entrainment speed reverses at the nose;
# 6. friction and wear (Ferrarese & Uehara, Coulomb, Archard), and the lumped 2-DOF dynamics.
#
# Set `CAMCONTACT_TUTORIAL_FINE=1` for multigrid level 9 (the thesis-table precision) instead of 7.

# %%
import os
import warnings

import attrs
import numpy as np

import camcontact as cc
from camcontact.dynamics.valve_train_ode import LumpedValveTrain
from camcontact.kinematics.motion_program import MotionProgram

fine = os.environ.get("CAMCONTACT_TUTORIAL_FINE") == "1"
steel = cc.Material(E="210 GPa", nu=0.3, hardness="7 GPa")
oil = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68, viscosity_pressure_law="roelands")
print(f"eta0 from the Roelands consistency relation: {oil.state(None).eta0:.6f} Pa s")

# %% [markdown]
# ## 1. Motion program
# `MotionProgram.thesis_ls1()` is the same as composing the segments by hand. The continuity table
# shows C2 (finite jerk) at every joint, with jerk jumps at 0° and 180° where the dwell meets P-1/P-2.

# %%
program = MotionProgram.from_segments([
    {"law": "P-1", "start": "0 deg", "end": "90 deg", "lift_start": "0 mm", "lift_end": "20 mm"},
    {"law": "P-2", "start": "90 deg", "end": "180 deg", "lift_start": "20 mm", "lift_end": "0 mm"},
    {"law": None, "start": "180 deg", "end": "360 deg", "lift_start": "0 mm"},
])
print(program.continuity()[["angle [deg]", "left", "right", "C0", "C1", "C2", "jerk_finite", "jerk_continuous"]])
harmonic = MotionProgram.rise_return_dwell(lift="20 mm", rise="90 deg", ret="90 deg", rise_law="harmonic",
                                           return_law="H-6")
print("harmonic with a dwell:", harmonic.diagnostics())

# %% [markdown]
# ## 2. Kinematics, and what runs
# Asking only for kinematic outputs runs the kinematics step and nothing else — no lubricant needed.

# %%
scene = cc.CamFollower(
    cam=cc.Cam(program=program, base_radius="40 mm", width="15 mm", material=steel, roughness="0.2 um"),
    follower=cc.Follower.roller(radius="10 mm", offset="5 mm", material=steel, roughness="0.2 um"),
    valve_train=cc.ValveTrain.ls1(), speed="1000 rpm", max_speed="3000 rpm", angle_step="1 deg",
    lubricant=oil, friction_coefficient=0.05,
)
kinematics = cc.Analysis(scene, outputs=["lift", "follower_velocity", "follower_acceleration", "follower_jerk",
                                         "pressure_angle", "cam_radius", "u_m", "profile_x", "profile_y"])
print("steps:", kinematics.steps())
k = kinematics.run()
frame = k.to_frame()
print(frame.iloc[::15].to_string(index=False, float_format=lambda v: f"{v:.4g}"))
print(f"pressure angle range {frame['pressure_angle [deg]'].min():.2f}° .. {frame['pressure_angle [deg]'].max():.2f}° "
      "(limit 30°)")
k.plot(panels=["svaj", "profile"]).savefig("tutorial_04_kinematics.png", dpi=110)

# %% [markdown]
# ## 3. Dynamics: F = m S̈ + c Ṡ + k f + F_pl
# The equivalent system of the push rod train (Table 6.1) gives m = 0.662 kg and k = 1.199e5 N/m.
# At 1000 rpm the spring dominates and the force peaks at the nose; k_min is the stiffness below
# which the follower would leave the cam at 3000 rpm.

# %%
train = cc.ValveTrain.from_pushrod_train(
    lifter_mass="0.122 kg", pushrod_mass="0.052 kg", rocker_inertia="3.86e-5 kg*m^2", valve_mass="0.114 kg",
    spring_mass="0.069 kg", pushrod_stiffness="5.25e7 N/m", valve_stiffness="8.23e7 N/m",
    spring_stiffness="4.03e4 N/m", pushrod_arm="22 mm", valve_arm="38 mm", preload="1000 N")
print(f"m = {train.si.mass:.5f} kg, k = {train.si.stiffness:.6g} N/m, c = {train.c:.3f} N s/m, "
      f"f_n = {train.natural_frequency / (2 * np.pi):.2f} Hz")
dynamics = cc.Analysis(scene, outputs=["contact_force", "inertia_force", "spring_force", "damping_force",
                                       "preload_force", "cam_torque", "k_min", "jump"]).run()
print(dynamics.summary_frame().T)

# %% [markdown]
# ## 4. Contact and film over the cycle
# Formulas at every degree cost milliseconds; the numerical film (`multigrid`, each angle started from
# the extrapolation of the two before, in one arc per thread) takes about 1 s for a whole 1° cycle at
# level 8 and tolerance 1e-5 on two cores, 2 s at the default 1e-7 (`benchmarks/cam_cycle.py`). Here it is run at the thesis's angles, in the thesis-compatible
# convention — which reproduces its Table 6.4 — and in camcontact's consistent one: the thesis
# used the mean speed where Moes uses the sum, so its films are those of half the physical
# entrainment speed.

# %%
cycle = cc.Analysis(scene, outputs=["p_h", "b", "M", "L", "h_min", "Lambda_min", "film_regime",
                                    "h_min_cycle", "p_h_max"], models={"film": ["pan_hamrock", "dowson_higginson"]}).run()
print(cycle.summary_frame(units={"h_min_cycle": "nm"}))
cycle.plot(panels=["pressure", "film"]).savefig("tutorial_04_film.png", dpi=110)

level = 9 if fine else 7
multigrid = cc.registry.get("film_models", "multigrid", levels=level)
angles = cc.Q_(np.arange(45.0, 136.0, 15.0), "deg")
table = {}
for convention in ("thesis", "consistent"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = cc.Analysis(cc.CamFollower(**{**{f: getattr(scene, f) for f in ("cam", "follower", "valve_train",
                                                                                  "speed", "lubricant")},
                                               "angles": angles, "convention": convention}),
                             outputs=["M", "L", "H0", "H_min", "H_c", "h_min", "film_regime"],
                             models={"film": multigrid}).run()
    table[convention] = result.to_frame(units={"h_min": "nm"})
    print(f"\n{convention} convention, multigrid level {level} (thesis Table 6.4: |H0| 0.2435 … 0.4238, "
          "H_min 0.2895 / 0.1801 / 0.146 / 0.1419 / 0.1543 / 0.1991 / 0.3155):")
    print(table[convention].to_string(index=False, float_format=lambda v: f"{v:.4f}"))

# %% [markdown]
# ## 5. Flat-faced follower: entrainment reversal at the nose
# The flat face's u_m = (R_o + f + 2 f'') ω / 2 changes sign at about 66° and 114°. A steady film does
# not exist there (it would live on squeeze); the steady films fall towards zero and the angles are
# flagged in `film_regime` instead of crashing or returning NaN.

# %%
flat = cc.CamFollower(
    cam=cc.Cam(program=program, base_radius="49.7494 mm", width="15 mm", material=steel),
    follower=cc.Follower.flat(material=steel), valve_train=cc.ValveTrain.ls1(), speed="1000 rpm",
    angles=cc.Q_(np.arange(60.0, 121.0, 2.0), "deg"), lubricant=oil, friction_coefficient=0.05,
)
flat_result = cc.Analysis(flat, outputs=["u_m", "M", "h_min", "film_regime"]).run().to_frame(units={"h_min": "nm"})
print(flat_result.to_string(index=False, float_format=lambda v: f"{v:.4g}"))

# %% [markdown]
# The effect `squeeze` solves the numerical film over the whole turn as one transient (implicit BDF2
# steps from angle to angle, starting from the steady film on the base circle): the squeeze term
# carries the film through the reversals instead of letting it collapse.

# %%
from camcontact.models.film_multigrid import Multigrid  # noqa: E402

turn = attrs.evolve(flat, angles=None, angle_step="2 deg")
squeeze_effects = {"elasticity", "piezoviscosity", "compressibility", "squeeze"}
for label, effects in (("quasi-steady", None), ("transient", squeeze_effects)):
    films = cc.Analysis(turn, outputs=["cam_angle", "u_m", "h_min"], models={"film": Multigrid(levels=6)},
                        effects=effects).run()
    near_nose = (np.degrees(films["cam_angle"]) > 60) & (np.degrees(films["cam_angle"]) < 120)
    print(f"{label:>12}: smallest film near the nose {1e9 * np.min(films['h_min'][near_nose]):.0f} nm, "
          f"{1e3 * films.wall_time:.0f} ms")

# %% [markdown]
# ## 6. Friction and wear; lumped dynamics
# The flat face slides: u_s = (R_o + f) ω. Coulomb friction and Archard wear need a coefficient;
# Ferrarese & Uehara's EHL friction and oxidative wear derive theirs from the Hertz area and a
# Newtonian film (with the constants derived from its component equations; the printed ones are an
# option, `constant="paper"`). With the `dynamics` effect the valve train's lumped 2-DOF model is
# integrated with unilateral cam contact instead of the prescribed-motion force. Ferrarese & Uehara's
# parameters belong to a small overhead cam with a soft return spring; under this 20 mm LS-1 lift
# the follower leaves the cam near the end of the return, and the scene says so.

# %%
flat_cycle = cc.CamFollower(**{**{f: getattr(flat, f) for f in ("cam", "follower", "lubricant", "friction_coefficient")},
                               "valve_train": cc.ValveTrain(mass="0.662 kg", stiffness="1.199e5 N/m", preload="1000 N",
                                                            lumped=LumpedValveTrain.ferrarese_2dof()),
                               "speed": "1000 rpm", "angle_step": "2 deg", "wear_coefficient": 1e-7})
for friction in ("coulomb", cc.registry.get("friction_models", "ferrarese_uehara", k_L=2.0)):
    out = cc.Analysis(flat_cycle, outputs=["friction_power_mean", "wear_rate_mean"],
                      models={"friction": friction}).run()
    print(f"{getattr(friction, 'name', friction):>17}: friction power {out['friction_power_mean']:.2f} W, "
          f"Archard wear {out['wear_rate_mean'] * 3.6e12:.4g} mm³/h")
lumped = cc.Analysis(flat_cycle, outputs=["contact_force", "jump"],
                     effects={"dynamics", "elasticity", "piezoviscosity", "compressibility"}).run()
print("2-DOF dynamics:", lumped["jump"], f"; peak contact force {lumped['contact_force'].max():.1f} N")
