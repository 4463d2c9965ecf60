"""The point-contact steps called alone with plain SI inputs: point_geometry, point_hertz (steps.contact),
point_subsurface_stresses (steps.stress) and point_film (steps.film).

Expected values: reduced radii 1/R = 1/R1 + 1/R2 per plane written out; the Hertz step equals
:func:`camcontact.contact.hertz_elliptical.hertz_elliptical` called directly and, for a circle, the closed
forms a = (3 F R/(2 E'))^(1/3), p_h = 3F/(2 pi a^2) (Johnson 1985 Eq. 4.22 with E* = E'/2); the stresses
equal :func:`camcontact.contact.subsurface_point.point_subsurface` (checked against Johnson's closed form in
test_subsurface_point.py); the film step equals the Hamrock–Dowson model called directly.
"""

import math

import pytest

from camcontact import registry
from camcontact.contact.hertz_elliptical import hertz_elliptical
from camcontact.contact.subsurface_point import point_subsurface
from camcontact.errors import InputError, ValidityWarning
from camcontact.steps.contact import point_geometry, point_hertz
from camcontact.steps.film import point_film
from camcontact.steps.stress import point_subsurface_stresses
from step_checks import assert_provides

E, NU = 207e9, 0.3
E_REDUCED = E / (1 - NU**2)


def test_geometry_of_a_ball_in_a_groove():
    """Ball 6.35 mm in an inner-ring groove (raceway radius 20 mm along rolling, groove radius 6.6 mm concave
    across): 1/Rx = 1/6.35 + 1/20 mm, 1/Ry = 1/6.35 - 1/6.6 mm."""
    out = point_geometry(E, NU, E, NU, 6.35e-3, 20e-3, 6.35e-3, -6.6e-3)
    assert_provides(point_geometry, out)
    assert out["Rx"] == pytest.approx(1 / (1 / 6.35e-3 + 1 / 20e-3), rel=1e-12)
    assert out["Ry"] == pytest.approx(1 / (1 / 6.35e-3 - 1 / 6.6e-3), rel=1e-12)
    assert out["E_reduced"] == pytest.approx(E_REDUCED, rel=1e-12)
    with pytest.raises(InputError, match="conforming"):
        point_geometry(E, NU, E, NU, 6.35e-3, math.inf, 6.35e-3, -6.35e-3)


def test_hertz_of_a_ball_on_a_flat_and_the_stress_limit():
    R, F = 6.35e-3, 100.0
    out = point_hertz(F, R, R, E_REDUCED, "exact", 4.2e9)
    assert_provides(point_hertz, out)
    a = (3 * F * R / (2 * E_REDUCED)) ** (1 / 3)
    assert out["a_rolling"] == pytest.approx(a, rel=1e-9) and out["a_transverse"] == pytest.approx(a, rel=1e-9)
    assert out["p_h"] == pytest.approx(3 * F / (2 * math.pi * a * a), rel=1e-9)
    assert out["ellipticity"] == pytest.approx(1.0, rel=1e-9) and out["stress_limit_exceeded"] is False
    direct = hertz_elliptical(F, 3e-3, 30e-3, E_REDUCED, method="hamrock_brewe")
    long = point_hertz(F, 3e-3, 30e-3, E_REDUCED, "hamrock_brewe", 4.2e9)
    assert (long["a_rolling"], long["a_transverse"], long["p_h"]) == (direct.a_x, direct.a_y, direct.p_max)
    with pytest.warns(ValidityWarning, match="exceeds the contact stress limit 1 GPa"):
        assert point_hertz(F, R, R, E_REDUCED, "exact", 1e9)["stress_limit_exceeded"] is True


def test_subsurface_step_is_the_axis_integral():
    out = point_subsurface_stresses(2e-4, 1e-4, 2e9, NU)
    assert_provides(point_subsurface_stresses, out)
    found = point_subsurface(2e-4, 1e-4, 2e9, NU)
    assert out == {"tresca_max": found.tresca_max, "z_tresca_max": found.z_tresca_max,
                   "von_mises_max": found.von_mises_max, "z_von_mises_max": found.z_von_mises_max}


def test_film_step_is_the_model_called_directly_and_names_it():
    model = registry.get("film_models", "hamrock_dowson")
    args = dict(Rx=6.35e-3, Ry=6.35e-3, F=50.0, E_reduced=E_REDUCED, u_m=2.0, eta0=0.06, alpha=2.2e-8)
    out = point_film(model, **args, piezoviscosity=True, lubricant_state=None, density_law="dowson_higginson")
    assert_provides(point_film, out)
    direct = model.evaluate(**args)
    assert out["h_c_isothermal"] == pytest.approx(float(direct["h_c"]), rel=1e-12)
    assert out["h_min_isothermal"] == pytest.approx(float(direct["h_min"]), rel=1e-12)
    assert out["film_valid"] and out["film_validity"] == "ok" and out["film_solution"] is None
    # a wide ellipse (k = 1.03 (Ry/Rx)^0.64 > 8) is outside Hamrock-Dowson's fit: named, not silent
    wide = point_film(model, **{**args, "Ry": 0.5}, piezoviscosity=True, lubricant_state=None,
                      density_law="dowson_higginson")
    assert not wide["film_valid"] and wide["film_validity"].startswith("hamrock_dowson: ")
    # without piezoviscosity Hamrock-Dowson refuses (fitted to piezoviscous solutions)
    with pytest.raises(InputError, match="no film at alpha = 0"):
        point_film(model, **args, piezoviscosity=False, lubricant_state=None, density_law="dowson_higginson")
