"""Hard inputs stay finite or fail loudly (no silent NaN)."""

import math

import numpy as np
import pytest

import camcontact as cc
from camcontact.contact.hertz_elliptical import ellipticity_exact, hertz_elliptical
from camcontact.contact.subsurface import line_subsurface
from camcontact.errors import InputError
from camcontact.models.film_line import moes_line_film
from camcontact.models.film_point import nijenbanning_film
from camcontact.models.viscosity_pressure import Roelands


@pytest.mark.parametrize("ratio", [1.001, 2.0, 1e3, 1e6, 1e8])
def test_ellipticity_satisfies_the_hertz_relation_up_to_near_line(ratio):
    kappa, K, E = ellipticity_exact(ratio)
    assert np.isfinite([kappa, K, E]).all() and kappa > 1.0
    assert (kappa**2 * E - K) / (K - E) == pytest.approx(ratio, rel=1e-8)


@pytest.mark.parametrize("excess", [1e-12, 1e-9, 1e-7])
def test_ellipticity_near_the_circle_is_continuous(excess):
    """r - 1 ~ 1.5 (kappa - 1) near the circle (first-order series of the Hertz relation:
    K = pi/2 (1 + m/4), E = pi/2 (1 - m/4), m ~ 2 (kappa - 1))."""
    kappa, K, E = ellipticity_exact(1.0 + excess)
    assert kappa - 1.0 == pytest.approx(excess / 1.5, rel=1e-3)
    assert K == pytest.approx(math.pi / 2, abs=1e-6) and E == pytest.approx(math.pi / 2, abs=1e-6)


def test_circle_exactly():
    assert ellipticity_exact(1.0) == (1.0, math.pi / 2, math.pi / 2)


def test_ellipticity_beyond_line_limit_is_an_error():
    with pytest.raises(InputError, match="line contact"):
        hertz_elliptical(1.0, 0.01, 1e7, 2e11)


def test_roelands_at_very_high_pressure_stays_finite_in_log_form():
    law = Roelands()
    p = np.array([1e9, 5e9, 2e10, 1e11])
    log_ratio = law.log_viscosity_ratio(p, 0.04, 2.2e-8)
    assert np.all(np.isfinite(log_ratio)) and np.all(np.diff(log_ratio) > 0)


@pytest.mark.parametrize("M", [1e-2, 1.0, 20.0, 1e3, 1e5])
@pytest.mark.parametrize("L", [0.0, 1e-3, 10.0, 25.0, 100.0])
def test_moes_line_film_finite_over_the_map(M, L):
    for elasticity in (True, False):
        H = moes_line_film(M, L, elasticity=elasticity)
        assert math.isfinite(H) and H > 0


@pytest.mark.parametrize("D", [0.05, 0.25, 1.0, 4.0, 20.0])
@pytest.mark.parametrize("M, L", [(1.0, 0.0), (20.0, 10.0), (1e3, 25.0)])
def test_nijenbanning_film_finite(M, L, D):
    H = nijenbanning_film(M, L, D)
    assert math.isfinite(H) and H > 0


@pytest.mark.parametrize("mu", [0.0, 0.5, 1.0])
def test_subsurface_finite_for_any_friction(mu):
    result = line_subsurface(1e-4, 1e9, friction=mu)
    for extremum in (result.principal_shear_max, result.von_mises_max, result.tau_xz_max, result.tau_xz_min):
        assert np.isfinite([extremum.value, extremum.x, extremum.z]).all()


def test_concave_radius_tighter_than_convex_is_refused(steel):
    contact = cc.LineContact(body1=cc.Body(material=steel, radius="10 mm"),
                             body2=cc.Body(material=steel, radius="9 mm", concave=True), load_per_length="1 N/mm")
    with pytest.raises(InputError, match="conforming"):
        cc.Analysis(contact, outputs=["b"], strict=True).run()


def test_opposite_surface_speeds_give_infinite_slide_roll_not_nan(steel):
    contact = cc.LineContact(body1=cc.Body(material=steel, radius="10 mm", speed="1 m/s"),
                             body2=cc.Body(material=steel, radius="10 mm", speed="-1 m/s"), load_per_length="1 N/mm")
    result = cc.Analysis(contact, outputs=["u_m", "slide_roll_ratio"]).run()
    assert result["u_m"] == 0.0 and result["slide_roll_ratio"] == math.inf
