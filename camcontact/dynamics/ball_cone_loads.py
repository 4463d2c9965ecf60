"""Forces in a ball-cone traction CVT: torque, loading-cam clamping, normal and tangential contact forces.

Saccheto (2008) §6.5 (reference ``ball_cone_cvt_saccheto2008.md`` §2.11), for power Pot [W] at
input speed omega [rad/s] through n balls, the cones' contact radius R_cont, a loading cam
(m balls on ramps of angle eta at radius R_cam):

* input torque T = Pot/omega; tangential force per input contact F_t = T/(R_cont n)  (Eq. 6.12);
* axial force of the cam F_2 m = T/(R_cam tan eta)  (Eq. 6.16);
* normal force per contact. The contact normal leans alpha off the radial direction (the ball
  centres sit on the circle R_cont + r cos(alpha)), so a contact force F_n has the axial component
  F_n sin(alpha) and the radial component F_n cos(alpha). **Default** ``clamping="axial_balance"``:
  the cone is in axial equilibrium when its n contacts carry the cam's thrust, n F_n sin(alpha) =
  F_2 m, so F_n = T/(R_cam tan(eta) n sin(alpha)) (5014 N per contact at 150 W, 60 rpm; the ball is
  then in axial balance between its two cones, and the ring takes the radial 2 F_n cos(alpha) of
  Eq. 6.18). ``clamping="thesis"`` is Saccheto's reading (Eq. 6.15, F_n n = F_2 m sin alpha;
  Eq. 6.17, F_n = T sin(alpha)/(R_cam tan(eta) n) = 1254 N): its contacts carry only
  sin^2(alpha) = 1/4 of the cam's thrust axially — statically impossible, kept because it is what
  reproduces the thesis's numbers (mu_min, the forces of its annex); :func:`contact_force_vectors`
  and :func:`axial_residuals` show the imbalance;
* the traction the input contact needs, mu_min = F_t/F_n: tan(eta) R_cam sin(alpha)/R_cont with
  axial balance, tan(eta) R_cam/(sin(alpha) R_cont) = 0.08813 with the thesis's clamping (Eq. 6.19);
  the output contact carries F_t BC/DE (the ball's torque balance), i.e. F_t omega_in/omega_out,
  with the same normal force (the thesis: "the normal force does not depend on the ratio").

The thesis reaches mu_min = 0.08813 with R_cam = 6 mm (its Tabela 6.1 prints 12 mm, most likely
the diameter) and R_cont of about 24 mm (reference §3.1 note).
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["CLAMPING", "axial_residuals", "ball_cone_loads", "contact_force_vectors", "minimum_traction"]

#: clamping readings; the first is the default (statics), the second Saccheto's Eq. 6.17
CLAMPING = ("axial_balance", "thesis")


def minimum_traction(cone_angle: float, cam_angle: float, cam_radius: float, cone_radius: float,
                     clamping: str = "axial_balance") -> float:
    """mu_min = F_t/F_n at the input contact [-]: tan(eta) R_cam sin(alpha)/R_cont with axial balance
    (default), tan(eta) R_cam/(sin(alpha) R_cont) with ``clamping="thesis"`` (Eq. 6.19)."""
    if clamping not in CLAMPING:
        raise InputError(f"clamping = {clamping!r}; allowed: {', '.join(map(repr, CLAMPING))}")
    ratio = math.tan(cam_angle) * cam_radius / cone_radius
    return ratio / math.sin(cone_angle) if clamping == "thesis" else ratio * math.sin(cone_angle)


def ball_cone_loads(power: float, input_speed: float, *, ball_count: int, cone_radius: float, cone_angle: float,
                    cam_angle: float, cam_radius: float, cam_ball_count: int, reduction_ratio: float,
                    clamping: str = "axial_balance") -> dict[str, float]:
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


def contact_force_vectors(normal_force: float, tangential_force_in: float, tangential_force_out: float,
                          cone_angle: float) -> dict[str, tuple[float, float, float]]:
    """The forces of the two cones on one ball as (axial, radial, circumferential) components [N].

    Axial is along the shaft from the input cone towards the output cone, radial outward from the
    shaft through the ball centre, circumferential along the input cone's rotation. The input cone
    pushes the ball along its contact normal, which leans ``cone_angle`` alpha off radial towards the
    output cone: F_n (sin alpha, cos alpha, 0), and drives it with F_t,in; the output cone pushes back
    along its mirrored normal, F_n (-sin alpha, cos alpha, 0), and resists with -F_t,out. Returns
    ``input`` and ``output`` (on the ball) and ``ring``, the force the ring/cage must add for the
    ball's equilibrium (radial: Eq. 6.18's -2 F_n cos alpha; circumferential: F_t,out - F_t,in).
    """
    s, c = math.sin(cone_angle), math.cos(cone_angle)
    inp = (normal_force * s, normal_force * c, tangential_force_in)
    out = (-normal_force * s, normal_force * c, -tangential_force_out)
    ring = tuple(-(i + o) for i, o in zip(inp, out))
    return {"input": inp, "output": out, "ring": ring}


def axial_residuals(loads: dict[str, float], *, ball_count: int, cone_angle: float) -> dict[str, float]:
    """Axial equilibrium of the clamped parts [N] for the forces of :func:`ball_cone_loads`.

    ``ball``: axial force on one ball from its two cones (zero by symmetry for any clamping);
    ``cone``: the loading cam's thrust on the input cone minus the axial reaction of its n ball
    contacts, F_2 m - n F_n sin(alpha) — zero for ``clamping="axial_balance"``, (1 - sin^2 alpha) F_2 m
    (3/4 of the thrust at alpha = 30 deg) unbalanced for the thesis's Eq. 6.17.
    """
    vectors = contact_force_vectors(loads["normal_force"], loads["tangential_force_in"],
                                    loads["tangential_force_out"], cone_angle)
    ball = vectors["input"][0] + vectors["output"][0]
    cone = loads["cam_axial_force"] - ball_count * vectors["input"][0]
    return {"ball": ball, "cone": cone}
