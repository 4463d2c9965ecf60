"""Kinematics of translating followers: motion, profile, pressure angle, curvature, entrainment.

Pure SI functions on arrays of cam angle θ [rad] (Tsuha 2015 §3.2–3.4). The lift and its
derivatives with respect to cam angle, f [m], f' [m/rad], f'' [m/rad²], f''' [m/rad³], come
from a :class:`~camcontact.kinematics.motion_program.MotionProgram`.

Geometry: cam centre at the origin, turning counter-clockwise; follower axis vertical, offset
ε to +x (roller). Contact point in the fixed frame: flat face (f', S) with S = R_o + f; roller
(ε + R_f sin A_p, S − R_f cos A_p) with S = sqrt(R_po² − ε²) + f (Eqs. 3.12, 3.20–3.23).

Two speed conventions (reference §0 item 10, DESIGN "Numerical EHL"):

``"consistent"``
    the surface speeds of cam and follower relative to the moving contact point; entrainment
    u_m = (u_cam + u_follower)/2. For the roller (pure rolling) both equal the speed at which the
    contact point runs along the cam profile, ω sqrt(S² + (f' − ε)²) R_cam/P_p.
``"thesis"``
    Tsuha's speeds: roller u_m = R_cam ω (Eq. 3.42), flat u_m = (R_o + f + 2 f'') ω / 2 (Eq. 3.34).
    For the flat face they coincide with the consistent ones; for the roller they coincide on the
    base circle only. (The factor 2 of the thesis's Moes groups is handled by the film step.)
"""

from __future__ import annotations

import attrs
import numpy as np

from ..errors import InputError

__all__ = ["FollowerGeometry", "FollowerKinematics", "follower_kinematics", "angular_speed"]

CONVENTIONS = ("consistent", "thesis")


@attrs.frozen
class FollowerGeometry:
    """SI geometry of a cam–follower pair: kind, base radius R_b [m], roller radius R_f [m], offset ε [m]."""

    kind: str
    base_radius: float
    roller_radius: float = 0.0
    offset: float = 0.0

    @property
    def prime_radius(self) -> float:
        """R_po = R_b + R_f [m] (roller) or R_b (flat)."""
        return self.base_radius + (self.roller_radius if self.kind == "roller" else 0.0)

    @property
    def base_distance(self) -> float:
        """S_0 [m]: follower position on the base circle (Eqs. 3.1/3.2)."""
        if self.kind == "flat":
            return self.base_radius
        if abs(self.offset) >= self.prime_radius:
            raise InputError(
                f"follower offset |ε| = {abs(self.offset) * 1e3:.4g} mm must be smaller than the prime-circle "
                f"radius R_po = {self.prime_radius * 1e3:.4g} mm"
            )
        return float(np.sqrt(self.prime_radius**2 - self.offset**2))


def angular_speed(theta, speed: float, angular_acceleration: float = 0.0):
    """ω(θ) [rad/s] at cam angle θ [rad] from ω(0) = ``speed`` and a constant angular acceleration [rad/s²].

    ω² = ω0² + 2 Ä θ; an acceleration that would stop or reverse the cam inside the range is an error.
    """
    theta = np.asarray(theta, dtype=float)
    squared = speed**2 + 2.0 * angular_acceleration * theta
    if np.any(squared <= 0.0):
        raise InputError(
            f"angular acceleration {angular_acceleration:g} rad/s² stops the cam (ω = 0) before "
            f"θ = {np.degrees(theta.max()):.4g}° at ω0 = {speed:g} rad/s"
        )
    return np.sqrt(squared)


@attrs.frozen
class FollowerKinematics:
    """Per-angle kinematics (arrays over θ; SI): see :func:`follower_kinematics`."""

    theta: np.ndarray  #: cam angle [rad]
    omega: np.ndarray  #: cam angular speed [rad/s]
    lift: np.ndarray  #: f [m]
    position: np.ndarray  #: S = S_0 + f [m]
    velocity: np.ndarray  #: Ṡ [m/s]
    acceleration: np.ndarray  #: S̈ [m/s²]
    jerk: np.ndarray  #: d³S/dt³ [m/s³]
    pressure_angle: np.ndarray  #: A_p [rad] (0 for a flat face)
    pitch_radius: np.ndarray  #: P_p [m], radius of curvature of the pitch curve (roller) or of the cam (flat)
    cam_radius: np.ndarray  #: R_cam [m] (negative = concave)
    reduced_radius: np.ndarray  #: R [m], 1/R = 1/R_cam + 1/R_f
    u_cam: np.ndarray  #: cam surface speed relative to the contact point [m/s]
    u_follower: np.ndarray  #: follower surface speed relative to the contact point [m/s]
    u_m: np.ndarray  #: entrainment speed (u_cam + u_follower)/2 [m/s] (in the chosen convention)
    u_s: np.ndarray  #: sliding speed u_cam − u_follower [m/s]
    profile_x: np.ndarray  #: cam profile in the cam frame [m]
    profile_y: np.ndarray
    profile_radius: np.ndarray  #: R_C, polar radius of the contact point on the cam [m] (Eqs. 3.15/3.23)
    profile_angle: np.ndarray  #: φ, its polar angle in the cam frame [rad]


def follower_kinematics(program, geometry: FollowerGeometry, theta, speed: float, angular_acceleration: float = 0.0,
                        convention: str = "consistent") -> FollowerKinematics:
    """Kinematics of a translating follower over cam angles ``theta`` [rad].

    Parameters
    ----------
    program : MotionProgram
        Gives f, f', f'', f''' at θ.
    geometry : FollowerGeometry
    theta : array
        Cam angles [rad].
    speed : float
        Cam angular speed at θ = 0 [rad/s] (> 0).
    angular_acceleration : float
        Constant cam angular acceleration Ä [rad/s²] (Tsuha 2015 Eq. 3.4).
    convention : {"consistent", "thesis"}
        Speed convention (module docstring).

    Notes
    -----
    Ṡ = f' ω, S̈ = f'' ω² + f' Ä, d³S/dt³ = f''' ω³ + 3 f'' ω Ä (Eqs. 3.3, 3.4).
    Roller: tan A_p = (f' − ε)/S (3.19); P_p = [S² + (f' − ε)²]^{3/2}/[S² − S f'' + (f' − ε)(2 f' − ε)]
    (3.40, corrected numerator); R_cam = P_p − R_f (3.41). Flat: R_cam = R_o + f + f'' (3.30);
    u_follower = f'' ω, u_cam = R_cam ω (3.31–3.33).
    """
    if convention not in CONVENTIONS:
        raise InputError(f"speed convention {convention!r} unknown; choose one of {CONVENTIONS}")
    if not speed > 0.0:
        raise InputError(f"cam speed = {speed!r} rad/s must be > 0")
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    values = program.evaluate(theta)
    f, f1, f2, f3 = (np.asarray(v, dtype=float) for v in values[:4])
    omega = angular_speed(theta - theta.min(), speed, angular_acceleration) if angular_acceleration else np.full_like(theta, speed)
    S = geometry.base_distance + f
    velocity = f1 * omega
    acceleration = f2 * omega**2 + f1 * angular_acceleration
    jerk = f3 * omega**3 + 3.0 * f2 * omega * angular_acceleration

    if geometry.kind == "flat":
        pressure_angle = np.zeros_like(theta)
        cam_radius = geometry.base_radius + f + f2
        pitch_radius = cam_radius
        reduced = cam_radius.copy()
        u_follower = f2 * omega
        u_cam = cam_radius * omega
        contact_x, contact_y = f1, S
    else:
        eps, R_f = geometry.offset, geometry.roller_radius
        slope = f1 - eps
        pressure_angle = np.arctan2(slope, S)
        # curvature of the pitch curve (finite through inflections, where P_p is infinite)
        curvature = (S**2 - S * f2 + slope * (2.0 * f1 - eps)) / (S**2 + slope**2) ** 1.5
        with np.errstate(divide="ignore"):
            pitch_radius = 1.0 / curvature
        cam_radius = pitch_radius - R_f
        reduced = R_f * (1.0 - R_f * curvature)  # = R_cam R_f/(R_cam + R_f)
        if convention == "thesis":
            u_cam = cam_radius * omega
            if not np.all(np.isfinite(u_cam)):
                raise InputError("thesis speed convention: u_m = R_cam ω is infinite where the pitch curve has an "
                                 "inflection; use convention='consistent'")
        else:
            u_cam = omega * np.sqrt(S**2 + slope**2) * (1.0 - R_f * curvature)
        u_follower = u_cam.copy()  # pure rolling
        contact_x = eps + R_f * np.sin(pressure_angle)
        contact_y = S - R_f * np.cos(pressure_angle)
    u_m = 0.5 * (u_cam + u_follower)
    u_s = u_cam - u_follower
    # the cam profile: the contact point carried into the cam frame (rotation by −θ)
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    profile_x = cos_t * contact_x + sin_t * contact_y
    profile_y = -sin_t * contact_x + cos_t * contact_y
    return FollowerKinematics(
        theta=theta, omega=omega, lift=f, position=S, velocity=velocity, acceleration=acceleration, jerk=jerk,
        pressure_angle=pressure_angle, pitch_radius=pitch_radius, cam_radius=cam_radius, reduced_radius=reduced,
        u_cam=u_cam, u_follower=u_follower, u_m=u_m, u_s=u_s, profile_x=profile_x, profile_y=profile_y,
        profile_radius=np.hypot(contact_x, contact_y), profile_angle=np.arctan2(profile_y, profile_x),
    )


def sign_changes(theta, values) -> np.ndarray:
    """Cam angles [rad] where ``values`` changes sign, by linear interpolation between samples."""
    theta = np.asarray(theta, dtype=float)
    values = np.asarray(values, dtype=float)
    crossings = []
    for i in range(values.size - 1):
        a, b = values[i], values[i + 1]
        if a == 0.0:
            crossings.append(theta[i])
        elif a * b < 0.0:
            crossings.append(theta[i] + (theta[i + 1] - theta[i]) * a / (a - b))
    if values.size and values[-1] == 0.0:
        crossings.append(theta[-1])
    return np.asarray(crossings)


def undercut_angles(kinematics: FollowerKinematics, geometry: FollowerGeometry) -> np.ndarray:
    """Cam angles [rad] where the profile undercuts or has a cusp.

    Flat face: R_cam <= 0 (Eq. 3.30). Roller: a convex pitch curve tighter than the roller,
    0 < P_p <= R_f (the cam radius R_cam = P_p − R_f would be <= 0 with a convex pitch curve).
    """
    if geometry.kind == "flat":
        bad = kinematics.cam_radius <= 0.0
    else:
        P = kinematics.pitch_radius
        bad = (P > 0.0) & (P <= geometry.roller_radius)
    return kinematics.theta[bad]
