"""Traction curves of the CVT's contacts (camcontact.steps.traction_curve): FASTSIM's called alone, the EHL
film's through the scene.

Independent checks: each point of a FASTSIM curve is FASTSIM at that creepage (lower-level call, 1e-12); the
curve without spin saturates at Ct (Coulomb bound) and is never below the curve with spin (spin takes part of
the bound; Kalker 1982); the operating point the traction step solved lies on the curve (interpolated on its
log grid within 1 %); an isothermal EHL curve ends at the capacity (taken at ``max_creepage``, 1e-12); FASTSIM's
gross slip has its operating creepage at infinity (its capacity is reached at unbounded creep only).
"""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact import registry
from camcontact.contact.fastsim import fastsim
from camcontact.errors import ValidityWarning
from camcontact.steps.traction import ball_cone_traction
from camcontact.steps.traction_curve import (CURVE_POINTS, ball_cone_ehl_traction_curve, ball_cone_traction_curve,  # noqa: F401
                                             creepage_grid)

A, B, N, CT = 0.2e-3, 0.5e-3, 1254.0, 0.1  # semi-axes along rolling / transverse [m], normal force [N]
G = 207e9 / (2 * 1.3)  # shear modulus of the thesis's steel [Pa]
MODEL = registry.get("traction_models", "fastsim")


def fastsim_curves(F_in, F_out, spin=True, phi_in=300.0, phi_out=150.0):
    solved = ball_cone_traction(MODEL, A, B, N, CT, G, F_in, F_out, phi_in, phi_out, spin, 1.0, 2.0)
    out = ball_cone_traction_curve(MODEL, A, B, N, CT, G, F_in, F_out, phi_in, phi_out, spin, solved["creepage_in"],
                                   solved["creepage_out"], solved["gross_slip_in"], solved["gross_slip_out"])
    assert set(out) == set(ball_cone_traction_curve.step.provides)
    return out


def test_grid_starts_at_zero_and_is_log_spaced():
    grid = creepage_grid(0.05)
    assert grid.size == CURVE_POINTS and grid[0] == 0.0 and grid[-1] == pytest.approx(0.05, rel=1e-12)
    assert np.allclose(np.diff(np.log(grid[1:])), math.log(1e3) / (CURVE_POINTS - 2))


def test_fastsim_curve_points_are_fastsim_and_saturate_at_the_coulomb_bound():
    curve = fastsim_curves(50.0, 100.0)["traction_curve_in"]
    assert curve.model == "fastsim (parabolic)" and curve.spin == 300.0
    for k in (5, 20, 40):
        again = fastsim(A, B, N, CT, G, creepage_x=-curve.creepage[k], spin=300.0)
        assert curve.coefficient[k] == pytest.approx(abs(again.Fx) / N, rel=1e-12)
    assert curve.coefficient[0] == pytest.approx(0.0, abs=1e-12)
    assert curve.coefficient_no_spin[-1] == pytest.approx(CT, rel=0.01)  # past 99 % of Ct N
    assert np.all(curve.coefficient <= curve.coefficient_no_spin + 1e-12)  # spin takes part of the bound
    assert np.all(np.diff(curve.coefficient_no_spin) >= -1e-12)
    assert curve.capacity_coefficient == CT and not curve.gross_slip


def test_fastsim_operating_point_lies_on_its_curve():
    out = fastsim_curves(50.0, 100.0)
    for side, force in (("in", 50.0), ("out", 100.0)):
        curve = out[f"traction_curve_{side}"]
        assert curve.operating_coefficient == pytest.approx(force / N, rel=1e-12)
        on_curve = np.interp(math.log(curve.operating_creepage), np.log(curve.creepage[1:]), curve.coefficient[1:])
        assert on_curve == pytest.approx(curve.operating_coefficient, rel=0.01)
    assert out["traction_curve_in"].to_frame().columns.tolist() == [
        "creepage [%]", "traction_coefficient [-]", "traction_coefficient_no_spin [-]"]


def test_without_the_spin_effect_the_curve_has_no_spin_and_no_second_curve():
    curve = fastsim_curves(50.0, 100.0, spin=False)["traction_curve_out"]
    assert curve.spin == 0.0 and curve.coefficient_no_spin is None
    assert list(curve.to_frame().columns) == ["creepage [%]", "traction_coefficient [-]"]


def test_fastsim_gross_slip_puts_the_operating_creepage_at_infinity():
    curve = fastsim_curves(1.2 * CT * N, 50.0)["traction_curve_in"]
    assert curve.gross_slip and curve.operating_creepage == math.inf
    assert curve.operating_coefficient == pytest.approx(1.2 * CT, rel=1e-12)
    assert np.all(np.isfinite(curve.coefficient)) and curve.coefficient.max() < CT


STEEL = cc.Material(E="207 GPa", nu=0.3)
FLUID = cc.Lubricant(name="traction fluid", nu40="30 cSt", nu100="5.5 cSt", density="0.90 g/cm^3",
                     alpha="2.5e-8 1/Pa", limiting_shear_slope=0.088)
CVT = cc.BallConeCVT(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
                     tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5, material=STEEL,
                     traction_coefficient=0.1, lubricant=FLUID, roughness="0.1 um")
OUTPUTS = ["traction_curve_in", "traction_curve_out", "creepage_in", "tangential_force_in", "normal_force",
           "traction_capacity_in", "gross_slip_in"]


def run(power="50 W", ratio=1.2, **options):
    scene = cc.LoadedBallConeCVT(cvt=CVT, power=power, input_speed="60 rpm", ratio=ratio, temperature="60 degC")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return cc.Analysis(scene, outputs=OUTPUTS, **options).run()


def test_ehl_curve_through_the_scene_holds_its_operating_point_and_ends_at_the_capacity():
    """ball_cone_ehl_traction_curve in the scene: the operating point on the curve (1 %), the isothermal curve's
    end at the capacity the traction step took at max_creepage (1e-12), spin lowering the curve."""
    result = run()
    assert [(r.step, r.model) for r in result.records][-1] == ("traction_curve", "ehl_traction (eyring)")
    curve, N_ = result["traction_curve_in"], result["normal_force"]
    assert curve.model == "ehl_traction (eyring)" and not curve.gross_slip
    assert curve.operating_coefficient == pytest.approx(abs(result["tangential_force_in"]) / N_, rel=1e-12)
    assert curve.coefficient[-1] == pytest.approx(result["traction_capacity_in"] / N_, rel=1e-12)
    on_curve = np.interp(math.log(curve.operating_creepage), np.log(curve.creepage[1:]), curve.coefficient[1:])
    assert on_curve == pytest.approx(curve.operating_coefficient, rel=0.01)
    assert np.all(curve.coefficient <= curve.coefficient_no_spin + 1e-12)


def test_the_curves_run_only_when_asked_for():
    scene = cc.LoadedBallConeCVT(cvt=CVT, power="50 W", input_speed="60 rpm", ratio=1.2, temperature="60 degC")
    assert "traction_curve" not in cc.Analysis(scene).steps()
    assert cc.Analysis(scene, outputs=["traction_curve_out"]).steps()[-1] == "traction_curve"
