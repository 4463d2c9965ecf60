"""Ratio, tilt, rolling radii, speeds and spin of a ball-cone traction CVT (Saccheto 2008).

Geometry (reference ``ball_cone_cvt_saccheto2008.md`` §2.10): a ball of radius r touches the input
and output cones at points offset y = r sin(alpha) from its equator (alpha the cone angle, the
angle between the cone axis and the tangent plane). Tilting the ball axis by beta changes its
rolling radii at the two contacts (Eq. 6.1 and the derived closed form)

.. math:: \\overline{BC} = r\\cos(\\alpha + \\beta), \\qquad \\overline{DE} = r\\cos(\\alpha - \\beta)

With the cones' contact radius R_1 and no slip (Appendix P-1, P-2), the ball turns at
omega_ball = omega_in R_1 / BC and the output cone at omega_out = omega_in DE / BC. The thesis's
ratio (Eq. 6.2) is rt = BC/DE = omega_in/omega_out ("reduction": rt > 1 for beta < 0); its appendix
(P-4) uses the inverse, omega_out/omega_in ("speed"). Both are offered; the convention is named
wherever a ratio is given.

Spin (Eqs. 5.55-5.57): phi = omega_cone sin(alpha) - omega_ball sin(beta - alpha) at the input
contact, the spin coefficient psi = phi/omega_cone = sin(alpha) - A sin(beta - alpha) with
A = R_1/BC; at the output contact A = R_1/DE and the angle is (-beta - alpha) (the mirror image:
input at rt behaves as output at 1/rt). Kalker's spin creepage (spin angular velocity per rolling
speed V = omega_cone R_1) is psi/R_1 [1/m].
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["RATIO_CONVENTIONS", "ball_cone_kinematics", "overrange", "ratio_of_tilt", "rolling_radii",
           "spin_coefficients", "tilt_of_ratio"]

RATIO_CONVENTIONS = ("reduction", "speed")


def _check_convention(convention: str) -> None:
    if convention not in RATIO_CONVENTIONS:
        raise InputError(f"ratio convention {convention!r}; allowed: 'reduction' (omega_in/omega_out, the thesis's "
                         "Eq. 6.2) or 'speed' (omega_out/omega_in, its appendix P-4)")


def rolling_radii(ball_radius: float, cone_angle: float, tilt: float) -> tuple[float, float]:
    """(BC, DE) [m]: the ball's rolling radii at the input and output contacts for tilt beta [rad]."""
    bc, de = ball_radius * math.cos(cone_angle + tilt), ball_radius * math.cos(cone_angle - tilt)
    if not (bc > 0.0 and de > 0.0):
        raise InputError(f"ball tilt {math.degrees(tilt):.4g} deg with cone angle {math.degrees(cone_angle):.4g} deg "
                         "leaves a contact on the ball's axis (alpha + |beta| must stay below 90 deg)")
    return bc, de


def ratio_of_tilt(cone_angle: float, tilt: float, convention: str = "reduction") -> float:
    """Ratio [-] at tilt beta [rad]: cos(alpha + beta)/cos(alpha - beta) ("reduction") or its inverse."""
    _check_convention(convention)
    bc, de = rolling_radii(1.0, cone_angle, tilt)
    return bc / de if convention == "reduction" else de / bc


def tilt_of_ratio(cone_angle: float, ratio: float, convention: str = "reduction") -> float:
    """Tilt beta [rad] giving ``ratio`` (Eq. 6.3 in closed form: tan(beta) = cot(alpha)(1 - rt)/(1 + rt)
    with rt the reduction ratio)."""
    _check_convention(convention)
    if not (math.isfinite(ratio) and ratio > 0.0):
        raise InputError(f"ratio = {ratio!r}; allowed: a finite number > 0")
    rt = ratio if convention == "reduction" else 1.0 / ratio
    return math.atan((1.0 - rt) / ((1.0 + rt) * math.tan(cone_angle)))


def overrange(cone_angle: float, tilt_max: float) -> float:
    """Largest / smallest ratio over beta in [-beta_max, beta_max]: [cos(alpha - beta_max)/cos(alpha + beta_max)]^2."""
    return (math.cos(cone_angle - tilt_max) / math.cos(cone_angle + tilt_max)) ** 2


def spin_coefficients(ball_radius: float, cone_angle: float, cone_radius: float, tilt: float) -> tuple[float, float]:
    """(psi_in, psi_out) [-]: the thesis's spin coefficients phi/omega_cone at both contacts (Eq. 5.57)."""
    bc, de = rolling_radii(ball_radius, cone_angle, tilt)
    s = math.sin(cone_angle)
    return (s - cone_radius / bc * math.sin(tilt - cone_angle),
            s - cone_radius / de * math.sin(-tilt - cone_angle))


def ball_cone_kinematics(ball_radius: float, cone_angle: float, cone_radius: float, tilt: float,
                         input_speed: float) -> dict[str, float]:
    """Speeds of one operating point (SI: rad, rad/s, m, m/s), slip neglected (Appendix P-1..P-6).

    Returns ``rolling_radius_in``/``_out`` (BC, DE), ``ball_speed``, ``output_speed``,
    ``rolling_speed_in``/``_out`` (omega_cone R_1), ``psi_in``/``_out``/``psi_total`` and the spin
    creepages ``spin_in``/``_out`` = psi / R_1 [1/m].
    """
    if not (math.isfinite(input_speed) and input_speed > 0.0):
        raise InputError(f"input speed {input_speed!r} rad/s; allowed > 0")
    bc, de = rolling_radii(ball_radius, cone_angle, tilt)
    ball_speed = input_speed * cone_radius / bc
    output_speed = input_speed * de / bc
    psi_in, psi_out = spin_coefficients(ball_radius, cone_angle, cone_radius, tilt)
    return {
        "rolling_radius_in": bc, "rolling_radius_out": de, "ball_speed": ball_speed, "output_speed": output_speed,
        "rolling_speed_in": input_speed * cone_radius, "rolling_speed_out": output_speed * cone_radius,
        "psi_in": psi_in, "psi_out": psi_out, "psi_total": psi_in + psi_out,
        "spin_in": psi_in / cone_radius, "spin_out": psi_out / cone_radius,
        "spin_roll_in": psi_in * input_speed / ball_speed, "spin_roll_out": psi_out * output_speed / ball_speed,
    }
