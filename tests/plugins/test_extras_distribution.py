"""The camcontact-extras distribution: discovered through its entry points only, and its models
tested against the published values they carry.

The README install command installs ``plugins/camcontact-extras``; these tests fail if it is missing.
"""

import importlib.metadata as metadata
import math
import sys

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import camcontact as cc
from camcontact import registry

EXTRAS = {"martin": "film_models", "blok": "film_models", "greenwood_tripp": "friction_models"}


def test_extras_are_installed_with_their_entry_points():
    try:
        dist = metadata.distribution("camcontact-extras")
    except metadata.PackageNotFoundError:
        pytest.fail("camcontact-extras is not installed; install it as the README says")
    declared = {(ep.group, ep.name) for ep in dist.entry_points}
    assert declared == {("camcontact." + family, name) for name, family in EXTRAS.items()}


def test_registry_discovers_extras_through_entry_points(clean_registry, monkeypatch):
    monkeypatch.delenv("CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD", raising=False)
    sys.modules.pop("camcontact_extras.rigid_films", None)
    rows = {(row.family, row.name): row for row in registry.entries()}
    for name, family in EXTRAS.items():
        row = rows[(family, name)]
        assert row.status == "ok" and row.source.startswith("camcontact-extras ")
        assert row.target.startswith("camcontact_extras.")
    # nothing of the package was imported before the registry loaded it
    assert "camcontact_extras.rigid_films" in sys.modules


def test_extras_are_invisible_with_autoload_off(clean_registry, monkeypatch):
    monkeypatch.setenv("CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD", "1")
    assert "martin" not in registry.available("film_models")


def _rigid_exit_and_load():
    """Rigid cylinder on plane, h = h0 (1 + xi^2): Reynolds (Swift–Stieber) exit xi* = c solves
    P(c) = 0 for dP/dxi = (xi^2 - c^2)/(1 + xi^2)^3, P(-inf) = 0."""
    f = lambda xi, c: (xi**2 - c**2) / (1 + xi**2) ** 3  # noqa: E731
    c = brentq(lambda c: quad(f, -np.inf, c, args=(c,))[0], 0.1, 1.0)
    load = quad(lambda xi: quad(f, -np.inf, xi, args=(c,))[0], -np.inf, c, limit=200)[0]
    peak = quad(f, -np.inf, -c, args=(c,))[0]
    return c, load, peak


def test_martin_coefficient_by_integration():
    """Martin (1916): h = 4.9 eta0 u_m R / w. Independent: with p = 12 eta0 u_m sqrt(2 R h0)/h0^2 P(xi)
    the load is w = 24 eta0 u_m R/h0 * int P dxi, i.e. h0 = 24 int(P) eta0 u_m R/w = 4.895 ..."""
    c, load, _ = _rigid_exit_and_load()
    assert c == pytest.approx(0.4751, abs=1e-4)
    assert 24 * load == pytest.approx(4.9, abs=0.01)


def test_blok_coefficient_by_integration():
    """Blok (Saccheto Eq. 4.47): h = 1.66 (alpha eta0 u_m)^(2/3) R^(1/3). Independent: the reduced
    pressure q = (1 - exp(-alpha p))/alpha obeys the isoviscous equation; its peak K I_max, with
    K = 12 eta0 u_m sqrt(2R) h0^(-3/2), reaches 1/alpha when h0 = (12 sqrt(2) I_max)^(2/3) (...)."""
    _, _, peak = _rigid_exit_and_load()
    assert (12 * math.sqrt(2) * peak) ** (2 / 3) == pytest.approx(1.66, abs=0.01)


@pytest.fixture
def rigid_state():
    return dict(R=0.01, w=1e4, E_reduced=2.3e11, u_m=2.0, eta0=0.05, alpha=2e-8)


def test_martin_and_blok_values(rigid_state):
    martin = registry.get("film_models", "martin")(rigid_state)
    assert martin["h_min"] == pytest.approx(4.9 * 0.05 * 2.0 * 0.01 / 1e4)
    blok = registry.get("film_models", "blok")(rigid_state)
    assert blok["h_c"] == pytest.approx(1.66 * (2e-8 * 0.05 * 2.0) ** (2 / 3) * 0.01 ** (1 / 3))
    with pytest.raises(cc.InputError, match="alpha must be > 0"):
        registry.get("film_models", "blok")({**rigid_state, "alpha": 0.0})


def test_martin_runs_in_a_rigid_isoviscous_scene(steel):
    oil = cc.Lubricant(eta0="0.05 Pa*s")
    contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="2 m/s"),
                             body2=cc.Body(material=steel, radius="20 mm", speed="2 m/s"),
                             load_per_length="10 N/mm", lubricant=oil)
    result = cc.Analysis(contact, outputs=["h_min"], effects=[], models={"film": "martin"}).run()
    assert result["h_min"] == pytest.approx(4.9 * 0.05 * 2.0 * 0.01 / 1e4)


def test_greenwood_tripp_gaussian_moments():
    """F_n(0) = 2^((n-1)/2) Gamma((n+1)/2)/sqrt(2 pi) (Gaussian moment): F_3/2(0) = 0.43002,
    F_5/2(0) = 0.61663; F_0 = 1 - Phi; F_1 = phi - lambda (1 - Phi); and direct quadrature."""
    from scipy.stats import norm

    from camcontact_extras.greenwood_tripp import gaussian_moment

    assert gaussian_moment(1.5, 0.0) == pytest.approx(0.4300200, abs=1e-7)
    assert gaussian_moment(2.5, 0.0) == pytest.approx(0.6166342, abs=1e-7)
    lam = np.linspace(-1, 4, 11)
    np.testing.assert_allclose(gaussian_moment(0.0, lam), norm.sf(lam), rtol=1e-10)
    np.testing.assert_allclose(gaussian_moment(1.0, lam), norm.pdf(lam) - lam * norm.sf(lam), rtol=1e-9)
    for x in (0.5, 1.7, 3.2):
        direct = quad(lambda s: (s - x) ** 2.5 * math.exp(-s * s / 2), x, np.inf)[0] / math.sqrt(2 * math.pi)
        assert gaussian_moment(2.5, x) == pytest.approx(direct, rel=1e-9)


@pytest.mark.parametrize("lam", [0.5, 1.0, 1.5, 2.0])
def test_greenwood_tripp_against_published_power_fit(lam):
    """The widely published fit F_5/2 = 4.4086e-5 (4 - lambda)^6.804 (attributed to Hu et al. 1994;
    used e.g. in AVL EXCITE) agrees with the exact moment within 10 % for 0.5 <= lambda <= 2."""
    from camcontact_extras.greenwood_tripp import gaussian_moment

    assert 4.4086e-5 * (4 - lam) ** 6.804 == pytest.approx(gaussian_moment(2.5, lam), rel=0.10)


def test_greenwood_tripp_friction_model():
    """p_a = (8 sqrt2/15) pi (eta beta sigma)^2 sqrt(sigma/beta) E' F_5/2(h/sigma); mixed mu = mu_b f_a."""
    from camcontact_extras.greenwood_tripp import gaussian_moment

    model = registry.get("friction_models", "greenwood_tripp", eta_beta_sigma=0.055, sigma_over_beta=1e-3)
    E_red = 2 * 115.385e9
    out = model(dict(h_c=0.3e-6, sigma=0.3e-6, E_reduced=E_red, contact_area=1e-5, F=1e3))
    expected = 8 * math.sqrt(2) / 15 * math.pi * 0.055**2 * math.sqrt(1e-3) * E_red * gaussian_moment(2.5, 1.0)
    assert out["asperity_pressure"] == pytest.approx(expected, rel=1e-12)
    assert out["asperity_pressure"] * 1e-6 == pytest.approx(4.214, abs=0.001)  # helper's worked example
    assert out["friction_coefficient"] == pytest.approx(0.1 * out["asperity_load_fraction"])
    thick = model(dict(h_c=3e-6, sigma=0.3e-6, E_reduced=E_red, contact_area=1e-5, F=1e3))
    assert thick["asperity_load_fraction"] < 1e-12
