"""Follower kinematics checked against independent calculations: the synthesised profile's own
curvature and arc speed, the polar profile equations, time derivatives by finite differences, and the
scene's plan (a kinematics-only scene runs nothing else) and its input checks."""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError, ValidityWarning
from camcontact.kinematics.follower import FollowerGeometry, follower_kinematics
from camcontact.kinematics.motion_program import MotionProgram

STEEL = cc.Material(E="210 GPa", nu=0.3)
PROGRAM = MotionProgram.thesis_ls1()
OMEGA = 1000 * math.pi / 30
GEOMETRIES = {
    "roller": FollowerGeometry("roller", 0.040, 0.010, 0.005),
    "flat": FollowerGeometry("flat", 0.0497494),
}


def _curvature_radius(x, y, h):
    """Radius of curvature of a sampled plane curve by central differences; the cam turns counter-clockwise,
    so its contact point runs clockwise over the profile and a convex profile has a negative signed
    curvature in this parametrisation (+ returned for convex)."""
    dx, dy = np.gradient(x, h), np.gradient(y, h)
    ddx, ddy = np.gradient(dx, h), np.gradient(dy, h)
    return -((dx**2 + dy**2) ** 1.5) / (dx * ddy - dy * ddx)


@pytest.mark.parametrize("kind", ["roller", "flat"])
def test_cam_radius_and_surface_speed_from_the_profile_itself(kind):
    """The radius of curvature (Eqs. 3.30, 3.40–3.41) equals the curvature radius of the synthesised
    profile, and the consistent cam surface speed equals the speed of the contact point along it."""
    geometry = GEOMETRIES[kind]
    h = 1e-4
    theta = np.arange(0.0, 2 * math.pi, h)
    k = follower_kinematics(PROGRAM, geometry, theta, OMEGA)
    radius = _curvature_radius(k.profile_x, k.profile_y, h)
    arc_speed = np.hypot(np.gradient(k.profile_x, h), np.gradient(k.profile_y, h)) * OMEGA
    inner = slice(10, -10)
    np.testing.assert_allclose(radius[inner], k.cam_radius[inner], rtol=2e-4)
    np.testing.assert_allclose(arc_speed[inner], np.abs(k.u_cam[inner]), rtol=1e-4)  # 1e-4: the 180° joint


def test_polar_profile_equations_and_closure():
    """R_C of Eqs. 3.15 (flat) and 3.23 (roller); the profile closes after a turn."""
    theta = np.radians(np.arange(0.0, 361.0, 1.0))
    f, f1 = PROGRAM.evaluate(theta)[:2]
    flat = follower_kinematics(PROGRAM, GEOMETRIES["flat"], theta, OMEGA)
    np.testing.assert_allclose(flat.profile_radius, np.sqrt((0.0497494 + f) ** 2 + f1**2), rtol=1e-12)
    roller = follower_kinematics(PROGRAM, GEOMETRIES["roller"], theta, OMEGA)
    S, Ap = roller.position, roller.pressure_angle
    np.testing.assert_allclose(roller.profile_radius,
                               np.sqrt((S - 0.010 * np.cos(Ap)) ** 2 + (0.005 + 0.010 * np.sin(Ap)) ** 2), rtol=1e-12)
    for k in (flat, roller):
        assert k.profile_x[-1] == pytest.approx(k.profile_x[0], abs=1e-12)
        assert k.profile_y[-1] == pytest.approx(k.profile_y[0], abs=1e-12)


def test_time_derivatives_with_angular_acceleration():
    """Eqs. 3.3–3.4 with a constant angular acceleration: velocity, acceleration and jerk equal finite
    differences in time of S(θ(t)), θ = ω0 t + Ä t²/2."""
    omega0, accel = 50.0, 400.0
    t = np.linspace(0.0, 0.02, 20001)
    dt = t[1] - t[0]
    theta = omega0 * t + 0.5 * accel * t**2
    k = follower_kinematics(PROGRAM, GEOMETRIES["roller"], theta, omega0, accel)
    np.testing.assert_allclose(k.omega, omega0 + accel * t, rtol=1e-12)
    inner = slice(5, -5)
    np.testing.assert_allclose(np.gradient(k.position, dt)[inner], k.velocity[inner], rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(np.gradient(k.velocity, dt)[inner], k.acceleration[inner], rtol=1e-5, atol=1e-4)
    np.testing.assert_allclose(np.gradient(k.acceleration, dt)[inner], k.jerk[inner], rtol=1e-4, atol=1.0)


def _scene(**changes):
    arguments = dict(
        cam=cc.Cam(program=PROGRAM, base_radius="40 mm", width="15 mm", material=STEEL),
        follower=cc.Follower.roller(radius="10 mm", offset="5 mm", material=STEEL),
        valve_train=cc.ValveTrain.ls1(), speed="1000 rpm", angle_step="15 deg",
    )
    arguments.update(changes)
    return cc.CamFollower(**arguments)


def test_kinematics_only_scene_runs_only_kinematics():
    """No lubricant, no dynamics, no Hertz, no film: asking for kinematics runs one step."""
    analysis = cc.Analysis(_scene(), outputs=["lift", "pressure_angle", "u_m"])
    assert analysis.steps() == ["kinematics"]
    result = analysis.run()
    assert [r.step for r in result.records] == ["kinematics"]
    frame = result.to_frame()
    assert list(frame.columns) == ["cam_angle [deg]", "lift [mm]", "pressure_angle [deg]", "u_m [m/s]"]
    assert len(frame) == 24 and frame["lift [mm]"].max() == pytest.approx(20.0, abs=1e-9)


def test_force_scene_runs_no_film_and_film_needs_a_lubricant():
    analysis = cc.Analysis(_scene(), outputs=["contact_force", "p_h"])
    assert "film" not in analysis.steps() and "lubricant" not in analysis.steps()
    with pytest.raises(InputError, match="lubricant: set CamFollower.lubricant"):
        cc.Analysis(_scene(), outputs=["h_min"])


def test_undercut_profile_is_an_error_naming_the_angle():
    """A flat face on a small cam with a fast rise: R_cam = R_o + f + f'' < 0 (Eq. 3.30)."""
    steep = MotionProgram.rise_return_dwell(lift="20 mm", rise="40 deg", ret="40 deg", rise_law="cycloidal",
                                            return_law="cycloidal")
    scene = _scene(cam=cc.Cam(program=steep, base_radius="15 mm", width="15 mm", material=STEEL),
                   follower=cc.Follower.flat(material=STEEL), angle_step="1 deg")
    with pytest.raises(InputError, match=r"undercuts .* at \d+(\.\d+)?°"):
        cc.Analysis(scene, outputs=["cam_radius"], strict=True).run()


def test_pressure_angle_over_the_limit_warns_with_the_angle():
    tight = _scene(follower=cc.Follower.roller(radius="10 mm", offset="5 mm", material=STEEL,
                                               max_pressure_angle="20 deg"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cc.Analysis(tight, outputs=["pressure_angle"]).run()
    messages = [str(w.message) for w in caught if issubclass(w.category, ValidityWarning)]
    assert messages and "pressure angle -25.16° at 135°" in messages[0] and "limit 20°" in messages[0]


@pytest.mark.parametrize("changes, pattern", [
    ({"speed": "1000"}, r"CamFollower.speed = 1000.*expected 1/\[time\]"),
    ({"speed": "-5 rpm"}, "CamFollower.speed"),
    ({"convention": "tsuha"}, "CamFollower.convention = 'tsuha'; allowed: 'consistent', 'thesis'"),
    ({"angle_step": "0 deg"}, "CamFollower.angle_step"),
    ({"angles": "30"}, "angle needs its unit"),
])
def test_bad_scene_input(changes, pattern):
    with pytest.raises(InputError, match=pattern):
        _scene(**changes)


def test_follower_and_cam_validation():
    with pytest.raises(InputError, match="needs roller_radius"):
        cc.Follower(kind="roller", material=STEEL)
    with pytest.raises(InputError, match="offset"):
        cc.Follower.flat(material=STEEL, offset="2 mm")
    with pytest.raises(InputError, match="expected a MotionProgram"):
        cc.Cam(program="P-1", base_radius="40 mm", width="15 mm", material=STEEL)
    with pytest.raises(InputError, match="prime-circle"):
        follower_kinematics(PROGRAM, FollowerGeometry("roller", 0.004, 0.001, 0.006), [0.0], OMEGA)
