"""Ball-bearing steps: ball loads and contact angles, the elliptical contacts of every ball, their films,
the stresses below the most loaded contact and ISO 281 / ISO 76 for ball bearings.

The load distribution with contact-angle change after Harris & Kotzalas (2007) ch. 7
(:mod:`camcontact.contact.ball_load_distribution`); each ball's inner and outer contact by exact elliptical
Hertz (Harris & Kotzalas ch. 6, :func:`camcontact.contact.hertz_elliptical.hertz_elliptical`) at its own
contact angle; films by a point film model (Hamrock & Dowson 1977 by default); the stresses on the axis of
the most loaded contact (:func:`camcontact.contact.subsurface_point.point_subsurface`); ISO 281:2007 for
radial ball bearings and ISO 76:2006 for the static equivalent load (:mod:`camcontact.models.iso281_ball`).
A pair of angular-contact bearings (back to back, face to face, tandem) has steps of its own for the load
distribution of both bearings (:func:`ball_pair_loads`) and for ISO 281 / ISO 76 / ISO/TS 16281 of the pair
(:func:`ball_pair_equivalent_load`, :func:`ball_pair_static_safety`, :func:`ball_pair_reference_life`); the contact,
film and kinematics steps take its 2Z balls as they take Z.
Forces [N], lengths [m], pressures [Pa], angles [rad], ring speeds n [rev/s].
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..contact.ball_load_distribution import ball_race_radii
from ..contact.hertz_elliptical import hertz_elliptical
from ..contact.subsurface_point import point_subsurface
from ..errors import InputError, ValidityWarning
from ..models.iso281_ball import (ball_equivalent_load, pair_equivalent_load, pair_reference_rating_life,
                                  pair_static_equivalent_load, reference_rating_life, static_equivalent_load)
from ..step_graph import step
from .contact import RACES
from .film import films_of, model_name, model_version

__all__ = ["BALL_LOADS", "PAIR_LOADS", "TRUNCATION", "ball_truncation", "ball_bearing_equivalent_load", "ball_films", "ball_hertz", "ball_kinematics",
           "ball_loads", "ball_pair_equivalent_load", "ball_pair_loads", "ball_pair_reference_life",
           "ball_pair_static_safety", "ball_reference_life", "ball_static_safety", "ball_subsurface"]

BALL_LOADS = ("ball_azimuth", "Q", "contact_angle", "loaded", "ball_approach", "Q_max", "loaded_balls", "load_zone",
              "delta_r", "delta_a", "ring_tilt", "tilting_moment", "contact_angle_max", "contact_angle_min", "force_residual")


#: what the load distribution of a pair adds: each ball's bearing, each bearing's axial load, whether one is unloaded
PAIR_LOADS = (*BALL_LOADS, "ball_row", "axial_load_row0", "axial_load_row1", "preload_relieved")


@step("load_distribution", provides=BALL_LOADS, model="harris_ball_rigid_rings")
def ball_loads(bearing, radial_load, axial_load, moment):
    """Ball loads Q [N] and contact angles [rad] of ``bearing`` under F_r, F_a [N] and the tilting ``moment``
    [N m] (None: the tilt held at zero), per ball (``loaded``: Q > 0; an unloaded ball has no contact angle and
    NaN contact values), with the inner ring's displacements [m] and tilt [rad], the moment of the balls
    [N m], the number of loaded balls, the angle of the last loaded ball from the load line [rad] and the
    extreme contact angles of the loaded balls [rad]."""
    return _load_outputs(bearing.load_distribution_si(radial_load, axial_load, moment))


@step("load_distribution", provides=PAIR_LOADS, model="harris_ball_rigid_rings (pair)")
def ball_pair_loads(bearing, radial_load, axial_load, moment, arrangement, preload, row_spacing):
    """:func:`ball_loads` of two identical angular-contact bearings mounted as a pair (``arrangement``
    "back_to_back", "face_to_face" or "tandem", axial ``preload`` [m], ``row_spacing`` [m] between their ball
    centres; :meth:`camcontact.components.BallBearing.pair_load_distribution_si`) under the pair's F_r, F_a [N] and
    moment [N m]: the 2Z balls, bearing 0 first, with ``ball_row`` (0 or 1) per ball, the axial load each bearing
    carries on its own flanks [N] and ``preload_relieved`` (True when one bearing carries no ball load: the axial
    load has relieved its preload)."""
    result = bearing.pair_load_distribution_si(radial_load, axial_load, moment, arrangement=arrangement,
                                               preload=preload, row_spacing=row_spacing)
    axial = result.row_axial_loads
    relieved = any(not np.any(result.loaded[result.row == k]) for k in (0, 1))
    return {**_load_outputs(result), "ball_row": result.row.astype(float), "axial_load_row0": float(axial[0]),
            "axial_load_row1": float(axial[1]), "preload_relieved": bool(relieved)}


def _load_outputs(result) -> dict:
    """The outputs :data:`BALL_LOADS` of a load distribution (one bearing's or a pair's)."""
    angles = result.contact_angle[result.loaded]
    return {
        "ball_azimuth": result.azimuth, "Q": result.Q, "contact_angle": result.contact_angle,
        "loaded": result.loaded.astype(bool), "ball_approach": result.approach, "Q_max": result.Q_max,
        "loaded_balls": float(result.loaded.sum()), "load_zone": result.load_zone, "delta_r": result.delta_r,
        "delta_a": result.delta_a, "ring_tilt": result.tilt, "tilting_moment": result.moment,
        "contact_angle_max": float(angles.max()) if angles.size else math.nan,
        "contact_angle_min": float(angles.min()) if angles.size else math.nan,
        "force_residual": result.residual,
    }


def _contact_radii(ball_diameter, pitch_diameter, osculations, angle):
    return {race: ball_race_radii(ball_diameter, pitch_diameter, osculations[race], angle, race) for race in RACES}


HERTZ = (*(f"{q}_{race}" for q in ("a_rolling", "a_transverse", "p_h") for race in RACES), "p_h_max",
         "stress_limit_exceeded")


@step("hertz", provides=HERTZ, model="hertz_elliptical (exact)")
def ball_hertz(Q, contact_angle, ball_diameter, pitch_diameter, osculations, E_reduced, contact_stress_limit):
    """Exact elliptical Hertz contact of every loaded ball at the inner and outer raceway at its own contact
    angle: semi-axes along and across rolling [m] and peak pressure [Pa] per ball (NaN unloaded), the bearing's
    peak pressure and whether it exceeds ``contact_stress_limit`` [Pa] (ISO 76's 4.2 GPa by default; a
    :class:`ValidityWarning` names it)."""
    out = {f"{q}_{race}": np.full(Q.size, np.nan) for q in ("a_rolling", "a_transverse", "p_h") for race in RACES}
    for j in np.flatnonzero(Q > 0.0):
        radii = _contact_radii(ball_diameter, pitch_diameter, osculations, contact_angle[j])
        for race in RACES:
            contact = hertz_elliptical(Q[j], *radii[race], E_reduced)
            out[f"a_rolling_{race}"][j], out[f"a_transverse_{race}"][j] = contact.a_x, contact.a_y
            out[f"p_h_{race}"][j] = contact.p_max
    pressures = np.concatenate([out[f"p_h_{race}"] for race in RACES])
    p_max = float(np.nanmax(pressures)) if np.any(np.isfinite(pressures)) else 0.0
    exceeded = p_max > contact_stress_limit
    if exceeded:
        warnings.warn(f"ball bearing: p_h = {p_max * 1e-9:.3g} GPa exceeds the contact stress limit "
                      f"{contact_stress_limit * 1e-9:.3g} GPa (LoadedBallBearing.contact_stress_limit; default: ISO "
                      "76:2006, static rating of ball bearings, 4.2 GPa)", ValidityWarning, stacklevel=2)
    return {**out, "p_h_max": p_max, "stress_limit_exceeded": bool(exceeded)}


#: what :func:`ball_truncation` provides
TRUNCATION = (*(f"{q}_{race}" for q in ("truncation_margin", "truncated") for race in RACES), "truncated_balls")


@step("truncation", provides=TRUNCATION, model="shoulder angle")
def ball_truncation(Q, contact_angle, a_transverse_inner, a_transverse_outer, shoulder_angles, osculations,
                    ball_diameter):
    """Whether each loaded ball's contact ellipse runs over a shoulder: the ellipse reaches |alpha| + a_y / r from the
    radial direction seen from the groove's curvature centre (a_y its half-width across rolling [m], r = f D_w the
    groove radius [m]); the shoulder sits at ``shoulder_angles[race]`` [rad]
    (:attr:`camcontact.components.BallBearing.shoulder_angles`). Per ball and race the margin theta_s - |alpha| -
    a_y / r [rad] (negative: truncated; NaN for unloaded balls) and ``truncated``; the number of balls truncated at
    either raceway. The Hertz pressure of a truncated contact rises above the untruncated one computed here."""
    loaded = Q > 0.0
    widths = {"inner": a_transverse_inner, "outer": a_transverse_outer}
    out = {}
    for race in RACES:
        reach = np.abs(contact_angle) + widths[race] / (osculations[race] * ball_diameter)
        margin = np.where(loaded, shoulder_angles[race] - reach, np.nan)
        out[f"truncation_margin_{race}"] = margin
        out[f"truncated_{race}"] = loaded & (np.nan_to_num(margin, nan=1.0) < 0.0)
    out["truncated_balls"] = float(np.count_nonzero(out["truncated_inner"] | out["truncated_outer"]))
    return out


@step("subsurface", provides=("tau_max", "z_tau_max", "von_mises_max", "z_von_mises_max", "most_loaded_race"),
      model="boussinesq_axis")
def ball_subsurface(Q, a_rolling_inner, a_transverse_inner, p_h_inner, a_rolling_outer, a_transverse_outer, p_h_outer,
                    nu):
    """The largest principal (Tresca) shear and von Mises stress [Pa] and their depths [m] below the contact
    with the highest pressure (frictionless, on its axis; Johnson 1985 Eqs. 3.19, 3.45), and its race; zero
    when no ball is loaded."""
    if not np.any(Q > 0.0):
        return {"tau_max": 0.0, "z_tau_max": 0.0, "von_mises_max": 0.0, "z_von_mises_max": 0.0,
                "most_loaded_race": "none"}
    race = "inner" if np.nanmax(p_h_inner) >= np.nanmax(p_h_outer) else "outer"
    a_x, a_y, p = {"inner": (a_rolling_inner, a_transverse_inner, p_h_inner),
                   "outer": (a_rolling_outer, a_transverse_outer, p_h_outer)}[race]
    j = int(np.nanargmax(p))
    found = point_subsurface(a_x[j], a_y[j], p[j], nu)
    return {"tau_max": found.tresca_max, "z_tau_max": found.z_tresca_max, "von_mises_max": found.von_mises_max,
            "z_von_mises_max": found.z_von_mises_max, "most_loaded_race": race}


@step("kinematics", provides=("cage_speed", "ball_speed", "u_m"), model="pure_rolling")
def ball_kinematics(n_inner, n_outer, contact_angle, Q, free_contact_angle, ball_diameter, pitch_diameter):
    """Pure rolling without spin (Harris & Kotzalas 2007 ch. 8) at each ball's contact angle (the free one
    for an unloaded ball), gamma = D cos(alpha)/d_m: entrainment speed of both contacts of each ball
    u_m = (pi d_m / 2)(1 - gamma^2)|n_i - n_o| [m/s]; the ball's speed about its axis
    2 pi (d_m / 2D)(1 - gamma^2)|n_i - n_o| [rad/s]; and the cage speed
    pi [n_i (1 - gamma) + n_o (1 + gamma)] [rad/s] at the contact angle of the most loaded ball."""
    angle = np.where(Q > 0.0, contact_angle, free_contact_angle)
    gamma = ball_diameter * np.cos(angle) / pitch_diameter
    relative = abs(n_inner - n_outer)
    most = float(gamma[int(np.argmax(Q))])
    return {"cage_speed": math.pi * (n_inner * (1.0 - most) + n_outer * (1.0 + most)),
            "ball_speed": 2.0 * math.pi * pitch_diameter / (2.0 * ball_diameter) * (1.0 - gamma**2) * relative,
            "u_m": 0.5 * math.pi * pitch_diameter * (1.0 - gamma**2) * relative}


@step("film", provides=("h_c_inner", "h_c_outer", "h_min_inner", "h_min_outer", "h_min_bearing", "film_validity",
                        "film_valid"),
      model=model_name, version=model_version)
def ball_films(film_model, Q, contact_angle, u_m, ball_diameter, pitch_diameter, osculations, E_reduced, eta0, alpha,
               piezoviscosity, lubricant_state, density_law):
    """Films [m] at the inner and outer raceway of every loaded ball by the point ``film_model`` (reduced radii at
    the ball's contact angle, its entrainment speed u_m [m/s]), NaN for unloaded balls; the bearing's thinnest
    film (h_min, or h_c for a model without one); the validity of the model at every contact ("ok" or its
    warnings, named by model, race and ball) and ``film_valid``."""
    films = films_of(film_model)
    out = {f"{q}_{race}": np.full(Q.size, np.nan) for q in films for race in RACES}
    if np.max(u_m) <= 0.0:
        raise InputError("ball bearing scene: the rings do not turn relative to each other (speed = outer_speed): "
                         "no entrainment, no steady film")
    warned: dict[str, list[tuple[int, str]]] = {race: [] for race in RACES}
    for j in np.flatnonzero(Q > 0.0):
        radii = _contact_radii(ball_diameter, pitch_diameter, osculations, contact_angle[j])
        for race in RACES:
            Rx, Ry = radii[race]
            produced = film_model({"Rx": Rx, "Ry": Ry, "F": Q[j], "E_reduced": E_reduced, "u_m": u_m[j], "eta0": eta0,
                                   "alpha": alpha if piezoviscosity else 0.0, "lubricant_state": lubricant_state,
                                   "density_law": density_law})
            for q in films:
                out[f"{q}_{race}"][j] = produced[q]
            warned[race] += [(int(j), m) for m in film_model.check_validity(dict(produced))]
    basis = "h_min" if "h_min" in films else "h_c"
    values = np.concatenate([out[f"{basis}_{race}"] for race in RACES])
    out["h_min_bearing"] = float(np.nanmin(values)) if np.any(np.isfinite(values)) else math.nan
    messages = [_validity_note(film_model.name, race, notes, int(np.count_nonzero(Q > 0.0)))
                for race, notes in warned.items() if notes]
    out["film_validity"] = "ok" if not messages else "; ".join(messages)
    out["film_valid"] = not messages
    return out


def _validity_note(model: str, race: str, notes: list[tuple[int, str]], loaded: int) -> str:
    """One note per raceway: the model, how many loaded balls it warns at, and the first ball's warning."""
    balls = sorted({j for j, _ in notes})
    first = balls[0]
    text = "; ".join(m for j, m in notes if j == first)
    return f"{model} ({race} raceway, {len(balls)} of {loaded} loaded balls; ball {first}): {text}"


@step("equivalent_load", provides=("P", "e", "X", "Y"), model="iso281_ball")
def ball_bearing_equivalent_load(radial_load, axial_load, kind, rating_contact_angle, C0, f0, ball_count,
                                 ball_diameter):
    """Dynamic equivalent load P = X F_r + Y F_a [N] of a radial ball bearing with its factors e, X, Y
    (ISO 281:2007 Table 3; :func:`camcontact.models.iso281_ball.ball_equivalent_load`)."""
    return ball_equivalent_load(radial_load, axial_load, kind=kind, contact_angle=rating_contact_angle, C0=C0, f0=f0,
                                ball_count=ball_count, ball_diameter=ball_diameter)


@step("static_safety", provides=("P0", "s0"), model="iso76_ball")
def ball_static_safety(radial_load, axial_load, kind, rating_contact_angle, C0):
    """Static equivalent load P0 [N] (ISO 76:2006 §6.2, X0 F_r + Y0 F_a, at least F_r) and the static safety
    factor s0 = C0 / P0 [-] (infinite without load)."""
    P0 = static_equivalent_load(radial_load, axial_load, kind=kind, contact_angle=rating_contact_angle)
    return {"P0": P0, "s0": C0 / P0 if P0 > 0.0 else math.inf}


@step("reference_life", provides=("L10r", "L10rh"), model="iso_ts_16281_ball")
def ball_reference_life(Q, C, ball_diameter, pitch_diameter, rating_contact_angle, osculations, n_inner, n_outer):
    """ISO/TS 16281:2008 basic reference rating life L_10r [revolutions] from the ball loads Q [N] of the load
    distribution (:func:`camcontact.models.iso281_ball.reference_rating_life`; the ring that turns faster turns
    against the load) and in time [s] at the rings' relative speed |n_i - n_o| [rev/s]."""
    life = reference_rating_life(Q, C=C, ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                                 contact_angle=rating_contact_angle, inner_osculation=osculations["inner"],
                                 outer_osculation=osculations["outer"], inner_rotates=abs(n_inner) >= abs(n_outer))
    return _life_in_time(life["L10r"], n_inner, n_outer)


def _life_in_time(L10r_million: float, n_inner: float, n_outer: float) -> dict[str, float]:
    """L10r [revolutions] from [10^6 revolutions] and in time [s] at the rings' relative speed [rev/s]."""
    L10r = L10r_million * 1e6
    relative = abs(n_inner - n_outer)
    return {"L10r": L10r, "L10rh": L10r / relative if relative > 0 else math.inf}


@step("equivalent_load", provides=("P", "e", "X", "Y"), model="iso281_ball_pair")
def ball_pair_equivalent_load(radial_load, axial_load, arrangement, rating_contact_angle, C0, f0, ball_count,
                              ball_diameter):
    """Dynamic equivalent load P = X F_r + Y F_a [N] of a pair of angular-contact bearings under the pair's loads with
    its factors e, X, Y (ISO 281:2007 Table 3: the double-row columns back to back and face to face, the single-row
    ones in tandem; :func:`camcontact.models.iso281_ball.pair_equivalent_load`; ``C0`` [N] and ``ball_count`` of one
    bearing). Its life is rated against the pair's C = 2^0.7 C (graph input ``C_pair``)."""
    return pair_equivalent_load(radial_load, axial_load, arrangement=arrangement, contact_angle=rating_contact_angle,
                                C0=C0, f0=f0, ball_count=ball_count, ball_diameter=ball_diameter)


@step("static_safety", provides=("P0", "s0"), model="iso76_ball_pair")
def ball_pair_static_safety(radial_load, axial_load, arrangement, rating_contact_angle, C0_pair):
    """Static equivalent load P0 [N] of a pair (ISO 76:2006: back to back / face to face F_r + 2 Y_0 F_a, in tandem
    the single row's; :func:`camcontact.models.iso281_ball.pair_static_equivalent_load`) and the static safety
    factor s0 = C0_pair / P0 [-] with the pair's static rating 2 C_0 [N] (infinite without load)."""
    P0 = pair_static_equivalent_load(radial_load, axial_load, arrangement=arrangement,
                                     contact_angle=rating_contact_angle)
    return {"P0": P0, "s0": C0_pair / P0 if P0 > 0.0 else math.inf}


@step("reference_life", provides=("L10r", "L10rh"), model="iso_ts_16281_ball_pair")
def ball_pair_reference_life(Q, ball_row, C, ball_diameter, pitch_diameter, rating_contact_angle, osculations, n_inner,
                             n_outer):
    """ISO/TS 16281:2008 basic reference rating life L_10r [revolutions] of a pair from the ball loads Q [N] of both
    bearings and their ``ball_row``: each bearing's with its own C [N], combined with the Weibull slope 10/9
    (:func:`camcontact.models.iso281_ball.pair_reference_rating_life`, as
    :meth:`camcontact.components.BallBearing.pair_reference_life`), and in time [s] at |n_i - n_o| [rev/s]."""
    life = pair_reference_rating_life(Q, np.asarray(ball_row).astype(int), C=C, ball_diameter=ball_diameter,
                                      pitch_diameter=pitch_diameter, contact_angle=rating_contact_angle,
                                      inner_osculation=osculations["inner"], outer_osculation=osculations["outer"],
                                      inner_rotates=abs(n_inner) >= abs(n_outer))
    return _life_in_time(life["L10r"], n_inner, n_outer)
