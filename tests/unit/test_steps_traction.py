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
    return ball_cone_traction(MODEL, A, B, N, CT, G, F_in, F_out, phi_in, phi_out, spin)


def test_creepage_transmits_the_tangential_force_without_spin():
    """Without the spin effect the contacts see no spin (phi given but not used); FASTSIM at the creepage
    found transmits F_t = 50 N (input) and 100 N (output) to 1e-9; both in partial slip."""
    out = traction(50.0, 100.0)
    assert set(out) == set(ball_cone_traction.step.provides)
    for side, force in (("in", 50.0), ("out", 100.0)):
        assert out[f"fastsim_{side}"].spin == 0.0
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
    assert out["fastsim_in"].spin == 100.0 and out["fastsim_out"].spin == 50.0
    check = fastsim(A, B, N, CT, G, creepage_x=out["creepage_in"], spin=100.0)
    assert check.Fx == pytest.approx(50.0, rel=1e-9)
    assert out["creepage_in"] != pytest.approx(traction(50.0, 100.0)["creepage_in"], rel=1e-3)


def test_gross_slip_saturates_at_ct_n():
    """F_t,out = 200 N > Ct N = 125.4 N: the output contact cannot transmit it: creepage -1e3 Ct N/(G a b),
    the whole area slips, |F_x| = Ct N (rel 1e-4), the regime names F_t/F_n = 0.1595 >= Ct = 0.1."""
    out = traction(50.0, 200.0)
    assert out["creepage_out"] == pytest.approx(-1e3 * CT * N / (G * A * B), rel=1e-12)
    assert out["slip_fraction_out"] == 1.0
    assert abs(out["fastsim_out"].Fx) == pytest.approx(CT * N, rel=1e-4)
    assert out["traction_regime_out"] == "gross slip: F_t/F_n = 0.1595 >= Ct = 0.1"
    assert out["traction_regime_in"] == "partial slip"
    assert np.all(np.isfinite(out["fastsim_out"].Tx))
    assert math.isfinite(out["creepage_in"])
