"""Stresses below the centre of an elliptical Hertz contact (camcontact.contact.subsurface_point).

Independent checks: the circle's closed form on the axis (Johnson 1985 Eq. 3.45), Johnson's printed maximum
shear 0.31 p0 at 0.48 a (nu = 0.3, §3.4), the line-contact limit of a long ellipse against the plane-strain
field of :func:`camcontact.contact.subsurface.line_subsurface` (another code: McEwen's closed form), and the
symmetry of the two semi-axes.
"""

import numpy as np
import pytest

from camcontact.contact.subsurface import line_subsurface
from camcontact.contact.subsurface_point import point_axis_stresses, point_subsurface
from camcontact.errors import InputError

A = 1e-4


def test_circle_against_johnsons_closed_form():
    """sigma_r = sigma_t = p0 [-(1 + nu)(1 - (z/a) atan(a/z)) + 1/(2 (1 + z^2/a^2))], sigma_z = -p0/(1 + z^2/a^2)."""
    nu = 0.3
    z = np.array([0.02, 0.1, 0.48, 1.0, 2.5, 10.0]) * A
    sx, sy, sz = point_axis_stresses(z, A, A, 1.0, nu)
    zeta = z / A
    sr = -(1 + nu) * (1 - zeta * np.arctan(1 / zeta)) + 0.5 / (1 + zeta**2)
    np.testing.assert_allclose(sx, sr, atol=1e-10)
    np.testing.assert_allclose(sy, sr, atol=1e-10)
    np.testing.assert_allclose(sz, -1 / (1 + zeta**2), atol=1e-10)
    found = point_subsurface(A, A, 1.0, nu)
    assert found.tresca_max == pytest.approx(0.31, abs=0.005)  # Johnson §3.4: 0.31 p0 at z = 0.48 a
    assert found.z_tresca_max / A == pytest.approx(0.48, abs=0.005)


@pytest.mark.parametrize("nu", [0.25, 0.3])
def test_long_ellipse_tends_to_the_line_contact(nu):
    """a_x = 1000 a_y: Tresca and von Mises maxima and depths within 0.3 % of the plane-strain line contact
    of half-width a_y (the shear converges as the ellipse lengthens: 0.324, 0.314, 0.302 p_h at ratios 2, 10, 100)."""
    line = line_subsurface(A, 1.0, nu=nu)
    long = point_subsurface(1000 * A, A, 1.0, nu)
    assert long.tresca_max == pytest.approx(line.tresca_max.value, rel=3e-3)
    assert long.z_tresca_max == pytest.approx(line.tresca_max.z, rel=3e-3)
    assert long.von_mises_max == pytest.approx(line.von_mises_max.value, rel=3e-3)
    assert long.z_von_mises_max == pytest.approx(line.von_mises_max.z, rel=5e-3)
    shears = [point_subsurface(k * A, A, 1.0, nu).tresca_max for k in (2, 10, 100)]
    assert shears[0] > shears[1] > shears[2] > long.tresca_max


def test_the_semi_axes_are_interchangeable_and_bad_input_is_named():
    one, other = point_subsurface(3 * A, A, 2e9, 0.3), point_subsurface(A, 3 * A, 2e9, 0.3)
    assert one.tresca_max == pytest.approx(other.tresca_max, rel=1e-12)
    assert one.z_tresca_max == pytest.approx(other.z_tresca_max, rel=1e-9)
    with pytest.raises(InputError, match="depths > 0"):
        point_axis_stresses([0.0], A, A, 1.0)
    with pytest.raises(InputError, match="a_y = -0.001 m"):
        point_axis_stresses([A], A, -1e-3, 1.0)
    with pytest.raises(InputError, match="nu = 0.5"):
        point_axis_stresses([A], A, A, 1.0, nu=0.5)
