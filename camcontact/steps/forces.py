"""Force and dynamics steps: the valve train (prescribed motion, lumped ODE, jump, k_min), the bearing's
roller loads and the ball-cone CVT's contact forces.

Valve train: Tsuha (2015) Eqs. 3.46-3.50 for the 1-DOF prescribed-motion force and the minimum spring
stiffness (:mod:`camcontact.dynamics.prescribed_motion`), the lumped 2-/5-DOF model of Ferrarese &
Uehara with unilateral contact (:mod:`camcontact.dynamics.valve_train_ode`). Bearing: the numerical
load distribution (:mod:`camcontact.contact.load_distribution`). CVT: Saccheto (2008) §6.5
(:func:`camcontact.dynamics.ball_cone_loads.ball_cone_loads`). Forces [N], torques [N m], masses [kg],
stiffness [N/m], damping [N s/m], speeds [rad/s].
"""

from __future__ import annotations

import math

import numpy as np

from ..dynamics.ball_cone_loads import ball_cone_loads
from ..dynamics.prescribed_motion import contact_force, minimum_stiffness
from ..errors import InputError
from ..step_graph import step
from .kinematics import degrees_text

__all__ = [
    "FORCES_1DOF", "ball_cone_contact_forces", "check_lumped_model", "jump_report", "load_distribution",
    "lumped_dynamics", "minimum_spring_stiffness", "normal_force", "prescribed_motion_forces",
    "valve_train_natural_frequency",
]

FORCES_1DOF = ("contact_force", "inertia_force", "damping_force", "spring_force", "preload_force", "cam_torque")
#: cam angles sampled for k_min (every 0.05 degree of a turn)
K_MIN_SAMPLES = 7201


@step("natural_frequency", provides=("natural_frequency",))
def valve_train_natural_frequency(mass, stiffness):
    """Undamped natural frequency sqrt(k/m) / 2 pi [Hz] of the equivalent valve train."""
    return {"natural_frequency": math.sqrt(stiffness / mass) / (2.0 * math.pi)}


@step("k_min", provides=("k_min",))
def minimum_spring_stiffness(program, speed, max_speed, mass, damping_ratio, preload):
    """The smallest spring stiffness [N/m] without jump at ``max_speed`` [rad/s] (None: ``speed``), from
    the motion program over a turn (Tsuha 2015 §6.1)."""
    omega = speed if max_speed is None else max_speed
    theta = np.linspace(0.0, 2.0 * math.pi, K_MIN_SAMPLES)
    f, f1, f2 = program.evaluate(theta)[:3]
    return {"k_min": minimum_stiffness(f, f1, f2, omega, mass=mass, damping_ratio=damping_ratio, preload=preload)}


@step("dynamics", provides=FORCES_1DOF, model="1-DOF prescribed motion")
def prescribed_motion_forces(lift, follower_velocity, follower_acceleration, angular_speed, mass, stiffness, damping,
                             preload):
    """The contact force of the 1-DOF valve train following the cam exactly (Tsuha 2015 Eq. 3.46) and its
    parts: inertia, damping, spring, preload [N]; the cam torque N v / omega [N m]."""
    forces = contact_force(lift, follower_velocity, follower_acceleration, angular_speed, mass=mass,
                           stiffness=stiffness, damping=damping, preload=preload)
    return {"contact_force": forces.total, "inertia_force": forces.inertia, "damping_force": forces.damping,
            "spring_force": forces.spring, "preload_force": forces.preload, "cam_torque": forces.torque}


def check_lumped_model(lumped_model, angular_acceleration) -> None:
    """InputError unless the valve train has a lumped model and the cam turns at constant speed."""
    if lumped_model is None:
        raise InputError("the 'dynamics' effect integrates the valve train's lumped model; give "
                         "ValveTrain(lumped=LumpedValveTrain.ferrarese_2dof()) or similar, or drop the effect")
    if angular_acceleration != 0.0:
        raise InputError("the 'dynamics' effect runs at constant cam speed; angular_acceleration must be 0")


@step("dynamics", provides=("contact_force", "cam_torque", "valve_train_response"), model="lumped ODE",
      check=check_lumped_model)
def lumped_dynamics(lumped_model, program, cam_angle, speed, follower_velocity, angular_speed, cycles):
    """The valve train's lumped model integrated over ``cycles`` cam turns with unilateral contact; the
    contact force [N] of the last turn at the scene's angles, the cam torque [N m] and the response."""
    from ..dynamics.valve_train_ode import simulate

    response = simulate(lumped_model, program.evaluate, speed, cycles=cycles)
    period = 2.0 * math.pi
    last = response.angle >= response.angle[-1] - period - 1e-12
    angle = np.mod(response.angle[last] - (response.angle[-1] - period), period)
    order = np.argsort(angle, kind="stable")
    N = np.interp(np.mod(cam_angle, period), angle[order], response.contact_force[last][order], period=period)
    return {"contact_force": N, "cam_torque": N * follower_velocity / angular_speed, "valve_train_response": response}


@step("normal_force", provides=("normal_force", "contact_open"))
def normal_force(contact_force, pressure_angle, convention):
    """The force normal to the contact [N]: the axial force F / cos(pressure angle), or F itself in the
    thesis convention; zero where the contact is open (F <= 0, flagged in ``contact_open``)."""
    normal = contact_force if convention == "thesis" else contact_force / np.cos(pressure_angle)
    return {"normal_force": np.clip(normal, 0.0, None), "contact_open": contact_force <= 0.0}


@step("jump", provides=("jump",))
def jump_report(contact_open, contact_force, cam_angle):
    """Whether the follower leaves the cam, where first, and the smallest contact force, as text: from
    ``contact_open`` (bool per angle), ``contact_force`` [N] and ``cam_angle`` [rad] (shown in degrees)."""
    if not np.any(contact_open):
        margin = float(np.min(contact_force))
        return {"jump": f"no jump (minimum contact force {margin:.4g} N)"}
    return {"jump": f"JUMP: the follower leaves the cam at {int(contact_open.sum())} angles, from "
                    f"{degrees_text(cam_angle[contact_open][:1])} (contact force {float(np.min(contact_force)):.4g} N)"}


@step("load_distribution", provides=("roller_row", "azimuth", "Q", "loaded", "roller_approach", "Q_max", "loaded_rollers",
                                     "load_zone", "last_loaded_azimuth", "delta_r", "delta_a", "force_residual"),
      model="iso_ts_16281_line")
def load_distribution(bearing, radial_load, axial_load):
    """Roller loads Q [N] of ``bearing`` under F_r, F_a [N] with its clearance (numerical, both rows),
    per roller row by row (``loaded``: Q > 0, the rollers in contact; an unloaded roller has no contact,
    so its Hertz, film and friction values are NaN), with the rings' displacements [m] and the force
    balance's residual.

    ``loaded_rollers``: the number of rollers with Q > 0 (both rows); ``load_zone`` [rad]: the load-zone
    half-angle psi_l = arccos(P_d / (2 delta_r)) of Harris & Kotzalas (ch. 7; with the axial
    displacement per row, :attr:`camcontact.contact.load_distribution.LoadDistribution.load_zone`),
    the largest over the rows; ``last_loaded_azimuth`` [rad]: the angle of the last loaded roller
    from the load line (largest over the rows), at or inside psi_l."""
    result = bearing.load_distribution_si(radial_load, axial_load)
    rows, Z = result.Q.shape
    return {
        "roller_row": np.repeat(np.arange(1.0, rows + 1), Z), "azimuth": result.azimuths.ravel(),
        "Q": result.Q.ravel(), "loaded": result.loaded.ravel().astype(bool), "roller_approach": result.approach.ravel(),
        "Q_max": result.Q_max,
        "loaded_rollers": float(result.loaded.sum()), "load_zone": float(result.load_zone.max()),
        "last_loaded_azimuth": float(result.last_loaded_azimuth.max()),
        "delta_r": result.delta_r, "delta_a": result.delta_a, "force_residual": result.residual,
    }


@step("loads", provides=("torque", "output_torque", "cam_axial_force", "cam_ball_force", "normal_force",
                         "ball_axial_resultant", "tangential_force_in", "tangential_force_out", "traction_needed_in",
                         "traction_needed_out", "mu_min", "traction_check", "traction_sufficient"),
      model=lambda clamping: f"saccheto_6.5 ({clamping})")
def ball_cone_contact_forces(power, input_speed, reduction_ratio, traction_coefficient, ball_count,
                             cone_contact_radius, cone_angle, cam_ramp_angle, cam_radius, cam_ball_count, clamping):
    """Torques [N m], the loading cam's forces and the normal and tangential forces [N] of a ball-cone
    contact at ``power`` [W] and ``input_speed`` [rad/s]; the traction each contact needs against the
    traction coefficient Ct: ``traction_sufficient`` (True where F_t/F_n < Ct at both contacts) and the
    reason as text (``traction_check``)."""
    out = ball_cone_loads(power, input_speed, ball_count=ball_count, cone_radius=cone_contact_radius,
                          cone_angle=cone_angle, cam_angle=cam_ramp_angle, cam_radius=cam_radius,
                          cam_ball_count=cam_ball_count, reduction_ratio=reduction_ratio, clamping=clamping)
    ct = traction_coefficient
    worst = max(out["traction_needed_in"], out["traction_needed_out"])
    side = "input" if out["traction_needed_in"] >= out["traction_needed_out"] else "output"
    out["traction_check"] = (f"ok: needs {worst:.4g} at the {side} contact < Ct = {ct:.4g}" if worst < ct else
                             f"gross slip: the {side} contact needs F_t/F_n = {worst:.4g} >= Ct = {ct:.4g}")
    out["traction_sufficient"] = bool(worst < ct)
    return out
