"""Kinematics steps: surface speeds, entrainment and sliding of every scene's contacts.

Entrainment speed u_m = (u1 + u2)/2, sliding speed u_s = u1 - u2 [m/s] throughout. The cam follower
after Tsuha (2015) Ch. 3 (:func:`camcontact.kinematics.follower.follower_kinematics`), pure rolling
of a bearing after Harris & Kotzalas (2007) ch. 8, the ball-cone CVT after Saccheto (2008) §2.9-2.11
(:func:`camcontact.kinematics.ball_cone.ball_cone_kinematics`), the raceway contact after
Delabenetta (2021) Eqs. 31, 45. Speeds of rotation [rad/s] unless named ``n_...`` [rev/s].
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..errors import InputError, ValidityWarning
from ..kinematics.ball_cone import ball_cone_kinematics
from ..kinematics.follower import follower_kinematics, undercut_angles
from ..models.film_thermal import slide_roll_measure
from ..step_graph import step

__all__ = [
    "FOLLOWER_KINEMATICS", "RACEWAY_KINEMATICS", "ball_cone_motion", "bearing_kinematics", "bearing_surface_speeds",
    "degrees_text",
    "follower_motion",
    "given_raceway_speeds", "motion_continuity", "pure_rolling_raceway", "raceway_sliding_speed", "split_speed",
    "surface_kinematics",
]

FOLLOWER_KINEMATICS = ("lift", "follower_velocity", "follower_acceleration", "follower_jerk", "pressure_angle",
                       "cam_radius", "R", "u_cam", "u_follower", "u_m", "u_s", "angular_speed", "profile_x",
                       "profile_y")
RACEWAY_KINEMATICS = ("u_raceway", "u_roller", "u_m", "slide_roll_measure", "speed_basis")


def degrees_text(theta) -> str:
    """``"30°, 45.5°"``: angles [rad] in degrees, for messages."""
    return ", ".join(f"{math.degrees(t):.4g}°" for t in np.atleast_1d(theta))


@step("kinematics", provides=("u_m", "u_s", "slide_roll_ratio"))
def surface_kinematics(u1, u2):
    """Entrainment u_m, sliding u_s [m/s] and the slide-to-roll ratio u_s/u_m of two surfaces moving at
    u1, u2 [m/s] (infinite for pure sliding, 0 without motion)."""
    u_m = 0.5 * (u1 + u2)
    u_s = u1 - u2
    if u_m != 0:
        ratio = u_s / u_m
    else:  # no entrainment: pure sliding (infinite ratio) or no motion at all (zero)
        ratio = 0.0 if u_s == 0 else float(np.copysign(np.inf, u_s))
    return {"u_m": u_m, "u_s": u_s, "slide_roll_ratio": ratio}


@step("kinematics", provides=FOLLOWER_KINEMATICS,
      model=lambda geometry, convention: f"{geometry.kind} follower ({convention})")
def follower_motion(program, geometry, cam_angle, speed, angular_acceleration, convention, max_pressure_angle):
    """Lift, velocity, acceleration, jerk, pressure angle, radii, surface and entrainment speeds and the
    cam profile at every cam angle [rad] (cam speed [rad/s], angular acceleration [rad/s^2]).

    InputError naming the angles where the profile undercuts; a ValidityWarning where the pressure angle
    exceeds ``max_pressure_angle`` [rad]. ``convention`` "consistent" or "thesis" (Tsuha's speeds).
    """
    k = follower_kinematics(program, geometry, cam_angle, speed, angular_acceleration, convention)
    bad = undercut_angles(k, geometry)
    if bad.size:
        what = "R_cam <= 0" if geometry.kind == "flat" else "pitch-curve radius <= roller radius"
        raise InputError(f"the cam profile undercuts (cusp, {what}) at {degrees_text(bad[:8])}"
                         f"{' …' if bad.size > 8 else ''}; raise the base radius or lower the lift/acceleration")
    over = np.abs(k.pressure_angle) > max_pressure_angle
    if np.any(over):
        worst = int(np.argmax(np.abs(k.pressure_angle)))
        warnings.warn(
            f"pressure angle {math.degrees(k.pressure_angle[worst]):.4g}° at {degrees_text(k.theta[worst])} exceeds "
            f"the limit {math.degrees(max_pressure_angle):.4g}° (at {int(over.sum())} of {over.size} angles)",
            ValidityWarning, stacklevel=2)
    return {"lift": k.lift, "follower_velocity": k.velocity, "follower_acceleration": k.acceleration,
            "follower_jerk": k.jerk, "pressure_angle": k.pressure_angle, "cam_radius": k.cam_radius,
            "R": k.reduced_radius, "u_cam": k.u_cam, "u_follower": k.u_follower, "u_m": k.u_m, "u_s": k.u_s,
            "angular_speed": k.omega, "profile_x": k.profile_x, "profile_y": k.profile_y}


@step("continuity", provides=("motion_continuity",))
def motion_continuity(program):
    """Where the motion program's acceleration jumps (infinite jerk) or its jerk jumps, as text."""
    table = program.continuity()
    infinite = table.loc[~table["jerk_finite"], "angle [deg]"].tolist()
    if infinite:
        where = ", ".join(f"{a:.4g}°" for a in infinite)
        return {"motion_continuity": f"acceleration jumps (infinite jerk) at {where}"}
    jumps = table.loc[~table["jerk_continuous"], "angle [deg]"].tolist()
    text = "C2 everywhere (finite jerk)"
    return {"motion_continuity": text + (f"; jerk jumps at {', '.join(f'{a:.4g}°' for a in jumps)}" if jumps else "")}


@step("kinematics", provides=("cage_speed", "roller_speed", "u_m"), model="pure_rolling")
def bearing_kinematics(n_inner, n_outer, gamma, pitch_diameter, roller_diameter):
    """Pure rolling in a bearing with ring speeds n_inner, n_outer [rev/s]: cage speed
    pi [n_i (1 - gamma) + n_o (1 + gamma)] [rad/s], roller speed about its axis
    2 pi (d_m / 2 D_w)(1 - gamma^2)|n_i - n_o| [rad/s] and the entrainment speed of both raceway contacts
    (pi d_m / 2)(1 - gamma^2)|n_i - n_o| [m/s] (gamma = D_w cos(alpha) / d_m)."""
    relative = abs(n_inner - n_outer)
    return {
        "cage_speed": 2 * math.pi * 0.5 * (n_inner * (1 - gamma) + n_outer * (1 + gamma)),
        "roller_speed": 2 * math.pi * pitch_diameter / (2 * roller_diameter) * (1 - gamma**2) * relative,
        "u_m": 0.5 * math.pi * pitch_diameter * (1 - gamma**2) * relative,
    }


def _slide_roll(u1: float, u2: float) -> float:
    if u1 + u2 <= 0.0:
        raise InputError("raceway_contact: the surfaces do not move (ring_speed = 0): no entrainment, no film")
    return float(slide_roll_measure(u1, u2))


def split_speed(u_m, slide_roll_ratio):
    """The two surface speeds [m/s] about the entrainment speed u_m [m/s] at the slide/roll ratio s = (u1 - u2)/u_m:
    (u_m (1 + s/2), u_m (1 - s/2))."""
    return u_m * (1.0 + 0.5 * slide_roll_ratio), u_m * (1.0 - 0.5 * slide_roll_ratio)


@step("surface_speeds", provides=("u1", "u2"))
def bearing_surface_speeds(u_m, **inputs):
    """Surface speeds [m/s] of ring and roller at a raceway contact, u_m (1 + s/2) and u_m (1 - s/2), with the
    scene's ``slide_roll_ratio`` s (``inputs``; pure rolling, s = 0, without one)."""
    u1, u2 = split_speed(u_m, inputs.get("slide_roll_ratio") or 0.0)
    return {"u1": u1, "u2": u2}


@step("kinematics", provides=RACEWAY_KINEMATICS, model="pure_rolling")
def pure_rolling_raceway(ring_speed, slide_roll_ratio, pitch_diameter, gamma):
    """Surface speeds [m/s] of a raceway contact rolling purely in the cage frame,
    u = (pi d_m / 2)(1 - gamma^2) n (ring speed n [rev/s]), split by the contact's slide/roll ratio."""
    rolling = 0.5 * math.pi * pitch_diameter * (1.0 - gamma**2) * ring_speed
    u1, u2 = split_speed(rolling, slide_roll_ratio)
    return {"u_raceway": u1, "u_roller": u2, "u_m": rolling, "slide_roll_measure": _slide_roll(u1, u2),
            "speed_basis": f"pure rolling in the cage frame (d_m = {pitch_diameter * 1e3:.4g} mm), "
                           f"slide/roll {slide_roll_ratio:g}"}


@step("sliding", provides=("u_s",))
def raceway_sliding_speed(u_raceway, u_roller):
    """Sliding speed u_s = u_raceway - u_roller [m/s] of a raceway contact (the shear of its film)."""
    return {"u_s": u_raceway - u_roller}


@step("kinematics", provides=RACEWAY_KINEMATICS, model="given_speeds")
def given_raceway_speeds(R1, R2, ring_speed, roller_speed):
    """Surface speeds [m/s] of the raceway (radius R1 [m], ring speed [rev/s]) and the roller (R2, roller
    speed [rev/s]) both in the ground frame, as Delabenetta (2021) Eq. 31."""
    u1 = R1 * 2 * math.pi * ring_speed
    u2 = R2 * 2 * math.pi * roller_speed
    return {"u_raceway": u1, "u_roller": u2, "u_m": 0.5 * (u1 + u2), "slide_roll_measure": _slide_roll(u1, u2),
            "speed_basis": "given ring and roller speeds, ground frame (Delabenetta Eq. 31)"}


BALL_CONE_KINEMATICS = ("tilt", "reduction_ratio", "overrange", "output_speed", "ball_speed", "rolling_radius_in",
                        "rolling_radius_out", "rolling_speed_in", "rolling_speed_out", "psi_in", "psi_out",
                        "psi_total", "spin_in", "spin_out", "spin_roll_in", "spin_roll_out")


@step("kinematics", provides=BALL_CONE_KINEMATICS, model=lambda cvt: f"ball_cone ({cvt.ratio_convention} ratio)")
def ball_cone_motion(cvt, ratio, input_speed):
    """Tilt, speeds, rolling radii and spin of the ball-cone CVT ``cvt`` at ``ratio`` (in its ratio
    convention) and input speed [rad/s] (Saccheto 2008 Tabela A.1)."""
    beta = cvt.tilt(ratio)
    out = ball_cone_kinematics(cvt.ball_radius, cvt.si.cone_angle, cvt.si.cone_contact_radius, beta, input_speed)
    return {**out, "tilt": beta, "reduction_ratio": cvt.reduction_ratio(ratio), "overrange": cvt.overrange}
