"""Lundberg–Palmgren life of traction contacts (Coy, Loewenthal & Zaretsky 1976) as used by
Saccheto (2008) §5.3–5.4, Eqs. 5.13–5.25.

Sources of the numbers:
* constants c = 31/3, h = 7/3, e = 10/9 (elliptical), 3/2 (line), K = 1.428e95: Saccheto Eqs.
  5.14, 5.15, 5.17 (reference report §3.4);
* H ~ P^-3 (Eqs. 5.21, 5.33) and H ~ size^8.4 (Eq. 5.22, "a 10 % size increase more than doubles
  the life"): checked through an independent chain — the exact Hertz elliptical or line contact
  of camcontact.contact and the numerical slice field of its central strip (camcontact.contact.
  slice_stress) — against the exponents that the Hertz scaling laws give in exact rational
  arithmetic (derived in each test);
* steel E = 207 GPa, nu = 0.3 (implied by Saccheto's Eq. 5.33 constant, reference report §4.6);
  track radius R1 = 23.28 mm (reference report §4.2 reconstruction of Tabela A.1); traction
  coefficient mu_min = 0.08813 (Saccheto Eq. 6.19); 9 stress cycles per cone revolution and a
  60 rpm cadence (reference report §6 checklist and Saccheto §7.2).
"""

import math
from fractions import Fraction

import numpy as np
import pytest

from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.contact.hertz_line import hertz_line
from camcontact.contact.slice_stress import semi_elliptical_load, slice_extrema
from camcontact.errors import InputError
from camcontact.models.base import LifeModel
from camcontact.models.life_lundberg_palmgren import (
    ELLIPTICAL_E,
    LINE_E,
    LundbergPalmgren,
    life_time,
    lundberg_palmgren_life,
    stressed_volume,
    system_life,
)

E_STEEL = 207e9  # [Pa], reference report §4.6
NU_STEEL = 0.3
E_REDUCED = E_STEEL / (1 - NU_STEEL**2)  # E' = 2 / (2 (1 - nu^2) / E) for two equal bodies
TRACK_RADIUS = 23.28e-3  # [m]
MU_MIN = 0.08813  # Saccheto Eq. 6.19

C = Fraction(31, 3)
H = Fraction(7, 3)
E_ELL = Fraction(10, 9)
E_LINE = Fraction(3, 2)


def _ball_contact_life(F, scale=1.0, measure="max_shear", model=None):
    """L10 [cycles] of an elliptical steel contact (Rx = 5 mm, Ry = 20 mm, both x scale) under
    load F [N], from Hertz + the slice field of its central strip with traction mu_min p."""
    hz = hertz_elliptical(F, 5e-3 * scale, 20e-3 * scale, E_REDUCED)
    s, p, q = semi_elliptical_load(hz.a_x, hz.p_max, traction_coefficient=MU_MIN, nodes=201)
    extremum = slice_extrema(s, p, q, measures=(measure,))[measure]
    model = model or LundbergPalmgren()
    return model.life(extremum.tau0, extremum.z0, hz.a_y, TRACK_RADIUS * scale)


def _slope(xs, ys):
    return np.polyfit(np.log(xs), np.log(ys), 1)[0]


def test_constants_are_the_printed_ones():
    model = LundbergPalmgren()
    assert (model.K, model.c, model.h, model.e) == (1.428e95, 31 / 3, 7 / 3, 10 / 9)
    assert LundbergPalmgren.line_contact().e == 1.5 == LINE_E
    assert ELLIPTICAL_E == 10 / 9
    assert issubclass(LundbergPalmgren, LifeModel) and LundbergPalmgren.name == "lundberg_palmgren"
    assert LundbergPalmgren.family == "life_models"
    assert "L10" in LundbergPalmgren.provides


def test_life_is_eq_5_16_with_the_volume_of_eq_5_24():
    """Direct power form of Eq. 5.16 (x 1e6 cycles), independent of the model's logarithmic form."""
    tau0, z0, a, R = 5.0e8, 1.0e-4, 5.0e-4, 0.02
    volume = 2 * math.pi * R * a * z0
    assert stressed_volume(z0, a, R) == pytest.approx(volume, rel=1e-15)
    h10 = (1.428e95 * z0 ** (7 / 3) / (tau0 ** (31 / 3) * volume)) ** (9 / 10)
    assert lundberg_palmgren_life(tau0, z0, a, R) == pytest.approx(1e6 * h10, rel=1e-12)
    result = LundbergPalmgren()({"tau0": tau0, "z0": z0, "a_transverse": a, "track_radius": R})
    assert result["L10"] == pytest.approx(1e6 * h10, rel=1e-12)
    assert result["stressed_volume"] == pytest.approx(volume, rel=1e-15)
    assert "L10h" not in result
    # stress exponent: doubling tau0 divides the life by 2^(c/e) = 2^9.3
    assert lundberg_palmgren_life(2 * tau0, z0, a, R) / lundberg_palmgren_life(tau0, z0, a, R) == pytest.approx(
        2 ** -(31 / 3 * 9 / 10), rel=1e-12)


def test_vectorised_inputs():
    tau0 = np.array([4e8, 5e8, 6e8])
    lives = lundberg_palmgren_life(tau0, 1e-4, 5e-4, 0.02)
    assert lives.shape == (3,)
    assert lives[1] == pytest.approx(lundberg_palmgren_life(5e8, 1e-4, 5e-4, 0.02), rel=1e-14)


@pytest.mark.parametrize("measure", ["max_shear", "orthogonal"])
def test_life_falls_as_load_cubed_elliptical(measure):
    """Eq. 5.21/5.33, H ~ P^-3.

    Independent calculation: Hertz gives a, b ~ P^(1/3) and p0 ~ P^(1/3) at fixed curvature; the
    slice field of a semi-elliptic strip scales with it (tau0 = k1 p0, Z0 = k2 b with k1, k2
    fixed by the profile shape and mu), so H ~ (P^(h/3) / (P^(c/3) P^(1/3) P^(1/3)))^(1/e) =
    P^((h - c - 2) / (3 e)) = P^-3 exactly. The test computes lives at four loads through the
    exact Hertz solution and the numerical slice field and fits the exponent.
    """
    assert (H - C - 2) / (3 * E_ELL) == -3
    loads = np.array([100.0, 200.0, 400.0, 800.0])
    lives = [_ball_contact_life(F, measure=measure) for F in loads]
    assert _slope(loads, lives) == pytest.approx(-3.0, abs=1e-6)


def test_line_contact_exponents():
    """Line contact (e = 3/2 as printed, Eq. 5.15): b, p0 ~ P'^(1/2), the transverse semi-axis
    (half the roller length) is fixed, so H ~ P'^((h/2 - c/2 - 1/2)/e) = P'^-3 — the same law as
    the elliptical contact. With Lundberg–Palmgren's roller slope e = 9/8 the same exponents give
    P'^-4, the classical line-contact load-life exponent; the printed 3/2 is kept configurable."""
    assert (H / 2 - C / 2 - Fraction(1, 2)) / E_LINE == -3
    assert (H / 2 - C / 2 - Fraction(1, 2)) / Fraction(9, 8) == -4
    loads = np.array([1e5, 2e5, 4e5, 8e5])  # load per unit length [N/m]
    half_length = 5e-3
    lives = {LINE_E: [], 9 / 8: []}
    for w in loads:
        hz = hertz_line(w, 10e-3, E_REDUCED)
        s, p, q = semi_elliptical_load(hz.b, hz.p_h, traction_coefficient=MU_MIN, nodes=201)
        extremum = slice_extrema(s, p, q, measures=("orthogonal",))["orthogonal"]
        for e in lives:
            model = LundbergPalmgren(e=e)
            lives[e].append(model.life(extremum.tau0, extremum.z0, half_length, TRACK_RADIUS))
    assert _slope(loads, lives[LINE_E]) == pytest.approx(-3.0, abs=1e-6)
    assert _slope(loads, lives[9 / 8]) == pytest.approx(-4.0, abs=1e-6)


def test_size_laws():
    """All lengths (radii of curvature and track radius) times s; tau0, Z0, a from Hertz + slice.

    Independent calculation (Hertz: a, Z0 ~ (P s)^(1/3), p0 ~ tau0 ~ P^(1/3) s^(-2/3); V ~ s a Z0):
    H ~ [P^((h - c - 2)/3) s^((h + 2c - 5)/3)]^(1/e), so with e = 10/9
    * constant load:      s^((h + 2c - 5)/(3e)) = s^5.4;
    * constant pressure (P ~ s^2): s^((h - 3)/e) = s^-0.6 (the larger stressed volume);
    * constant torque (P ~ 1/s, same traction coefficient): s^(5.4 + 3) = s^8.4.
    Saccheto's Eq. 5.22, "H ~ size^8.4", is the constant-torque reading of Lundberg–Palmgren; at
    constant load LP gives 5.4. Both are kept visible here.
    """
    assert (H + 2 * C - 5) / (3 * E_ELL) == Fraction(27, 5)
    assert (H - 3) / E_ELL == Fraction(-3, 5)
    assert (H + 2 * C - 5) / (3 * E_ELL) + 3 == Fraction(42, 5)  # = 8.4, Eq. 5.22
    sizes = np.array([1.0, 1.1, 1.5, 2.0])
    F = 300.0
    constant_load = [_ball_contact_life(F, s) for s in sizes]
    constant_pressure = [_ball_contact_life(F * s**2, s) for s in sizes]
    constant_torque = [_ball_contact_life(F / s, s) for s in sizes]
    assert _slope(sizes, constant_load) == pytest.approx(5.4, abs=1e-6)
    assert _slope(sizes, constant_pressure) == pytest.approx(-0.6, abs=1e-6)
    assert _slope(sizes, constant_torque) == pytest.approx(8.4, abs=1e-6)
    # "a 10 % size increase more than doubles the life" (Saccheto §5.3) holds at constant torque
    assert constant_torque[1] / constant_torque[0] == pytest.approx(1.1**8.4, rel=1e-6)
    assert constant_torque[1] / constant_torque[0] > 2.0
    assert constant_load[1] / constant_load[0] < 2.0  # 1.1^5.4 = 1.67


def test_units_of_k_si_reading_documented():
    """K's units are unstated (Eq. 5.17); the module docstring argues for SI with this case:
    steel ball contact, Rx = 5 mm, Ry = 20 mm, F = 200 N (p0 = 1.8 GPa), R = 23.28 mm, Mohr tau0
    of the slice with mu_min. SI gives L10 of about 3e9 cycles; reading K in psi and inch (the
    same tau0, Z0, a, R converted: 1 psi = 6894.757 Pa, 1 in = 0.0254 m) gives about 1e44. Which
    of the two is physically plausible is a judgement (stated in the docstring), not a source
    value; the test pins the two numbers the docstring quotes."""
    hz = hertz_elliptical(200.0, 5e-3, 20e-3, E_REDUCED)
    assert hz.p_max == pytest.approx(1.8e9, rel=0.01)
    s, p, q = semi_elliptical_load(hz.a_x, hz.p_max, traction_coefficient=MU_MIN, nodes=201)
    ext = slice_extrema(s, p, q, measures=("max_shear",))["max_shear"]
    si = LundbergPalmgren().life(ext.tau0, ext.z0, hz.a_y, TRACK_RADIUS)
    psi, inch = 6894.757, 0.0254
    english = LundbergPalmgren().life(ext.tau0 / psi, ext.z0 / inch, hz.a_y / inch, TRACK_RADIUS / inch)
    assert si == pytest.approx(3e9, rel=0.1)
    assert 1e43 < english < 1e45


@pytest.mark.parametrize("e", [ELLIPTICAL_E, LINE_E])
def test_system_life_of_equal_contacts(e):
    """Eq. 5.20 with n equal contacts: H_sys = H n^(-1/e); the corrected Eq. 5.19 sum (H/H_i)^e = 1."""
    for n in (1, 2, 5, 45):  # 45 = 5 contacts x 9 balls of the CVT (reference report §6)
        lives = np.full(n, 1.0e4)
        combined = system_life(lives, e)
        assert combined == pytest.approx(1.0e4 * n ** (-1 / e), rel=1e-12)
        assert np.sum((combined / lives) ** e) == pytest.approx(1.0, rel=1e-12)


def test_system_life_properties():
    lives = np.array([3.0e3, 1.0e4, 7.0e4, 2.0e5])
    combined = system_life(lives)
    assert combined < lives.min()
    assert system_life(lives[::-1]) == pytest.approx(combined, rel=1e-14)
    assert np.sum((combined / lives) ** ELLIPTICAL_E) == pytest.approx(1.0, rel=1e-12)
    # one dominant (short-lived) contact: others 1e6 x longer change H_sys by ~ 3 (1e-6)^(10/9) / e
    dominant = system_life([1.0, 1e6, 1e6, 1e6])
    assert dominant == pytest.approx(1.0, rel=1e-6)
    assert dominant < 1.0
    # huge lives do not overflow H^-e: the combination is scale invariant
    assert system_life(lives * 1e300 / 1e6) == pytest.approx(combined * 1e294, rel=1e-12)
    # a 2-D array combines along the axis given
    table = np.vstack([lives, 2 * lives])
    np.testing.assert_allclose(system_life(table, axis=1), [combined, 2 * combined], rtol=1e-12)
    assert LundbergPalmgren().system_life(lives) == pytest.approx(combined, rel=1e-14)


def test_cycles_to_time_eq_5_18():
    """Eq. 5.18: hours = eta/(c_r omega) 10^6/60 with eta in millions, omega in rpm. With 1000
    million cycles, c_r = 9 (balls per cone revolution) and 60 rpm: 1000/(9 60) 1e6/60 h."""
    hours = 1000.0 / (9 * 60.0) * 1e6 / 60.0
    seconds = life_time(1000.0e6, 9, 60.0 / 60.0)
    assert seconds / 3600.0 == pytest.approx(hours, rel=1e-14)
    model = LundbergPalmgren()
    state = {"tau0": 5e8, "z0": 1e-4, "a_transverse": 5e-4, "track_radius": 0.02, "stress_cycle_rate": 9 * 1.0}
    result = model(state)
    assert result["L10h"] == pytest.approx(life_time(result["L10"], 9, 1.0), rel=1e-14)


def test_parameters_are_validated():
    for field, value in (("K", 0.0), ("K", -1e95), ("c", 0.0), ("e", 0.0), ("e", -1.0), ("h", -0.1)):
        with pytest.raises(InputError, match=f"LundbergPalmgren.{field}"):
            LundbergPalmgren(**{field: value})
    with pytest.raises(InputError, match="LundbergPalmgren.K"):
        LundbergPalmgren(K=float("nan"))
    with pytest.raises(InputError, match="LundbergPalmgren.c"):
        LundbergPalmgren(c="eleven")
    assert LundbergPalmgren(h=0.0).h == 0.0


def test_inputs_are_validated():
    model = LundbergPalmgren()
    good = {"tau0": 5e8, "z0": 1e-4, "a_transverse": 5e-4, "track_radius": 0.02}
    for key, value in (("tau0", 0.0), ("z0", -1e-4), ("a_transverse", float("nan")), ("track_radius", float("inf"))):
        with pytest.raises(InputError, match=key):
            model({**good, key: value})
    with pytest.raises(InputError, match="track_radius"):
        model({k: v for k, v in good.items() if k != "track_radius"})
    with pytest.raises(InputError, match="stress_cycle_rate"):
        model({**good, "stress_cycle_rate": 0.0})
    with pytest.raises(InputError, match="e = 0"):
        system_life([1.0, 2.0], 0)
    with pytest.raises(InputError, match="lives"):
        system_life([1.0, -2.0])
    with pytest.raises(InputError, match="speed"):
        life_time(1e9, 9, 0.0)
    with pytest.raises(InputError, match="c = -1"):
        lundberg_palmgren_life(5e8, 1e-4, 5e-4, 0.02, c=-1.0)
