"""FASTSIM kernel, forward and inverse API and the traction models: twins, limits, bad input.

Contact inputs below (a = 1 mm, b = 0.5 mm, N = 1 kN, mu = 0.1) are arbitrary illustrative values,
not taken from a source; G = 207 GPa / (2 (1 + 0.3)) is the steel of Saccheto (2008) (reference
§4.6: E ~ 207 GPa, nu = 0.3 implied). Every expected value is derived in the test.
"""

import math
import re

import numpy as np
import pytest

from camcontact import registry
from camcontact.contact import _fastsim_kernels
from camcontact.contact.fastsim import GrossSlipError, fastsim, solve_creepage
from camcontact.contact.kalker import creepage_coefficients, flexibility_parameters
from camcontact.errors import InputError
from camcontact.models.traction import TRACTION_FLUIDS, ConstantTraction, Fastsim

A, B, N, MU = 1.0e-3, 0.5e-3, 1000.0, 0.1
G = 207e9 / (2 * 1.3)
C11, C22, C23 = creepage_coefficients(B / A)
#: creepage at which Kalker's linear Fx would reach mu N (the natural creepage scale)
NU_REF = MU * N / (C11 * G * A * B)
#: spin creepage at which the linear spin Fy would reach mu N
PHI_REF = MU * N / (C23 * G * (A * B) ** 1.5)

CASES = {
    "stick": (1e-3 * NU_REF, 0.0, 0.0),
    "mixed": (0.4 * NU_REF, -0.3 * NU_REF, 0.5 * PHI_REF),
    "spin": (0.0, 0.0, 2.0 * PHI_REF),
    "gross": (50 * NU_REF, 10 * NU_REF, 3 * PHI_REF),
}


# ----------------------------------------------------------------- twin vs compiled
@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("grid", [(7, 5), (24, 31)])
@pytest.mark.parametrize("pressure", ["parabolic", "hertz"])
def test_compiled_kernel_equals_its_python_twin(case, grid, pressure):
    """(d) The numba kernel and the plain-Python twin agree to 1e-12 (same operations), with either
    pressure of the traction bound."""
    nx, ny = grid
    python = fastsim(A, B, N, MU, G, *CASES[case], nx=nx, ny=ny, compiled=False, pressure=pressure)
    numba = fastsim(A, B, N, MU, G, *CASES[case], nx=nx, ny=ny, compiled=True, pressure=pressure)
    assert numba.pressure == python.pressure == pressure
    for name in ("Fx", "Fy", "Mz", "slip_fraction"):
        assert getattr(numba, name) == pytest.approx(getattr(python, name), rel=1e-12, abs=1e-12 * MU * N)
    for name in ("Tx", "Ty", "p", "x"):
        np.testing.assert_allclose(getattr(numba, name), getattr(python, name), rtol=1e-12, atol=1e-12 * 1e9)
    np.testing.assert_array_equal(numba.stick, python.stick)


def test_kernel_table_and_lazy_compilation():
    """``compiled(name)`` returns the same compiled object each time; the twin is plain Python."""
    assert _fastsim_kernels.PY["fastsim_strips"] is _fastsim_kernels.fastsim_strips
    assert _fastsim_kernels.compiled("fastsim_strips") is _fastsim_kernels.compiled("fastsim_strips")


# ----------------------------------------------------------------- degenerate inputs stay finite
def _finite(result):
    fields = [result.Fx, result.Fy, result.Mz, result.slip_fraction, result.traction_ratio]
    return all(math.isfinite(v) for v in fields) and all(
        np.all(np.isfinite(getattr(result, k))) for k in ("Tx", "Ty", "p"))


@pytest.mark.parametrize("compiled", [True, False])
def test_zero_creepage_gives_exactly_zero_force(compiled):
    """(c) No creepage, no spin: the predictor stays 0, every element sticks, F = 0 exactly."""
    result = fastsim(A, B, N, MU, G, nx=12, ny=9, compiled=compiled)
    assert (result.Fx, result.Fy, result.Mz, result.slip_fraction) == (0.0, 0.0, 0.0, 0.0)
    assert result.full_stick and not result.full_slip and result.traction_ratio == 0.0


def test_pure_spin_is_finite_and_symmetric():
    """(c) Pure spin: finite; Fx = 0 by the y -> -y symmetry of the spin traction (Tx odd in y);
    Fy and Mz oppose the spin (Fy = -C23 G (ab)^1.5 phi in the linear limit)."""
    for phi in (1e-3 * PHI_REF, PHI_REF, 1e3 * PHI_REF):
        result = fastsim(A, B, N, MU, G, spin=phi)
        assert _finite(result)
        assert abs(result.Fx) <= 1e-12 * MU * N
        assert result.Fy < 0.0 and result.Mz < 0.0
        assert result.traction_ratio <= 1.0 + 1e-12
    reverse = fastsim(A, B, N, MU, G, spin=-PHI_REF)
    assert reverse.Fy == pytest.approx(-fastsim(A, B, N, MU, G, spin=PHI_REF).Fy, rel=1e-12)


def test_zero_load_and_zero_friction_stay_finite():
    """(c) N = 0 and mu = 0: the bound mu p is 0, every creeping element slips with T = 0."""
    for kwargs in ({"normal_force": 0.0, "mu": MU}, {"normal_force": N, "mu": 0.0}):
        result = fastsim(A, B, kwargs["normal_force"], kwargs["mu"], G, 0.3 * NU_REF, 0.1 * NU_REF, PHI_REF)
        assert _finite(result)
        assert (result.Fx, result.Fy, result.Mz) == (0.0, 0.0, 0.0)
        assert result.full_slip and result.slip_fraction == 1.0 and result.traction_ratio == 0.0


def test_force_is_odd_in_the_creepages():
    """Reversing every creepage and the spin reverses the forces and the moment (T -> -T)."""
    plus = fastsim(A, B, N, MU, G, *CASES["mixed"])
    minus = fastsim(A, B, N, MU, G, *(-c for c in CASES["mixed"]))
    assert (minus.Fx, minus.Fy, minus.Mz) == pytest.approx((-plus.Fx, -plus.Fy, -plus.Mz), rel=1e-12)


@pytest.mark.parametrize("pressure", ["parabolic", "hertz"])
def test_pressure_carries_the_load_and_grid_shapes(pressure):
    """The sampled pressure (Kalker's parabolic or Hertz) is normalised to carry N exactly; grid
    shapes are (ny, nx)."""
    result = fastsim(A, B, N, MU, G, 0.2 * NU_REF, nx=11, ny=7, pressure=pressure)
    assert result.Tx.shape == result.p.shape == result.stick.shape == result.x.shape == (7, 11)
    assert result.y.shape == result.dx.shape == (7,)
    area = result.dx[:, None] * result.dy
    assert float(np.sum(result.p * area)) == pytest.approx(N, rel=1e-13)
    # element centres inside the ellipse, strips symmetric about y = 0
    assert np.all(result.x**2 / A**2 + result.y[:, None] ** 2 / B**2 < 1.0)
    np.testing.assert_allclose(result.y, -result.y[::-1], atol=1e-18)
    # the traction never exceeds the Coulomb bound
    assert np.all(np.hypot(result.Tx, result.Ty) <= MU * result.p * (1 + 1e-12))


def test_user_coefficients_override_the_table():
    """``coefficients=`` bypasses Tabela 5.1, also outside its b/a range."""
    result = fastsim(A, 20 * A, N, MU, G, 1e-3 * NU_REF, coefficients=(3.0, 2.5, 0.4))
    assert result.L1 == pytest.approx(8 * A / (3 * 3.0 * G), rel=1e-14)
    # default: the table's coefficients at b/a, L = 8a/(3 C G), pi a sqrt(a/b)/(4 C23 G)
    assert flexibility_parameters(A, B, G) == pytest.approx(
        (8 * A / (3 * C11 * G), 8 * A / (3 * C22 * G), math.pi * A * math.sqrt(A / B) / (4 * C23 * G)), rel=1e-14)


# ----------------------------------------------------------------- inverse problem
@pytest.mark.parametrize("fraction", [1e-4, 0.3, 0.9, 0.999])
@pytest.mark.parametrize("spin", [0.0, 0.7 * PHI_REF])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_solve_creepage_reproduces_the_required_force(fraction, spin, sign):
    """(e) brentq on a doubling bracket: the force found equals the required one to 1e-9 relative;
    the creepage has the opposite sign of the force (force on the body opposes the creepage)."""
    required = sign * fraction * MU * N
    solution = solve_creepage(required, A, B, N, MU, G, spin=spin)
    assert solution.converged
    assert solution.result.Fx == pytest.approx(required, rel=1e-9)
    assert abs(solution.force_error) <= 1e-9 * abs(required)
    assert np.sign(solution.creepage) == -sign
    low, high = solution.bracket
    assert low <= solution.creepage <= high
    assert len(solution.evaluations) >= 2 and all(map(math.isfinite, np.ravel(solution.evaluations)))


def test_solve_creepage_lateral_direction_with_spin():
    """direction="y" solves nu_y for Fy with the spin and nu_x held fixed."""
    required = -0.4 * MU * N
    solution = solve_creepage(required, A, B, N, MU, G, spin=0.3 * PHI_REF, direction="y",
                              other_creepage=0.1 * NU_REF)
    assert solution.result.Fy == pytest.approx(required, rel=1e-9)
    assert solution.result.creepage_x == 0.1 * NU_REF and solution.result.creepage_y == solution.creepage


def test_solve_creepage_zero_force_without_spin_is_zero_creepage():
    """The linear guess -F/(C11 G a b) = 0 is already exact."""
    solution = solve_creepage(0.0, A, B, N, MU, G)
    assert solution.creepage == 0.0 and solution.iterations == 0 and solution.result.Fx == 0.0


@pytest.mark.parametrize("ratio", [1.0, 1.5])
def test_force_at_or_above_the_traction_limit_is_gross_slip(ratio):
    """(e) |F| >= mu N: no creepage transmits it; GrossSlipError (an InputError), never NaN."""
    with pytest.raises(GrossSlipError, match="gross slip") as caught:
        solve_creepage(ratio * MU * N, A, B, N, MU, G, spin=PHI_REF)
    assert isinstance(caught.value, InputError)
    assert caught.value.limit == pytest.approx(MU * N)
    assert caught.value.traction_needed == pytest.approx(ratio * MU)
    with pytest.raises(GrossSlipError):
        solve_creepage(1.0, A, B, 0.0, MU, G)  # no load transmits nothing


# ----------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, name", [
    ({"a": 0.0}, "a"), ({"b": -1e-3}, "b"), ({"normal_force": -1.0}, "normal_force"),
    ({"mu": float("nan")}, "mu"), ({"shear_modulus": 0.0}, "shear_modulus"),
    ({"creepage_x": float("inf")}, "creepage_x"), ({"creepage_y": "x"}, "creepage_y"),
    ({"spin": float("nan")}, "spin"), ({"nx": 0}, "nx"), ({"ny": 2.5}, "ny"), ({"nx": True}, "nx"),
    ({"b": 0.05e-3}, "b/a"), ({"b": 11e-3}, "b/a"), ({"coefficients": (1.0, 2.0)}, "coefficients"),
    ({"coefficients": (1.0, -2.0, 1.0)}, "C22"),
])
def test_bad_input_is_named(kwargs, name):
    """(g) Each bad argument raises InputError naming it (and the value)."""
    arguments = {"a": A, "b": B, "normal_force": N, "mu": MU, "shear_modulus": G, **kwargs}
    with pytest.raises(InputError, match=re.escape(name) + " = "):
        fastsim(**arguments)


def test_bad_solve_creepage_input_is_named():
    with pytest.raises(InputError, match="direction"):
        solve_creepage(1.0, A, B, N, MU, G, direction="z")
    with pytest.raises(InputError, match="required_force"):
        solve_creepage(float("nan"), A, B, N, MU, G)
    with pytest.raises(InputError, match="other_creepage"):
        solve_creepage(1.0, A, B, N, MU, G, other_creepage=float("inf"))


def test_kalker_range_error_names_b_over_a_and_range():
    with pytest.raises(InputError, match=r"b/a = 12.0.*0.1 <= b/a <= 10"):
        creepage_coefficients(12.0)


# ----------------------------------------------------------------- traction models
def test_fastsim_model_broadcasts_and_handles_no_load():
    """The model runs FASTSIM per point; N = 0 (contact open, a = b = 0) gives zeros."""
    model = Fastsim(nx=20, ny=20)
    out = model.evaluate(normal_force=np.array([N, 0.0]), a_rolling=np.array([A, 0.0]),
                         b_lateral=np.array([B, 0.0]), traction_coefficient=MU, shear_modulus=G,
                         creepage_x=1e-3 * NU_REF, creepage_y=0.0, spin_creepage=0.0)
    direct = fastsim(A, B, N, MU, G, 1e-3 * NU_REF, nx=20, ny=20)
    assert out["creep_force_x"][0] == direct.Fx and out["creep_force_x"][1] == 0.0
    assert model.pressure == "parabolic" and direct.pressure == "parabolic"  # Kalker's FASTSIM by default
    assert set(out) == set(Fastsim.provides)
    assert all(np.all(np.isfinite(v)) for v in out.values())
    scalar = model({"normal_force": N, "a_rolling": A, "b_lateral": B, "traction_coefficient": MU,
                    "shear_modulus": G, "creepage_x": 50 * NU_REF, "creepage_y": 0.0, "spin_creepage": 0.0})
    assert scalar["traction_ratio"] == pytest.approx(1.0, rel=1e-12) and scalar["slip_fraction"] == 1.0
    with pytest.raises(InputError, match="nx"):
        Fastsim(nx=0)


def test_constant_traction_model_and_fluid_table():
    """Saccheto (2008) Tabela 4.2: Santotrac 50 Ct = 0.095; Tabela 4.3: naphthenic 0.058-0.065."""
    model = ConstantTraction.for_fluid("santotrac_50")
    assert model.coefficient == 0.095
    out = model.evaluate(normal_force=np.array([0.0, 100.0]))
    np.testing.assert_allclose(out["traction_limit"], [0.0, 9.5])
    assert ConstantTraction.for_fluid("naphthenic").coefficient == 0.058  # lower end of the range
    assert TRACTION_FLUIDS["santotrac_40_50_70"].low == 0.100  # the other table's Santotrac 50 value
    with pytest.raises(InputError, match="fluid = 'castor'"):
        ConstantTraction.for_fluid("castor")
    with pytest.raises(InputError, match="coefficient"):
        ConstantTraction(coefficient=1.5)


def test_models_are_registered_builtins(clean_registry, monkeypatch):
    monkeypatch.setenv(registry.DISABLE_ENV, "1")
    assert isinstance(registry.get("traction_models", "fastsim"), Fastsim)
    assert registry.get("traction_models", "constant", coefficient=0.08813).coefficient == 0.08813
