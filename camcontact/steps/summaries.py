"""Cycle summaries: peaks, minima and means over a cam turn (scalars of the per-angle outputs).

Means are over equally spaced cam angles of a full turn (a time mean at constant cam speed).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..step_graph import step

__all__ = ["cycle_mean", "friction_power_mean", "friction_torque_mean", "h_min_cycle", "jump_margin", "peak_contact_force",
           "peak_pressure", "wear_rate_mean"]


def cycle_mean(cam_angle: np.ndarray, values: np.ndarray) -> float:
    """Mean of ``values`` over a turn sampled at equally spaced ``cam_angle`` [rad] (InputError otherwise)."""
    if cam_angle.size > 1 and not np.allclose(np.diff(cam_angle), cam_angle[1] - cam_angle[0]):
        raise InputError("cycle means need equally spaced cam angles over a full turn (use angle_step)")
    return float(np.mean(values))


@step("jump_margin", provides=("jump_margin",))
def jump_margin(contact_force):
    """The smallest contact force over the turn [N] (negative: the follower jumps)."""
    return {"jump_margin": float(np.min(contact_force))}


@step("contact_force_max", provides=("contact_force_max",))
def peak_contact_force(contact_force):
    """The largest contact force over the turn [N]."""
    return {"contact_force_max": float(np.max(contact_force))}


@step("p_h_max", provides=("p_h_max",))
def peak_pressure(p_h):
    """The largest Hertz pressure over the turn [Pa]."""
    return {"p_h_max": float(np.max(p_h))}


@step("h_min_cycle", provides=("h_min_cycle",))
def h_min_cycle(h_min):
    """The thinnest film over the turn [m] (0 when no angle has one)."""
    return {"h_min_cycle": float(np.nanmin(h_min)) if np.any(np.isfinite(h_min)) else 0.0}


def _per_turn(cam_angle, rate, angular_speed) -> tuple[float, float]:
    """(time mean [unit of rate], integral over one turn [unit of rate x s]) of a rate sampled over the turn at
    the cam's angular speed omega(theta) [rad/s]: the turn lasts T = int dtheta/omega, the integral is
    int rate dtheta/omega (with a constant speed: the angle mean and mean x 2 pi/omega)."""
    per_angle = cycle_mean(cam_angle, np.asarray(rate, dtype=float) / angular_speed) * 2.0 * math.pi
    duration = cycle_mean(cam_angle, 1.0 / np.asarray(angular_speed, dtype=float)) * 2.0 * math.pi
    return per_angle / duration, per_angle


@step("friction_power_mean", provides=("friction_power_mean", "friction_energy_per_cycle"))
def friction_power_mean(friction_power, angular_speed, cam_angle):
    """The friction power averaged over the time of a turn [W] and the energy it dissipates per cam turn [J],
    at the cam's angular speed over the turn [rad/s] (which changes under an angular acceleration)."""
    mean, energy = _per_turn(cam_angle, friction_power, angular_speed)
    return {"friction_power_mean": mean, "friction_energy_per_cycle": energy}


@step("friction_torque_mean", provides=("friction_torque_mean", "cam_torque_with_friction_max"))
def friction_torque_mean(friction_torque, cam_torque_with_friction, cam_angle):
    """The camshaft friction torque averaged over the turn [N m] (its work per turn over 2 pi) and the
    largest drive torque with friction [N m]."""
    return {"friction_torque_mean": cycle_mean(cam_angle, friction_torque),
            "cam_torque_with_friction_max": float(np.max(cam_torque_with_friction))}


@step("wear_rate_mean", provides=("wear_rate_mean", "wear_volume_per_cycle"))
def wear_rate_mean(wear_rate, angular_speed, cam_angle):
    """The wear rate averaged over the time of a turn [m^3/s] and the volume worn per turn [m^3], at the cam's
    angular speed over the turn [rad/s]."""
    mean, volume = _per_turn(cam_angle, wear_rate, angular_speed)
    return {"wear_rate_mean": mean, "wear_volume_per_cycle": volume}
