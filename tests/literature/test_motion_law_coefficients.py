"""Motion-law peak coefficients and the Tsuha (2015) LS-1 program against published values.

Peak coefficients are max|y'|, max|y''|, max|y'''| of the unit-lift law on x in [0, 1]
(in L/β, L/β², L/β³ units), as tabulated by Rothbart (2004) *Cam Design Handbook* ch. 3 and
Norton (2009) *Cam Design and Manufacturing Handbook*.
"""

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from camcontact import registry
from camcontact.kinematics.motion_program import MotionProgram, peak_coefficients

PI = math.pi

PEAKS = [
    # name, (velocity, acceleration, jerk), relative tolerance, source / derivation
    # cycloid: y' = 1 − cos 2πx, y'' = 2π sin 2πx, y''' = 4π² cos 2πx (exact)
    ("cycloidal", (2.0, 2 * PI, 4 * PI**2), 1e-9),
    # harmonic: y' = (π/2) sin πx, y'' = (π²/2) cos πx, y''' = −(π³/2) sin πx (exact)
    ("harmonic", (PI / 2, PI**2 / 2, PI**3 / 2), 1e-9),
    # 3-4-5: y' = 30x²(1−x)² → 30/16 at x = 1/2; y'' = 60x(1−x)(1−2x), extreme where
    # y''' = 60(1 − 6x + 6x²) = 0, i.e. x(1−x) = 1/6, giving 10(1 − 2x) = 10/√3; y''' = 60 at x = 0, 1 (exact)
    ("polynomial_345", (1.875, 10 / math.sqrt(3), 60.0), 1e-9),
    # 4-5-6-7: y' = 140x³(1−x)³ → 140/64 = 2.1875 at x = 1/2; y'' = 420x²(1−x)²(1−2x) and
    # y''' = 840x(1−x)(1 − 5x + 5x²): y''' = 0 at x(1−x) = 1/5, where y'' = 16.8(1−2x) = 16.8/√5 = 7.5132;
    # with u = x(1−x), |y'''| = 840u|1 − 5u| is largest at u = 1/4 (x = 1/2): 52.5 (exact)
    ("polynomial_4567", (2.1875, 16.8 / math.sqrt(5), 52.5), 1e-9),
]

# handbook values, printed to 3–4 significant digits (Rothbart 2004 ch. 3; Norton 2009)
HANDBOOK_PEAKS = [
    ("modified_trapezoid", (2.0, 4.888, 61.43)),
    ("modified_sine", (1.76, 5.528, 69.47)),
]


@pytest.mark.parametrize("name, expected, rtol", PEAKS)
def test_peak_coefficients_exact(name, expected, rtol):
    np.testing.assert_allclose(peak_coefficients(name), expected, rtol=rtol)


@pytest.mark.parametrize("name, expected", HANDBOOK_PEAKS)
def test_peak_coefficients_handbook(name, expected):
    """Tolerance: half a unit of the last printed digit (1.76 → ±0.005, 4.888 → ±0.0005, 61.43 → ±0.005)."""
    velocity, acceleration, jerk = peak_coefficients(name)
    assert velocity == pytest.approx(expected[0], abs=0.005 if name == "modified_sine" else 1e-9)
    assert acceleration == pytest.approx(expected[1], abs=0.0005)
    assert jerk == pytest.approx(expected[2], abs=0.005)


def test_modified_laws_closed_forms():
    """C_a = 8π/(π+2) (trapezoid) and 4π²/(π+4) (sine); jerk 4π C_a; sine velocity 4π/(π+4)."""
    np.testing.assert_allclose(peak_coefficients("modified_trapezoid"),
                               (2.0, 8 * PI / (PI + 2), 32 * PI**2 / (PI + 2)), rtol=1e-9)
    np.testing.assert_allclose(peak_coefficients("modified_sine"),
                               (4 * PI / (PI + 4), 4 * PI**2 / (PI + 4), 16 * PI**3 / (PI + 4)), rtol=1e-9)


def test_p1_p2_boundary_conditions():
    """Tsuha (2015) reference §8 item 1: P-1 y(0)=y'(0)=y''(0)=0; y(1)=1, y'(1)=0, y''(1)=−5.268,
    y'''(1)=0; P-2(x) = P-1(1−x). Tolerance: y''(1) to the printed digits (±5e-4), the rest 1e-9."""
    p1, p2 = registry.get("motion_laws", "P-1"), registry.get("motion_laws", "P-2")
    y, d1, d2, d3 = (np.asarray(v) for v in p1.derivatives(np.array([0.0, 1.0])))
    np.testing.assert_allclose([y[0], d1[0], d2[0]], 0.0, atol=1e-12)
    assert y[1] == pytest.approx(1.0, abs=1e-9) and d1[1] == pytest.approx(0.0, abs=1e-9)
    assert d2[1] == pytest.approx(-5.268, abs=5e-4)
    assert d3[1] == pytest.approx(0.0, abs=1e-9)
    assert d3[0] == pytest.approx(36.585, abs=5e-4)  # reference §2.1: jerk jump 36.585 L/β³
    x = np.linspace(0, 1, 41)
    np.testing.assert_allclose(p2.derivatives(x)[0], p1.derivatives(1 - x)[0], atol=1e-12)


def _extreme(program, order, low_deg, high_deg, sign):
    """Angle [deg] and value of the extreme of f^(order) (sign +1 max, −1 min) in [low, high] degrees."""
    result = minimize_scalar(lambda t: -sign * float(program.evaluate(t)[order]),
                             bounds=(math.radians(low_deg), math.radians(high_deg)), method="bounded",
                             options={"xatol": 1e-10})
    return math.degrees(result.x), float(program.evaluate(result.x)[order])


def test_ls1_extremes():
    """Tsuha (2015) reference §2.1 [DERIVED] (L = 20 mm, β = π/2): max f' = 0.022621 m/rad at 47.94°,
    min f' = −0.022621 at 132.06°, max f'' = 0.042703 m/rad² at 21.75° and 158.25°,
    f''(90°) = −0.042703 m/rad². Tolerance: half a unit of the last printed digit."""
    program = MotionProgram.thesis_ls1()
    angle, value = _extreme(program, 1, 10, 80, +1)
    assert value == pytest.approx(0.022621, abs=5e-7) and angle == pytest.approx(47.94, abs=0.005)
    angle, value = _extreme(program, 1, 100, 170, -1)
    assert value == pytest.approx(-0.022621, abs=5e-7) and angle == pytest.approx(132.06, abs=0.005)
    for low, high, where in ((5, 60, 21.75), (120, 175, 158.25)):
        angle, value = _extreme(program, 2, low, high, +1)
        assert value == pytest.approx(0.042703, abs=5e-7) and angle == pytest.approx(where, abs=0.005)
    assert float(program.evaluate(PI / 2)[2]) == pytest.approx(-0.042703, abs=5e-7)
    f = program.evaluate(np.linspace(0, 2 * PI, 3601))[2]
    assert f.min() == pytest.approx(-0.042703, abs=5e-7)  # the minimum is at 90°


def test_ls1_jerk_jumps_and_c2_at_the_nose():
    """Reference §2.1: jerk jumps by 36.585 L/β³ = 0.18879 m/rad³ at 0° and 180°; C² with continuous
    jerk at 90° (y' = 0, y'' = −5.268 L/β², y''' = 0 on both sides)."""
    table = MotionProgram.thesis_ls1().continuity().set_index("angle [deg]")
    jerk = table["jump f''' [m/rad^3]"]
    assert abs(jerk[0.0]) == pytest.approx(0.18879, abs=5e-6)
    assert abs(jerk[180.0]) == pytest.approx(0.18879, abs=5e-6)
    assert table.loc[90.0, "C2"] and table.loc[90.0, "jerk_continuous"]
    assert table["C2"].all()
