"""Hard cam-cycle cases: the flat-faced follower's entrainment reversal at the nose (u_m = 0,
Tsuha 2015 §6.2.1, reference §5 item 12) and a speed at which the follower jumps (§6.1)."""

import math
import warnings

import numpy as np
import pytest

import camcontact as cc
from camcontact.kinematics.follower import sign_changes
from camcontact.kinematics.motion_program import MotionProgram

STEEL = cc.Material(E="210 GPa", nu=0.3)
OIL = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68, viscosity_pressure_law="roelands")


def flat_scene(angles, **changes):
    arguments = dict(
        cam=cc.Cam(program=MotionProgram.thesis_ls1(), base_radius="49.7494 mm", width="15 mm", material=STEEL),
        follower=cc.Follower.flat(material=STEEL), valve_train=cc.ValveTrain.ls1(), speed="1000 rpm",
        angles=cc.Q_(np.asarray(angles, dtype=float), "deg"), lubricant=OIL,
    )
    arguments.update(changes)
    return cc.CamFollower(**arguments)


def _reversal_angles():
    fine = np.arange(0.0, 180.0, 0.001)
    u_m = cc.Analysis(flat_scene(fine), outputs=["u_m"]).run()["u_m"]
    return np.degrees(sign_changes(np.radians(fine), u_m))


@pytest.mark.parametrize("film", ["pan_hamrock", "dowson_higginson", "multigrid"])
def test_flat_follower_through_zero_entrainment_never_returns_nan(film):
    """1° steps over the nose plus the two reversal angles themselves (u_m within ~1e-6 m/s of zero):
    finite films everywhere, no exception, and the near-zero angles flagged in film_regime."""
    reversal = _reversal_angles()
    angles = np.sort(np.concatenate([np.arange(55.0, 126.0, 1.0), reversal]))
    model = cc.registry.get("film_models", "multigrid", levels=6) if film == "multigrid" else film
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = cc.Analysis(flat_scene(angles), outputs=["u_m", "M", "h_min", "film_regime"],
                             models={"film": model}).run()
    h = result["h_min"]
    assert np.all(np.isfinite(h)) and np.all(h >= 0.0)
    flagged = [i for i, text in enumerate(result["film_regime"]) if "u_m" in text]
    near = [int(np.argmin(np.abs(angles - r))) for r in reversal]
    assert set(near) <= set(flagged)
    assert all("squeeze" in result["film_regime"][i] for i in near)
    # away from the reversal the steady film is an ordinary EHL film
    assert result["film_regime"][int(np.argmin(np.abs(angles - 90.0)))] in ("ok",) or film != "multigrid"
    assert h[int(np.argmin(np.abs(angles - 90.0)))] > 0.05e-6


def test_exactly_zero_entrainment_is_flagged_not_nan():
    """An angle where u_m is exactly zero cannot be hit by sampling; a motion whose u_m vanishes on a whole
    interval (f'' = -(R_o + f)/2 is impossible for a real program), so the check goes through the film step
    directly with u_m = 0 on one angle."""
    from camcontact.steps.film_cycle import quasi_steady_films

    model = cc.registry.get("film_models", "pan_hamrock")
    state = OIL.state(None)
    s = {"contact_open": np.array([False, False]), "w": np.array([1e5, 1e5]), "R": np.array([0.02, 0.02]),
         "E_reduced": 2.3077e11, "u_m": np.array([0.0, 1.0]), "eta0": state.eta0, "alpha_effective": state.alpha,
         "lubricant_state": state, "density_law": "dowson_higginson", "M": np.array([math.inf, 10.0]),
         "U": np.array([0.0, 1e-11]), "G": np.array([5000.0, 5000.0]), "W": np.array([2e-5, 2e-5]),
         "L": np.array([0.0, 10.0])}
    films = quasi_steady_films(model, **s, film_speed_factor=1.0)
    assert films["h_min"][0] == 0.0 and np.isfinite(films["h_min"][1]) and films["h_min"][1] > 0
    assert "u_m = 0" in films["film_regime"][0]


def test_high_speed_jump_is_detected_and_reported():
    """At 4000 rpm with a weak spring the inertia force exceeds spring + preload near the nose: the
    prescribed-motion force goes negative, the scene says JUMP with the first angle, the contact is open
    there (zero normal force, no Hertz), and k_min says which stiffness would have prevented it."""
    weak = cc.ValveTrain(mass="0.662 kg", stiffness="2e4 N/m", preload="300 N", damping_ratio=0.06)
    angles = np.arange(0.0, 360.0, 1.0)
    result = cc.Analysis(flat_scene(angles, valve_train=weak, speed="4000 rpm"),
                         outputs=["contact_force", "normal_force", "p_h", "h_min", "film_regime", "jump",
                                  "k_min"]).run()
    assert result["jump"].startswith("JUMP")
    open_ = result["contact_force"] < 0
    assert open_.any() and np.all(result["normal_force"][open_] == 0.0) and np.all(result["p_h"][open_] == 0.0)
    assert all(text.startswith("contact lost") for text in np.asarray(result["film_regime"])[open_])
    assert np.all(np.isfinite(result["h_min"][~open_]))
    assert result["k_min"] > 2e4
    safe = cc.ValveTrain(mass="0.662 kg", stiffness=f"{1.01 * result['k_min']!r} N/m", preload="300 N",
                         damping_ratio=0.06)
    again = cc.Analysis(flat_scene(angles, valve_train=safe, speed="4000 rpm"), outputs=["jump"]).run()
    assert again["jump"].startswith("no jump")


def test_a_warm_start_that_does_not_converge_is_retried_cold():
    """The LS-1 roller at 50° (consistent convention, M = 6.00, L = 19.20, level 8): warm-started from
    49° every attempt of the ladder stagnated or diverged, while a cold full-multigrid start
    converges. The film step therefore retries cold when the warm result is not converged (not only
    when it raises), and keeps the converged one."""
    from camcontact.steps.film_cycle import solve_numerically

    class Scripted:
        """A film model whose warm start does not converge and whose cold start does."""

        name = "multigrid"

        def __init__(self):
            self.starts = []

        def evaluate(self, initial=None, **state):
            self.starts.append("warm" if initial is not None else "cold")
            record = type("Record", (), {"converged": initial is None})()
            return {"h_min": 1e-6 if initial is None else 2e-6, "convergence": record}

    model = Scripted()
    produced, failure = solve_numerically(model, {}, previous=object())
    assert failure is None and model.starts == ["warm", "cold"]
    assert produced["convergence"].converged and produced["h_min"] == 1e-6
    model = Scripted()
    produced, _ = solve_numerically(model, {}, previous=None)  # no neighbour: one cold start only
    assert model.starts == ["cold"] and produced["convergence"].converged


def test_threaded_arcs_agree_with_one_warm_started_chain():
    """The numerical film of a cycle cut into two warm-started arcs (threads) equals the single chain
    within the solver tolerance (the second arc starts cold, so the iterates differ), angle by angle,
    all converged; the thread count is validated."""
    from camcontact.models.film_multigrid import Multigrid
    from camcontact.steps.film_cycle import MIN_CHAIN, chain_count

    roller = cc.CamFollower(
        cam=cc.Cam(program=MotionProgram.thesis_ls1(), base_radius="40 mm", width="15 mm", material=STEEL),
        follower=cc.Follower.roller(radius="10 mm", offset="5 mm", material=STEEL), valve_train=cc.ValveTrain.ls1(),
        speed="1000 rpm", angles=cc.Q_(np.arange(30.0, 30.0 + 2 * MIN_CHAIN), "deg"), lubricant=OIL)
    films = {}
    for threads in (1, 2):
        model = Multigrid(levels=6, tolerance=1e-8, threads=threads)
        assert chain_count(model, 2 * MIN_CHAIN) == threads
        result = cc.Analysis(roller, outputs=["h_min", "film_regime"], models={"film": model}).run()
        assert all(text == "ok" for text in result["film_regime"])
        films[threads] = np.asarray(result["h_min"], dtype=float)
    np.testing.assert_allclose(films[2], films[1], rtol=1e-5)
    assert chain_count(Multigrid(threads=4), MIN_CHAIN + 1) == 1  # no arc shorter than MIN_CHAIN
    with pytest.raises(cc.InputError, match="threads = 0"):
        Multigrid(threads=0)


def _flat_ls1(step="4 deg"):
    import attrs

    from camcontact.scene_file import load_scene

    scene = load_scene()
    follower = cc.Follower.flat(material=scene.component.follower.material)
    return attrs.evolve(scene.component, follower=follower, angle_step=step,
                        cam=attrs.evolve(scene.component.cam, base_radius="49.7494 mm"))


def test_squeeze_effect_carries_the_film_through_entrainment_reversal():
    """LS-1 cam with a flat-faced follower at 1000 rpm: u_m changes sign near 66 and 114 deg. The
    quasi-steady film collapses towards zero there; the transient march (effect 'squeeze') gives
    finite, positive films at every angle, thicker than the quasi-steady ones at the reversals, and
    equal to them (within 2 %) on the base circle, where nothing changes."""
    from camcontact.models.film_multigrid import Multigrid

    model = {"film": Multigrid(levels=6, tolerance=1e-5)}
    outputs = ["cam_angle", "u_m", "h_min", "film_regime"]
    steady = cc.Analysis(_flat_ls1(), outputs=outputs, models=model).run()
    transient = cc.Analysis(_flat_ls1(), outputs=outputs, models=model,
                            effects={"elasticity", "piezoviscosity", "compressibility", "squeeze"}).run()
    h_t, h_s = np.asarray(transient["h_min"]), np.asarray(steady["h_min"])
    assert np.all(np.isfinite(h_t)) and np.all(h_t > 0)
    assert all(str(r).startswith("transient (squeeze)") and "not converged" not in str(r)
               for r in transient["film_regime"])
    u = np.asarray(transient["u_m"])
    reversal = np.flatnonzero(np.sign(u[:-1]) * np.sign(u[1:]) < 0)
    assert reversal.size == 2
    for i in reversal:
        assert min(h_t[i], h_t[i + 1]) > 1.5 * min(h_s[i], h_s[i + 1])
    base_circle = np.asarray(transient["cam_angle"]) > np.radians(200)
    assert h_t[base_circle] == pytest.approx(h_s[base_circle], rel=0.02)


def test_squeeze_effect_needs_the_numerical_film_and_contact():
    with pytest.raises(cc.InputError, match="the 'squeeze' effect solves the film numerically"):
        cc.Analysis(_flat_ls1(), outputs=["h_min"], effects={"elasticity", "piezoviscosity", "squeeze"})


def test_mass_conserving_squeeze_film_meets_its_own_exit_film_after_reversal():
    """LS-1 flat follower, 1000 rpm, squeeze effect, cavitation 'mass_conserving' (film fraction carried from
    angle to angle) against the default clipping: the same films until the first reversal (~66 deg); just
    after each reversal the contact is fed by the partly filled film it left behind and runs thinner (measured
    -5.2 % at 72 deg, -3.7 % at 120 deg, level 6); on the base circle the same film again. Angles whose step
    does not converge are flagged in film_regime and film_valid (measured: 5 of 90 around the reversals).
    Before the first reversal the two marches agree to 4e-5 (each step converged to its tolerance)."""
    from camcontact.models.film_multigrid import Multigrid

    outputs = ["cam_angle", "u_m", "h_min", "film_regime", "film_valid"]
    effects = {"elasticity", "piezoviscosity", "compressibility", "squeeze"}
    runs = {}
    for cavitation in ("reynolds", "mass_conserving"):
        model = {"film": Multigrid(levels=6, tolerance=1e-7, cavitation=cavitation)}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", cc.ConvergenceWarning)
            runs[cavitation] = cc.Analysis(_flat_ls1(), outputs=outputs, models=model, effects=effects).run()
    flooded, conserving = runs["reynolds"], runs["mass_conserving"]
    angle = np.degrees(np.asarray(flooded["cam_angle"], dtype=float))
    h_f, h_m = np.asarray(flooded["h_min"], dtype=float), np.asarray(conserving["h_min"], dtype=float)
    before = angle < 64.0
    np.testing.assert_allclose(h_m[before], h_f[before], rtol=2e-4)  # converged to 1e-7 each, differently
    after = (angle > 68.0) & (angle < 80.0)
    assert (h_m[after] / h_f[after]).min() < 0.97
    base_circle = angle > 200.0
    np.testing.assert_allclose(h_m[base_circle], h_f[base_circle], rtol=1e-3)
    valid = np.asarray(conserving["film_valid"], dtype=bool)
    assert all(("not converged" in str(text)) == (not ok) for text, ok in zip(conserving["film_regime"], valid))
    assert np.all(np.isfinite(h_m)) and np.all(h_m > 0) and (~valid).sum() <= 8
    with pytest.raises(cc.InputError, match="cavitation = 'elrod'"):
        Multigrid(cavitation="elrod")


def test_a_starved_flat_follower_runs_on_its_oil_layer_and_thins_at_the_nose():
    """LS-1 flat follower, 1000 rpm, squeeze, mass-conserving, level 6 (4 degree steps), fed by a 0.3 um layer
    (CamFollower.oil_layer) against the flooded march. Where the flooded film is thicker than the layer brings
    (flanks, base circle: 0.44-2.5 um) the starved contact carries the layer, rho_c h_c = h_oil (measured
    269-277 nm against 1.2-2.5 um); through the nose the contact lives on the film it left behind, so the
    minimum over the turn falls (measured 158 nm against 186 nm flooded) at the same angle (116 deg); every
    film finite and positive; formula films, the quasi-steady turn and the Reynolds cavitation refuse the
    layer."""
    import attrs

    from camcontact.models.film_multigrid import Multigrid

    outputs = ["cam_angle", "u_m", "h_c", "h_min", "film_valid"]
    effects = {"elasticity", "piezoviscosity", "compressibility", "squeeze"}
    model = {"film": Multigrid(levels=6, tolerance=1e-7, cavitation="mass_conserving")}
    runs = {}
    for layer in (None, "0.3 um"):
        scene = attrs.evolve(_flat_ls1(), oil_layer=layer)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", cc.ConvergenceWarning)
            runs[layer] = cc.Analysis(scene, outputs=outputs, models=model, effects=effects).run()
    flooded, starved = runs[None], runs["0.3 um"]
    angle = np.degrees(np.asarray(flooded["cam_angle"], dtype=float))
    h_f, h_s = np.asarray(flooded["h_c"], dtype=float), np.asarray(starved["h_c"], dtype=float)
    m_f, m_s = np.asarray(flooded["h_min"], dtype=float), np.asarray(starved["h_min"], dtype=float)
    assert np.all(np.isfinite(m_s)) and np.all(m_s > 0.0)
    assert (~np.asarray(starved["film_valid"], dtype=bool)).sum() <= 4
    thick = h_f > 1e-6
    assert thick.sum() > 40
    np.testing.assert_allclose(h_s[thick], 0.275e-6, rtol=0.03)  # h_oil / rho_c, rho_c ~ 1.09
    assert m_s.min() < 0.9 * m_f.min()
    assert abs(angle[np.argmin(m_s)] - angle[np.argmin(m_f)]) <= 8.0
    for bad_model, bad_effects in ((Multigrid(levels=6), effects), ("pan_hamrock", {"elasticity", "piezoviscosity"}),
                                   (model["film"], {"elasticity", "piezoviscosity"})):
        with pytest.raises(cc.InputError, match="oil_layer"):
            cc.Analysis(attrs.evolve(_flat_ls1(), oil_layer="0.3 um"), outputs=["h_min"],
                        models={"film": bad_model}, effects=bad_effects).run()
