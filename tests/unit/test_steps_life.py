"""Life step functions (camcontact.steps.life) called alone.

Expected values: ISO 281:2007 written out here (P = F_r + 0.45 cot(alpha) F_a for F_a/F_r <= e = 1.5 tan(alpha),
else 0.67 F_r + 0.67 cot(alpha) F_a; L10 = (C/P)^(10/3) 10^6; nu1 = 45000 n^-0.83 d_m^-0.5 (n < 1000 r/min);
a_ISO = 0.1 [1 - (1.5859 - 1.2348/kappa^0.071739)(e_C C_u/P)^0.4]^-9.185 for 1 <= kappa <= 4; Table 12 a1);
the SKF catalogue's "Vibrating screen" example (C/P = 7.3 at 756 r/min, nu1 = 12.4 mm^2/s); Lundberg–Palmgren
after Coy et al. (Saccheto 2008 Eqs. 5.16-5.25: L = 10^6 (K Z0^h/(tau0^c 2 pi R a Z0))^(1/e), time = L/(c_r n),
system (sum L_i^-e)^(-1/e)).
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.models.life_lundberg_palmgren import LundbergPalmgren
from camcontact.steps.life import (
    ball_cone_life,
    bearing_equivalent_load,
    modified_rating_life,
    rating_life,
)
from step_checks import assert_provides


# ----------------------------------------------------------------------------- ISO 281
def test_bearing_equivalent_load_both_branches():
    """alpha = 9 deg, e = 1.5 tan(alpha) = 0.2376: F_a/F_r = 10/150 <= e -> P = F_r + 0.45 cot(alpha) F_a;
    F_a/F_r = 60/150 > e -> P = 0.67 F_r + 0.67 cot(alpha) F_a; pure axial load: 0.67 cot(alpha) F_a."""
    alpha = math.radians(9)
    cot = 1 / math.tan(alpha)
    out = bearing_equivalent_load(150e3, 10e3, alpha)
    assert_provides(bearing_equivalent_load, out)
    assert out["P"] == pytest.approx(150e3 + 0.45 * cot * 10e3, rel=1e-12)
    assert bearing_equivalent_load(150e3, 60e3, alpha)["P"] == pytest.approx(0.67 * 150e3 + 0.67 * cot * 60e3)
    assert bearing_equivalent_load(0.0, 10e3, alpha)["P"] == pytest.approx(0.67 * cot * 10e3)
    with pytest.raises(InputError, match="contact_angle"):
        bearing_equivalent_load(150e3, 10e3, 0.0)


def test_rating_life_skf_vibrating_screen():
    """SKF "Vibrating screen": C/P = 7.3, 756 r/min: L10 = 7.3^(10/3) 10^6 rev, L10h = L10/(756/60) s
    (= 1e6/(60 x 756) x 7.3^(10/3) h); the speed is the rings' relative speed |n_i - n_o|."""
    out = rating_life(7.3 * 186e3, 186e3, 756 / 60, 0.0, "roller")
    assert_provides(rating_life, out)
    assert out["L10"] == pytest.approx(7.3 ** (10 / 3) * 1e6, rel=1e-12)
    assert out["L10h"] / 3600 == pytest.approx(1e6 / (60 * 756) * 7.3 ** (10 / 3), rel=1e-12)
    assert rating_life(7.3 * 186e3, 186e3, 2.0, 2.0 + 756 / 60, "roller")["L10h"] == pytest.approx(out["L10h"], rel=1e-12)


def test_rating_life_without_load_or_motion_is_infinite():
    """P = 0: infinite L10 and L10h; rings at the same speed: finite L10 but no revolutions, infinite L10h."""
    assert rating_life(1e6, 0.0, 5.0, 0.0, "roller") == {"L10": math.inf, "L10h": math.inf}
    still = rating_life(1e6, 1e5, 5.0, 5.0, "roller")
    assert still["L10"] == pytest.approx(1e6 * 10 ** (10 / 3)) and still["L10h"] == math.inf


def test_modified_rating_life_iso_281():
    """Vibrating screen with nu = 40 mm^2/s, C_u = 132 kN, e_C = 0.5: nu1 = 45000 x 756^-0.83 x 220^-0.5 =
    12.38 mm^2/s (ISO 281, the literature test's 12.4), kappa = 40/nu1, a_ISO (1 <= kappa <= 4 band), a1 = 1
    at 90 %, 0.25 at 99 % (Table 12); L_nm = a1 a_ISO L10, L_nmh = L_nm/n."""
    C, P, n = 7.3 * 186e3, 186e3, 756 / 60
    state = SimpleNamespace(kinematic_viscosity=40e-6)
    out = modified_rating_life("iso281", C, P, n, 0.0, None, state, 132e3, 90.0, 0.5, 0.220, "roller")
    assert_provides(modified_rating_life, out)
    nu1 = 45000 * 756**-0.83 * 220**-0.5
    assert out["nu1"] * 1e6 == pytest.approx(nu1, rel=1e-12) and out["nu1"] * 1e6 == pytest.approx(12.38, abs=0.005)
    kappa = 40 / nu1
    assert out["kappa"] == pytest.approx(kappa, rel=1e-12)
    a_iso = 0.1 * (1 - (1.5859 - 1.2348 / kappa**0.071739) * (0.5 * 132e3 / P) ** 0.4) ** -9.185
    assert out["a_ISO"] == pytest.approx(a_iso, rel=1e-12)
    L10 = 7.3 ** (10 / 3) * 1e6
    assert out["a1"] == 1.0 and out["L_nm"] == pytest.approx(a_iso * L10, rel=1e-12)
    assert out["L_nmh"] == pytest.approx(a_iso * L10 / n, rel=1e-12)
    strict = modified_rating_life("iso281", C, P, n, 0.0, None, state, 132e3, 99.0, 0.5, 0.220, "roller")
    assert strict["a1"] == 0.25 and strict["L_nm"] == pytest.approx(0.25 * a_iso * L10, rel=1e-12)
    model = cc.registry.get("life_models", "iso281", reliability=99.0, contamination=0.5)
    assert modified_rating_life(model, C, P, n, 0.0, None, state, 132e3, 90.0, 1.0, 0.220, "roller")["a1"] == 0.25  # the instance rules


def test_modified_rating_life_needs_the_kinematic_viscosity():
    """A lubricant state without kinematic viscosity (no density): InputError naming the lubricant."""
    lubricant = cc.Lubricant(name="no density", eta0="0.05 Pa*s", alpha="2e-8 1/Pa")
    state = lubricant.state(None)
    assert state.kinematic_viscosity is None
    with pytest.raises(InputError, match="'no density': its kinematic viscosity"):
        modified_rating_life("iso281", 1e6, 1e5, 5.0, 0.0, lubricant, state, 2e5, 90.0, 0.5, 0.25, "roller")


# ----------------------------------------------------------------------------- Lundberg–Palmgren
def lp_cycles(tau0, z0, a, R, K=1.428e95, c=31 / 3, h=7 / 3, e=10 / 9):
    return 1e6 * (K * z0**h / (tau0**c * 2 * math.pi * R * a * z0)) ** (1 / e)


def test_ball_cone_life_tracks_and_system():
    """Per track: cycles by Lundberg–Palmgren (Saccheto Eqs. 5.16, 5.24, 5.25), time = cycles/(c_r n) with
    c_r = n_balls on the cones, 1 on a ball track; system life of 2 cones + 9 balls x 2 tracks (Eq. 5.20)."""
    a, R_cont, balls = 0.5e-3, 0.024, 9
    tau_in, z_in, tau_out, z_out = 5.0e8, 0.15e-3, 4.5e8, 0.16e-3
    bc, de = 6.874e-3, 4.583e-3
    w_in = 2 * math.pi
    w_out, w_ball = w_in * de / bc, w_in * R_cont / bc
    out = ball_cone_life(LundbergPalmgren(), a, tau_in, z_in, tau_out, z_out, bc, de, w_in, w_out, w_ball, R_cont, balls)
    assert_provides(ball_cone_life, out)
    expected = {
        "cone_in": (lp_cycles(tau_in, z_in, a, R_cont), balls, w_in),
        "ball_in": (lp_cycles(tau_in, z_in, a, bc), 1, w_ball),
        "ball_out": (lp_cycles(tau_out, z_out, a, de), 1, w_ball),
        "cone_out": (lp_cycles(tau_out, z_out, a, R_cont), balls, w_out),
    }
    for track, (cycles, per_rev, omega) in expected.items():
        assert out[f"cycles_{track}"] == pytest.approx(cycles, rel=1e-10), track
        assert out[f"life_{track}"] == pytest.approx(cycles / (per_rev * omega / (2 * math.pi)), rel=1e-10), track
    lives = np.array([out["life_cone_in"], out["life_cone_out"]] + [out["life_ball_in"], out["life_ball_out"]] * balls)
    e = 10 / 9
    assert out["life_system"] == pytest.approx(np.sum(lives**-e) ** (-1 / e), rel=1e-10)
    assert out["life_system"] < min(lives)


def test_ball_cone_life_refuses_a_contact_without_stress():
    """tau0 = 0 (no stress found): the life is undefined -> InputError naming tau0."""
    with pytest.raises(InputError, match="tau0"):
        ball_cone_life(LundbergPalmgren(), 0.5e-3, 0.0, 0.15e-3, 4.5e8, 0.16e-3, 6.9e-3, 4.6e-3, 6.28, 4.2, 21.9,
                       0.024, 9)
