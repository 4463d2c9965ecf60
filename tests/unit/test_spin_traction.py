"""EHL traction with creep and spin over the Hertz ellipse (camcontact.contact.spin_traction, issue 17).

Independent checks: the Newtonian closed forms at low creep (F_x = -(V nu_x/h) int eta dA, M_z = -(V phi/h)
int eta (x^2 + y^2) dA; for a constant viscosity pi a b and pi a b (a^2 + b^2)/4 times eta0), the Barus
integral by scipy's dblquad, the full-slip (rigid-plastic) limit tau = Lambda_L p along the slip: the pivoting
moment of a circular Hertz contact (3 pi/16) Lambda_L P a (Lubkin's twisting contact; Johnson, Contact
Mechanics §7.4 with mu -> Lambda_L) and the longitudinal force with spin by dblquad.
"""

import math

import numpy as np
import pytest
from scipy import integrate

from camcontact.contact.fluid_traction import TractionThermal
from camcontact.contact.spin_traction import PressureField, SpinTractionContact
from camcontact.errors import InputError
from camcontact.models.traction_fluid import EyringTraction
from camcontact.models.traction_spin import EhlTraction

A, B, PH, H, V, ETA0 = 5.5e-4, 6.4e-4, 1.5e9, 5e-8, 2.0, 0.02


def isoviscous(p):
    return np.zeros_like(p)


def contact(**changes):
    fields = dict(a=A, b=B, p_h=PH, film_thickness=H, rolling_speed=V, eta0=ETA0, log_viscosity_ratio=isoviscous,
                  rheology="newtonian")
    fields.update(changes)
    return SpinTractionContact(**fields)


def test_newtonian_closed_forms_creep_and_spin():
    """Constant viscosity: F_x = -eta0 V nu_x pi a b/h, F_y likewise with nu_y, M_z = -eta0 V phi pi a b (a^2+b^2)/(4h);
    the film is linear, so creep and spin superpose (1e-9)."""
    c = contact()
    nu_x, nu_y, phi = 1e-4, -3e-5, 0.4
    state = c.evaluate(nu_x, nu_y, phi)
    area = math.pi * A * B
    assert state.Fx == pytest.approx(-ETA0 * V * nu_x * area / H, rel=1e-9)
    assert state.Fy == pytest.approx(-ETA0 * V * nu_y * area / H, rel=1e-9)
    assert state.Mz == pytest.approx(-ETA0 * V * phi * area * (A**2 + B**2) / (4 * H), rel=1e-9)
    assert c.normal_force == pytest.approx(2 / 3 * math.pi * A * B * PH, rel=1e-12)
    # losses: the dissipation splits exactly into creep and spin losses
    assert state.power_loss == pytest.approx(state.creep_loss + state.spin_loss, rel=1e-9)
    assert state.spin_loss == pytest.approx(-V * phi * state.Mz, rel=1e-12) and state.power_loss > 0


def test_barus_low_creep_against_dblquad():
    """Barus eta0 exp(alpha p), alpha = 1e-8/Pa at p_h = 1.5 GPa (eta up to e^15): F_x/nu_x and M_z/phi against
    the double integrals of eta and eta (x^2 + y^2) over the ellipse by dblquad (1e-6)."""
    alpha = 1e-8
    c = contact(log_viscosity_ratio=lambda p: alpha * p, n_radial=48, n_angular=64)

    def eta(y, x):
        return ETA0 * math.exp(alpha * PH * math.sqrt(max(0.0, 1 - (x / A) ** 2 - (y / B) ** 2)))

    def edge(x):
        return B * math.sqrt(max(0.0, 1 - (x / A) ** 2))

    opts = dict(epsabs=0, epsrel=1e-10)
    mass = integrate.dblquad(eta, -A, A, lambda x: -edge(x), edge, **opts)[0]
    inertia = integrate.dblquad(lambda y, x: eta(y, x) * (x * x + y * y), -A, A, lambda x: -edge(x), edge, **opts)[0]
    nu, phi = 1e-9, 1e-6  # stresses far below any limit: linear
    assert c.evaluate(nu).Fx == pytest.approx(-V * nu * mass / H, rel=1e-6)
    assert c.evaluate(0.0, 0.0, phi).Mz == pytest.approx(-V * phi * inertia / H, rel=1e-6)


def test_eyring_tends_to_newtonian_at_low_creep():
    """eta gamma << tau0: asinh(s) = s, so the Eyring film carries the Newtonian force (1e-6 at s ~ 1e-3)."""
    newton = contact().evaluate(1e-6, 0.0, 1e-3)
    eyring = contact(rheology="eyring", eyring_stress=5e6).evaluate(1e-6, 0.0, 1e-3)
    assert ETA0 * V * 1e-6 / H / 5e6 < 2e-3
    assert eyring.Fx == pytest.approx(newton.Fx, rel=1e-6) and eyring.Mz == pytest.approx(newton.Mz, rel=1e-6)


def plastic(**changes):
    """A film at its limiting shear stress Lambda_L p everywhere (huge viscosity): rigid-plastic, mu = Lambda_L."""
    return contact(eta0=1e6, limiting_shear_slope=0.08, **changes)


def test_full_slip_pivoting_moment_of_a_circular_contact():
    """Pure spin in full slip: M = (3 pi/16) Lambda_L P a (p = p0 sqrt(1 - r^2/a^2), P = 2 pi p0 a^2/3)."""
    c = plastic(b=A, n_radial=32)
    state = c.evaluate(0.0, 0.0, 50.0)
    assert state.limited_fraction == 1.0
    assert -state.Mz == pytest.approx(3 * math.pi / 16 * 0.08 * c.normal_force * A, rel=1e-9)
    assert state.Fx == pytest.approx(0.0, abs=1e-9 * c.normal_force)


def full_slip_force(nu, phi):
    """F_x/(Lambda_L N) of the rigid-plastic film with creep nu and spin phi: -int p (nu - phi y)/|w| dA / N."""
    def integrand(y, x):
        p = PH * math.sqrt(max(0.0, 1 - (x / A) ** 2 - (y / B) ** 2))
        wx, wy = nu - phi * y, phi * x
        return -p * wx / math.hypot(wx, wy)

    def edge(x):
        return B * math.sqrt(max(0.0, 1 - (x / A) ** 2))

    pole = nu / phi  # the integrand turns at (0, pole): split there for dblquad's accuracy
    total = 0.0
    for lower, upper in ((lambda x: -edge(x), lambda x: min(max(pole, -edge(x)), edge(x))),
                         (lambda x: min(max(pole, -edge(x)), edge(x)), edge)):
        total += integrate.dblquad(integrand, -A, A, lower, upper, epsabs=0, epsrel=1e-9)[0]
    return total / (2 / 3 * math.pi * A * B * PH)


@pytest.mark.parametrize("nu, phi", [(0.02, 100.0), (0.05, 100.0), (0.01, 30.0)])
def test_full_slip_force_with_spin_against_dblquad(nu, phi):
    """The longitudinal force of a rigid-plastic contact loses capacity to spin: against dblquad (pole inside the
    contact for nu/phi < b: first rows). The kink at the pole limits the 16 x 64 rule to ~0.7 %."""
    c = plastic()
    expected = full_slip_force(nu, phi)
    assert c.evaluate(nu, 0.0, phi).Fx / (0.08 * c.normal_force) == pytest.approx(expected, rel=1e-2)
    fine = plastic(n_radial=64, n_angular=256).evaluate(nu, 0.0, phi)
    assert fine.Fx / (0.08 * c.normal_force) == pytest.approx(expected, rel=1e-3)


def test_capacity_falls_with_spin():
    """The must-show's trend: the capacity at |nu_x| <= 5 % falls as the spin grows (plateau film; the values
    follow the rigid-plastic integral: 1.0, 0.99, 0.80, 0.31 of Lambda_L N for phi = 0, 30, 100, 300 /m at
    b = 0.64 mm, where nu/phi = 1.7 mm, 0.5 mm, 0.17 mm sets the slip pole; 1 % for the pole's kink)."""
    c = plastic()
    capacities = [-c.capacity(spin=phi).Fx / (0.08 * c.normal_force) for phi in (0.0, 30.0, 100.0, 300.0)]
    assert np.all(np.diff(capacities) < 0)
    assert capacities[0] == pytest.approx(1.0, rel=1e-9)
    for phi, value in zip((30.0, 100.0, 300.0), capacities[1:]):
        assert value == pytest.approx(-full_slip_force(0.05, phi), rel=1e-2)


def test_solve_creepage_transmits_the_force_and_flags_gross_slip():
    c = contact(rheology="eyring", eyring_stress=5e6, limiting_shear_slope=0.075, log_viscosity_ratio=lambda p: 2e-8 * p)
    state, peak = c.solve_creepage(50.0, spin=60.0)
    assert state.Fx == pytest.approx(50.0, rel=1e-9) and state.creepage_x < 0
    assert -peak.Fx > 50.0
    over, peak = c.solve_creepage(-2.0 * (-peak.Fx), spin=60.0)
    assert over.Fx == pytest.approx(peak.Fx, rel=1e-12) and over.creepage_x > 0  # saturated, force's sign


def test_thermal_capacity_peaks_below_the_bound():
    """With the lumped temperature (beta 0.03/K, k 0.1 W/(m K), steel effusivity, V = 10 m/s, p_h 0.8 GPa) the
    Eyring film's traction curve peaks near 25 % creep and falls beyond (the viscosity falls by exp(-beta dT)
    faster than asinh grows): the capacity lies inside the bound, the heated force is below the isothermal one."""
    thermal = TractionThermal(0.1, 0.03, 11_600.0, 11_600.0)
    args = dict(rheology="eyring", eyring_stress=5e6, limiting_shear_slope=0.075, log_viscosity_ratio=lambda p: 2e-8 * p,
                rolling_speed=10.0, p_h=0.8e9)
    hot = contact(thermal=thermal, **args)
    peak = hot.capacity(spin=20.0, max_creepage=0.5)
    assert peak.converged and 0.1 < peak.creepage_x < 0.4 and peak.temperature_rise > 10.0
    assert -hot.evaluate(0.5, 0.0, 20.0).Fx < -peak.Fx
    assert -hot.evaluate(0.5 * peak.creepage_x, 0.0, 20.0).Fx < -peak.Fx
    cold = contact(**args).evaluate(peak.creepage_x, 0.0, 20.0)
    assert -cold.Fx > -peak.Fx


@pytest.mark.parametrize("field, value, match", [
    ("a", 0.0, "a = 0.0"), ("p_h", -1.0, "p_h = -1.0"), ("film_thickness", float("nan"), "film_thickness"),
    ("rheology", "bingham", "rheology = 'bingham'"), ("n_radial", 2, "n_radial = 2"),
    ("log_viscosity_ratio", 3.0, "log_viscosity_ratio"),
])
def test_bad_input_is_named(field, value, match):
    with pytest.raises(InputError, match=match):
        contact(**{field: value})
    with pytest.raises(InputError, match="creepage_x"):
        contact().evaluate(float("inf"))
    for request in (0.0, -0.01):  # a creep bound must be > 0 (the curve is odd in the creepage)
        with pytest.raises(InputError, match=f"max_creepage = {request!r}; allowed: finite, > 0"):
            contact().capacity(max_creepage=request)


def test_model_checks_the_load_and_fields():
    class State:
        eta0 = ETA0

        @staticmethod
        def log_viscosity_ratio(p):
            return 2e-8 * p

    model = EhlTraction(fluid=EyringTraction(limiting_shear_slope=0.088))  # a traction fluid's (5P4E)
    N = 2 / 3 * math.pi * A * B * PH
    out = model.evaluate(N, A, B, PH, H, V, 60.0, 50.0, State())
    assert out["creepage"] < 0 and not out["gross_slip"] and 0 < out["traction_margin"] < 1
    assert out["power_loss"] == pytest.approx(out["creep_loss"] + out["spin_loss"], rel=1e-9)
    with pytest.raises(InputError, match="carries"):
        model.evaluate(2 * N, A, B, PH, H, V, 60.0, 50.0, State())
    assert model.evaluate(N, A, B, PH, H, V, 60.0, 500.0, State())["gross_slip"]
    for request in (0.0, -0.01):
        with pytest.raises(InputError, match=f"EhlTraction.max_creepage = {request!r} is out of range"):
            EhlTraction(max_creepage=request)
    with pytest.raises(InputError, match="fluid"):
        EhlTraction(fluid="eyring")


# ---------------------------------------------------------------------------- on a pressure field (numerical rung)
def hertz_field(nx=241, ny=241, film=None, extent=1.2):
    """The Hertz pressure and a film sampled on a uniform rectangular grid in the solver's frame (x along the
    entrainment, inlet at -x): the field path must reproduce the ellipse quadrature to the grid's accuracy."""
    x, y = np.linspace(-extent * A, extent * A, nx), np.linspace(-extent * B, extent * B, ny)
    X, Y = np.meshgrid(x, y)
    p = PH * np.sqrt(np.clip(1 - (X / A) ** 2 - (Y / B) ** 2, 0.0, None))
    h = np.full(p.shape, H) if film is None else film(X, Y)
    return PressureField(x, y, p, h)


def test_field_of_the_hertz_pressure_matches_the_ellipse_quadrature():
    """Barus film with creep and spin: the forces and moment over a 241^2 grid of the same pressure and film equal
    the 16 x 64 ellipse quadrature's within 0.5 % (load within 0.1 %)."""
    law = {"log_viscosity_ratio": lambda p: 1e-8 * p, "rheology": "eyring", "eyring_stress": 5e6,
           "limiting_shear_slope": 0.08}
    ellipse, field = contact(**law), contact(**law, field=hertz_field())
    assert field.normal_force == pytest.approx(ellipse.normal_force, rel=1e-3)
    for nu, phi in ((2e-3, 0.0), (1e-3, 3.0), (-5e-4, 10.0)):
        a, b = ellipse.evaluate(nu, 0.0, phi), field.evaluate(nu, 0.0, phi)
        assert b.Fx == pytest.approx(a.Fx, rel=5e-3)
        assert b.Mz == pytest.approx(a.Mz, rel=5e-3, abs=1e-6 * abs(a.Fx) * A)
        assert b.power_loss == pytest.approx(a.power_loss, rel=5e-3)


def test_field_reads_the_local_film_and_the_inlet_direction():
    """Newtonian, constant viscosity: F_x = -eta0 V nu_x int dA/h(x, y) (the local film, not the central one, an
    independent sum); the field's x is the solver's (inlet at -x), the traction's Kalker x = -x: a pressure
    confined to the solver's inlet half lies on Kalker's x > 0 half (its centre line there)."""
    film = lambda X, Y: H * (1.0 + 0.5 * X / A)  # noqa: E731  thinner towards the inlet
    field = hertz_field(film=film)
    c = contact(field=field)
    nu = 1e-4
    X, Y = np.meshgrid(field.x, field.y)
    cell = (field.x[1] - field.x[0]) * (field.y[1] - field.y[0])
    expected = -ETA0 * V * nu * np.sum((field.p > 0) / film(X, Y)) * cell
    assert c.evaluate(nu).Fx == pytest.approx(expected, rel=1e-12)
    inlet = PressureField(field.x, field.y, np.where(X < 0, field.p, 0.0), field.h)
    line = contact(field=inlet).centre_line(contact(field=inlet).evaluate(nu), n=40)
    assert np.all(line.p[0, line.x[0] < -0.05 * A] == 0.0) and np.all(line.p[0, line.x[0] > 0.05 * A] > 0.0)


@pytest.mark.parametrize("change, match", [
    (dict(h=np.ones((6, 5))), "shapes"),
    (dict(x=np.array([0.0, 1.0, 3.0, 4.0, 5.0, 6.0])), "uniform"),
    (dict(h=np.full((5, 6), -1e-8)), "positive film"),
    (dict(p=np.zeros((5, 6))), "pressurised"),
    (dict(p=np.full((5, 6), np.nan)), "non-finite"),
])
def test_bad_pressure_field_is_named(change, match):
    fields = dict(x=np.arange(6.0), y=np.arange(5.0), p=np.ones((5, 6)), h=np.ones((5, 6)))
    fields.update(change)
    with pytest.raises(InputError, match=match):
        PressureField(**fields)
    with pytest.raises(InputError, match="PressureField"):
        contact(field={"p": 1.0})


# ---------------------------------------------------------------------------- mixed lubrication (asperities)
MU_B, P_A = 0.12, 2.0e8  # boundary friction, asperity pressure [Pa]


def test_asperities_add_a_coulomb_shear_along_the_sliding():
    """Coulomb asperities tau_a = mu_b p_a w/|w| over the ellipse, on top of the film (independent closed forms):
    pure creep: F_x - F_x(film alone) = -mu_b p_a pi a b for any nu_x > 0 (1e-10: the rule's weights sum to pi);
    pure spin on a circle: M_z - M_z(film) = -mu_b p_a int r dA = -mu_b p_a 2 pi a^3/3 (1e-9); the load is the
    film's plus p_a pi a b; the dissipation still splits into creep and spin losses; creep and spin together
    against the rigid-Coulomb integral by dblquad (the film made negligible)."""
    film, mixed = contact(), contact(asperity_pressure=P_A, boundary_friction=MU_B)
    area = math.pi * A * B
    assert mixed.normal_force == pytest.approx(film.normal_force + P_A * area, rel=1e-12)
    for nu in (1e-9, 1e-4):
        assert mixed.evaluate(nu).Fx - film.evaluate(nu).Fx == pytest.approx(-MU_B * P_A * area, rel=1e-10)
    circle, circle_film = (contact(b=A, asperity_pressure=P_A, boundary_friction=MU_B), contact(b=A))
    spin = circle.evaluate(0.0, 0.0, 40.0).Mz - circle_film.evaluate(0.0, 0.0, 40.0).Mz
    assert spin == pytest.approx(-MU_B * P_A * 2 * math.pi * A**3 / 3, rel=1e-9)
    state = mixed.evaluate(2e-4, 1e-5, 60.0)
    assert state.power_loss == pytest.approx(state.creep_loss + state.spin_loss, rel=1e-9)
    # creep with spin: the asperities' force against dblquad of -mu_b p_a (nu - phi y)/|w| (pole inside: 1 %)
    dry = contact(eta0=1e-30, asperity_pressure=P_A, boundary_friction=MU_B, n_radial=64, n_angular=256)
    nu, phi = 0.02, 100.0

    def integrand(y, x):
        wx, wy = nu - phi * y, phi * x
        return -MU_B * P_A * wx / math.hypot(wx, wy)

    def edge(x):
        return B * math.sqrt(max(0.0, 1 - (x / A) ** 2))

    pole = nu / phi
    expected = sum(integrate.dblquad(integrand, -A, A, low, high, epsabs=0, epsrel=1e-9)[0] for low, high in (
        (lambda x: -edge(x), lambda x: min(max(pole, -edge(x)), edge(x))),
        (lambda x: min(max(pole, -edge(x)), edge(x)), edge)))
    assert dry.evaluate(nu, 0.0, phi).Fx == pytest.approx(expected, rel=1e-2)


def test_rigid_coulomb_asperities_stick_below_their_bound():
    """Without spin the asperities hold a force below mu_b p_a pi a b without creep (rigid-Coulomb: creepage 0, no
    loss); above it the film carries the rest at the creepage a film-only contact needs for that rest."""
    mixed, film = contact(asperity_pressure=P_A, boundary_friction=MU_B), contact()
    bound = MU_B * P_A * math.pi * A * B
    held, _ = mixed.solve_creepage(0.5 * bound)
    assert abs(held.creepage_x) < 1e-12 and abs(held.power_loss) < 1e-9
    rest = film.evaluate(-2e-4).Fx
    state, _ = mixed.solve_creepage(bound + rest)
    assert state.creepage_x == pytest.approx(-2e-4, rel=1e-8)


def test_model_splits_the_hertz_load_between_film_and_asperities():
    """EhlTraction.contact with an asperity share f: the film at (1 - f) p_h, the asperities at f 2 p_h/3 uniform,
    so the total load stays 2/3 pi a b p_h; a share outside [0, 1) or with a numerical field is refused."""
    class State:
        eta0 = ETA0

        @staticmethod
        def log_viscosity_ratio(p):
            return np.zeros_like(p)

    model = EhlTraction(fluid=EyringTraction(limiting_shear_slope=0.088))
    whole = model.contact(A, B, PH, H, V, State())
    shared = model.contact(A, B, PH, H, V, State(), asperity_load_fraction=0.3, boundary_friction=MU_B)
    assert shared.normal_force == pytest.approx(whole.normal_force, rel=1e-12)
    assert shared.p_h == pytest.approx(0.7 * PH) and shared.asperity_pressure == pytest.approx(0.3 * 2 * PH / 3)
    for share in (-0.1, 1.0):
        with pytest.raises(InputError, match=f"asperity_load_fraction = {share!r}"):
            model.contact(A, B, PH, H, V, State(), asperity_load_fraction=share)
    with pytest.raises(InputError, match="numerical pressure field"):
        model.contact(A, B, PH, H, V, State(), field=hertz_field(), asperity_load_fraction=0.1)
    with pytest.raises(InputError, match="boundary_friction"):
        contact(asperity_pressure=P_A, boundary_friction=-0.1)


def test_centre_line_records_the_whole_contact_pressure_with_asperities():
    """The centre-line record's pressure is the film's (1 - f) p_h sqrt(1 - x^2/a^2) plus the asperities' uniform
    p_a: its readers take Tx/p as the surface's traction coefficient (the slice stresses), which a film-only
    pressure would inflate by 1/(1 - f)."""
    mixed = contact(p_h=0.6 * PH, asperity_pressure=0.4 * 2 * PH / 3, boundary_friction=MU_B)
    line = mixed.centre_line(mixed.evaluate(1e-4, 0.0, 20.0))
    x = line.x[0]
    expected = 0.6 * PH * np.sqrt(1 - (x / A) ** 2) + 0.4 * 2 * PH / 3
    np.testing.assert_allclose(line.p[0], expected, rtol=1e-12)
