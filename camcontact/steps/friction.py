"""Friction and wear steps: the cam follower's friction and wear models per angle, Benedict–Kelley
friction of raceway contacts with their flash temperatures and whether each contact lies inside the
correlation's validity (boolean columns).

Cam follower: any model of the ``friction_models`` / ``wear_models`` families (Coulomb, Archard,
Ferrarese & Uehara), resolved when its step is planned (:class:`SlotModel`). Raceways: the
Benedict–Kelley correlation (Delabenetta 2021 Eq. 49, :class:`camcontact.models.friction.Kelley`) and
Blok's flash temperature (Eq. 48, :func:`camcontact.contact.contact_temperature.flash_temperature`).
Forces [N], speeds [m/s], powers [W], wear rates [m^3/s], temperatures [K].
"""

from __future__ import annotations

import math
from typing import Any

import attrs
import numpy as np

from .. import registry
from ..contact.contact_temperature import flash_temperature
from ..errors import InputError
from ..models.friction import Kelley
from ..step_graph import step
from .contact import RACES
from .ehl_friction import FLUID_TRACTION_LIMIT
from .kinematics import split_speed

__all__ = ["ALIASES", "SlotModel", "cam_friction", "cam_wear", "raceway_kelley_friction", "roller_fluid_friction",
           "roller_friction"]

#: state names the cam scene gives under other names for the friction and wear models
ALIASES = {"sliding_speed": "u_s"}


@attrs.frozen
class SlotModel:
    """A model slot resolved when its step is planned (an unasked friction model needs no parameters).

    The default models ``coulomb`` and ``archard`` take their coefficient from the scene
    (``CamFollower.friction_coefficient`` / ``wear_coefficient``); without it their step requires the
    pseudo-input ``coefficient_input``, which the plan reports as missing with the scene's hint.
    """

    family: str
    spec: Any
    slot: str
    coefficient: float | None = None
    coefficient_input: str = ""

    #: names of the models whose only parameter ``coefficient`` the scene may supply
    SCENE_COEFFICIENT = ("coulomb", "archard")

    @property
    def kind(self) -> Any:
        """The model class registered under ``spec`` in ``family`` (a string spec), or ``spec`` itself."""
        return registry.get_class(self.family, self.spec) if isinstance(self.spec, str) else self.spec

    @property
    def name(self) -> str:
        """The model's registry name (``str(spec)`` if it has none)."""
        return getattr(self.kind, "name", str(self.spec))

    @property
    def version(self) -> str:
        """The model's version ("" if it has none)."""
        return getattr(self.kind, "version", "")

    @property
    def parameters(self) -> dict[str, Any]:
        """Keyword parameters for the model: the scene's ``coefficient`` for a scene-coefficient model, else none."""
        if isinstance(self.spec, str) and self.spec in self.SCENE_COEFFICIENT and self.coefficient is not None:
            return {"coefficient": self.coefficient}
        return {}

    @property
    def optional(self) -> tuple[str, ...]:
        """The state names the model reads when the scene has them, under the scene's names."""
        return tuple(ALIASES.get(name, name) for name in getattr(self.kind, "optional_requires", ()))

    @property
    def requires(self) -> tuple[str, ...]:
        """The state names the model reads, under the scene's names (:data:`ALIASES`), with the
        pseudo-input of a missing scene coefficient."""
        names = tuple(ALIASES.get(name, name) for name in getattr(self.kind, "requires", ()))
        if isinstance(self.spec, str) and self.spec in self.SCENE_COEFFICIENT and self.coefficient is None:
            names += (self.coefficient_input,)
        return names

    def resolve(self):
        """The model instance (InputError naming the slot when the model needs parameters)."""
        try:
            return registry.get(self.family, self.spec, **self.parameters)
        except TypeError as exc:
            raise InputError(
                f"{self.slot} model {self.name!r} needs parameters ({exc}); pass an instance, e.g. "
                f"models={{'{self.slot}': camcontact.registry.get('{self.family}', '{self.name}', ...)}}"
            ) from None


def _state(normal_force, u_s, angular_speed, cam_angle, inputs) -> dict:
    state = {"normal_force": normal_force, "u_s": u_s, "angular_speed": angular_speed, "cam_angle": cam_angle,
             **inputs}
    state.update({alias: state[name] for alias, name in ALIASES.items() if name in state})
    return state


def _check_friction(friction_model) -> None:
    friction_model.resolve()


def _check_wear(wear_model) -> None:
    wear_model.resolve()


@step("friction", provides=("friction_force", "friction_coefficient", "friction_power"),
      model=lambda friction_model: friction_model.name, version=lambda friction_model: friction_model.version,
      check=_check_friction)
def cam_friction(friction_model, normal_force, u_s, angular_speed, cam_angle, **inputs):
    """Friction force [N], coefficient [-] and power [W] at every cam angle by the slot's friction model
    (``inputs``: the further state names it reads); power = force |u_s| unless the model gives it."""
    produced = friction_model.resolve()(_state(normal_force, u_s, angular_speed, cam_angle, inputs))
    force = np.asarray(produced["friction_force"], dtype=float) * np.ones(cam_angle.size)
    if "friction_power" in produced:
        power = np.asarray(produced["friction_power"], dtype=float) * np.ones_like(force)
    else:
        power = force * np.abs(u_s)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(normal_force > 0.0, force / normal_force, 0.0)
    return {"friction_force": force, "friction_coefficient": mu, "friction_power": power}


@step("wear", provides=("wear_rate",), model=lambda wear_model: wear_model.name,
      version=lambda wear_model: wear_model.version, check=_check_wear)
def cam_wear(wear_model, normal_force, u_s, angular_speed, cam_angle, **inputs):
    """Wear rate [m^3/s] at every cam angle by the slot's wear model (``inputs``: the state it reads)."""
    produced = wear_model.resolve()(_state(normal_force, u_s, angular_speed, cam_angle, inputs))
    return {"wear_rate": np.asarray(produced["wear_rate"], dtype=float) * np.ones(cam_angle.size)}


@step("friction", provides=("friction_coefficient", "friction_valid", "friction_validity"), model="kelley")
def raceway_kelley_friction(F, length, eta0, u_raceway, u_roller):
    """Benedict–Kelley friction coefficient [-] of a raceway contact (Delabenetta 2021 Eq. 49) and whether
    the contact lies inside the correlation's validity (``friction_valid``, bool;
    :attr:`camcontact.models.friction.Kelley.validity`: slide-to-roll ratio |u1 - u2|/u_m in [0.01, 2]),
    with the reason in ``friction_validity`` ("ok" inside). Outside, mu is still the correlation's
    value; pure rolling lies outside the correlation: mu NaN (no frictional heating)."""
    if u_raceway == u_roller:
        return {"friction_coefficient": math.nan, "friction_valid": False,
                "friction_validity": "pure rolling: the Kelley correlation needs sliding (no frictional heating)"}
    kelley = Kelley()
    mu = kelley({"normal_force": F, "contact_length": length, "eta0": eta0,
                 "u1": u_raceway, "u2": u_roller})["friction_coefficient"]
    messages = kelley.check_validity(kelley.validity_values(u_raceway, u_roller))
    return {"friction_coefficient": float(mu), "friction_valid": bool(kelley.inside_validity(u_raceway, u_roller)),
            "friction_validity": "ok" if not messages else "outside the Kelley correlation: " + "; ".join(messages)}


@step("friction", provides=("friction_coefficient_inner", "friction_coefficient_outer", "friction_valid_inner",
                            "friction_valid_outer", "friction_validity", "flash_temperature_inner",
                            "flash_temperature_outer", "friction_power"), model="kelley")
def roller_friction(Q, u_m, slide_roll_ratio, eta0, E_reduced, effusivity, contact_radii, contact_length_inner,
                    contact_length_outer):
    """Benedict–Kelley friction at both raceway contacts of every loaded roller with the slide/roll ratio,
    the flash temperature [K] of each contact and the bearing's sliding friction power sum(mu Q |u1 - u2|)
    [W]; NaN for unloaded rollers (Delabenetta 2021 Eqs. 48, 49); each contact over its length l [m].

    ``friction_valid_inner`` / ``_outer`` (bool per roller): the contact is loaded and inside the
    correlation's validity (:attr:`camcontact.models.friction.Kelley.validity`, slide-to-roll ratio in
    [0.01, 2]; False for unloaded rollers, which have no contact); ``friction_validity``: "ok" or why
    the loaded contacts lie outside it (the coefficient is still the correlation's value)."""
    u1, u2 = split_speed(u_m, slide_roll_ratio)
    loaded = Q > 0.0
    kelley = Kelley()
    inside = bool(kelley.inside_validity(u1, u2))
    messages = kelley.check_validity(kelley.validity_values(u1, u2))
    out = {"friction_validity": "ok" if not messages else "outside the Kelley correlation: " + "; ".join(messages)}
    lengths = {"inner": contact_length_inner, "outer": contact_length_outer}
    mu = {race: np.full(Q.size, np.nan) for race in RACES}
    for race in RACES:
        if loaded.any():
            mu[race][loaded] = kelley({"normal_force": Q[loaded], "contact_length": lengths[race][loaded],
                                       "eta0": eta0, "u1": u1, "u2": u2})["friction_coefficient"]
        out[f"friction_valid_{race}"] = loaded & inside
    return out | _raceway_heat(Q, mu, u1, u2, E_reduced, effusivity, contact_radii, lengths)


def _raceway_heat(Q, mu, u1, u2, E_reduced, effusivity, contact_radii, lengths) -> dict:
    """Per race the coefficients ``mu[race]`` (NaN for unloaded rollers), Blok's flash temperature [K] of each
    loaded contact (Delabenetta 2021 Eq. 48) and the bearing's sliding power sum(mu Q |u1 - u2|) [W]."""
    out, power = {}, 0.0
    for race in RACES:
        flash = np.full(Q.size, np.nan)
        for j in np.flatnonzero(Q > 0.0):
            flash[j] = flash_temperature(Q[j] / lengths[race][j], E_reduced, contact_radii[race], mu[race][j], u1, u2,
                                         effusivity, effusivity)
        loaded = Q > 0.0
        power += float(np.sum(mu[race][loaded] * Q[loaded])) * abs(u1 - u2)
        out[f"friction_coefficient_{race}"], out[f"flash_temperature_{race}"] = mu[race], flash
    out["friction_power"] = power
    return out


@step("friction", provides=("friction_coefficient_inner", "friction_coefficient_outer", "friction_valid_inner",
                            "friction_valid_outer", "friction_validity", "flash_temperature_inner",
                            "flash_temperature_outer", "friction_power"),
      model=lambda traction_model: f"{traction_model.name} fluid traction")
def roller_fluid_friction(traction_model, Q, u_m, slide_roll_ratio, p_h_inner, p_h_outer, b_inner, b_outer,
                          h_c_inner, h_c_outer, lubricant_state, E_reduced, effusivity, contact_radii,
                          contact_length_inner, contact_length_outer, **inputs):
    """Fluid traction of the film at both raceway contacts of every loaded roller at the slide/roll ratio
    (a ``traction_models`` model over the Hertz pressure with the central film,
    :mod:`camcontact.models.traction_fluid`: it falls to zero with the slip, as EHL traction does), the flash
    temperature [K] of each contact (Delabenetta 2021 Eq. 48) and the bearing's sliding friction power
    sum(mu Q |u1 - u2|) [W]; NaN
    for unloaded rollers; ``friction_valid_*`` whether the contact is loaded with a physical coefficient.

    With the ``mixed`` step's ``asperity_load_fraction_<race>`` and ``h_c_mixed_<race>`` in ``inputs`` (and the
    lubricant's ``boundary_friction``) each contact's coefficient is mu_b f_a + mu_fluid (1 - f_a), the fluid
    shearing the film at its share (reference ``friction_traction_thermal.md`` §2)."""
    u1, u2 = split_speed(u_m, slide_roll_ratio)
    loaded = Q > 0.0
    films = {"inner": (p_h_inner, b_inner, h_c_inner), "outer": (p_h_outer, b_outer, h_c_outer)}
    mu = {race: np.full(Q.size, np.nan) for race in RACES}
    fluid_valid = {}
    mu_b = float(inputs.get("boundary_friction", 0.0))
    for race in RACES:
        share = np.asarray(inputs.get(f"asperity_load_fraction_{race}", np.zeros(Q.size)), dtype=float)[loaded]
        film = inputs.get(f"h_c_mixed_{race}", films[race][2])
        p_h, b, h = (np.asarray(v, dtype=float)[loaded] for v in (*films[race][:2], film))
        fluid = np.full(Q.size, np.nan)
        if loaded.any():
            contact = traction_model.contact(p_h, b, h, u_m, lubricant_state, effusivity)
            fluid[loaded] = np.abs(contact.solve(np.full(p_h.size, u1 - u2)).coefficient)
            mu[race][loaded] = mu_b * share * (u1 != u2) + fluid[loaded] * (1.0 - share)
        fluid_valid[race] = np.isfinite(fluid) & (fluid <= FLUID_TRACTION_LIMIT)
    out = _raceway_heat(Q, mu, u1, u2, E_reduced, effusivity, contact_radii,
                        {"inner": contact_length_inner, "outer": contact_length_outer})
    for race in RACES:
        out[f"friction_valid_{race}"] = loaded & np.isfinite(mu[race]) & fluid_valid[race]
    valid = all(out[f"friction_valid_{race}"][loaded].all() for race in RACES)
    out["friction_validity"] = "ok" if valid else "a loaded contact has no film or an unphysical traction (> 0.15)"
    return out
