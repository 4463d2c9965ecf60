"""EHL friction steps: asperity load sharing (``mixed``), fluid traction from the film's rheology
(``non_newtonian``, with the contact temperature of ``thermal``) and their sum, per cam angle.

Mixed lubrication (:func:`camcontact.models.mixed_lubrication.mixed_line_contact`): Greenwood & Tripp's
(1970–71) asperity pressure over the Hertz area and Johnson, Greenwood & Poon's (1972, Wear 19:91–108) load
split, W = W/gamma1 (fluid) + W/gamma2 (asperities), the film at the fluid's share. Fluid traction
(:mod:`camcontact.contact.fluid_traction` through a ``traction_models`` model,
:mod:`camcontact.models.traction_fluid`): the shear stress of the central film integrated over the Hertz
pressure. The friction of a contact: F = mu_b W_asperity sign(u_s) + mu_fluid(u_s) W_fluid (Gelinck &
Schipper 2000, Tribol. Int. 33:175–181). Forces [N], speeds [m/s], films [m], pressures [Pa], temperatures [K].
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .. import registry
from ..dynamics.roller_follower import coulomb_table, slip_grid
from ..errors import InputError
from ..models.film_line import Moes
from ..models.film_point import Nijenbanning
from ..models.mixed_lubrication import mixed_line_contact, mixed_point_contact
from ..step_graph import step
from .contact import RACES

__all__ = ["ASPERITY_DEFAULTS", "EHL_EFFECTS", "FLUID_TRACTION_LIMIT", "MIXED_FRICTION_READS", "contact_ehl_friction", "ehl_friction_inputs",
           "ehl_sliding_friction", "fluid_traction_model", "BALL_CONE_MIXED_OUTPUTS", "ball_cone_mixed", "fluid_traction_table", "mixed_contact", "mixed_film_cycle", "ROLLER_MIXED_OUTPUTS",
           "roller_mixed"]

#: effects that replace Coulomb friction by the EHL friction of the film
EHL_EFFECTS = frozenset({"mixed", "non_newtonian"})
#: (eta beta sigma, sigma / beta) when the scene gives no asperity parameters: orders of magnitude of ground
#: steel surfaces as Stribeck-curve models use them (Gelinck & Schipper 2000), not data
ASPERITY_DEFAULTS = (0.05, 0.05)

#: the highest fluid traction coefficient measured in EHL contacts is about 0.1 (traction fluids, Saccheto 2008
#: Tabelas 4.2/4.3; Evans & Johnson 1986): a fluid coefficient above 0.15 flags the rheology as outside its
#: validity (a Newtonian film at Hertzian pressures without a limiting shear stress)
FLUID_TRACTION_LIMIT = 0.15
MIXED_OUTPUTS = ("asperity_load_fraction", "h_c_mixed", "Lambda_mixed", "lubrication_regime", "asperity_capacity",
                 "mixed_valid")
#: what the friction steps read with ``mixed``: the mixed step's share and film, the lubricant's boundary friction
MIXED_FRICTION_READS = ("asperity_load_fraction", "h_c_mixed", "boundary_friction")


def ehl_friction_inputs(lubricant: Any, materials: tuple, roughness: tuple, effects: frozenset, *,
                        asperity_density: float | None = None, asperity_radius: float | None = None) -> dict[str, Any]:
    """The graph inputs of the EHL friction of two surfaces of ``materials`` (each a
    :class:`~camcontact.components.Material`; empty: no effusivity here) with RMS ``roughness`` [m] (a pair, None where not given): the
    lubricant's boundary friction, the surfaces' thermal effusivities (when the materials give them) and, with
    ``mixed``, the asperity radius [m] and density [1/m^2] (given, or :data:`ASPERITY_DEFAULTS` with the
    composite roughness)."""
    inputs: dict[str, Any] = {}
    if lubricant is not None:
        inputs["boundary_friction"] = lubricant.boundary_friction
    try:
        if materials:  # none given: the scene states the effusivity itself
            inputs["effusivity"] = tuple(material.thermal_effusivity() for material in materials)
    except InputError:
        pass  # only a thermal traction model needs it: reported up front as missing
    if "mixed" in effects and None not in roughness:
        sigma = math.hypot(*roughness)
        product, ratio = ASPERITY_DEFAULTS
        radius = asperity_radius if asperity_radius is not None else sigma / ratio
        density = (asperity_density if asperity_density is not None
                   else product / (radius * sigma) if sigma > 0 else None)
        inputs |= {"asperity_radius": radius} | ({"asperity_density": density} if density else {})
    return inputs


def fluid_traction_model(lubricant: Any, effects: frozenset, spec: Any = None) -> Any:
    """A scene's fluid traction model: ``spec`` (a model, or a name of the ``traction_models`` family), else
    ``"eyring"`` with the ``non_newtonian`` effect, else ``"newtonian"`` — both bounded by the lubricant's
    limiting shear stress tau_L0 + Lambda_L p (Bair & Winer 1979): a Newtonian film without it would carry
    traction coefficients of order 10-1000 at Hertzian pressures, which no oil transmits (the unbounded
    textbook film stays available as ``models={"traction": NewtonianTraction(limiting_shear_slope=None)}``
    and is flagged by ``traction_valid``); parameters from the lubricant where it gives them
    (``eyring_stress``, ``limiting_shear_stress``, ``limiting_shear_slope``); thermal (its contact
    temperature) with the ``thermal`` effect."""
    if spec is not None and not isinstance(spec, str):
        return spec
    name = spec or ("eyring" if "non_newtonian" in effects else "newtonian")
    parameters: dict[str, Any] = {"thermal": "thermal" in effects}
    if lubricant is not None:
        given = {"eyring_stress": lubricant.si.eyring_stress, "limiting_shear_stress": lubricant.si.limiting_shear_stress,
                 "limiting_shear_slope": lubricant.limiting_shear_slope}
        parameters |= {k: v for k, v in given.items() if v is not None and (k != "eyring_stress" or name == "eyring")}
    try:
        return registry.get("traction_models", name, **parameters)
    except TypeError as exc:
        raise InputError(f"traction model {name!r} cannot take {sorted(parameters)} ({exc}); pass a model "
                         "instance as models={'traction': ...}") from None


@step("mixed", provides=MIXED_OUTPUTS, model="greenwood_tripp + johnson_greenwood_poon")
def mixed_film_cycle(w, R, E_reduced, u_m, eta0, alpha_effective, h_c, sigma, asperity_density, asperity_radius,
                     piezoviscosity):
    """Per angle: the asperity share of the load [-], the film at the fluid's share h_c [m], Lambda = h_c/sigma,
    the regime ("boundary", "mixed", "full_film"; "open" where the contact is open, "unknown" where the scene
    has no film), the asperities' capacity A_Hertz p_a(0)/W [-] and whether the model can reach the boundary
    regime there (``mixed_valid``: capacity >= 1 or Lambda >= 1 — below, the smooth film formulas cannot thin
    the film enough for the asperities to carry the load, and the asperity share is a lower bound).

    The load sharing runs on the scene's own film ``h_c`` (its film model, its thermal reduction): the Moes
    film of each load share is scaled by h_c / h_c(Moes, full load) (``film_scale`` of
    :func:`camcontact.models.mixed_lubrication.mixed_line_contact`)."""
    w, R, u_m, h_c = (np.asarray(v, dtype=float) for v in (w, R, u_m, h_c))
    n = w.size
    out = {"asperity_load_fraction": np.zeros(n), "h_c_mixed": np.full(n, np.nan), "Lambda_mixed": np.full(n, np.nan),
           "lubrication_regime": np.full(n, "open", dtype=object), "asperity_capacity": np.full(n, np.nan),
           "mixed_valid": np.zeros(n, dtype=bool)}
    h_c = np.broadcast_to(h_c, w.shape)
    # no entrainment (u_m = 0): no film by definition, the asperities carry the load (boundary), not unknown
    filmed = np.isfinite(h_c) & ((h_c > 0.0) | (np.broadcast_to(u_m, w.shape) == 0.0))
    out["lubrication_regime"][(w > 0.0) & ~filmed] = "unknown"
    out["asperity_load_fraction"][(w > 0.0) & ~filmed] = np.nan
    loaded = (w > 0.0) & filmed
    if loaded.any():
        speed = np.abs(u_m[loaded])
        scale = np.ones(speed.size)
        moving = speed > 0.0  # without entrainment the model has no film to scale (boundary lubrication)
        if moving.any():
            moes = Moes(piezoviscosity=piezoviscosity).evaluate(R[loaded][moving], w[loaded][moving], E_reduced,
                                                                 speed[moving], eta0, alpha_effective)["h_c"]
            scale[moving] = h_c[loaded][moving] / np.asarray(moes, dtype=float)
        result = mixed_line_contact(w[loaded], R[loaded], E_reduced, speed, eta0, alpha_effective, sigma,
                                    asperity_density, asperity_radius, piezoviscosity=piezoviscosity, film_scale=scale)
        out["asperity_load_fraction"][loaded] = result["asperity_load_fraction"]
        out["h_c_mixed"][loaded] = result["h_c"]
        out["Lambda_mixed"][loaded] = result["lambda_ratio"]
        out["lubrication_regime"][loaded] = result["regime"]
        out["asperity_capacity"][loaded] = result["asperity_capacity"]
        out["mixed_valid"][loaded] = (result["asperity_capacity"] >= 1.0) | (result["lambda_ratio"] >= 1.0)
    return out


def _traction_film(h_c, inputs) -> np.ndarray:
    """The film the fluid shears: the mixed film where the scene has one, else the central film."""
    return np.asarray(inputs.get("h_c_mixed", h_c), dtype=float)


def _shares(normal_force, inputs) -> tuple[np.ndarray, np.ndarray, float]:
    fraction = np.asarray(inputs.get("asperity_load_fraction", 0.0), dtype=float)
    return normal_force * fraction, normal_force * (1.0 - fraction), float(inputs.get("boundary_friction", 0.0))


def _fluid(traction_model, p_h, b, h, u_m, lubricant_state, inputs):
    """The prepared fluid contact per angle (open contacts and angles without a film: p_h = 0)."""
    usable = (np.asarray(p_h) > 0.0) & np.isfinite(h) & (h > 0.0) & (np.asarray(b) > 0.0)
    return traction_model.contact(np.where(usable, p_h, 0.0), np.where(usable, b, 1.0), np.where(usable, h, 1.0),
                                  np.where(usable, u_m, 1.0), lubricant_state, inputs.get("effusivity")), usable


def _on_numerical_pressure(traction_model, fluid, usable, solutions, p_h, b, h, u_s, u_m, lubricant_state, inputs):
    """``fluid`` with the angles that have a numerical line solution re-evaluated over its pressure and film
    profile (:meth:`camcontact.ehl.line_solution.LineEHLSolution.traction_profile`) instead of the Hertz
    pressure with a uniform film."""
    chosen = [i for i, solution in enumerate(solutions) if solution is not None and usable[i]
              and hasattr(solution, "traction_profile")]
    if not chosen:
        return fluid
    fields = {name: np.array(getattr(fluid, name), copy=True) for name in fluid._fields}
    for i in chosen:
        contact = traction_model.contact(p_h[i], b[i], h[i], u_m[i], lubricant_state, inputs.get("effusivity"),
                                         profile=solutions[i].traction_profile())
        one = contact.solve(u_s[i])
        for name, values in fields.items():
            values[i] = getattr(one, name)
        solved = _solved_traction(traction_model, solutions[i], inputs)
        if solved is not None:
            fields["coefficient"][i], fields["temperature_rise"][i] = solved
    return type(fluid)(**fields)


def _solved_traction(traction_model, solution, inputs) -> tuple[float, float] | None:
    """(mu, film temperature rise [K]) of a film solution that computed its own traction with the traction model's
    rheology — the thermal / non-Newtonian line solver (:class:`camcontact.ehl.line_thermal.ThermalLineSolution`,
    whose film model the scene gave the traction model's Eyring and limiting shear stresses) — else None; not
    with a mixed film (the fluid there carries part of the load on a thinner film than the solution's)."""
    coefficient = getattr(solution, "traction_coefficient", None)
    if coefficient is None or "h_c_mixed" in inputs or getattr(traction_model, "rheology", None) != solution.rheology:
        return None
    return coefficient, solution.max_temperature_rise if solution.thermal else 0.0


@step("friction", provides=("friction_force", "friction_coefficient", "friction_power", "fluid_traction_coefficient",
                            "traction_regime", "traction_temperature_rise", "traction_valid"),
      model=lambda traction_model: f"{traction_model.name} fluid + boundary")
def ehl_sliding_friction(traction_model, normal_force, p_h, b, h_c, u_s, u_m, lubricant_state, **inputs):
    """Friction of a sliding contact at each angle: mu_b W_asperity + mu_fluid(u_s) W_fluid [N] (``inputs``:
    the mixed step's ``asperity_load_fraction`` and ``h_c_mixed``, the lubricant's ``boundary_friction``, the
    surfaces' ``effusivity`` for a thermal traction model, the numerical film's ``film_solutions``), its
    coefficient [-], power F |u_s| [W], the fluid's traction coefficient, regime ("linear", "nonlinear",
    "plateau", "open"), temperature rise [K] and whether the fluid coefficient is a physical one
    (<= :data:`FLUID_TRACTION_LIMIT`).

    The fluid's shear stress is integrated over the Hertz pressure with the central film, or — at the angles
    where the film model left a numerical line solution (``film="multigrid"``) — over that solution's pressure
    and film (the film scaled to the scene's h_c: its thermal or mixed reduction). Where that solution is the
    thermal / non-Newtonian solver's, its own traction and film temperature are taken (:func:`_solved_traction`)."""
    h = _traction_film(h_c, inputs)
    contact, usable = _fluid(traction_model, p_h, b, h, u_m, lubricant_state, inputs)
    fluid = contact.solve(np.where(usable, u_s, 0.0))
    if inputs.get("film_solutions") is not None:
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (p_h, b, h, u_s, u_m)))
        fluid = _on_numerical_pressure(traction_model, fluid, np.broadcast_to(usable, arrays[0].shape),
                                       inputs["film_solutions"], *arrays, lubricant_state, inputs)
    asperity, carried, mu_b = _shares(normal_force, inputs)
    force = np.abs(mu_b * asperity * np.sign(u_s) + fluid.coefficient * carried)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(normal_force > 0.0, force / normal_force, 0.0)
    return {"friction_force": force, "friction_coefficient": mu, "friction_power": force * np.abs(u_s),
            "fluid_traction_coefficient": np.abs(fluid.coefficient),
            "traction_regime": np.where(usable, fluid.regime, "open").astype(object),
            "traction_temperature_rise": np.asarray(fluid.temperature_rise, dtype=float),
            "traction_valid": np.abs(fluid.coefficient) <= FLUID_TRACTION_LIMIT}


@step("traction_curve", provides=("traction_grid", "traction_table"),
      model=lambda traction_model: f"{traction_model.name} fluid + boundary")
def fluid_traction_table(traction_model, normal_force, p_h, b, h_c, u_cam, u_m, lubricant_state, **inputs):
    """The traction force [N] a contact transmits against the sliding speed [m/s] (angles x nodes of
    :func:`camcontact.dynamics.roller_follower.slip_grid`): mu_b W_asperity (a sign regularised over 1e-4 of
    the rolling speed) + mu_fluid(u_s) W_fluid. A thermal curve that falls past its peak is held at the peak
    (the traction available; the roller's implicit spin step needs a non-decreasing curve)."""
    grid = slip_grid(u_cam)
    h = _traction_film(h_c, inputs)
    contact, usable = _fluid(traction_model, p_h[:, None], b[:, None], h[:, None], u_m[:, None], lubricant_state,
                             inputs)
    fluid = contact.solve(np.where(usable, grid, 0.0)) if contact.thermal is not None else None
    mu = fluid.coefficient if fluid is not None else contact.coefficient(np.where(usable, grid, 0.0))
    asperity, carried, mu_b = _shares(normal_force, inputs)
    table = coulomb_table(mu_b * asperity, grid, u_cam) + np.asarray(mu, dtype=float) * carried[:, None]
    middle = grid.shape[1] // 2  # the node s = 0
    table[:, middle:] = np.maximum.accumulate(table[:, middle:], axis=1)
    table[:, :middle + 1] = np.minimum.accumulate(table[:, middle::-1], axis=1)[:, ::-1]
    return {"traction_grid": grid, "traction_table": table}


def _one(values: dict) -> dict:
    """The single entry of each per-angle array (a one-contact scene's scalars)."""
    return {k: (v.item() if isinstance(v, np.ndarray) else v) for k, v in values.items()}


@step("mixed", provides=MIXED_OUTPUTS, model="greenwood_tripp + johnson_greenwood_poon")
def mixed_contact(w, R, E_reduced, u_m, eta0, alpha_effective, h_c, sigma, asperity_density, asperity_radius,
                  piezoviscosity):
    """:func:`mixed_film_cycle` of one line contact (load per length ``w`` [N/m]): scalar outputs."""
    values = mixed_film_cycle(np.atleast_1d(w), np.atleast_1d(R), E_reduced, np.atleast_1d(u_m), eta0,
                              alpha_effective, np.atleast_1d(h_c), sigma, asperity_density, asperity_radius,
                              piezoviscosity)
    return _one(values)


@step("friction", provides=("friction_per_length", "traction_coefficient", "friction_power_per_length",
                            "fluid_traction_coefficient", "traction_regime", "traction_temperature_rise",
                            "traction_valid"),
      model=lambda traction_model: f"{traction_model.name} fluid + boundary")
def contact_ehl_friction(traction_model, w, p_h, b, h_c, u_s, u_m, lubricant_state, **inputs):
    """:func:`ehl_sliding_friction` of one line contact at its sliding speed u_s = u1 - u2: the friction force
    per unit length [N/m], the contact's friction (traction) coefficient [-], the friction power per unit
    length [W/m] and the fluid's coefficient, regime, temperature rise [K] and validity (over the numerical
    pressure of ``film_solution`` when the film model left one)."""
    if "film_solution" in inputs:
        inputs["film_solutions"] = [inputs.pop("film_solution")]
    values = ehl_sliding_friction(traction_model, np.atleast_1d(w), np.atleast_1d(p_h), np.atleast_1d(b),
                                  np.atleast_1d(h_c), np.atleast_1d(u_s), np.atleast_1d(u_m), lubricant_state,
                                  **inputs)
    names = {"friction_force": "friction_per_length", "friction_coefficient": "traction_coefficient",
             "friction_power": "friction_power_per_length"}
    return _one({names.get(k, k): v for k, v in values.items()})


#: the per-roller outputs of :func:`roller_mixed` (each race)
ROLLER_MIXED_OUTPUTS = tuple(f"{q}_{race}" for q in ("asperity_load_fraction", "h_c_mixed", "lubrication_regime",
                                                     "mixed_valid") for race in RACES)


@step("mixed", provides=ROLLER_MIXED_OUTPUTS, model="greenwood_tripp + johnson_greenwood_poon")
def roller_mixed(Q, contact_length_inner, contact_length_outer, contact_radii, E_reduced, u_m, eta0, alpha,
                 piezoviscosity, h_c_inner, h_c_outer, sigma, asperity_density, asperity_radius):
    """:func:`mixed_film_cycle` at both raceway contacts of every roller (w = Q / l over each contact's length l [m], the rolling-direction
    radius of each race, the composite roughness sqrt 2 sigma of two surfaces of RMS ``sigma`` [m]): the asperities'
    share of the roller load [-], the film at the fluid's share [m], the regime ("unloaded" for a roller without
    load) and ``mixed_valid`` per roller and race."""
    alpha_effective = alpha if piezoviscosity else 0.0
    composite = math.hypot(sigma, sigma)
    out = {}
    for race, h_c, length in (("inner", h_c_inner, contact_length_inner), ("outer", h_c_outer, contact_length_outer)):
        w = np.divide(Q, length, out=np.zeros(Q.size), where=Q > 0.0)
        values = mixed_film_cycle(w, np.full(Q.size, contact_radii[race]), E_reduced,
                                  np.full(Q.size, u_m), eta0, alpha_effective, h_c, composite, asperity_density,
                                  asperity_radius, piezoviscosity)
        values["lubrication_regime"][Q <= 0.0] = "unloaded"
        values["asperity_load_fraction"][Q <= 0.0] = np.nan  # no contact: no share (the regime says why)
        for q in ("asperity_load_fraction", "h_c_mixed", "lubrication_regime", "mixed_valid"):
            out[f"{q}_{race}"] = values[q]
    return out


#: the per-contact outputs of :func:`ball_cone_mixed` (input and output contact)
BALL_CONE_MIXED_OUTPUTS = tuple(f"{q}_{side}" for q in MIXED_OUTPUTS for side in ("in", "out"))


@step("mixed", provides=BALL_CONE_MIXED_OUTPUTS, model="greenwood_tripp + johnson_greenwood_poon")
def ball_cone_mixed(normal_force, Rx, Ry, E_reduced, rolling_speed_in, rolling_speed_out, eta0, alpha, piezoviscosity,
                    h_c_in, h_c_out, sigma, asperity_density, asperity_radius):
    """Load sharing at the CVT's input and output contact
    (:func:`camcontact.models.mixed_lubrication.mixed_point_contact`, the composite roughness sqrt 2 sigma of
    two surfaces of RMS ``sigma`` [m]) on the scene's own film (the Nijenbanning film of each share scaled by
    h_c / h_c(Nijenbanning, full load)): the asperities' share of the normal force [-], the film at the fluid's
    share [m], Lambda of it, the regime ("boundary", "mixed", "full_film"), the asperities' capacity
    A_Hertz p_a(0)/N [-] and ``mixed_valid`` (capacity >= 1 or Lambda >= 1, as :func:`mixed_film_cycle`)."""
    alpha_effective = alpha if piezoviscosity else 0.0
    composite = math.hypot(sigma, sigma)
    out = {}
    for side, speed, h_c in (("in", rolling_speed_in, h_c_in), ("out", rolling_speed_out, h_c_out)):
        if not (math.isfinite(h_c) and h_c > 0.0):
            raise InputError(f"mixed step: the {side}put contact's central film h_c = {h_c!r} m; the load sharing "
                             "needs a film > 0")
        smooth = Nijenbanning(piezoviscosity=piezoviscosity).evaluate(Rx, Ry, normal_force, E_reduced, abs(speed),
                                                                      eta0, alpha_effective)["h_c"]
        result = mixed_point_contact(normal_force, Rx, Ry, E_reduced, speed, eta0, alpha_effective, composite,
                                     asperity_density, asperity_radius, piezoviscosity=piezoviscosity,
                                     film_scale=h_c / float(smooth))
        values = {"asperity_load_fraction": result["asperity_load_fraction"], "h_c_mixed": result["h_c"],
                  "Lambda_mixed": result["lambda_ratio"], "lubrication_regime": result["regime"],
                  "asperity_capacity": result["asperity_capacity"],
                  "mixed_valid": bool(result["asperity_capacity"] >= 1.0 or result["lambda_ratio"] >= 1.0)}
        out.update({f"{key}_{side}": value for key, value in values.items()})
    return out
