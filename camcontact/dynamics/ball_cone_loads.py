"""Forces in a ball-cone traction CVT: torque, loading-cam clamping, normal and tangential contact forces.

Saccheto (2008) §6.5 (reference ``ball_cone_cvt_saccheto2008.md`` §2.11), for power Pot [W] at
input speed omega [rad/s] through n balls, the cones' contact radius R_cont, a loading cam
(m balls on ramps of angle eta at radius R_cam):

* input torque T = Pot/omega; tangential force per input contact F_t = T/(R_cont n)  (Eq. 6.12);
* axial force of the cam F_2 m = T/(R_cam tan eta)  (Eq. 6.16);
* normal force per contact, as the thesis balances it (Eq. 6.15, F_n n = F_2 m sin alpha):
  F_n = T sin(alpha)/(R_cam tan(eta) n)  (Eq. 6.17) — ``clamping="thesis"``; the axial balance of
  the cone, n F_n sin(alpha) = F_2 m, gives F_n = T/(R_cam tan(eta) n sin(alpha)) —
  ``clamping="axial_balance"`` (the reference's remark: the thesis form is what reproduces its numbers);
* the traction the input contact needs, mu_min = F_t/F_n = tan(eta) R_cam/(sin(alpha) R_cont)
  (Eq. 6.19, thesis clamping); the output contact carries F_t BC/DE (the ball's torque balance),
  i.e. F_t omega_in/omega_out, with the same normal force (the thesis: "the normal force does not
  depend on the ratio").

The thesis reaches mu_min = 0.08813 with R_cam = 6 mm (its Tabela 6.1 prints 12 mm, most likely
the diameter) and R_cont of about 24 mm (reference §3.1 note).
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["CLAMPING", "ball_cone_loads", "minimum_traction"]

CLAMPING = ("thesis", "axial_balance")


def minimum_traction(cone_angle: float, cam_angle: float, cam_radius: float, cone_radius: float,
                     clamping: str = "thesis") -> float:
    """mu_min = F_t/F_n at the input contact [-] (Eq. 6.19; with axial balance tan(eta) R_cam sin(alpha)/R_cont)."""
    if clamping not in CLAMPING:
        raise InputError(f"clamping = {clamping!r}; allowed: {', '.join(map(repr, CLAMPING))}")
    ratio = math.tan(cam_angle) * cam_radius / cone_radius
    return ratio / math.sin(cone_angle) if clamping == "thesis" else ratio * math.sin(cone_angle)


def ball_cone_loads(power: float, input_speed: float, *, ball_count: int, cone_radius: float, cone_angle: float,
                    cam_angle: float, cam_radius: float, cam_ball_count: int, reduction_ratio: float,
                    clamping: str = "thesis") -> dict[str, float]:
    """Forces of one operating point [N, N m] (see the module docstring).

    ``reduction_ratio`` is omega_in/omega_out = BC/DE. Returns ``torque``, ``output_torque``,
    ``cam_axial_force`` (F_2 m, all cam balls), ``cam_ball_force`` (F_2), ``normal_force`` (per
    contact), ``ball_axial_resultant`` (Eq. 6.18, 2 F_n cos alpha), ``tangential_force_in``/``_out``,
    ``traction_needed_in``/``_out`` (F_t/F_n) and ``mu_min``.
    """
    for label, value in (("power", power), ("input_speed", input_speed), ("cone_radius", cone_radius),
                         ("cam_radius", cam_radius), ("reduction_ratio", reduction_ratio)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"ball_cone_loads: {label} = {value!r}; allowed: finite and > 0")
    torque = power / input_speed
    tangential_in = torque / (cone_radius * ball_count)
    cam_axial = torque / (cam_radius * math.tan(cam_angle))
    if clamping == "thesis":
        normal = cam_axial * math.sin(cone_angle) / ball_count
    elif clamping == "axial_balance":
        normal = cam_axial / (ball_count * math.sin(cone_angle))
    else:
        raise InputError(f"clamping = {clamping!r}; allowed: {', '.join(map(repr, CLAMPING))}")
    tangential_out = tangential_in * reduction_ratio
    return {
        "torque": torque, "output_torque": torque * reduction_ratio, "cam_axial_force": cam_axial,
        "cam_ball_force": cam_axial / cam_ball_count, "normal_force": normal,
        "ball_axial_resultant": 2.0 * normal * math.cos(cone_angle),
        "tangential_force_in": tangential_in, "tangential_force_out": tangential_out,
        "traction_needed_in": tangential_in / normal, "traction_needed_out": tangential_out / normal,
        "mu_min": minimum_traction(cone_angle, cam_angle, cam_radius, cone_radius, clamping),
    }
