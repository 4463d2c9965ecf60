"""Motion laws (family ``motion_laws``) and the motion-program composer.

Derivatives are checked against central finite differences of y alone, and the laws against
formulas written out independently below (Tsuha 2015 reference §2.1 table for the C/H/P series).
"""

import math

import numpy as np
import pytest

from camcontact import Q_, registry
from camcontact.errors import InputError, UnknownModelError
from camcontact.kinematics.motion_program import (
    MotionContinuityWarning,
    MotionProgram,
    Segment,
    peak_coefficients,
)
from camcontact.models.base import MotionLaw

PI = math.pi
RISE_LAWS = ["cycloidal", "harmonic", "polynomial_345", "polynomial_4567", "modified_trapezoid", "modified_sine",
             "C-1", "C-2", "C-5", "H-1", "H-2", "H-5", "P-1"]
RETURN_LAWS = ["C-3", "C-4", "C-6", "H-3", "H-4", "H-6", "P-2"]
ALL_LAWS = RISE_LAWS + RETURN_LAWS

# y(x) written out independently of the implementation (reference §2.1 table; handbook polynomials)
FORMULAS = {
    "cycloidal": lambda x: x - np.sin(2 * PI * x) / (2 * PI),
    "harmonic": lambda x: 0.5 * (1 - np.cos(PI * x)),
    "polynomial_345": lambda x: 10 * x**3 - 15 * x**4 + 6 * x**5,
    "polynomial_4567": lambda x: 35 * x**4 - 84 * x**5 + 70 * x**6 - 20 * x**7,
    "C-1": lambda x: x - np.sin(PI * x) / PI,
    "C-2": lambda x: x + np.sin(PI * x) / PI,
    "C-3": lambda x: 1 - x + np.sin(PI * x) / PI,
    "C-4": lambda x: 1 - x - np.sin(PI * x) / PI,
    "C-5": lambda x: x - np.sin(2 * PI * x) / (2 * PI),
    "C-6": lambda x: 1 - x + np.sin(2 * PI * x) / (2 * PI),
    "H-1": lambda x: 1 - np.cos(PI * x / 2),
    "H-2": lambda x: np.sin(PI * x / 2),
    "H-3": lambda x: np.cos(PI * x / 2),
    "H-4": lambda x: 1 - np.sin(PI * x / 2),
    "H-5": lambda x: 0.5 * (1 - np.cos(PI * x)),
    "H-6": lambda x: 0.5 * (1 + np.cos(PI * x)),
    "P-1": lambda x: 6.09755 * x**3 - 20.78040 * x**5 + 26.73155 * x**6 - 13.60965 * x**7 + 2.56095 * x**8,
}

# breaks of the piecewise laws (y'''' jumps there); finite differences keep away from them
BREAKS = np.array([1 / 8, 3 / 8, 5 / 8, 7 / 8])


def law(name):
    return registry.get("motion_laws", name)


def test_all_laws_are_registered_motion_laws():
    available = registry.available("motion_laws")
    for name in ALL_LAWS:
        assert name in available
        model = law(name)
        assert isinstance(model, MotionLaw) and model.family == "motion_laws"
        assert model.reference and model.validity == {"x": (0.0, 1.0)}
        assert model.direction == ("return" if name in RETURN_LAWS else "rise")
        assert model.__doc__ and ".. math::" in model.__doc__


@pytest.mark.parametrize("name", ALL_LAWS)
def test_boundary_values_and_direction(name):
    y, d1, _, _ = law(name).derivatives(np.array([0.0, 1.0]))
    expected = [0.0, 1.0] if name in RISE_LAWS else [1.0, 0.0]
    np.testing.assert_allclose(y, expected, atol=1e-12)
    assert np.all(np.diff(law(name).derivatives(np.linspace(0, 1, 201))[0]) * (1 if name in RISE_LAWS else -1) >= -1e-12)
    assert d1.dtype == float


@pytest.mark.parametrize("name", ALL_LAWS)
def test_derivatives_match_central_differences_of_y(name):
    model = law(name)
    x = np.linspace(0.03, 0.97, 48)
    x = x[np.min(np.abs(x[:, None] - BREAKS[None, :]), axis=1) > 0.01]
    y = lambda t: model.derivatives(t)[0]  # noqa: E731
    _, d1, d2, d3 = model.derivatives(x)
    h1, h2, h3 = 1e-5, 1e-4, 2e-3
    fd1 = (y(x + h1) - y(x - h1)) / (2 * h1)
    fd2 = (y(x + h2) - 2 * y(x) + y(x - h2)) / h2**2
    fd3 = (y(x + 2 * h3) - 2 * y(x + h3) + 2 * y(x - h3) - y(x - 2 * h3)) / (2 * h3**3)
    np.testing.assert_allclose(d1, fd1, atol=1e-8)
    np.testing.assert_allclose(d2, fd2, atol=2e-5 * max(1.0, np.abs(d2).max()))
    np.testing.assert_allclose(d3, fd3, atol=1e-3 * max(1.0, np.abs(d3).max()))


@pytest.mark.parametrize("name", sorted(FORMULAS))
def test_law_matches_written_out_formula(name):
    x = np.linspace(0, 1, 101)
    np.testing.assert_allclose(law(name).derivatives(x)[0], FORMULAS[name](x), atol=1e-13)


def test_p2_is_the_printed_expansion_and_p1_reversed():
    """Reference §2.1 table: P-2 = 1 − 2.63415x² + 2.78055x⁵ + 3.17060x⁶ − 6.87795x⁷ + 2.56095x⁸ = P-1(1−x)
    (coefficients printed to 5 decimals, so agreement to ~1e-5)."""
    x = np.linspace(0, 1, 101)
    printed = 1 - 2.63415 * x**2 + 2.78055 * x**5 + 3.17060 * x**6 - 6.87795 * x**7 + 2.56095 * x**8
    y2 = law("P-2").derivatives(x)
    y1 = law("P-1").derivatives(1 - x)
    np.testing.assert_allclose(y2[0], printed, atol=2e-5)
    for k in range(4):
        np.testing.assert_allclose(y2[k], (-1) ** k * y1[k], atol=1e-12)


@pytest.mark.parametrize("full, series", [("cycloidal", "C-5"), ("harmonic", "H-5")])
def test_full_period_laws_equal_their_series_names(full, series):
    x = np.linspace(0, 1, 51)
    for a, b in zip(law(full).derivatives(x), law(series).derivatives(x)):
        np.testing.assert_array_equal(a, b)


def test_piecewise_laws_end_at_rest():
    for name in ("modified_trapezoid", "modified_sine"):
        y, d1, d2, _ = law(name).derivatives(np.array([0.0, 1.0]))
        np.testing.assert_allclose(d1, 0.0, atol=1e-12)
        np.testing.assert_allclose(d2, 0.0, atol=1e-12)


def test_shapes_and_model_interface():
    model = law("P-1")
    values = model.derivatives(0.5)
    assert len(values) == 4 and all(isinstance(v, np.ndarray) and v.shape == () for v in values)
    assert model.derivatives(np.zeros((2, 3)))[3].shape == (2, 3)
    assert set(model({"x": 0.25})) == {"y", "dy", "d2y", "d3y"}


@pytest.mark.parametrize("bad", [1.5, -0.1, float("nan")])
def test_x_outside_unit_interval_is_refused(bad):
    with pytest.raises(InputError, match=r"x = .*outside \[0, 1\]") as info:
        law("cycloidal").derivatives(np.array([0.2, bad]))
    assert repr(bad) in str(info.value)


# ----------------------------------------------------------------- segments and programs
def ls1():
    return MotionProgram.thesis_ls1()


def test_segment_maps_law_onto_angles_and_partial_lifts():
    seg = Segment("C-5", "30 deg", "90 deg", "5 mm", "12 mm")
    beta, rise = math.radians(60), 0.007
    f, f1, f2, f3 = seg.evaluate(np.radians([30.0, 60.0, 90.0]))
    np.testing.assert_allclose(f, [0.005, 0.0085, 0.012], rtol=1e-12)
    np.testing.assert_allclose(f1[1], rise * 2 / beta)  # cycloid y'(1/2) = 2
    np.testing.assert_allclose(f3[0], rise * 4 * PI**2 / beta**3)
    assert seg.name == "C-5" and seg.span == pytest.approx(beta)


def test_rise_law_on_falling_lift_is_the_mirrored_return():
    mirrored = MotionProgram.rise_return_dwell("10 mm", "100 deg", "80 deg", "cycloidal", "cycloidal")
    proper = MotionProgram.rise_return_dwell("10 mm", "100 deg", "80 deg", "cycloidal", "C-6")
    theta = np.linspace(0, 2 * PI, 721)
    for a, b in zip(mirrored.evaluate(theta), proper.evaluate(theta)):
        np.testing.assert_allclose(a, b, atol=1e-15)


def test_law_given_as_class_or_instance():
    from camcontact.models.motion_laws import P1, P2

    a = MotionProgram.rise_return_dwell("20 mm", "90 deg", "90 deg", P1, P2())
    theta = np.linspace(0, 2 * PI, 97)
    np.testing.assert_array_equal(a.evaluate(theta)[2], ls1().evaluate(theta)[2])


def test_evaluate_wraps_and_uses_the_segment_starting_at_a_joint():
    program = MotionProgram.rise_return_dwell("20 mm", "90 deg", "90 deg", "harmonic", "H-6")
    beta = PI / 2
    f, f1, f2, f3 = program.evaluate(np.array([0.0, 2 * PI, -2 * PI, PI]))
    # at 0 (and 360°, −360°) the harmonic rise starts: f'' = L π²/(2β²)
    np.testing.assert_allclose(f2[:3], 0.02 * PI**2 / (2 * beta**2))
    assert f2[3] == 0.0  # at 180° the dwell starts
    theta = np.linspace(0.1, 6.0, 13)
    for a, b in zip(program.evaluate(theta), program.evaluate(theta + 4 * PI)):
        np.testing.assert_allclose(a, b, atol=1e-15)
    assert program.evaluate(0.3)[0].shape == ()


def test_lift_joints_and_constructors_agree():
    program = ls1()
    assert program.lift == pytest.approx(0.02, rel=1e-12)
    np.testing.assert_allclose(np.degrees(program.joints), [0, 90, 180])
    from_dicts = MotionProgram.from_segments([
        {"law": "P-1", "start": "0 deg", "end": "90 deg", "lift_start": "0 mm", "lift_end": "20 mm"},
        {"law": "P-2", "start": Q_(90, "deg"), "end": "180 deg", "lift_start": "20 mm", "lift_end": Q_(0, "m")},
        {"law": "dwell", "start": "180 deg", "end": "360 deg", "lift_start": "0 mm", "lift_end": "0 mm"},
    ])
    assert from_dicts.segments[2].law is None and from_dicts.segments[2].name == "dwell"
    floats = MotionProgram.rise_return_dwell("20 mm", PI / 2, PI / 2)
    theta = np.linspace(0, 2 * PI, 361)
    for other in (from_dicts, floats):
        for a, b in zip(program.evaluate(theta), other.evaluate(theta)):
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-18)
    full = MotionProgram.rise_return_dwell("5 mm", "180 deg", "180 deg", "cycloidal", "C-6")
    assert len(full.segments) == 2


def test_program_derivatives_match_differences_of_lift():
    program = MotionProgram.from_segments([
        {"law": "C-1", "start": "0 deg", "end": "40 deg", "lift_start": "0 mm", "lift_end": "4 mm"},
        {"law": "polynomial_345", "start": "40 deg", "end": "150 deg", "lift_start": "4 mm", "lift_end": "11 mm"},
        {"law": "modified_sine", "start": "150 deg", "end": "260 deg", "lift_start": "11 mm", "lift_end": "0 mm"},
        {"law": None, "start": "260 deg", "end": "360 deg", "lift_start": "0 mm"},
    ])
    theta = np.radians(np.array([10.0, 33.0, 77.0, 120.0, 170.0, 211.0]))
    h = 1e-6
    f, f1, _, _ = program.evaluate(theta)
    np.testing.assert_allclose(f1, (program.evaluate(theta + h)[0] - program.evaluate(theta - h)[0]) / (2 * h),
                               rtol=1e-6, atol=1e-12)
    np.testing.assert_allclose(program.evaluate(np.radians([40.0, 150.0, 260.0]))[0], [0.004, 0.011, 0.0])


# ----------------------------------------------------------------- continuity diagnostics
def flags(program, column):
    table = program.continuity()
    return dict(zip(table["angle [deg]"].round(6), table[column]))


def test_ls1_is_c2_with_jerk_jumps_at_the_dwells():
    table = ls1().continuity()
    assert list(table["angle [deg]"]) == [0.0, 90.0, 180.0]
    assert table["C2"].all() and table["jerk_finite"].all()
    assert list(table["jerk_continuous"]) == [False, True, False]
    assert list(table.columns[:7]) == ["angle [deg]", "left", "right", "jump f [m]", "jump f' [m/rad]",
                                       "jump f'' [m/rad^2]", "jump f''' [m/rad^3]"]
    assert ls1().diagnostics() == []


def test_harmonic_with_dwells_has_infinite_jerk():
    program = MotionProgram.rise_return_dwell("20 mm", "90 deg", "90 deg", "harmonic", "H-6")
    assert flags(program, "jerk_finite") == {0.0: False, 90.0: True, 180.0: False}
    assert flags(program, "C1") == {0.0: True, 90.0: True, 180.0: True}
    messages = program.diagnostics()
    assert len(messages) == 2 and all("jerk is infinite" in m for m in messages)
    assert "0°" in messages[0] and "180°" in messages[1]
    with pytest.warns(MotionContinuityWarning, match="jerk is infinite"):
        program.check(strict=True)  # C1 holds: strict only warns


def test_cycloidal_is_c2_everywhere():
    program = MotionProgram.rise_return_dwell("8 mm", "120 deg", "100 deg", "cycloidal", "C-6")
    table = program.continuity()
    assert table["C2"].all() and program.diagnostics() == []
    assert not table["jerk_continuous"].iloc[0]  # 4π² L/β³ jump from the dwell


def partial_rise(l1_mm):
    """0–30° C-1 (0 → L1), 30–90° C-2 (L1 → 20 mm), 90–180° C-6 return, dwell."""
    return MotionProgram.from_segments([
        {"law": "C-1", "start": "0 deg", "end": "30 deg", "lift_start": "0 mm", "lift_end": f"{l1_mm!r} mm"},
        {"law": "C-2", "start": "30 deg", "end": "90 deg", "lift_start": f"{l1_mm!r} mm", "lift_end": "20 mm"},
        {"law": "C-6", "start": "90 deg", "end": "180 deg", "lift_start": "20 mm", "lift_end": "0 mm"},
        {"law": None, "start": "180 deg", "end": "360 deg", "lift_start": "0 mm"},
    ])


def test_partial_lift_half_cycloids_with_matched_velocity_are_c1():
    # C-1 ends with f' = 2 L1/β1, C-2 starts with 2 L2/β2: equal when L1/β1 = L2/β2, L1 = 20·30/90 mm
    program = partial_rise(20.0 / 3.0)
    assert flags(program, "C1")[30.0]
    assert flags(program, "C2")[30.0]  # both half cycloids have y'' = 0 at the joint
    assert program.diagnostics() == []
    program.check(strict=True)


def test_partial_lift_with_mismatched_velocity_is_flagged():
    program = partial_rise(10.0)
    assert flags(program, "C1") == {0.0: True, 30.0: False, 90.0: True, 180.0: True}
    jump = program.continuity().set_index("angle [deg]").loc[30.0, "jump f' [m/rad]"]
    assert jump == pytest.approx(2 * 0.010 / math.radians(60) - 2 * 0.010 / math.radians(30))
    assert "velocity f' jumps" in program.diagnostics()[0]
    with pytest.warns(MotionContinuityWarning, match="acceleration is infinite"):
        program.check()
    with pytest.raises(InputError, match="not C1.*30°"):
        program.check(strict=True)


# ----------------------------------------------------------------- bad input
def test_gap_and_overlap_name_the_segment():
    base = {"law": "P-1", "start": "0 deg", "end": "90 deg", "lift_start": "0 mm", "lift_end": "20 mm"}
    for start, kind in (("95 deg", "gap"), ("85 deg", "overlap")):
        with pytest.raises(InputError, match=rf"segment 1 \(P-2.*starts at {start[:2]}° .* segment 0 .*ends at 90°: {kind} of 5°"):
            MotionProgram.from_segments([
                base,
                {"law": "P-2", "start": start, "end": "180 deg", "lift_start": "20 mm", "lift_end": "0 mm"},
                {"law": None, "start": "180 deg", "end": "360 deg", "lift_start": "0 mm"},
            ])
    with pytest.raises(InputError, match="must start at 0°"):
        MotionProgram([Segment(None, "10 deg", "360 deg", 0.0)])
    with pytest.raises(InputError, match="must end at 360°"):
        MotionProgram([Segment(None, "0 deg", "350 deg", 0.0)])
    with pytest.raises(InputError, match="rise \\+ ret <= 360°"):
        MotionProgram.rise_return_dwell("20 mm", "200 deg", "200 deg")


def test_lift_mismatch_names_segment_angles_and_size():
    with pytest.raises(InputError, match=r"segment 1 \(P-2, 90°–180°\) starts at lift 19 mm .*segment 0 .*20 mm: "
                                          r"lift mismatch of -1 mm at 90°"):
        MotionProgram.from_segments([
            {"law": "P-1", "start": "0 deg", "end": "90 deg", "lift_start": "0 mm", "lift_end": "20 mm"},
            {"law": "P-2", "start": "90 deg", "end": "180 deg", "lift_start": "19 mm", "lift_end": "0 mm"},
            {"law": None, "start": "180 deg", "end": "360 deg", "lift_start": "0 mm"},
        ])
    with pytest.raises(InputError, match=r"segment 0 .* lift mismatch of -2 mm at 0°"):  # the 360° → 0° joint
        MotionProgram.from_segments([
            {"law": "P-1", "start": "0 deg", "end": "180 deg", "lift_start": "0 mm", "lift_end": "20 mm"},
            {"law": "C-4", "start": "180 deg", "end": "360 deg", "lift_start": "20 mm", "lift_end": "2 mm"},
        ])
    with pytest.raises(InputError, match="dwell segment .*must be equal"):
        Segment(None, 0.0, 1.0, 0.0, 0.001)
    with pytest.raises(InputError, match="must be after"):
        Segment("P-1", "90 deg", "90 deg", "0 mm", "1 mm")


def test_unknown_law_lists_available():
    with pytest.raises(UnknownModelError, match=r"no motion_laws model named 'P-9'; available: .*C-1.*P-1.*cycloidal"):
        MotionProgram.rise_return_dwell("20 mm", "90 deg", "90 deg", rise_law="P-9")


@pytest.mark.parametrize("field, value", [("lift_end", 0.02), ("start", 0.0), ("end", 1.5707963267948966)])
def test_bare_numbers_refused_for_dimensional_fields(field, value):
    item = {"law": "P-1", "start": "0 deg", "end": "90 deg", "lift_start": "0 mm", "lift_end": "20 mm"}
    item[field] = value
    with pytest.raises(InputError, match=rf"segment 0 \(P-1\): {field} = .*bare number"):
        MotionProgram.from_segments([item])


def test_bad_units_and_lifts_in_constructors():
    with pytest.raises(InputError, match="lift = 0.02: a bare number"):
        MotionProgram.rise_return_dwell(0.02, "90 deg", "90 deg")
    with pytest.raises(InputError, match=r"start = 3 mm: wrong dimension"):
        MotionProgram.from_segments([{"law": None, "start": "3 mm", "end": "360 deg", "lift_start": "0 mm"}])
    with pytest.raises(InputError, match="unknown keys"):
        MotionProgram.from_segments([{"law": None, "start": "0 deg", "end": "360 deg", "lift": "0 mm"}])
    with pytest.raises(InputError, match="must be > 0"):
        MotionProgram.rise_return_dwell("-1 mm", "90 deg", "90 deg")


def test_peak_coefficients_of_a_simple_law():
    # 3-4-5: y' = 30x²(1−x)² peaks at x = 1/2 with 30/16
    assert peak_coefficients("polynomial_345")[0] == pytest.approx(30 / 16, rel=1e-12)
