"""The numerical point-contact film as a film model (``multigrid_point``; ``"multigrid"`` in point scenes).

A dimensional circular contact, Rx = Ry = 10 mm, F = 10 N, E' = 220 GPa, u_m = 2 m/s, eta0 = 0.04 Pa s,
alpha = 2e-8 1/Pa (Moes M = 18.3, L = 12.9, inside the solver's measured range M 10-100, L 5-25),
Roelands, incompressible: the central film within 5 % of Nijenbanning, Venner & Moes (1994) — the
same check as tests/literature/test_point_ehl_literature.py, through the model's dimensional path.
"""

import warnings

import pytest

import camcontact as cc
from camcontact.errors import ConvergenceWarning
from camcontact.models.film_multigrid_point import MultigridPoint

STATE = {"Rx": 0.01, "Ry": 0.01, "F": 10.0, "E_reduced": 2.2e11, "u_m": 2.0, "eta0": 0.04, "alpha": 2e-8,
         "density_law": "incompressible"}


def test_dimensional_central_film_matches_nijenbanning():
    model = cc.registry.get("film_models", "multigrid_point", levels=4)
    assert isinstance(model, MultigridPoint)
    numerical = model(STATE)
    formula = cc.registry.get("film_models", "nijenbanning")(STATE)
    assert numerical["convergence"].converged
    assert numerical["h_c"] == pytest.approx(formula["h_c"], rel=0.05)
    assert 0 < numerical["h_min"] < numerical["h_c"]
    assert numerical["M"] == pytest.approx(18.3, abs=0.1) and numerical["L"] == pytest.approx(12.85, abs=0.01)


def test_ball_cone_contact_is_beyond_the_solver_and_says_so():
    """The CVT's contact at 150 W has Moes M of about 8e4: the numerical film does not converge there and
    the analysis warns (the record travels with the warning) instead of returning a silent number."""
    steel = cc.Material(E="207 GPa", nu=0.3)
    fluid = cc.Lubricant(name="fluid", nu40="30 cSt", nu100="5.5 cSt", density="0.90 g/cm^3", alpha="2.5e-8 1/Pa")
    cvt = cc.BallConeCVT(cone_angle="30 deg", cone_contact_radius="24 mm", ball_diameter="14 mm", ball_count=9,
                         tilt_max="30 deg", cam_ramp_angle="10 deg", cam_radius="6 mm", cam_ball_count=5,
                         material=steel, traction_coefficient=0.1, lubricant=fluid)
    point = cc.LoadedBallConeCVT(cvt=cvt, power="150 W", input_speed="60 rpm", temperature="60 degC")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = cc.Analysis(point, outputs=["h_min_in"], models={"film": MultigridPoint(levels=3)}).run()
    assert any(issubclass(w.category, ConvergenceWarning) for w in caught)
    assert result["h_min_in"] == result["h_min_in"]  # finite or flagged, never NaN
    with pytest.raises(cc.InputError, match="is for line contacts; the ball-cone contact needs a point model"):
        cc.Analysis(point, outputs=["h_min_in"], models={"film": "pan_hamrock"})
