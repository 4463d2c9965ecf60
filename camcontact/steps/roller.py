"""Roller-follower steps: the traction the contact can transmit, the roller's spin and slip, the tangential
force of a sliding follower, and the friction torque on the camshaft.

The roller (:mod:`camcontact.dynamics.roller_follower`): its angular speed is a state integrated over the
turn; the tangential force is what accelerates the roller and overcomes its pin friction, limited by the
traction curve of the contact (a Coulomb limit mu N, or a fluid traction model). Camshaft torque with
friction (Norton, *Cam Design and Manufacturing Handbook*, 2nd ed. 2009, §10 cam torque with friction;
reference ``friction_traction_thermal.md`` §5): the tangential force F_t acts along the contact's common
tangent, whose distance from the cam axis is p = S cos(A_p) - eps sin(A_p) - R_f (roller; flat-faced:
p = R_o + f), so T_f = F_t p adds to the frictionless torque F dS/dt / omega. Forces [N], torques [N m],
speeds [m/s], angular speeds [rad/s].
"""

from __future__ import annotations

import numpy as np

from ..dynamics.roller_follower import (coulomb_table, pin_friction_torque, required_traction, rim_rate, roller_cycle,
                                       slip_grid)
from ..errors import InputError
from ..step_graph import step

__all__ = ["ROLLER_OUTPUTS", "cam_friction_torque", "coulomb_traction_table", "roller_spin",
           "sliding_tangential_force", "SLIP_THRESHOLD", "check_roller"]

#: |slide-to-roll ratio| above which a roller angle is flagged as slipping (1 %; below it the contact
#: creeps, Duffy 1993 reports gross slip as tens of per cent)
SLIP_THRESHOLD = 0.01
#: fraction of the traction available at which the contact runs on its plateau (gross slip)
SATURATION = 0.99
ROLLER_OUTPUTS = ("roller_speed", "roller_slip", "roller_slipping", "traction_exceeded", "tangential_force", "traction_required",
                  "traction_available", "pin_torque", "friction_force", "friction_coefficient", "friction_power",
                  "roller_cycle")


@step("traction_curve", provides=("traction_grid", "traction_table"), model="coulomb_limit")
def coulomb_traction_table(normal_force, u_cam, traction_limit_coefficient):
    """The traction force [N] a contact of Coulomb limit mu N transmits against the sliding speed [m/s]
    (angles x nodes): mu N s / s_c within the creep s_c = 1e-4 |u_cam|, mu N beyond (stick, then slip)."""
    grid = slip_grid(u_cam)
    return {"traction_grid": grid, "traction_table": coulomb_table(traction_limit_coefficient * normal_force, grid,
                                                                   u_cam)}


def check_roller(roller_radius, roller_inertia) -> None:
    """InputError unless the roller's radius [m] and inertia [kg m^2] are positive."""
    if not (roller_radius > 0.0 and roller_inertia > 0.0):
        raise InputError(f"roller dynamics: roller_radius = {roller_radius!r} m and roller_inertia = "
                         f"{roller_inertia!r} kg m^2 must be > 0")


@step("roller_dynamics", provides=ROLLER_OUTPUTS, model="spin ODE (implicit Euler)",
      check=check_roller)
def roller_spin(cam_angle, angular_speed, u_cam, pressure_angle, normal_force, traction_grid, traction_table,
                roller_radius, roller_inertia, pin_radius, pin_friction_coefficient):
    """The roller's angular speed [rad/s], slide-to-roll ratio u_s/u_m [-] and slipping flag (|u_s/u_m| > 1 %, or
    the traction at 99 % of what the contact can transmit),
    whether the no-slip requirement exceeds the traction available, the tangential
    force on it [N] (along the cam surface's motion), the no-slip requirement and the traction available
    [N] (the table's plateau in the direction required), the pin torque [N m], the contact's friction force
    |F_t| [N], coefficient |F_t|/N [-] and the power lost at the contact and the pin [W], over a periodic
    cam turn (:func:`camcontact.dynamics.roller_follower.roller_cycle`)."""
    pin = pin_friction_torque(normal_force, pin_friction_coefficient, pin_radius)
    # the contact point travels round the roller's rim at dA_p/dt: in pure rolling R omega_r = u_cam - R dA_p/dt
    rolling = u_cam - roller_radius * rim_rate(cam_angle, angular_speed, pressure_angle)
    cycle = roller_cycle(cam_angle, angular_speed, rolling, pin, traction_grid, traction_table,
                         radius=roller_radius, inertia=roller_inertia)
    required = required_traction(cam_angle, angular_speed, rolling, pin, roller_radius, roller_inertia)
    available = np.where(required >= 0.0, traction_table[:, -1], -traction_table[:, 0])
    limit = np.where(cycle.traction_force >= 0.0, traction_table[:, -1], -traction_table[:, 0])
    saturated = np.abs(cycle.traction_force) >= SATURATION * limit
    u_roll = u_cam - 0.5 * cycle.sliding_speed  # (u_cam + u_roller)/2, both relative to the contact point
    with np.errstate(divide="ignore", invalid="ignore"):
        slip = np.where(u_roll != 0.0, cycle.sliding_speed / u_roll, 0.0)
        mu = np.where(normal_force > 0.0, np.abs(cycle.traction_force) / normal_force, 0.0)
    power = np.abs(cycle.traction_force * cycle.sliding_speed) + pin * np.abs(cycle.roller_speed)
    return {"roller_speed": cycle.roller_speed, "roller_slip": slip,
            "roller_slipping": ((np.abs(slip) > SLIP_THRESHOLD) | saturated) & (normal_force > 0.0),
            "traction_exceeded": (np.abs(required) > available) & (normal_force > 0.0),
            "tangential_force": cycle.traction_force, "traction_required": required, "traction_available": available,
            "pin_torque": pin, "friction_force": np.abs(cycle.traction_force), "friction_coefficient": mu,
            "friction_power": power, "roller_cycle": cycle}


@step("tangential_force", provides=("tangential_force",))
def sliding_tangential_force(friction_force, u_s):
    """The friction force on a sliding follower [N] signed along the cam surface's motion relative to it
    (the sign of the sliding speed u_s = u_cam - u_follower)."""
    return {"tangential_force": np.sign(u_s) * friction_force}


@step("cam_torque", provides=("friction_torque", "cam_torque_with_friction", "friction_arm"))
def cam_friction_torque(tangential_force, cam_torque, lift, pressure_angle, geometry):
    """The camshaft torque of the tangential force, T_f = F_t p [N m], with the distance p [m] of the
    contact's tangent from the cam axis (module docstring), and the cam torque with it [N m]. The normal
    force is taken from the axial force alone (F / cos A_p): the tangential force's own axial component
    F_t sin A_p of a roller (at most a few per cent of N) is left out of the force balance."""
    position = geometry.base_distance + lift
    if geometry.kind == "flat":
        arm = position
    else:
        arm = position * np.cos(pressure_angle) - geometry.offset * np.sin(pressure_angle) - geometry.roller_radius
    torque = tangential_force * arm
    return {"friction_torque": torque, "cam_torque_with_friction": cam_torque + torque, "friction_arm": arm}
