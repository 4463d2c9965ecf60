"""Friction and wear step functions (camcontact.steps.friction) called alone.

Expected values: Coulomb F = mu N, Archard dV/dt = K N |u_s|/H, Ferrarese & Uehara's component equations
(A_L = k_L pi (3 N R/(4 E))^(2/3), h = 2.8 R^0.77 eta^0.65 V^0.65 E^-0.44 N^-0.21, F = A_L eta V/h, V = omega R,
E = E'/2), the Benedict–Kelley correlation mu = 0.0127 log10[29.66e-3 F/(eta0 l |u1 - u2| (u1 + u2)^2)]
(Delabenetta 2021 Eq. 49; Table 8 / §4.2: mu = 0.03748) and Blok's flash temperature
T_F = 0.893 w^0.75 (E'/(4R))^0.25 mu |u1 - u2|/(e1 sqrt(u1) + e2 sqrt(u2)) (Eq. 48), all written out here.
"""

import math

import numpy as np
import pytest

import camcontact as cc

from camcontact.errors import InputError
from camcontact.models.base import FrictionModel
from camcontact.steps.friction import (
    SlotModel,
    cam_friction,
    cam_wear,
    raceway_kelley_friction,
    roller_friction,
)
from step_checks import assert_provides

THETA = np.radians([0.0, 90.0, 180.0, 270.0])
N = np.array([1000.0, 3000.0, 0.0, 500.0])
U_S = np.array([0.5, -1.0, 0.2, 0.0])
OMEGA = np.full(4, 100.0)
EFFUSIVITY = math.sqrt(7810 * 464 * 42.4)  # AISI 52100 of Delabenetta (2021) Table 1, Eq. 50


# ----------------------------------------------------------------------------- cam friction and wear
def test_cam_friction_coulomb():
    """Coulomb with the scene's mu = 0.08: F = mu N, P = F |u_s|, mu reported 0 where the contact is open."""
    slot = SlotModel("friction_models", "coulomb", "friction", 0.08, "coulomb_coefficient")
    out = cam_friction(slot, N, U_S, OMEGA, THETA)
    assert_provides(cam_friction, out)
    np.testing.assert_allclose(out["friction_force"], 0.08 * N)
    np.testing.assert_allclose(out["friction_power"], 0.08 * N * np.abs(U_S))
    np.testing.assert_allclose(out["friction_coefficient"], [0.08, 0.08, 0.0, 0.08])


def test_cam_friction_ferrarese_uehara_reads_further_inputs():
    """Ferrarese & Uehara (k_L = 2) needs R, E_reduced, eta0 (passed as further inputs): the component
    equations by hand; its own power F V (V = omega R) is kept, not F |u_s|."""
    from camcontact import registry

    model = registry.get("friction_models", "ferrarese_uehara", k_L=2.0)
    slot = SlotModel("friction_models", model, "friction")
    assert slot.requires == ("normal_force", "R", "E_reduced", "eta0", "angular_speed")
    R, E_red, eta = np.array([0.01, 0.008, 0.01, 0.012]), 2.3e11, 0.03
    out = cam_friction(slot, N, U_S, OMEGA, THETA, R=R, E_reduced=E_red, eta0=eta)
    E, V = E_red / 2, OMEGA * R
    loaded = N > 0
    area = 2.0 * math.pi * (3 * N[loaded] * R[loaded] / (4 * E)) ** (2 / 3)
    h = 2.8 * R[loaded] ** 0.77 * eta**0.65 * V[loaded] ** 0.65 * E**-0.44 * N[loaded] ** -0.21
    force = area * eta * V[loaded] / h
    np.testing.assert_allclose(out["friction_force"][loaded], force, rtol=1e-10)
    assert out["friction_force"][2] == 0.0 and out["friction_coefficient"][2] == 0.0
    np.testing.assert_allclose(out["friction_power"][loaded], force * V[loaded], rtol=1e-10)
    np.testing.assert_allclose(out["friction_coefficient"][loaded], force / N[loaded], rtol=1e-10)


class ConstantForce(FrictionModel):
    """A test model giving a friction force only (no coefficient, no power)."""

    name = "constant_force_test"
    requires = ("normal_force",)
    provides = ("friction_force",)

    def evaluate(self, normal_force):
        return {"friction_force": 0.05 * np.asarray(normal_force, dtype=float)}


def test_cam_friction_power_from_the_force_when_the_model_gives_none():
    """A model without friction_power: the step computes P = F |u_s| and mu = F/N."""
    out = cam_friction(SlotModel("friction_models", ConstantForce(), "friction"), N, U_S, OMEGA, THETA)
    np.testing.assert_allclose(out["friction_power"], 0.05 * N * np.abs(U_S))
    np.testing.assert_allclose(out["friction_coefficient"], [0.05, 0.05, 0.0, 0.05])


def test_cam_friction_check_refuses_a_model_without_its_parameter():
    """Coulomb without the scene's coefficient cannot be made: the step's check raises InputError naming the slot."""
    slot = SlotModel("friction_models", "coulomb", "friction", None, "coulomb_coefficient")
    assert slot.requires == ("normal_force", "u_s", "coulomb_coefficient")
    with pytest.raises(InputError, match="friction model 'coulomb' needs parameters"):
        cam_friction.step.check(slot)


def test_cam_wear_archard():
    """Archard with K = 1e-6 on H = 6 GPa: dV/dt = K N |u_s|/H per angle (hardness passed as a further input)."""
    slot = SlotModel("wear_models", "archard", "wear", 1e-6, "archard_coefficient")
    out = cam_wear(slot, N, U_S, OMEGA, THETA, hardness=6e9)
    assert_provides(cam_wear, out)
    np.testing.assert_allclose(out["wear_rate"], 1e-6 * N * np.abs(U_S) / 6e9)
    with pytest.raises(InputError, match="wear model 'archard' needs parameters"):
        cam_wear.step.check(SlotModel("wear_models", "archard", "wear", None, "archard_coefficient"))


# ----------------------------------------------------------------------------- Kelley
def _thesis_eta(theta):
    """Delabenetta's base oil (575/50 cSt, 920 kg/m^3) at theta [degC], Walther with K = degC + 273."""
    x1, x2 = math.log10(313.0), math.log10(373.0)
    y1, y2 = (math.log10(math.log10(v + 0.7)) for v in (575.0, 50.0))
    m = (y1 - y2) / (x2 - x1)
    nu = 10 ** (10 ** (y1 + m * x1 - m * math.log10(theta + 273.0))) - 0.7
    return nu * 1e-6 * 920.0


def kelley(F, length, eta, u1, u2):
    return 0.0127 * math.log10(29.66e-3 * F / (eta * length * abs(u1 - u2) * (u1 + u2) ** 2))


def test_raceway_kelley_friction_delabenetta_table_8():
    """F = 10 kN, l = 41.35 mm, eta0 at 84.9 degC, u1 = 4.681, u2 = 2.686 m/s: mu = 0.03748 (Delabenetta
    §4.2, +-5e-6) and the correlation by hand."""
    eta = _thesis_eta(84.9)
    u1, u2 = 0.149 * 2 * math.pi * 5, 0.0135 * 2 * math.pi * 1900 / 60
    out = raceway_kelley_friction(10e3, 0.04135, eta, u1, u2)
    assert_provides(raceway_kelley_friction, out)
    assert out["friction_coefficient"] == pytest.approx(kelley(10e3, 0.04135, eta, u1, u2), rel=1e-12)
    assert out["friction_coefficient"] == pytest.approx(0.03748, abs=5e-6)
    assert out["friction_validity"] == "ok"
    assert out["friction_valid"] is True  # slide-to-roll ratio |u1 - u2|/u_m = 0.54, inside [0.01, 2]


def test_raceway_kelley_friction_flags_small_slip_outside_its_validity():
    """0.2 % slip (|u1 - u2|/u_m = 0.002): below the correlation's range [0.01, 2], flagged False with the
    reason, mu still the correlation's value (it rises as the slip falls: 0.2 % gives more than 2 %);
    10 % slip lies inside."""
    eta = 0.05
    low = raceway_kelley_friction(10e3, 0.04, eta, 2.002, 1.998)
    assert low["friction_valid"] is False
    assert low["friction_validity"].startswith("outside the Kelley correlation: slide_roll_ratio = 0.002 below")
    assert low["friction_coefficient"] == pytest.approx(kelley(10e3, 0.04, eta, 2.002, 1.998), rel=1e-12)
    mid = raceway_kelley_friction(10e3, 0.04, eta, 2.1, 1.9)
    assert mid["friction_valid"] is True and mid["friction_validity"] == "ok"
    assert low["friction_coefficient"] > mid["friction_coefficient"]


def test_raceway_kelley_friction_pure_rolling_is_nan_with_reason():
    """u1 = u2: outside the correlation (no sliding): NaN and the reason."""
    out = raceway_kelley_friction(10e3, 0.04135, 0.07, 3.0, 3.0)
    assert math.isnan(out["friction_coefficient"]) and out["friction_valid"] is False
    assert out["friction_validity"].startswith("pure rolling")


def test_roller_friction_per_roller_and_race():
    """u1, u2 = u_m (1 +- s/2) with s = 0.1; per loaded roller Kelley's mu (same at both races: it does not
    depend on the radius), Blok's flash temperature with each race's radius, NaN for unloaded rollers;
    P = sum over races and rollers of mu Q |u1 - u2|."""
    Q = np.array([20e3, 0.0, 5e3])
    radii = {"inner": 0.0121, "outer": 0.0149}
    u_m, s, eta, E, length = 3.0, 0.1, 0.06, 2.3e11, 0.04
    lengths = np.where(Q > 0.0, length, np.nan)
    out = roller_friction(Q, u_m, s, eta, E, EFFUSIVITY, radii, lengths, lengths)
    assert_provides(roller_friction, out)
    u1, u2 = u_m * 1.05, u_m * 0.95
    power = 0.0
    for race, R in radii.items():
        for j in (0, 2):
            mu = kelley(Q[j], length, eta, u1, u2)
            assert out[f"friction_coefficient_{race}"][j] == pytest.approx(mu, rel=1e-12)
            flash = (0.893 * (Q[j] / length) ** 0.75 * (E / (4 * R)) ** 0.25 * mu * abs(u1 - u2)
                     / (EFFUSIVITY * (math.sqrt(u1) + math.sqrt(u2))))
            assert out[f"flash_temperature_{race}"][j] == pytest.approx(flash, rel=1e-12)
            power += mu * Q[j] * abs(u1 - u2)
        assert math.isnan(out[f"friction_coefficient_{race}"][1]) and math.isnan(out[f"flash_temperature_{race}"][1])
    assert out["friction_power"] == pytest.approx(power, rel=1e-12)
    # s = 10 %: inside the validity at the loaded rollers; the unloaded roller has no contact
    for race in radii:
        assert out[f"friction_valid_{race}"].dtype == bool
        np.testing.assert_array_equal(out[f"friction_valid_{race}"], [True, False, True])
    assert out["friction_validity"] == "ok"
    idle = roller_friction(np.zeros(3), u_m, s, eta, E, EFFUSIVITY, radii, np.full(3, np.nan), np.full(3, np.nan))
    assert idle["friction_power"] == 0.0 and np.all(np.isnan(idle["friction_coefficient_inner"]))
    assert not idle["friction_valid_outer"].any()
    # a contact over half the length (a conformal roller's inner contact) has Kelley's mu of its own length
    short = roller_friction(Q, u_m, s, eta, E, EFFUSIVITY, radii, 0.5 * lengths, lengths)
    assert short["friction_coefficient_inner"][0] == pytest.approx(kelley(Q[0], 0.5 * length, eta, u1, u2), rel=1e-12)
    assert short["friction_coefficient_outer"][0] == pytest.approx(out["friction_coefficient_outer"][0], rel=1e-12)


def test_roller_friction_flags_contacts_below_the_correlations_slip_range():
    """0.2 % slip: every loaded contact is flagged outside the Kelley correlation (False) with the reason,
    while 2 % (the tutorial's assumed slip) lies inside [0.01, 2]."""
    Q = np.array([20e3, 0.0, 5e3])
    radii = {"inner": 0.0121, "outer": 0.0149}
    lengths = np.where(Q > 0.0, 0.04, np.nan)
    low = roller_friction(Q, 2.0, 0.002, 0.06, 2.3e11, EFFUSIVITY, radii, lengths, lengths)
    assert not low["friction_valid_inner"].any() and not low["friction_valid_outer"].any()
    assert "slide_roll_ratio = 0.002 below the validated range" in low["friction_validity"]
    assert np.all(np.isfinite(low["friction_coefficient_outer"][[0, 2]]))
    usual = roller_friction(Q, 2.0, 0.02, 0.06, 2.3e11, EFFUSIVITY, radii, lengths, lengths)
    np.testing.assert_array_equal(usual["friction_valid_inner"], [True, False, True])
    assert usual["friction_validity"] == "ok"
    assert np.all(low["friction_coefficient_outer"][[0, 2]] > usual["friction_coefficient_outer"][[0, 2]])


def test_roller_fluid_friction_per_contact_against_the_traction_model():
    """Each loaded contact's coefficient is the traction model's at u1 - u2 = S u_m (a direct call), the flash
    temperature Blok's with that mu, the power sum(mu Q |u1 - u2|); unloaded rollers NaN and not valid."""
    from camcontact import registry
    from camcontact.contact.contact_temperature import flash_temperature as blok
    from camcontact.steps.friction import roller_fluid_friction

    model = registry.get("traction_models", "eyring")
    state = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68).state(None)
    Q = np.array([0.0, 20e3, 10e3])
    p_h, b, h = np.array([np.nan, 1.2e9, 0.9e9]), np.array([np.nan, 2e-4, 1.5e-4]), np.array([np.nan, 4e-7, 4.5e-7])
    radii = {"inner": 0.03, "outer": 0.1}
    lengths = np.where(Q > 0.0, 0.04, np.nan)
    out = roller_fluid_friction(model, Q, 4.0, 0.02, p_h, p_h * 0.8, b, b * 1.2, h, h, state, 2.3e11, 1.2e4, radii,
                                lengths, lengths)
    assert_provides(roller_fluid_friction, out)
    mu = np.abs(model.contact(p_h[1:], b[1:], h[1:], 4.0, state).coefficient(0.02 * 4.0))
    np.testing.assert_allclose(out["friction_coefficient_inner"][1:], mu, rtol=1e-12)
    assert np.isnan(out["friction_coefficient_inner"][0]) and not out["friction_valid_inner"][0]
    assert out["friction_valid_inner"][1:].all() and out["friction_validity"] == "ok"
    u1, u2 = 4.0 * 1.01, 4.0 * 0.99
    assert out["flash_temperature_inner"][1] == pytest.approx(blok(Q[1] / 0.04, 2.3e11, 0.03, mu[0], u1, u2, 1.2e4,
                                                                   1.2e4), rel=1e-12)
    total = sum(np.nansum(out[f"friction_coefficient_{race}"] * Q) for race in ("inner", "outer")) * (u1 - u2)
    assert out["friction_power"] == pytest.approx(total, rel=1e-12)
