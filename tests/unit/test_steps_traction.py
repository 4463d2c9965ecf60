"""FASTSIM traction of the CVT contacts (camcontact.steps.traction.ball_cone_traction) called alone.

The step's own contribution is bookkeeping around Kalker's FASTSIM: find the creepage that transmits each
contact's tangential force (or saturate the traction when the contact cannot), per side, with or without
spin. Checked against the lower-level :func:`camcontact.contact.fastsim.fastsim` evaluated at the creepage
returned (it must transmit F_t), against the linear (no-slip) limit of Kalker's theory (force proportional
to creepage) and against Coulomb saturation in gross slip (|F_x| = Ct N, creepage -1e3 Ct N/(G a b)).
"""

import math

import numpy as np
import pytest

from camcontact import registry
from camcontact.contact.fastsim import fastsim
from camcontact.steps.traction import ball_cone_traction

A, B, N, CT = 0.2e-3, 0.5e-3, 1254.0, 0.1  # semi-axes along rolling / transverse [m], normal force [N]
G = 207e9 / (2 * 1.3)  # shear modulus of the thesis's steel
MODEL = registry.get("traction_models", "fastsim")


def traction(F_in, F_out, spin=False, phi_in=100.0, phi_out=50.0):
    return ball_cone_traction(MODEL, A, B, N, CT, G, F_in, F_out, phi_in, phi_out, spin, 1.0, 2.0)


def test_creepage_transmits_the_tangential_force_without_spin():
    """Without the spin effect the contacts see no spin (phi given but not used); FASTSIM at the creepage
    found transmits F_t = 50 N (input) and 100 N (output) to 1e-9; both in partial slip."""
    out = traction(50.0, 100.0)
    assert set(out) == set(ball_cone_traction.step.provides)
    for side, force in (("in", 50.0), ("out", 100.0)):
        assert out[f"surface_traction_{side}"].spin == 0.0
        check = fastsim(A, B, N, CT, G, creepage_x=out[f"creepage_{side}"], spin=0.0)
        assert check.Fx == pytest.approx(force, rel=1e-9)
        assert out[f"traction_regime_{side}"] == "partial slip"
        assert 0.0 < out[f"slip_fraction_{side}"] < 1.0
        assert out[f"slip_fraction_{side}"] == check.slip_fraction
    assert out["slip_fraction_out"] > out["slip_fraction_in"]  # more force, more slip


def test_small_forces_are_in_the_linear_regime():
    """No spin, F_t -> 0: Kalker's linear theory F_x = -C11 G a b nu_x, so doubling F_t doubles the creepage
    (rel 1e-6) and its sign is opposite to the force; F_t = 0 needs no creepage."""
    out = traction(1e-3, 2e-3)
    assert out["creepage_in"] < 0.0
    assert out["creepage_out"] == pytest.approx(2 * out["creepage_in"], rel=1e-6)
    assert traction(0.0, 0.0)["creepage_in"] == 0.0


def test_spin_enters_with_the_spin_effect():
    """With the effect, each side's spin creepage is used and the creepage found still transmits F_t."""
    out = traction(50.0, 100.0, spin=True)
    assert out["surface_traction_in"].spin == 100.0 and out["surface_traction_out"].spin == 50.0
    check = fastsim(A, B, N, CT, G, creepage_x=out["creepage_in"], spin=100.0)
    assert check.Fx == pytest.approx(50.0, rel=1e-9)
    assert out["creepage_in"] != pytest.approx(traction(50.0, 100.0)["creepage_in"], rel=1e-3)


def test_gross_slip_saturates_at_ct_n():
    """F_t,out = 200 N > Ct N = 125.4 N: the output contact cannot transmit it: creepage -1e3 Ct N/(G a b),
    the whole area slips, |F_x| = Ct N (rel 1e-4), regime "gross slip" and the boolean, capacity Ct N and the
    margin 1 - 200/125.4 < 0; the losses are the creep force's work on the creepage (no spin here)."""
    out = traction(50.0, 200.0)
    assert out["creepage_out"] == pytest.approx(-1e3 * CT * N / (G * A * B), rel=1e-12)
    assert out["slip_fraction_out"] == 1.0
    assert abs(out["surface_traction_out"].Fx) == pytest.approx(CT * N, rel=1e-4)
    assert out["traction_regime_out"] == "gross slip" and out["gross_slip_out"] and not out["gross_slip_in"]
    assert out["traction_regime_in"] == "partial slip"
    assert out["traction_capacity_out"] == pytest.approx(CT * N) and out["traction_margin_out"] == pytest.approx(
        1 - 200 / (CT * N))
    field = out["surface_traction_out"]
    assert out["power_loss_out"] == pytest.approx(-2.0 * out["creepage_out"] * field.Fx, rel=1e-12)
    assert out["spin_loss_out"] == 0.0 and out["power_loss_out"] > 0
    assert np.all(np.isfinite(out["surface_traction_out"].Tx))
    assert math.isfinite(out["creepage_in"])


# ------------------------------------------------------------------ EHL traction with spin, losses
class _State:
    """A lubricant state: eta0 [Pa s] and a Barus law ln(eta/eta0) = 2e-8 p."""

    eta0 = 0.02
    name = "test fluid"

    @staticmethod
    def log_viscosity_ratio(p):
        return 2e-8 * np.asarray(p)


def test_ehl_traction_step_transmits_the_forces_with_spin():
    """The EHL step solves each contact's creepage on its own film and spin: the contact model at the creepage
    found transmits F_t (1e-9); the outputs per side, the centre-line traction for the stresses, the losses'
    split; without the spin effect the spin loss is zero."""
    from camcontact.models.traction_fluid import EyringTraction
    from camcontact.models.traction_spin import EhlTraction
    from camcontact.steps.traction import ball_cone_ehl_traction

    model, fluid = EhlTraction(), EyringTraction()
    p_h = 1.5 * N / (math.pi * A * B)
    args = dict(traction_model=model, fluid_model=fluid, a_rolling=A, a_transverse=B, p_h=p_h, h_c_in=5e-8,
                h_c_out=6e-8, tangential_force_in=20.0, tangential_force_out=40.0, spin_in=100.0, spin_out=50.0,
                rolling_speed_in=1.0, rolling_speed_out=2.0, lubricant_state=_State())
    out = ball_cone_ehl_traction(spin=True, **args)
    assert set(out) == set(ball_cone_ehl_traction.step.provides)
    for side, force, h, phi, speed in (("in", 20.0, 5e-8, 100.0, 1.0), ("out", 40.0, 6e-8, 50.0, 2.0)):
        contact = model.contact(A, B, p_h, h, speed, _State(), fluid=fluid)
        state = contact.evaluate(out[f"creepage_{side}"], 0.0, phi)
        assert state.Fx == pytest.approx(force, rel=1e-9)
        assert out[f"power_loss_{side}"] == pytest.approx(out[f"creep_loss_{side}"] + out[f"spin_loss_{side}"])
        assert out[f"spin_loss_{side}"] > 0 and not out[f"gross_slip_{side}"]
        assert out[f"surface_traction_{side}"].Tx.shape == (1, 41)
    still = ball_cone_ehl_traction(spin=False, **args)
    assert still["spin_loss_in"] == 0.0 and abs(still["creepage_in"]) < abs(out["creepage_in"])


def test_efficiency_step():
    """n (P_in + P_out) lost of the power: 9 x (1 + 2) W of 150 W -> 0.82; NaN in gross slip."""
    from camcontact.steps.traction import ball_cone_efficiency

    out = ball_cone_efficiency(150.0, 9, 1.0, 2.0, False, False)
    assert out == {"power_loss": 27.0, "efficiency": pytest.approx(1 - 27 / 150)}
    # a contact in gross slip: the drive transmits no power, no efficiency (the gross_slip columns say why)
    slipping = ball_cone_efficiency(150.0, 9, 1.0, 2.0, False, True)
    assert math.isnan(slipping["efficiency"]) and math.isnan(slipping["power_loss"])


def test_ehl_traction_step_on_a_pressure_field_and_its_fallback():
    """A pressure field of the same Hertz pressure and film gives the Hertz result (capacity 0.5 %; the creepage 2 %:
    near the plateau the force is flat in the creepage, so the grid's 0.2 % in force moves it more); a numerical
    film whose
    side has no field (its solution did not converge) falls back to the Hertz pressure with traction_valid False."""
    from camcontact.contact.spin_traction import PressureField
    from camcontact.models.traction_fluid import EyringTraction
    from camcontact.models.traction_spin import EhlTraction
    from camcontact.steps.traction import ball_cone_ehl_traction

    p_h = 1.5 * N / (math.pi * A * B)
    x, y = np.linspace(-1.1 * A, 1.1 * A, 201), np.linspace(-1.1 * B, 1.1 * B, 201)
    X, Y = np.meshgrid(x, y)
    p = p_h * np.sqrt(np.clip(1 - (X / A) ** 2 - (Y / B) ** 2, 0.0, None))
    field = PressureField(x, y, p, np.full(p.shape, 5e-8))
    args = dict(traction_model=EhlTraction(), fluid_model=EyringTraction(), a_rolling=A, a_transverse=B, p_h=p_h,
                h_c_in=5e-8, h_c_out=5e-8, tangential_force_in=20.0, tangential_force_out=40.0, spin_in=100.0,
                spin_out=50.0, spin=True, rolling_speed_in=1.0, rolling_speed_out=2.0, lubricant_state=_State())
    hertz = ball_cone_ehl_traction(**args)
    numerical = ball_cone_ehl_traction(**args, pressure_field_in=field, pressure_field_out=None, numerical_pressure=True)
    assert numerical["creepage_in"] == pytest.approx(hertz["creepage_in"], rel=2e-2)
    assert numerical["traction_capacity_in"] == pytest.approx(hertz["traction_capacity_in"], rel=5e-3)
    assert numerical["traction_valid_in"] and not numerical["traction_valid_out"]
    assert numerical["creepage_out"] == hertz["creepage_out"]  # the Hertz fallback, flagged
    # a film that closed (a numerical film that did not converge, h_c <= 0): a clear error naming it
    from camcontact.errors import InputError

    with pytest.raises(InputError, match="output contact's central film h_c = -1e-08 m"):
        ball_cone_ehl_traction(**(args | {"h_c_out": -1e-8}))
