"""The film over a cam cycle: EHL groups per angle, quasi-steady films (formulas, or the numerical film in
warm-started chains on threads), or one transient march with the squeeze term.

The quasi-steady film of each angle is the steady film of its load, radius and entrainment speed
(Tsuha 2015 §6); the numerical one (film model ``"multigrid"``) is warm-started from the previous
angle, a dwell is solved once, an angle the solver cannot do falls back to the Pan–Hamrock formula
with the reason in ``film_regime``. The ``squeeze`` effect solves the turn as one transient
(:func:`camcontact.ehl.line_transient.transient_cycle`). Arrays are over the scene's cam angles
[rad]; loads per length [N/m], radii and films [m], speeds [m/s].
"""

from __future__ import annotations

import math
import os
import warnings
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from .. import registry
from ..ehl.groups import hamrock_line, moes_line
from ..errors import ConvergenceError, InputError
from ..models.film_line import LINE_INPUTS
from ..step_graph import step
from ..models.film_thermal import thermal_reduction
from .film import FILMS, check_thermal_data, films_of, model_name, model_version
from .kinematics import degrees_text

__all__ = [
    "MIN_CHAIN", "STEADY_M_LIMIT", "chain_count", "cycle_ehl_groups", "cycle_inlet_thermal", "numerical_film_details",
    "march_domain", "march_laws", "march_order", "quasi_steady_films", "solve_chain", "solve_numerically",
    "spike_height",
    "steadiest_angle", "thermal_transient_films", "transient_films",
]

#: beyond this Moes M (entrainment speed near zero) no steady solution is attempted: the steady
#: film tends to zero and the real film lives on squeeze (the ``squeeze`` effect solves it transiently)
STEADY_M_LIMIT = 2000.0
#: the fewest distinct angles per warm-started chain (each chain starts cold, ~0.1-0.4 s at level 8)
MIN_CHAIN = 16
FILM_OUTPUTS = (*FILMS, "film_regime", "film_valid", "film_solutions")


@step("ehl_groups", provides=("alpha_effective", "U", "G", "W", "M", "L"))
def cycle_ehl_groups(w, R, E_reduced, u_m, eta0, alpha, piezoviscosity, film_speed_factor):
    """U, G, W, M, L [-] at every angle for the film speed |u_m| x ``film_speed_factor`` (0.5 in the thesis
    convention, which feeds the films the mean speed where Moes uses the sum); M = inf where the
    contact is loaded but nothing entrains, 0 where it is not loaded. Inputs: arrays over the angles
    w [N/m], R [m], u_m [m/s]; E' [Pa], eta0 [Pa s], alpha [1/Pa]; alpha_effective [1/Pa] out."""
    alpha = alpha if piezoviscosity else 0.0
    u = np.abs(u_m) * film_speed_factor
    n = u.size
    U, G, W, M, L = (np.zeros(n) for _ in range(5))
    for i in range(n):
        if w[i] > 0.0 and u[i] > 0.0:
            U[i], G[i], W[i] = hamrock_line(float(w[i]), float(R[i]), E_reduced, float(u[i]), eta0, alpha)
            M[i], L[i] = moes_line(U[i], G[i], W[i])
        else:
            G[i] = alpha * E_reduced
            M[i] = math.inf if w[i] > 0.0 else 0.0
    return {"alpha_effective": alpha, "U": U, "G": G, "W": W, "M": M, "L": L}


def check_squeeze(film_model) -> None:
    """InputError unless the film model is the numerical ``multigrid`` (the squeeze effect needs it)."""
    if getattr(film_model, "name", "") != "multigrid":
        raise InputError("the 'squeeze' effect solves the film numerically over the turn: use the film model "
                         "'multigrid' (models={'film': 'multigrid'}), or leave the effect off for the "
                         f"quasi-steady {getattr(film_model, 'name', 'formula')} film")


@step("film", provides=FILM_OUTPUTS, model=model_name, version=model_version)
def quasi_steady_films(film_model, w, R, E_reduced, u_m, eta0, alpha_effective, U, G, W, M, L, lubricant_state,
                       density_law, contact_open, film_speed_factor):
    """Films [m] at every angle: steady solutions, warm-started, cached (a dwell is solved once).

    Numerical solves run as warm-started chains along the cycle: the distinct contact states in
    angle order are cut into :func:`chain_count` arcs, solved side by side in threads (the compiled
    kernels release the GIL), each arc warm-started angle by angle from a cold start. ``film_regime``
    says per angle "ok" or why not (contact lost, u_m = 0, reversal, fallback, validity, convergence);
    ``film_solutions`` holds the numerical solutions (None elsewhere).
    """
    u_film = np.abs(u_m) * film_speed_factor
    n = u_film.size
    films = films_of(film_model)
    values = {q: np.zeros(n) for q in films}
    regime = np.empty(n, dtype=object)
    solutions: list = [None] * n
    numerical = getattr(film_model, "name", "") == "multigrid"
    fallback = registry.get("film_models", "pan_hamrock") if numerical else None
    # the samples on both sides of a sign change of u_m bracket an entrainment reversal
    sign = np.sign(np.asarray(u_m, dtype=float))
    reversal = np.zeros(n, dtype=bool)
    change = sign[:-1] * sign[1:] < 0.0
    reversal[:-1] |= change
    reversal[1:] |= change
    # --- plan: which angles need which solve (identical inputs share one)
    keys: list = [None] * n
    states: dict = {}  # key -> (state, model to use, note)
    for i in range(n):
        if contact_open[i] or w[i] <= 0.0:
            for q in films:
                values[q][i] = np.nan
            regime[i] = "contact lost (jump): no film"
            continue
        if u_film[i] == 0.0:
            regime[i] = "u_m = 0: no steady film (the squeeze film needs the transient solution: effect 'squeeze')"
            continue
        state = {"R": float(R[i]), "w": float(w[i]), "E_reduced": E_reduced, "u_m": float(u_film[i]),
                 "eta0": eta0, "alpha": alpha_effective, "lubricant_state": lubricant_state,
                 "density_law": density_law}
        key = keys[i] = tuple(state[k] for k in LINE_INPUTS)
        if key in states:
            continue
        use, note = film_model, ""
        if numerical and M[i] > STEADY_M_LIMIT:
            use, note = fallback, (f"u_m ≈ 0 (|u_m| = {abs(u_m[i]):.3g} m/s, M = {M[i]:.4g} > "
                                   f"{STEADY_M_LIMIT:g}): Pan–Hamrock formula; squeeze film: effect 'squeeze'")
        states[key] = (state, use, note)
    # --- solve: formulas directly, the numerical film in warm-started chains
    cache: dict = {}
    chain = [key for key, (_, use, _) in states.items() if use is film_model and numerical]
    for key, (state, use, note) in states.items():
        if key not in chain:
            cache[key] = (use(state), use, note)
    if chain:
        arcs = [list(arc) for arc in np.array_split(np.arange(len(chain)), chain_count(film_model, len(chain)))]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the record says it; the regime column reports it
            if len(arcs) == 1:
                results = [solve_chain(film_model, fallback, [states[chain[j]][0] for j in arcs[0]])]
            else:
                with ThreadPoolExecutor(len(arcs)) as pool:
                    results = list(pool.map(
                        lambda arc: solve_chain(film_model, fallback, [states[chain[j]][0] for j in arc]), arcs))
        for arc, produced_arc in zip(arcs, results):
            for j, entry in zip(arc, produced_arc):
                cache[chain[j]] = entry
    # --- fill the angles
    groups = {"U": U, "G": G, "W": W, "M": M, "L": L}
    for i in range(n):
        if keys[i] is None:
            continue
        produced, use, note = cache[keys[i]]
        for q in films:
            values[q][i] = produced[q]
        messages = [note] if note else []
        record = produced.get("convergence")
        if record is not None:
            solutions[i] = produced.get("ehl_solution")
            if not record.converged:
                messages.append(f"not converged: {record.message}")
        elif use is film_model:
            messages += [f"{use.name}: {message}" for message in use.check_validity({k: v[i] for k, v in groups.items()})]
        if (M[i] > STEADY_M_LIMIT or reversal[i]) and not note:
            messages.insert(0, f"u_m ≈ 0: entrainment reversal (u_m = {u_m[i]:.3g} m/s, M = {M[i]:.4g}); "
                               "the steady film → 0 there; squeeze film: effect 'squeeze'")
        regime[i] = "; ".join(messages) if messages else "ok"
    return {**values, "film_regime": regime, "film_valid": np.array([r == "ok" for r in regime], dtype=bool),
            "film_solutions": solutions}


def steadiest_angle(w: np.ndarray, R: np.ndarray, u: np.ndarray) -> int:
    """Index of the angle whose neighbours differ least in w [N/m], R [m] and u [m/s] (arrays over the
    angles; the base circle of a cam): the transient march starts there from the steady film, so its
    start is the periodic state."""
    def change(a):
        scale = np.max(np.abs(a)) or 1.0
        return (np.abs(a - np.roll(a, 1)) + np.abs(np.roll(a, -1) - a)) / scale

    score = change(w) + change(R) + change(u)
    score[u == 0.0] = np.inf
    return int(np.argmin(score))


def march_order(cam_angle, angular_speed, w, R, u, contact_open) -> tuple[np.ndarray, np.ndarray]:
    """(order, times [s]) of a transient march over the turn: the angles from the steadiest one
    (:func:`steadiest_angle`) round the turn and the times of those instants; InputError unless the contact is
    closed at every angle and the cam turns at a constant speed over at least 3 angles."""
    theta, omega = np.asarray(cam_angle, dtype=float), float(angular_speed[0])
    open_ = np.asarray(contact_open) | (np.asarray(w) <= 0.0)
    if np.any(open_):
        raise InputError(f"the squeeze (transient) film needs contact at every angle; the follower leaves the cam at "
                         f"{degrees_text(theta[open_][:3])}: stiffen the spring or lower the speed")
    if not np.allclose(angular_speed, omega) or theta.size < 3:
        raise InputError("the squeeze (transient) film needs a constant cam speed and at least 3 angles over the turn")
    start = steadiest_angle(np.asarray(w), np.asarray(R), u)
    order = np.roll(np.arange(theta.size), -start)
    return order, np.mod(theta[order] - theta[start], 2.0 * np.pi) / omega


def march_laws(lubricant_state, piezoviscosity, alpha_effective) -> dict:
    """The viscosity law keywords of a transient march: Roelands with the lubricant's z where its pressure law
    is Roelands and piezoviscosity is on, else Barus (alpha 0 without piezoviscosity)."""
    roelands = getattr(lubricant_state.pressure_law, "name", "roelands") == "roelands" and piezoviscosity
    return {"alpha": alpha_effective if piezoviscosity else 0.0, "z": lubricant_state.roelands_z if roelands else None,
            "viscosity": "roelands" if roelands else "barus"}


def _in_order(order, *series) -> list[np.ndarray]:
    """Arrays over the march (``order``) back in the scene's angle order."""
    out = []
    for values in series:
        back = np.empty(len(values), dtype=np.asarray(values).dtype)
        back[order] = values
        out.append(back)
    return out


def march_domain(film_model, u_m) -> tuple | None:
    """The transient march's domain [X_a, X_b] (units of its reference half-width) from the film model's ``domain``:
    as given while the entrainment u_m [m/s] keeps one direction, made symmetric, (min(X_a, -X_b), max(X_b, -X_a)),
    when it reverses (either end is then the inlet); None (the model's domain None): the march's automatic domain
    (:func:`~camcontact.ehl.line_transient.automatic_transient_domain`)."""
    domain = getattr(film_model, "domain", None)
    if domain is None:
        return None
    X_a, X_b = (float(x) for x in domain)
    u = np.asarray(u_m, dtype=float)
    if np.any(u > 0.0) and np.any(u < 0.0):
        return (min(X_a, -X_b), max(X_b, -X_a))
    return (X_a, X_b)


@step("film", provides=(*FILM_OUTPUTS, "x_min"),
      model=lambda film_model: f"{model_name(film_model)} (transient, squeeze)", version=model_version,
      check=check_squeeze)
def transient_films(film_model, w, R, E_reduced, u_m, eta0, alpha_effective, lubricant_state, density_law,
                    contact_open, film_speed_factor, piezoviscosity, cam_angle, angular_speed, **inputs):
    """Films [m] over the turn from one transient march with the squeeze term (the ``squeeze`` effect):
    implicit BDF2 steps from angle to angle through any entrainment reversal, from the steady film at
    the steadiest angle; needs contact and a constant cam speed at every angle. The march's domain is the film
    model's ``domain`` (units of the reference half-width, :func:`~camcontact.ehl.line_transient.transient_cycle`;
    symmetric through a reversal, :func:`march_domain`) or
    :func:`~camcontact.ehl.line_transient.automatic_transient_domain` (in one direction the inlet of the steady
    automatic domain, :func:`~camcontact.ehl.line_transient.march_inlet`; through a reversal [-4, 4]).
    Optional ``oil_layer`` [m]: a starved inflow (the film model's cavitation ``"mass_conserving"``;
    :class:`~camcontact.ehl.line_transient.TransientLineSolver`), whose march starts from the steady starved film;
    ``x_min`` [m]: where the film is thinnest, from the contact centre, positive in the direction of u_m > 0."""
    from ..ehl.line_transient import transient_cycle

    u = np.asarray(u_m, dtype=float) * film_speed_factor
    order, times = march_order(cam_angle, angular_speed, w, R, u, contact_open)
    result = transient_cycle(
        times, np.asarray(w)[order], np.asarray(R)[order], u[order], E_reduced=E_reduced, eta0=eta0,
        **march_laws(lubricant_state, piezoviscosity, alpha_effective), density=density_law,
        levels=film_model.levels, tolerance=max(film_model.tolerance, 1e-6), strict=film_model.strict,
        cavitation=getattr(film_model, "cavitation", "reynolds"), oil_layer=inputs.get("oil_layer"),
        domain=march_domain(film_model, u))
    h_c, h_min, x_min, converged = _in_order(order, result.h_c, result.h_min, result.x_min,
                                             np.asarray(result.converged, dtype=bool))
    messages = _in_order(order, np.array([record.message for record in result.records], dtype=object))[0]
    regime = np.empty(u.size, dtype=object)
    for i in range(u.size):
        note = "transient (squeeze)" + (" at u_m = 0" if u[i] == 0.0 else "")
        regime[i] = note if converged[i] else f"{note}: not converged: {messages[i]}"
    return {"h_c": h_c, "h_min": h_min, "film_regime": regime, "film_valid": converged,
            "film_solutions": [None] * u.size, "x_min": x_min}


@step("film", provides=(*FILM_OUTPUTS, "film_temperature_rise", "film_thermal", "x_min"),
      model=lambda film_model: f"{model_name(film_model)} (transient, squeeze, "
                               f"{'thermal' if film_model.thermal else 'non-Newtonian'})",
      version=model_version, check=check_squeeze)
def thermal_transient_films(film_model, w, R, E_reduced, u_cam, u_follower, eta0, alpha_effective, lubricant_state,
                            density_law, contact_open, film_speed_factor, piezoviscosity, cam_angle, angular_speed,
                            **inputs):
    """Films [m] over the turn from one transient march with the squeeze term and the film model's thermal and/or
    non-Newtonian film (the ``squeeze`` effect with ``thermal`` or ``non_newtonian`` and the ``multigrid`` film;
    :func:`camcontact.ehl.line_thermal.thermal_transient_cycle`: the energy equation across the film with the
    surfaces' flash-temperature conduction after each step, its flow factors in the next one). The surface speeds
    u_cam, u_follower [m/s] (times ``film_speed_factor``) heat the film; the film model's ``cavitation`` and the
    optional ``oil_layer`` [m] (a starved inflow) as in :func:`transient_films`; ``effusivity`` (a pair
    [W s^0.5/(m^2 K)]) and the lubricant's thermal data are needed with ``thermal``.

    ``film_temperature_rise`` [K]: the largest mean film temperature rise over the contact at each angle; NaN
    where the energy equation cannot run (a surface at rest or moving against the entrainment: a flat face on
    the base circle and around its reversal) and everywhere without ``thermal`` (an isothermal Eyring march);
    ``film_thermal`` (bool) says where it ran. Where the flow factors an angle's film took came from a viscosity
    profile that reached its bound (:attr:`camcontact.ehl.line_thermal.ThermalTransientResult.profile_bounded`),
    ``film_valid`` is False and ``film_regime`` says why.
    The film of an angle takes the flow factors of the last angle's solution across the film, so the march's
    first angle (the steadiest one) and the angle after one without such a solution have an isothermal
    (Newtonian) film; ``film_regime`` says so."""
    from ..ehl.line_thermal import profile_bound_note, thermal_transient_cycle

    u1 = np.asarray(u_cam, dtype=float) * film_speed_factor
    u2 = np.asarray(u_follower, dtype=float) * film_speed_factor
    u = 0.5 * (u1 + u2)
    order, times = march_order(cam_angle, angular_speed, w, R, u, contact_open)
    alpha = alpha_effective if piezoviscosity else 0.0
    first = order[0]
    # the model's problem gives the contact its laws (as the steady thermal solve's)
    problem = film_model.problem(float(R[first]), float(w[first]), E_reduced, float(abs(u[first])) or 1.0, eta0,
                                 alpha, lubricant_state, density_law)
    # the contact's own speeds are not used by the march (any positive pair)
    contact = film_model.thermal_contact(problem, float(R[first]), float(w[first]), E_reduced,
                                         float(np.max(np.abs(u1))) or 1.0, float(np.max(np.abs(u2))) or 1.0, eta0,
                                         alpha, lubricant_state, inputs.get("effusivity"))
    result = thermal_transient_cycle(
        times, np.asarray(w)[order], np.asarray(R)[order], u1[order], u2[order], contact=contact,
        levels=film_model.levels, thermal=film_model.thermal, non_newtonian=film_model.non_newtonian,
        tolerance=max(film_model.tolerance, 1e-6), strict=film_model.strict,
        cavitation=getattr(film_model, "cavitation", "reynolds"), oil_layer=inputs.get("oil_layer"),
        domain=march_domain(film_model, u))
    films = result.films
    energy = np.asarray(result.thermal, dtype=bool)  # the energy equation ran after the instant's film
    heated = np.concatenate([[False], energy[:-1]])  # the instant's film took the last instant's flow factors
    # ... and those of a viscosity profile that reached its bound (shear bands the film points do not resolve)
    bounded = np.concatenate([[0], np.asarray(result.profile_bounded)[:-1]])
    h_c, h_min, x_min, converged, energy, heated, rise, bounded = _in_order(
        order, films.h_c, films.h_min, films.x_min, np.asarray(films.converged, dtype=bool), energy, heated,
        result.temperature_rise, bounded)
    messages = _in_order(order, np.array([record.message for record in films.records], dtype=object))[0]
    kind = "thermal" if film_model.thermal else "non-Newtonian"
    regime = np.empty(u.size, dtype=object)
    for i in range(u.size):
        note = (f"transient (squeeze, {kind})" if heated[i] else
                f"transient (squeeze), {'isothermal' if film_model.thermal else 'Newtonian'} here: "
                + ("the march's start" if i == first else "a surface did not move with the entrainment"))
        if bounded[i]:
            note += "; " + profile_bound_note(int(bounded[i]))
        regime[i] = note if converged[i] else f"{note}: not converged: {messages[i]}"
    return {"h_c": h_c, "h_min": h_min, "film_regime": regime, "film_valid": converged & (bounded == 0),
            "film_solutions": [None] * u.size, "x_min": x_min,
            "film_temperature_rise": np.where(energy & film_model.thermal, rise, np.nan),
            "film_thermal": energy & film_model.thermal}


def spike_height(solution) -> float:
    """P_s of a numerical solution's pressure spike; NaN when it has no distinct spike (a single pressure
    maximum), 0 where no numerical solution was made (contact lost, u_m = 0, formula fallback)."""
    if solution is None:
        return 0.0
    spike = solution.spike
    return math.nan if spike is None else spike[0]


@step("ehl_details", provides=("H0", "H_min", "H_c", "spike_pressure", "pressure_spike"))
def numerical_film_details(film_solutions):
    """H0, H_min, H_c and the spike height P_s [-] of the numerical solution at every angle (0 where
    there is none; NaN where the solution has no distinct spike, which ``pressure_spike`` (bool) says);
    InputError when the film model is not numerical."""
    if all(sol is None for sol in film_solutions):
        raise InputError("H0, H_min, H_c and spike_pressure come from the numerical solution: use the film model "
                         "'multigrid'")
    pick = (lambda attr: np.array([getattr(sol, attr) if sol is not None else 0.0 for sol in film_solutions]))
    return {"H0": pick("H0"), "H_min": pick("H_min"), "H_c": pick("H_c"),
            "spike_pressure": (spike := np.array([spike_height(sol) for sol in film_solutions])),
            "pressure_spike": ~np.isnan(spike)}


def chain_count(model, solves: int) -> int:
    """How many warm-started chains (threads) the numerical film of a cycle uses: the model's
    ``threads`` (None: the CPUs, at most 4), but no chain shorter than :data:`MIN_CHAIN`."""
    threads = getattr(model, "threads", 1)
    threads = min(os.cpu_count() or 1, 4) if threads is None else int(threads)
    return max(1, min(threads, solves // MIN_CHAIN))


def solve_chain(model, fallback, states) -> list:
    """Solve the states in order, each warm-started from the numerical solutions of the two states before it
    (their extrapolation, a continuation in angle); an angle the solver cannot do falls back to the Pan–Hamrock
    formula with the reason, and the next one starts from the last solution only."""
    previous = before = None
    out = []
    for state in states:
        produced, failure = solve_numerically(model, state, previous, before)
        if produced is None:
            out.append((fallback(state), fallback, f"multigrid failed ({failure}): Pan–Hamrock formula"))
            before = None
            continue
        previous, before = produced["ehl_solution"], previous
        out.append((produced, model, ""))
    return out


def solve_numerically(model, state, previous, before=None):
    """Multigrid film warm-started from ``previous`` (extrapolated with ``before``, the solution before it); if
    that diverges or does not converge, once more from a cold (full-multigrid) start, keeping a converged result
    if either gives one. The caller silences the solver's ConvergenceWarning (the regime column reports it).

    Returns (produced, None) or (None, failure message).
    """
    failure = None
    best = None
    for initial in ((previous, None) if previous is not None else (None,)):
        try:
            produced = model.evaluate(**state, initial=initial, before=before if initial is not None else None)
        except ConvergenceError as exc:
            failure = str(exc).split(";")[0]
            continue
        if produced["convergence"].converged:
            return produced, None
        best = best or produced  # not converged: the record says so in the regime column
    return (best, None) if best is not None else (None, failure)


@step("thermal", provides=("thermal_loading_m", "thermal_factor", "thermal_valid"), model=lambda thermal_model: thermal_model,
      check=check_thermal_data)
def cycle_inlet_thermal(thermal_model, u_cam, u_follower, thermoviscous_coefficient, eta0, lubricant_conductivity,
                        p_h, E_reduced):
    """The thermal loading on the mean speed L_m = beta eta0 u_m^2 / k [-] and the inlet shear-heating
    factor phi_T [-] of the film at every cam angle, by ``thermal_model`` (a factor of
    :data:`camcontact.models.film_thermal.THERMAL_FACTORS`, with the slide-to-roll term where it has one;
    phi_T = 1 where the entrainment reverses) and whether the angle lies inside the fits' range: the surfaces
    move the same way, Z = |u1 - u2|/|u1 + u2| <= 1 (simple sliding, the largest slip of the sources'
    analyses; a flat face near its entrainment reversal lies beyond it)."""
    L_m, phi = thermal_reduction(thermal_model, thermoviscous_coefficient, eta0, u_cam, u_follower,
                                 lubricant_conductivity, p_h, E_reduced)
    total = np.abs(np.asarray(u_cam, dtype=float) + u_follower)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(total > 0.0, np.abs(np.asarray(u_cam, dtype=float) - u_follower) / total, np.inf)
    phi = np.asarray(phi, dtype=float)
    return {"thermal_loading_m": np.asarray(L_m, dtype=float), "thermal_factor": phi,
            "thermal_valid": np.isfinite(phi) & (ratio <= 1.0)}
