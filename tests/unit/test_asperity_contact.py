"""Greenwood–Tripp integrals F_n, asperity pressure and real contact area (camcontact.contact.asperity_contact).

References checked here:
* the definition F_n(lam) = (1/sqrt(2 pi)) int_lam^inf (s - lam)^n exp(-s^2/2) ds, integrated
  independently by scipy.integrate.quad (tolerance of the task: 1e-6 relative; met with margin);
* F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi) (the integral at lam = 0 in closed form);
* the Bessel closed forms of F_3/2 and F_5/2 (derived from DLMF 12.7.10, 12.8.1, 12.8.2; see the
  module docstring), coded here independently of the implementation;
* dF_n/dlam = -n F_(n-1) and F_(n+1) = n F_(n-1) - lam F_n (differentiating the definition);
* Greenwood & Tripp (1970–71) pressure and area rebuilt from Hertz contacts of asperity pairs
  (two-dimensional quadrature), which pins the coefficient 16 sqrt(2) pi / 15 to Johnson's E*.
"""

import itertools
import math
import warnings

import numpy as np
import pytest
from scipy import integrate, special

from camcontact.contact.asperity_contact import (
    asperity_pressure,
    greenwood_tripp_coefficient,
    greenwood_tripp_integral,
    real_contact_area_fraction,
)
from camcontact.errors import InputError


def quad_integral(n, lam):
    """F_n(lam) by adaptive quadrature of the definition (split where the integrand peaks)."""
    def integrand(s):
        return (s - lam) ** n * math.exp(-0.5 * s * s)

    breaks = sorted({lam, max(lam, 0.0), lam + 1.0})
    pieces = [integrate.quad(integrand, a, b, epsabs=0.0, epsrel=1e-13, limit=200)[0]
              for a, b in itertools.pairwise(breaks) if b > a]
    pieces.append(integrate.quad(integrand, breaks[-1], np.inf, epsabs=0.0, epsrel=1e-13, limit=200)[0])
    return sum(pieces) / math.sqrt(2.0 * math.pi)


LAMBDAS = np.concatenate([np.linspace(-3.0, 4.0, 29), np.linspace(4.5, 8.0, 8)])


@pytest.mark.parametrize("n", [1.5, 2.5, 2.0, 0.0, 1.0, 0.5, 3.0, 4.3])
def test_integral_matches_quadrature(n):
    """Every order against quad over lambda in [-3, 8]: the task's 1e-6 relative, met to 1e-9."""
    reference = np.array([quad_integral(n, lam) for lam in LAMBDAS])
    values = greenwood_tripp_integral(n, LAMBDAS)
    np.testing.assert_allclose(values, reference, rtol=1e-9, atol=0.0)
    assert np.max(np.abs(values / reference - 1.0)) <= 1e-6


@pytest.mark.parametrize("n", [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.7])
def test_value_at_zero_separation(n):
    """F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi): F_3/2(0) = 0.43002, F_2(0) = 1/2, F_5/2(0) = 0.61663."""
    exact = 2.0 ** ((n - 1.0) / 2.0) * math.gamma((n + 1.0) / 2.0) / math.sqrt(2.0 * math.pi)
    assert greenwood_tripp_integral(n, 0.0) == pytest.approx(exact, rel=1e-13)


def test_bessel_closed_forms_of_three_halves_and_five_halves():
    """F_3/2 and F_5/2 from K_1/4, K_3/4 (w = lam^2/4), coded independently, for lam in (0, 8]."""
    lam = np.linspace(0.05, 8.0, 160)
    w = lam * lam / 4.0
    k14, k34 = special.kv(0.25, w), special.kv(0.75, w)
    f32 = np.exp(-w) / (4.0 * math.sqrt(math.pi)) * np.sqrt(lam) * ((1.0 + lam**2) * k14 - lam**2 * k34)
    f52 = np.exp(-w) / (8.0 * math.sqrt(math.pi)) * lam**1.5 * ((2.0 * lam**2 + 3.0) * k34 - (2.0 * lam**2 + 5.0) * k14)
    np.testing.assert_allclose(greenwood_tripp_integral(1.5, lam), f32, rtol=1e-9)
    np.testing.assert_allclose(greenwood_tripp_integral(2.5, lam), f52, rtol=1e-9)


def test_derivative_and_recurrence_identities():
    """dF_n/dlam = -n F_(n-1) (central differences) and F_(n+1) = n F_(n-1) - lam F_n on [-2, 6]."""
    lam = np.linspace(-2.0, 6.0, 33)
    step = 1e-5
    for n in (1.5, 2.0, 2.5):
        derivative = (greenwood_tripp_integral(n, lam + step) - greenwood_tripp_integral(n, lam - step)) / (2 * step)
        np.testing.assert_allclose(derivative, -n * greenwood_tripp_integral(n - 1.0, lam), rtol=1e-7)
    for n in (0.5, 1.0, 1.5):
        upper = greenwood_tripp_integral(n + 1.0, lam)
        recurrence = n * greenwood_tripp_integral(n - 1.0, lam) - lam * greenwood_tripp_integral(n, lam)
        np.testing.assert_allclose(upper, recurrence, rtol=2e-8, atol=1e-300)


def test_large_separation_decays_to_zero_without_nan_or_warning():
    lam = np.array([8.0, 12.0, 20.0, 37.0, 38.4, 38.6, 50.0, 1e3, 1e12, np.inf])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for n in (0.0, 1.0, 1.5, 2.0, 2.5, 3.3):
            values = greenwood_tripp_integral(n, lam)
            assert np.all(np.isfinite(values)) and np.all(values >= 0.0)
            assert np.all(np.diff(values) <= 0.0)
            assert values[-4:].tolist() == [0.0] * 4


def test_deep_interference_is_finite_and_tends_to_the_power_law():
    """lam -> -inf: F_n -> E[(X - lam)^n] ~ |lam|^n (1 + n(n-1)/(2 lam^2)); F_2 -> 1 + lam^2 (the
    neglected tail is below 1e-20 relative for lam <= -10)."""
    lam = np.array([-10.0, -29.9, -30.1, -60.0, -1e3])
    np.testing.assert_allclose(greenwood_tripp_integral(2.0, lam), 1.0 + lam**2, rtol=1e-13)
    for n in (1.5, 2.5):
        c = -lam[-3:]
        np.testing.assert_allclose(greenwood_tripp_integral(n, lam[-3:]), c**n * (1 + n * (n - 1) / (2 * c * c)),
                                   rtol=1e-5)
    # the series branch (lam < -30) joins the parabolic-cylinder branch continuously
    for n in (1.5, 2.5):
        assert greenwood_tripp_integral(n, -30.0 - 1e-9) == pytest.approx(greenwood_tripp_integral(n, -30.0), rel=1e-9)


def test_vectorised_shapes_and_scalars():
    lam = np.linspace(-3.0, 8.0, 10_000)
    assert greenwood_tripp_integral(2.5, lam).shape == (10_000,)
    assert isinstance(greenwood_tripp_integral(2.5, 1.0), float)
    table = greenwood_tripp_integral(np.array([[1.5], [2.0], [2.5]]), np.array([0.0, 1.0, 2.0]))
    assert table.shape == (3, 3)
    assert table[2, 0] == pytest.approx(greenwood_tripp_integral(2.5, 0.0))


@pytest.mark.parametrize(("n", "lam", "text"), [
    (-1.0, 1.0, "n = -1.0"),
    (float("nan"), 1.0, "n = nan"),
    (2.5, float("nan"), "lam = nan"),
    (2.5, -np.inf, "lam = -inf"),
    (2.5, "thick", "lam = 'thick'"),
])
def test_bad_arguments_raise_input_error_naming_them(n, lam, text):
    with pytest.raises(InputError, match=text.replace("(", r"\(")):
        greenwood_tripp_integral(n, lam)


# ----------------------------------------------------------------------------------- pressure, area
E_REDUCED = 2.3077e11  # Hamrock's E' of a steel pair (210 GPa, nu = 0.3): E* = E'/2
SIGMA, BETA = 0.2e-6, 4e-6
ETA = 0.05 / (BETA * SIGMA)  # eta beta sigma = 0.05


def pair_integral(h, *, area: bool):
    """Greenwood–Tripp from its construction: asperity pairs (tip radius beta each, heights summing
    to z ~ N(0, sigma^2)) at lateral offset r overlap by delta = z - h - r^2/(4 beta); each carries the
    Hertz load (4/3) E* (beta/2)^(1/2) delta^(3/2) over the area pi (beta/2) delta; eta^2 2 pi r dr
    pairs per unit area. Returns the pressure [Pa] (E* = E'/2) or the area fraction [-]."""
    e_star = 0.5 * E_REDUCED

    def inner(z):
        depth = z - h
        if depth <= 0.0:
            return 0.0
        r_max = math.sqrt(4.0 * BETA * depth)

        def per_offset(r):
            delta = depth - r * r / (4.0 * BETA)
            single = math.pi * 0.5 * BETA * delta if area else 4.0 / 3.0 * e_star * math.sqrt(0.5 * BETA) * delta**1.5
            return 2.0 * math.pi * r * single

        return integrate.quad(per_offset, 0.0, r_max, epsrel=1e-11)[0]

    def density(z):
        return math.exp(-0.5 * (z / SIGMA) ** 2) / (SIGMA * math.sqrt(2.0 * math.pi))

    total = integrate.quad(lambda z: inner(z) * density(z), h, h + 12 * SIGMA, epsrel=1e-10, limit=200)[0]
    return ETA**2 * total


@pytest.mark.parametrize("lam", [0.0, 1.0, 2.5])
def test_pressure_and_area_rebuilt_from_hertz_pairs_use_johnsons_modulus(lam):
    """p_a = K (E'/2) F_5/2 and A_r/A = pi^2 (eta beta sigma)^2 F_2 agree with the pair construction
    (Hertz with E* = E'/2) to 1e-6 (the nested quadrature's accuracy); with Hamrock's E' in the formula the pressure would be 2x."""
    h = lam * SIGMA
    pressure = asperity_pressure(h, SIGMA, ETA, BETA, E_REDUCED)
    assert pressure == pytest.approx(pair_integral(h, area=False), rel=1e-6)
    assert real_contact_area_fraction(h, SIGMA, ETA, BETA) == pytest.approx(pair_integral(h, area=True), rel=1e-6)
    K = greenwood_tripp_coefficient(SIGMA, ETA, BETA)
    assert K == pytest.approx(16 * math.sqrt(2) / 15 * math.pi * 0.05**2 * math.sqrt(SIGMA / BETA), rel=1e-14)
    assert pressure == pytest.approx(K * 0.5 * E_REDUCED * greenwood_tripp_integral(2.5, lam), rel=1e-14)


def test_pressure_and_area_broadcast_and_vanish_far_apart():
    h = np.array([-0.5, 0.0, 1.0, 3.0, 100.0]) * SIGMA
    p = asperity_pressure(h, SIGMA, ETA, BETA, E_REDUCED)
    a = real_contact_area_fraction(h, SIGMA, ETA, BETA)
    assert p.shape == a.shape == (5,)
    assert np.all(np.diff(p) < 0.0) and p[-1] == 0.0 and a[-1] == 0.0
    assert asperity_pressure(np.inf, SIGMA, ETA, BETA, E_REDUCED) == 0.0


@pytest.mark.parametrize(("kwargs", "text"), [
    ({"sigma": 0.0}, "sigma = 0.0"),
    ({"sigma": -1e-7}, "sigma = -1e-07"),
    ({"asperity_density": float("nan")}, "asperity_density = nan"),
    ({"asperity_radius": 0.0}, "asperity_radius = 0.0"),
    ({"E_reduced": -2e11}, "E_reduced = -2"),
    ({"separation": float("nan")}, "separation = nan"),
])
def test_pressure_rejects_bad_inputs_by_name(kwargs, text):
    arguments = {"separation": 1e-7, "sigma": SIGMA, "asperity_density": ETA, "asperity_radius": BETA,
                 "E_reduced": E_REDUCED, **kwargs}
    with pytest.raises(InputError, match=text):
        asperity_pressure(**arguments)
