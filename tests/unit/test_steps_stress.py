"""Stress step functions (camcontact.steps.stress) called alone, with plain SI inputs.

Expected values: the classical frictionless line-contact extremes (Johnson 1985 §4.2: tau_1 = 0.300 p_h
at z = 0.786 b; |tau_xz| = 0.250 p_h at x = +-0.866 b, z = 0.5 b; von Mises 0.557 p_h at 0.70 b for
nu = 0.3); with friction, the maxima of McEwen's closed-form field (Johnson 1985 §7.1, written out in
:func:`mcewen` below) searched on a zoomed grid in the test; Delabenetta (2021) Table 7 (tau_max 248 MPa,
Z_s 146.4 um, tau_xz 206.67 MPa, Z_0 78.12 um, tau_oct 2.232e8 Pa, roughness stress 1.592818e9 Pa) and
its §4.1 rules as printed in its Table 8 checks; Johnson (1985) §13.2 for the full-contact pressure of a
sinusoid.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from camcontact.scenes.raceway_conventions import CORRECTED, THESIS
from camcontact.steps.stress import (
    ball_cone_slice_stresses,
    line_subsurface_stresses,
    most_loaded_subsurface,
    raceway_checks,
    raceway_subsurface,
    roughness_full_contact_pressure,
    roughness_stress_step,
)
from step_checks import assert_provides


def mcewen(x, z, mu=0.0, nu=0.3):
    """McEwen's field for b = p_h = 1 with traction mu p on the surface (Johnson 1985 Eqs. 7.5-7.7 in the
    m, n form): returns (tau_1, tresca, von_mises, tau_xz)."""
    q = 1 - x * x + z * z
    root = np.sqrt(q * q + 4 * x * x * z * z)
    m = np.sqrt(np.clip(0.5 * (root + q), 0, None))
    n = np.sign(x) * np.sqrt(np.clip(0.5 * (root - q), 0, None))
    d = np.maximum(m * m + n * n, 1e-300)
    sx = -(m * (1 + (z * z + n * n) / d) - 2 * z) + mu * (n * (2 - (z * z - m * m) / d) - 2 * x)
    sz = -m * (1 - (z * z + n * n) / d) - mu * n * (m * m - z * z) / d
    txz = -n * (m * m - z * z) / d - mu * (m * (1 + (z * z + n * n) / d) - 2 * z)
    sy = nu * (sx + sz)
    tau1 = np.sqrt((0.5 * (sx - sz)) ** 2 + txz**2)
    s1, s3 = 0.5 * (sx + sz) + tau1, 0.5 * (sx + sz) - tau1
    tresca = 0.5 * (np.maximum(np.maximum(s1, s3), sy) - np.minimum(np.minimum(s1, s3), sy))
    vm = np.sqrt(0.5 * ((s1 - s3) ** 2 + (s1 - sy) ** 2 + (s3 - sy) ** 2))
    return tau1, tresca, vm, txz


def grid_max(measure, mu, nu=0.3):
    """Largest value of measure k of :func:`mcewen` (b = p_h = 1): a 601 x 301 grid over |x| <= 1.5,
    0 <= z <= 1.5, zoomed four times around the best point; returns (value, x, z)."""
    x, z = np.meshgrid(np.linspace(-1.5, 1.5, 601), np.linspace(0.0, 1.5, 301))
    values = mcewen(x, z, mu, nu)[measure]
    k = int(np.argmax(values))
    cx, cz, half = x.flat[k], z.flat[k], 0.01
    for _ in range(4):
        x, z = np.meshgrid(np.linspace(cx - half, cx + half, 41), np.clip(np.linspace(cz - half, cz + half, 41), 0, None))
        values = mcewen(x, z, mu, nu)[measure]
        k = int(np.argmax(values))
        cx, cz, half = x.flat[k], z.flat[k], half / 10
    return float(values.flat[k]), float(cx), float(cz)


# ----------------------------------------------------------------------------- line_subsurface_stresses
def test_line_subsurface_stresses_frictionless_classical_values():
    """b = 100 um, p_h = 1 GPa, mu = 0: tau_1 = 0.300 p_h at 0.786 b, Tresca the same (sigma_y is the
    middle principal stress), von Mises 0.557 p_h at 0.70 b, tau_xz = 0.250 p_h at |x| = 0.866 b,
    z = 0.5 b, range 2 tau_0 = 0.5 p_h (Johnson 1985 §4.2)."""
    b, p_h = 100e-6, 1e9
    out = line_subsurface_stresses(b, p_h, 0.3, 0.0)
    assert_provides(line_subsurface_stresses, out)
    assert out["tau_max"] == pytest.approx(0.300 * p_h, rel=2e-3)
    assert out["z_tau_max"] == pytest.approx(0.786 * b, rel=2e-3) and abs(out["x_tau_max"]) < 1e-3 * b
    assert out["tresca_max"] == pytest.approx(out["tau_max"], rel=1e-6)
    assert out["von_mises_max"] == pytest.approx(0.557 * p_h, rel=2e-3)
    assert out["z_von_mises_max"] == pytest.approx(0.70 * b, rel=0.01)
    assert out["tau_xz_max"] == pytest.approx(0.250 * p_h, rel=1e-3)
    assert abs(out["x_tau_xz_max"]) == pytest.approx(0.866 * b, rel=1e-3)
    assert out["z_tau_xz_max"] == pytest.approx(0.5 * b, rel=1e-3)
    assert out["tau_xz_range"] == pytest.approx(0.5 * p_h, rel=1e-3)


@pytest.mark.parametrize("mu", [0.1, 0.4])
def test_line_subsurface_stresses_with_friction_against_mcewen_grid(mu):
    """With traction mu p (mu = 0.1: the maximum stays below the surface; 0.4: it reaches the surface)
    the extremes equal the maxima of McEwen's closed form searched here (rel 1e-4), the range 2 tau_0 its
    max - min of tau_xz on a fine grid (rel 2e-3)."""
    b, p_h = 150e-6, 800e6
    out = line_subsurface_stresses(b, p_h, 0.3, mu)
    for key, measure in (("tau_max", 0), ("tresca_max", 1), ("von_mises_max", 2), ("tau_xz_max", 3)):
        value = grid_max(measure, mu)[0]
        assert out[key] == pytest.approx(value * p_h, rel=1e-4), key
    value, _, z = grid_max(0, mu)
    assert out["z_tau_max"] == pytest.approx(z * b, abs=2e-3 * b)
    x, zz = np.meshgrid(np.linspace(-1.5, 1.5, 1201), np.linspace(0.0, 1.5, 601))
    txz = mcewen(x, zz, mu)[3]
    assert out["tau_xz_range"] == pytest.approx((txz.max() - txz.min()) * p_h, rel=2e-3)


# ----------------------------------------------------------------------------- raceway_subsurface
def test_raceway_subsurface_thesis_constants_delabenetta_table_7():
    """Thesis convention (Delabenetta Eqs. 7, 9, 10) with a = 186.2393 um, P_o = 826.67 MPa: tau_max =
    0.30 P_o = 248 MPa at 0.7861 a = 146.4 um, tau_oct = 0.27 P_o = 2.232e8 Pa, tau_xz = 0.25 P_o = 206.67 MPa
    at x = 0.85 a, Z_0 = 0.42 x 186 um = 78.12 um (a rounded to whole micrometres, erratum 4), 2 tau_0 = 0.5 P_o."""
    b, p_h = 1.862393e-4, 826.67e6
    out = raceway_subsurface(b, p_h, 0.3, THESIS)
    assert_provides(raceway_subsurface, out)
    assert round(out["tau_max"] * 1e-6) == 248 and round(out["z_tau_max"] * 1e6, 1) == 146.4
    assert out["tresca_max"] == pytest.approx(0.30 * p_h)
    assert out["tau_oct_max"] == pytest.approx(2.232e8, rel=5e-4)
    assert round(out["tau_xz_max"] * 1e-6, 2) == 206.67
    assert out["x_tau_xz_max"] == pytest.approx(0.85 * b)
    assert round(out["z_tau_xz_max"] * 1e6, 2) == 78.12
    assert out["tau_xz_range"] == pytest.approx(0.5 * p_h)


def test_raceway_subsurface_exact_field():
    """Corrected convention, exact field: tau_1 0.300 p_h at 0.786 b, tau_oct = sqrt(2)/3 x von Mises =
    sqrt(2)/3 x 0.557 p_h, tau_xz 0.250 p_h at x = +0.866 b (absolute), z = 0.5 b (classical values)."""
    b, p_h = 1.862393e-4, 826.67e6
    out = raceway_subsurface(b, p_h, 0.3, CORRECTED)
    assert out["tau_max"] == pytest.approx(0.300 * p_h, rel=2e-3)
    assert out["z_tau_max"] == pytest.approx(0.786 * b, rel=2e-3)
    assert out["tau_oct_max"] == pytest.approx(math.sqrt(2) / 3 * 0.557 * p_h, rel=2e-3)
    assert out["tau_xz_max"] == pytest.approx(0.25 * p_h, rel=1e-3)
    assert out["x_tau_xz_max"] == pytest.approx(0.866 * b, rel=1e-3)
    assert out["z_tau_xz_max"] == pytest.approx(0.5 * b, rel=1e-3)


# ----------------------------------------------------------------------------- most_loaded_subsurface
def test_most_loaded_subsurface_picks_the_highest_pressure():
    """The outer race's second roller has the highest p_h (1.2 GPa, b = 150 um): tau_max = 0.300 p_h at
    0.786 b there; unloaded rollers (NaN) are skipped; no load at all gives zeros."""
    Q = np.array([0.0, 1e4, 2e4])
    b_in, b_out = np.array([np.nan, 80e-6, 100e-6]), np.array([np.nan, 150e-6, 90e-6])
    p_in, p_out = np.array([np.nan, 0.9e9, 1.1e9]), np.array([np.nan, 1.2e9, 1.0e9])
    out = most_loaded_subsurface(Q, b_in, b_out, p_in, p_out, 0.3)
    assert_provides(most_loaded_subsurface, out)
    assert out["tau_max"] == pytest.approx(0.300 * 1.2e9, rel=2e-3)
    assert out["z_tau_max"] == pytest.approx(0.786 * 150e-6, rel=2e-3)
    none = most_loaded_subsurface(np.zeros(3), b_in, b_out, p_in, p_out, 0.3)
    assert none == {"tau_max": 0.0, "z_tau_max": 0.0}


# ----------------------------------------------------------------------------- roughness, checks
def test_roughness_stress_delabenetta_eq_8():
    """5.172 ((amp/lambda)(R_x/a))^0.931 p0 (Delabenetta Eq. 8) with amp = 0.23 um, lambda = 88.3 um,
    R_x = 2/(1/149 mm + 1/13.5 mm), a = 186.2393 um, p0 = 826.67 MPa: 1.592818e9 Pa (its §4.2), 1.59 GPa
    (Table 7)."""
    R_x = 2 / (1 / 0.149 + 1 / 0.0135)
    out = roughness_stress_step(0.23e-6, 88.3e-6, R_x, 1.862393e-4, 826.67e6)
    assert_provides(roughness_stress_step, out)
    assert out["tau_roughness"] == pytest.approx(5.172 * (0.23 / 88.3 * R_x / 1.862393e-4) ** 0.931 * 826.67e6,
                                                 rel=1e-12)
    assert out["tau_roughness"] == pytest.approx(1.592818e9, rel=1e-5)
    # twice the amplitude (sqrt 2 sigma for a sinusoid of RMS sigma instead of the thesis's sigma/sqrt 2)
    double = roughness_stress_step(0.46e-6, 88.3e-6, R_x, 1.862393e-4, 826.67e6)
    assert double["tau_roughness"] / out["tau_roughness"] == pytest.approx(2.0**0.931, rel=1e-12)


def test_roughness_full_contact_pressure_johnson():
    """p* = pi E* A / lambda flattens a 2-D sinusoid (Johnson 1985 §13.2): by hand with E* = 109.89011 GPa
    (E = 200 GPa, nu = 0.3 both bodies), A = sqrt 2 x 0.32527 um = 0.46 um, lambda = 88.3 um:
    pi x 109.89011e9 x 0.46e-6 / 88.3e-6 = 1.7985e9 Pa (1.80 GPa, issue 16); bad inputs are refused."""
    E_star = 1.0 / (2 * (1 - 0.3**2) / 200e9)
    assert E_star == pytest.approx(109.89011e9, rel=1e-7)
    out = roughness_full_contact_pressure(0.46e-6, 88.3e-6, E_star)
    assert_provides(roughness_full_contact_pressure, out)
    assert out["p_full_contact_roughness"] == pytest.approx(3.141592653589793 * 109.89011e9 * 0.46e-6 / 88.3e-6,
                                                            rel=1e-7)
    assert round(out["p_full_contact_roughness"] * 1e-9, 2) == 1.80
    assert roughness_full_contact_pressure(0.0, 88.3e-6, E_star)["p_full_contact_roughness"] == 0.0
    from camcontact.errors import InputError

    with pytest.raises(InputError, match="wavelength"):
        roughness_full_contact_pressure(0.46e-6, 0.0, E_star)
    with pytest.raises(InputError, match="E_star"):
        roughness_full_contact_pressure(0.46e-6, 88.3e-6, math.nan)


def test_raceway_checks_thesis_and_tresca_rules():
    """Delabenetta Table 8 wording: tau_max 248 MPa < sigma_y 400 MPa -> no plastic deformation (thesis
    rule); 2 tau_0 = 413.3 MPa > 400 MPa -> fatigue probable. Tresca rule: 248 MPa >= 400/2 -> plastic."""
    tau, tresca, rng, sy = 248.0e6, 248.0e6, 413.335e6, 400e6
    out = raceway_checks(tau, tresca, rng, sy, THESIS)
    assert_provides(raceway_checks, out)
    assert out["yield_check"] == "no plastic deformation: 248 MPa vs 400 MPa (tau_max vs sigma_y (thesis §4.1))"
    assert out["fatigue_check"].startswith("fatigue probable") and "413.3 MPa" in out["fatigue_check"]
    corrected = raceway_checks(tau, tresca, rng, sy, CORRECTED)
    assert corrected["yield_check"] == "plastic deformation: 248 MPa vs 200 MPa (Tresca: tau_max vs sigma_y / 2)"
    safe = raceway_checks(100e6, 100e6, 300e6, sy, CORRECTED)
    assert safe["yield_check"].startswith("no plastic deformation")
    assert safe["fatigue_check"].startswith("no fatigue by the thesis's rule")


# ----------------------------------------------------------------------------- ball-cone slice
def strip(a, p_h, ratio, n=200):
    """A FASTSIM-like result with one central strip (y = 0): element centres from the leading edge +a to
    the trailing edge -a (cosine spaced), Hertz pressure and traction ratio Tx/p = ``ratio``."""
    x = a * np.cos(np.linspace(0.0, math.pi, n + 2)[1:-1])
    p = p_h * np.sqrt(1 - (x / a) ** 2)
    return SimpleNamespace(x=x[None, :], y=np.array([0.0]), p=p[None, :], Tx=ratio * p[None, :])


def test_ball_cone_slice_stresses_hertz_and_full_slip():
    """Input side without traction: the slice is Hertz: tau0 = 0.300 p_h at z0 = 0.786 a (Johnson);
    output side in full slip (Tx = 0.3 p): tau0 equals the maximum of McEwen's field with mu = 0.3 (rel 2e-3:
    piecewise-linear load on 200 nodes); "orthogonal": |tau_xz| = 0.25 p_h at 0.5 a."""
    a, p_h = 200e-6, 1.5e9
    out = ball_cone_slice_stresses(a, p_h, strip(a, p_h, 0.0), strip(a, p_h, 0.3), "max_shear")
    assert_provides(ball_cone_slice_stresses, out)
    assert out["tau0_in"] == pytest.approx(0.300 * p_h, rel=1e-3)
    assert out["z0_in"] == pytest.approx(0.786 * a, rel=3e-3)
    value, _, z = grid_max(0, 0.3)
    assert out["tau0_out"] == pytest.approx(value * p_h, rel=2e-3)
    assert out["z0_out"] == pytest.approx(z * a, abs=0.02 * a)
    ortho = ball_cone_slice_stresses(a, p_h, strip(a, p_h, 0.0), strip(a, p_h, 0.0), "orthogonal")
    assert ortho["tau0_in"] == pytest.approx(0.25 * p_h, rel=1e-3)
    assert ortho["z0_in"] == pytest.approx(0.5 * a, rel=3e-3)
