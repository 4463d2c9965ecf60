"""Plane-strain slice stresses (Saccheto 2008 §3.4 with Johnson's kernels) under piecewise-linear loads.

Oracles: McEwen's closed form (camcontact.contact.subsurface.line_contact_stresses, itself
Johnson 1985 §7.1), direct adaptive quadrature of Johnson (1985) Eq. 2.23, the surface
conditions sigma_z = -p, tau_xz = -q, and the classical line-contact extremes (Johnson 1985
§4.2; Saccheto §3.3 and reference report §2.2): Mohr shear 0.300 p0 at z = 0.786 b, orthogonal
shear 0.250 p0 at z = 0.5 b, x = +-0.866 b (= +-sqrt(3)/2 b).
"""

import math

import numpy as np
import pytest
from scipy import integrate

from camcontact.contact import _slice_kernels
from camcontact.contact.slice_stress import (
    SliceStress,
    semi_elliptical_load,
    slice_extrema,
    slice_extremum,
    slice_stresses,
)
from camcontact.contact.subsurface import line_contact_stresses, line_subsurface
from camcontact.errors import InputError

B = 0.2e-3  # half-width [m] (a typical heavily loaded steel line contact)
P0 = 1.5e9  # peak pressure [Pa]


def _grid(x_low, x_high, nx, z_low, z_high, nz):
    return np.meshgrid(np.linspace(x_low, x_high, nx), np.linspace(z_low, z_high, nz))


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.3])
def test_semi_elliptic_load_matches_mcewen(mu):
    """Hertz strip with q = mu p on 201 cosine-spaced nodes vs McEwen's closed form.

    Tolerance: 2e-4 p0 on every component at depths z >= 0.1 b over |x| <= 2 b (the only error
    is the piecewise-linear interpolation of the semi-ellipse; measured 5e-5 p0), and 1e-3
    relative on the Mohr shear wherever it exceeds 0.05 p0.
    """
    s, p, q = semi_elliptical_load(B, P0, traction_coefficient=mu, nodes=201)
    X, Z = _grid(-2 * B, 2 * B, 81, 0.1 * B, 2 * B, 39)
    field = slice_stresses(s, p, q, X, Z)
    exact = line_contact_stresses(X, Z, B, P0, friction=mu)
    for key in ("sigma_x", "sigma_z", "tau_xz"):
        error = np.max(np.abs(getattr(field, key) - exact[key])) / P0
        assert error < 2e-4, (key, error)
    mohr = exact["principal_shear"]
    mask = mohr > 0.05 * P0
    relative = np.max(np.abs(field.max_shear[mask] - mohr[mask]) / mohr[mask])
    assert relative < 1e-3


def test_uniform_nodes_converge_towards_mcewen():
    """Uniform nodes resolve the square-root edges less well, but the error falls as nodes are added."""
    X, Z = _grid(-2 * B, 2 * B, 41, 0.1 * B, 2 * B, 20)
    exact = line_contact_stresses(X, Z, B, P0, friction=0.3)["principal_shear"]
    errors = []
    for nodes in (51, 201, 801):
        s, p, q = semi_elliptical_load(B, P0, traction_coefficient=0.3, nodes=nodes, spacing="uniform")
        errors.append(np.max(np.abs(slice_stresses(s, p, q, X, Z).max_shear - exact)) / P0)
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 1e-3


def _johnson_quadrature(s, p, q, x, z):
    """Johnson (1985) Eq. 2.23 by adaptive quadrature of the piecewise-linear loads (independent oracle)."""

    def load(values, t):
        return np.interp(t, s, values)

    def integral(function):
        points = sorted(set(s.tolist()) | ({x} if s[0] < x < s[-1] else set()))
        total = 0.0
        for low, high in zip(points[:-1], points[1:]):
            total += integrate.quad(function, low, high, epsabs=0.0, epsrel=1e-12, limit=200)[0]
        return total

    def r4(t):
        return ((x - t) ** 2 + z * z) ** 2

    c = -2.0 / math.pi
    sigma_x = c * (z * integral(lambda t: load(p, t) * (x - t) ** 2 / r4(t))
                   + integral(lambda t: load(q, t) * (x - t) ** 3 / r4(t)))
    sigma_z = c * (z**3 * integral(lambda t: load(p, t) / r4(t))
                   + z * z * integral(lambda t: load(q, t) * (x - t) / r4(t)))
    tau_xz = c * (z * z * integral(lambda t: load(p, t) * (x - t) / r4(t))
                  + z * integral(lambda t: load(q, t) * (x - t) ** 2 / r4(t)))
    return sigma_x, sigma_z, tau_xz


def test_exact_for_piecewise_linear_loads_with_end_steps():
    """Arbitrary irregular nodes, loads not zero at the ends (steps), traction changing sign.

    The closed-form integration must equal adaptive quadrature of Johnson's Eq. 2.23 to
    quadrature accuracy (1e-9 of the peak load), near the surface (z = 1e-3 of the span, right
    under a node and between nodes) as well as deep.
    """
    s = np.array([0.0, 0.7, 1.1, 2.0, 2.2, 3.5, 4.0]) * 1e-4
    p = np.array([0.3, 1.0, 1.6, 1.2, 1.4, 0.5, 0.2]) * 1e9
    q = np.array([-0.1, 0.05, 0.2, 0.3, -0.2, 0.1, 0.05]) * 1e9
    points = [(1.1e-4, 4e-7), (1.5e-4, 4e-7), (0.35e-4, 2e-5), (2.1e-4, 1e-4), (-1e-4, 3e-5), (5e-4, 2e-4)]
    x = np.array([pt[0] for pt in points])
    z = np.array([pt[1] for pt in points])
    field = slice_stresses(s, p, q, x, z)
    for i, (xi, zi) in enumerate(points):
        expected = _johnson_quadrature(s, p, q, xi, zi)
        got = (field.sigma_x[i], field.sigma_z[i], field.tau_xz[i])
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9 * 1.6e9, err_msg=str((xi, zi)))


def test_surface_values_are_the_applied_loads():
    """At z = 0: sigma_z = -p and tau_xz = -q (boundary conditions), at nodes and between them."""
    s = np.array([-1.0, -0.4, 0.1, 0.5, 1.0]) * 1e-4
    p = np.array([0.0, 1.0, 2.0, 0.5, 0.0]) * 1e9
    q = np.array([0.0, -0.3, 0.4, 0.2, 0.0]) * 1e9
    x = np.array([-0.4, -0.2, 0.1, 0.3, 0.7, 1.5]) * 1e-4
    field = slice_stresses(s, p, q, x, np.zeros_like(x))
    np.testing.assert_allclose(field.sigma_z, -np.interp(x, s, p, left=0, right=0), rtol=0, atol=1e-6 * 2e9)
    np.testing.assert_allclose(field.tau_xz, -np.interp(x, s, q, left=0, right=0), rtol=0, atol=1e-6 * 2e9)


def test_surface_of_hertz_strip_with_traction_matches_mcewen():
    """Surface sigma_x under q = 0.3 p (the traction's Hilbert transform) vs McEwen, inside the strip."""
    s, p, q = semi_elliptical_load(B, P0, traction_coefficient=0.3, nodes=401)
    x = np.linspace(-0.9 * B, 0.9 * B, 19)
    field = slice_stresses(s, p, q, x, 0.0)
    exact = line_contact_stresses(x, np.zeros_like(x), B, P0, friction=0.3)
    np.testing.assert_allclose(field.sigma_x, exact["sigma_x"], rtol=0, atol=1e-4 * P0)


def test_classical_line_contact_extremes():
    """Frictionless Hertz strip: Mohr shear 0.300 p0 at 0.786 b under the centre; orthogonal shear
    0.250 p0 at 0.5 b, x = +-0.866 b, range 0.500 p0 (Johnson 1985 §4.2). Tolerance: half a unit of
    the quoted last digit plus the 201-node interpolation error (< 1e-4 p0)."""
    s, p, q = semi_elliptical_load(B, P0, nodes=201)
    result = slice_extrema(s, p, q)
    mohr, orthogonal = result["max_shear"], result["orthogonal"]
    assert mohr.tau0 / P0 == pytest.approx(0.300, abs=6e-4)
    assert mohr.z0 / B == pytest.approx(0.786, abs=1e-3)
    assert mohr.x0 / B == pytest.approx(0.0, abs=1e-3)
    assert orthogonal.tau0 / P0 == pytest.approx(0.250, abs=6e-4)
    assert orthogonal.z0 / B == pytest.approx(0.5, abs=1e-3)
    assert abs(orthogonal.x0) / B == pytest.approx(math.sqrt(3) / 2, abs=1e-3)
    assert orthogonal.orthogonal_range / P0 == pytest.approx(0.500, abs=1e-3)
    assert orthogonal.x_tau_xz_max == pytest.approx(-orthogonal.x_tau_xz_min, abs=1e-3 * B)


@pytest.mark.parametrize("mu", [0.1, 0.3])
def test_extrema_with_traction_match_closed_form_search(mu):
    """Extremum finder vs line_subsurface (McEwen field, independent search): tau0 to 1e-4 p0,
    positions to 2e-3 b; the orthogonal range equals tau_xz,max - tau_xz,min of McEwen's field at
    the depth of the largest |tau_xz| to 2e-4 p0."""
    s, p, q = semi_elliptical_load(B, P0, traction_coefficient=mu, nodes=201)
    result = slice_extrema(s, p, q)
    closed = line_subsurface(B, P0, friction=mu)
    mohr = result["max_shear"]
    assert mohr.tau0 == pytest.approx(closed.principal_shear_max.value, abs=1e-4 * P0)
    assert mohr.z0 == pytest.approx(closed.principal_shear_max.z, abs=2e-3 * B)
    assert mohr.x0 == pytest.approx(closed.principal_shear_max.x, abs=2e-3 * B)
    orthogonal = result["orthogonal"]
    # with traction in +x the largest |tau_xz| is the negative lobe (McEwen)
    assert orthogonal.tau0 == pytest.approx(-closed.tau_xz_min.value, abs=1e-4 * P0)
    assert orthogonal.z0 == pytest.approx(closed.tau_xz_min.z, abs=2e-3 * B)
    line_x = np.linspace(-2 * B, 2 * B, 40001)
    tau_line = line_contact_stresses(line_x, np.full_like(line_x, orthogonal.z0), B, P0, friction=mu)["tau_xz"]
    assert orthogonal.orthogonal_range == pytest.approx(tau_line.max() - tau_line.min(), abs=2e-4 * P0)


def test_mohr_shear_uses_the_difference_of_normal_stresses():
    """Saccheto Eq. 3.71 prints (sx + sz)/2; at the surface centre of a frictionless Hertz strip
    sx = sz = -p0 (hydrostatic in the plane), so the correct Mohr shear is 0, the printed one p0."""
    s, p, q = semi_elliptical_load(B, P0, nodes=201)
    field = slice_stresses(s, p, None, 0.0, 0.0)
    assert float(field.sigma_x) == pytest.approx(-P0, rel=1e-9)
    assert float(field.sigma_z) == pytest.approx(-P0, rel=1e-9)
    assert float(field.max_shear) == pytest.approx(0.0, abs=1e-9 * P0)
    printed = math.hypot(0.5 * (float(field.sigma_x) + float(field.sigma_z)), float(field.tau_xz))
    assert printed == pytest.approx(P0, rel=1e-9)


def test_scale_and_shift_invariance():
    """Line-load kernels are homogeneous of degree -1: scaling all lengths by 1e3 and shifting
    the origin leaves the stresses unchanged (to rounding)."""
    s, p, q = semi_elliptical_load(1.0, P0, traction_coefficient=0.2, nodes=101)
    X, Z = _grid(-2, 2, 13, 0, 1.5, 7)
    small = slice_stresses(s, p, q, X, Z)
    big = slice_stresses(1e3 * s + 7.0, p, q, 1e3 * X + 7.0, 1e3 * Z)
    for key in ("sigma_x", "sigma_z", "tau_xz"):
        np.testing.assert_allclose(getattr(big, key), getattr(small, key), rtol=0, atol=1e-10 * P0)


def test_superposition_of_pressure_and_traction():
    """The field of (p, q) is the field of p plus the field of q (linearity)."""
    s, p, q = semi_elliptical_load(B, P0, traction_coefficient=0.3, nodes=41)
    X, Z = _grid(-2 * B, 2 * B, 9, 0, B, 5)
    both = slice_stresses(s, p, q, X, Z)
    normal = slice_stresses(s, p, None, X, Z)
    tangential = slice_stresses(s, np.zeros_like(p), q, X, Z)
    for key in ("sigma_x", "sigma_z", "tau_xz"):
        np.testing.assert_allclose(getattr(both, key), getattr(normal, key) + getattr(tangential, key),
                                   rtol=0, atol=1e-12 * P0)


def test_compiled_kernel_equals_python_twin():
    """numba kernel vs its plain-Python twin, on a small case with end steps and surface points."""
    s = np.array([0.0, 0.3, 0.5, 1.0, 1.4]) * 1e-4
    p = np.array([0.2, 1.0, 1.3, 0.7, 0.1]) * 1e9
    q = np.array([0.05, -0.1, 0.2, 0.1, 0.0]) * 1e9
    X, Z = _grid(-0.5e-4, 2e-4, 11, 0.0, 1e-4, 5)
    x, z = np.ascontiguousarray(X.ravel()), np.ascontiguousarray(Z.ravel())
    outputs = []
    for kernel in (_slice_kernels.PY["slice_field"], _slice_kernels.compiled("slice_field")):
        out = [np.empty(x.size) for _ in range(3)]
        kernel(s, p, q, x, z, *out)
        outputs.append(out)
    for python, compiled in zip(*outputs):
        np.testing.assert_allclose(compiled, python, rtol=1e-12, atol=1e-12 * 1.3e9)
    twin = slice_stresses(s, p, q, X, Z, compiled=False)
    assert isinstance(twin, SliceStress) and twin.sigma_x.shape == X.shape


def test_extremum_twin_equals_compiled():
    """The extremum search gives the same answer on the twin and the compiled kernel (coarse grid)."""
    s, p, q = semi_elliptical_load(B, P0, traction_coefficient=0.2, nodes=15)
    axes = {"x": np.linspace(-1.5 * B, 1.5 * B, 13), "z": np.linspace(0.0, 1.2 * B, 9)}
    for measure in ("max_shear", "orthogonal"):
        twin = slice_extremum(s, p, q, measure=measure, refine=False, compiled=False, **axes)
        fast = slice_extremum(s, p, q, measure=measure, refine=False, compiled=True, **axes)
        assert fast.tau0 == pytest.approx(twin.tau0, rel=1e-12)
        assert (fast.x0, fast.z0) == (twin.x0, twin.z0)
        assert fast.orthogonal_range == pytest.approx(twin.orthogonal_range, rel=1e-12)


@pytest.mark.parametrize(
    ("arguments", "fragment"),
    [
        (dict(s=[0.0, 1.0, 1.0], p=[0, 1, 0]), "increase strictly"),
        (dict(s=[0.0, 2.0, 1.0], p=[0, 1, 0]), "increase strictly"),
        (dict(s=[0.0], p=[1.0]), "at least 2 nodes"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, 1]), "pressure p has 2 values"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, -1.0, 0]), "pressure p[1] = -1.0"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, float("nan"), 0]), "pressure p[1] = nan"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, 1, 0], q=[0, 1]), "traction q has 2 values"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, 1, 0], z=-0.1), "depth z = -0.1"),
        (dict(s=[0.0, 1.0, 2.0], p=[0, 1, 0], x=float("inf")), "field point x = inf"),
        (dict(s=[[0.0, 1.0]], p=[0, 1]), "must be 1-D"),
    ],
)
def test_bad_input_is_named(arguments, fragment):
    call = {"q": None, "x": 0.5, "z": 0.5, **arguments}
    with pytest.raises(InputError, match=fragment.replace("[", r"\[").replace("]", r"\]")):
        slice_stresses(call["s"], call["p"], call["q"], call["x"], call["z"])


def test_bad_extremum_and_load_arguments_are_named():
    s, p, q = semi_elliptical_load(B, P0, nodes=11)
    with pytest.raises(InputError, match="measure = 'tresca'"):
        slice_extremum(s, p, q, measure="tresca")
    with pytest.raises(InputError, match="search grid z"):
        slice_extremum(s, p, q, z=[0.0, 1.0])
    with pytest.raises(InputError, match="half_width = -1"):
        semi_elliptical_load(-1.0, P0)
    with pytest.raises(InputError, match="spacing = 'log'"):
        semi_elliptical_load(B, P0, spacing="log")
    with pytest.raises(InputError, match="nodes = 2"):
        semi_elliptical_load(B, P0, nodes=2)
