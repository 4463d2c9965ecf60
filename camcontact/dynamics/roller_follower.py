"""Spin dynamics of a roller follower: roller speed, slip and the tangential (traction) force per cam angle.

A roller follower rolls on the cam only as long as the traction the film can transmit accelerates the
roller and overcomes its pin friction and rolling resistance. With the roller's angular speed omega_r as
the state (Duffy 1993, SAE 930691; Chiu 1992, SAE 921693; reference ``friction_traction_thermal.md`` §5)

.. math::
    I_r \\dot\\omega_r = R_f F_t(u_s) - T_{pin} - R_f F_{rr}, \\qquad
    u_s = u_{cam} - R_f (\\omega_r + \\dot A_p),
    \\qquad T_{pin} = \\mu_{pin} N r_{pin}

with F_t the traction force the contact transmits at the sliding speed u_s (from a traction model, or a
Coulomb limit mu N), the pin (needle or bush) friction torque T_pin and the rolling-resistance force
F_rr; u_cam is the cam's surface speed relative to the contact point, which itself travels round the
roller's rim at the rate of the pressure angle A_p (:func:`rim_rate`). Where the roller rolls
(omega_r = u_roll / R_f, u_roll = u_cam - R_f dA_p/dt), F_t equals the no-slip requirement

.. math:: F_{req} = \\frac{I_r}{R_f}\\frac{d}{dt}\\left(\\frac{u_{roll}}{R_f}\\right) + \\frac{T_{pin}}{R_f} + F_{rr}

(:func:`required_traction`, the independent estimate); where F_req exceeds the traction available the
roller slips. :func:`roller_cycle` integrates the equation over periodic cam turns (implicit Euler,
exact on a piecewise-linear traction table per angle, numba kernel with its plain-Python twin).
Forces [N], torques [N m], speeds [m/s], angular speeds [rad/s], inertia [kg m^2].
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..errors import InputError
from . import _roller_kernels

__all__ = ["COULOMB_CREEP", "RollerCycle", "check_full_turn", "coulomb_table", "full_turn", "rim_rate", "pin_friction_torque", "required_traction", "roller_cycle", "slip_grid",
           "solid_roller_inertia"]

#: creep (fraction of the rolling speed) at which a Coulomb-limited contact reaches its limit: a regularised
#: stick, so that the traction table is single-valued
COULOMB_CREEP = 1e-4
#: sliding speeds of the traction table as fractions of the rolling speed (both signs and 0)
SLIP_FRACTIONS = np.concatenate((-np.logspace(0.5, -7, 48), [0.0], np.logspace(-7, 0.5, 48)))


def solid_roller_inertia(radius: float, width: float, density: float) -> float:
    """Polar moment of inertia of a solid cylindrical roller, (pi/2) rho w R^4 [kg m^2]."""
    for name, value in (("radius", radius), ("width", width), ("density", density)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"solid_roller_inertia: {name} = {value!r}; allowed: finite, > 0")
    return 0.5 * math.pi * density * width * radius**4


def pin_friction_torque(normal_force, coefficient: float, pin_radius: float):
    """Friction torque of the roller's pin bearing mu_pin N r_pin [N m] (the pin carries the contact force)."""
    return coefficient * pin_radius * np.asarray(normal_force, dtype=float)


def _periodic_derivative(values: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """d values / d theta of a periodic sample over a full turn (second-order central differences)."""
    step = 2.0 * math.pi / theta.size
    return (np.roll(values, -1) - np.roll(values, 1)) / (2.0 * step)


def full_turn(theta) -> bool:
    """Whether the cam angles ``theta`` [rad] sample one full turn uniformly with at least 36 angles."""
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    n = theta.size
    expected = theta[0] + np.arange(n) * (2.0 * math.pi / max(n, 1))
    return n >= 36 and bool(np.allclose(theta, expected, rtol=0.0, atol=1e-9))


def check_full_turn(theta) -> np.ndarray:
    """``theta`` [rad] as an array when it samples one full turn uniformly; InputError otherwise."""
    theta = np.asarray(theta, dtype=float)
    n = theta.size
    if not full_turn(theta):
        raise InputError(
            f"the roller's spin dynamics integrate over the cam turn: the cam angles must sample a full turn "
            f"uniformly with at least 36 angles (got {n} angles); set CamFollower.angle_step instead of angles, "
            "or ask for outputs that need no roller dynamics")
    return theta


def rim_rate(theta, angular_speed, pressure_angle):
    """dA_p/dt [rad/s]: the rate at which the contact point travels round the roller's rim (the pressure
    angle's rate over a full turn of cam angles ``theta`` [rad] at cam speed ``angular_speed`` [rad/s]). In
    pure rolling the roller spins at omega_r = u_cam / R_f - dA_p/dt, u_cam relative to the contact point."""
    theta = check_full_turn(theta)
    angle = np.unwrap(np.asarray(pressure_angle, dtype=float))
    return np.asarray(angular_speed, dtype=float) * _periodic_derivative(angle, theta)


def required_traction(theta, angular_speed, u_cam, pin_torque, radius: float, inertia: float, resistance=0.0):
    """The tangential force [N] that keeps the roller rolling, F_req (module docstring), over a full turn
    of cam angles ``theta`` [rad] at cam speed ``angular_speed`` [rad/s]; ``u_cam`` [m/s] is the roller's
    pure-rolling surface speed u_roll; d/dt = omega d/dtheta."""
    theta = check_full_turn(theta)
    spin_rate = np.asarray(angular_speed, dtype=float) * _periodic_derivative(np.asarray(u_cam, float) / radius,
                                                                               theta)
    return inertia * spin_rate / radius + np.asarray(pin_torque, dtype=float) / radius + resistance


def slip_grid(u_roll) -> np.ndarray:
    """Sliding speeds [m/s] of the traction table at each angle: :data:`SLIP_FRACTIONS` of |u_roll|
    (angles x nodes; at least 1e-6 m/s of scale where the roller stands)."""
    scale = np.maximum(np.abs(np.asarray(u_roll, dtype=float)), 1e-6)
    return scale[:, None] * SLIP_FRACTIONS[None, :]


def coulomb_table(limit, grid, u_roll) -> np.ndarray:
    """Traction force [N] of a Coulomb limit ``limit`` [N] (per angle) on the sliding speeds ``grid`` [m/s]
    (angles x nodes): limit s / s_c within the creep s_c = :data:`COULOMB_CREEP` |u_roll|, the limit beyond."""
    creep = COULOMB_CREEP * np.maximum(np.abs(np.asarray(u_roll, dtype=float)), 1e-6)
    return np.asarray(limit, dtype=float)[:, None] * np.clip(grid / creep[:, None], -1.0, 1.0)


@attrs.frozen
class RollerCycle:
    """The roller's spin over the last integrated turn, per cam angle."""

    roller_speed: np.ndarray  #: omega_r [rad/s]
    sliding_speed: np.ndarray  #: u_s = u_cam - R omega_r [m/s]
    traction_force: np.ndarray  #: F_t on the roller along the cam surface's motion [N]
    periodicity: float  #: largest change of omega_r from the turn before, relative to max |omega_r| [-]
    turns: int  #: turns integrated

    @property
    def converged(self) -> bool:
        """Whether the last turn repeats the one before to 1e-6 (a periodic cycle)."""
        return self.periodicity <= 1e-6


def roller_cycle(theta, angular_speed, u_cam, pin_torque, grid, force, *, radius: float, inertia: float,
                 resistance=None, turns: int = 4, substeps: int = 8, compiled: bool = True) -> RollerCycle:
    """The roller's speed, sliding speed and traction force over periodic cam turns.

    Parameters
    ----------
    theta : array
        Cam angles [rad] sampling one full turn uniformly.
    angular_speed : array
        Cam speed [rad/s] at each angle.
    u_cam : array
        The roller's surface speed in pure rolling, u_roll = u_cam - R_f dA_p/dt [m/s] (the drive: the
        sliding speed is u_roll - R_f omega_r).
    pin_torque : array
        Pin friction torque [N m] (opposes the roller's spin).
    grid, force : arrays (angles x nodes)
        The traction force on the roller [N] against the sliding speed [m/s] at each angle (non-decreasing
        along each row; constant beyond the row's ends), e.g. on :func:`slip_grid`.
    radius, inertia : float
        Roller radius R_f [m] and polar moment of inertia I_r [kg m^2] (> 0).
    resistance : array, optional
        Rolling-resistance force [N] (default 0).
    turns, substeps : int
        Turns integrated from pure rolling at the first angle (the last one is returned) and implicit
        Euler steps between neighbouring angles.
    compiled : bool
        numba kernel (default) or its plain-Python twin.
    """
    theta = check_full_turn(theta)
    n = theta.size
    if not (radius > 0.0 and inertia > 0.0):
        raise InputError(f"roller_cycle: radius = {radius!r} m and inertia = {inertia!r} kg m^2 must be > 0")
    omega = np.broadcast_to(np.asarray(angular_speed, dtype=float), (n,))
    if np.any(omega <= 0.0):
        raise InputError("roller_cycle: the cam speed must be > 0 at every angle")
    arrays = [np.ascontiguousarray(np.broadcast_to(np.asarray(v, dtype=float), (n,)))
              for v in (u_cam, pin_torque, 0.0 if resistance is None else resistance)]
    grid = np.ascontiguousarray(grid, dtype=float)
    force = np.ascontiguousarray(force, dtype=float)
    if grid.shape != force.shape or grid.shape[0] != n or grid.shape[1] < 2:
        raise InputError(f"roller_cycle: traction table shapes {grid.shape} and {force.shape}; expected "
                         f"({n}, nodes >= 2) both")
    if not (np.all(np.isfinite(force)) and np.all(np.diff(grid, axis=1) > 0) and np.all(np.diff(force, axis=1) >= 0)):
        raise InputError("roller_cycle: the traction table must be finite, its sliding speeds increasing and its "
                         "forces non-decreasing along each angle's row")
    step = 2.0 * math.pi / n
    dt = step / (0.5 * (omega + np.roll(omega, -1)))
    out = np.zeros((4, n))
    kernel = _roller_kernels.compiled("march_roller") if compiled else _roller_kernels.march_roller
    change = kernel(dt, *arrays, grid, force, float(radius), float(inertia), int(turns), int(substeps), out)
    scale = max(float(np.max(np.abs(out[0]))), 1e-300)
    return RollerCycle(out[0].copy(), out[1].copy(), out[2].copy(), float(change) / scale, int(turns))
