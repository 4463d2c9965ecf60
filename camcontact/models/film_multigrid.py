"""Numerical film of a line contact: the FAS multigrid EHL solver as a film model.

Registered as ``multigrid`` in the ``film_models`` family, so an Analysis can ask for the
numerical solution by name instead of a formula. Accuracy is chosen by ``levels`` (finest grid
n = 14 2^(levels-1) + 1 nodes) and ``tolerance``; the solver and its convergence record are in
:mod:`camcontact.ehl.line_multigrid`. The numba kernels are compiled on the first solve only.
"""

from __future__ import annotations

import math

import attrs
import numpy as np

from ..ehl.line_domain import DOMAIN_RATIO, INLET_TAIL, automatic_domain, inlet_tail_fraction
from ..errors import InputError
from .base import FilmModel, builtin
from .film_line import LINE_INPUTS

__all__ = ["DOMAIN_RATIO", "INLET_TAIL", "Multigrid", "automatic_domain", "inlet_tail_fraction", "solver_laws"]


def solver_laws(model: str, lubricant_state, density_law) -> tuple[str, str]:
    """(viscosity, density) law names of the numerical solvers from a lubricant state, or an
    InputError naming the law they do not support (they know roelands/barus and
    dowson_higginson/incompressible)."""
    viscosity = getattr(getattr(lubricant_state, "pressure_law", None), "name", "roelands")
    if viscosity not in ("roelands", "barus"):
        raise InputError(f"film model {model!r} supports the barus and roelands laws, not {viscosity!r}")
    density = getattr(density_law, "name", density_law)
    if density not in ("dowson_higginson", "incompressible"):
        raise InputError(f"film model {model!r} supports the dowson_higginson and incompressible density "
                         f"laws, not {density!r}")
    return viscosity, density


@builtin
@attrs.frozen
class Multigrid(FilmModel):
    """Central and minimum film of a line contact from the numerical EHL solution.

    Steady isothermal Reynolds with cavitation, elastic half-space deformation (MLMI), load
    balance through H0, Roelands or Barus viscosity and Dowson–Higginson (or no) compressibility,
    solved by FAS multigrid; inputs R [m], w [N/m], E' [Pa], u_m [m/s], eta0 [Pa*s],
    alpha [1/Pa] and the lubricant's laws. Results: h_c = H(0) b^2/R and h_min [m].

    Parameters
    ----------
    levels : int
        Finest grid level (9: 3585 nodes; 12: 28673 nodes).
    tolerance : float
        Convergence tolerance on the per-cycle change of H_min and H0 (Hertz units).
    domain : (float, float), optional
        [X_a, X_b] in units of b; None chooses :func:`automatic_domain`.
    strict : bool
        Raise ConvergenceError when the solver does not converge (default: warn).
    piezoviscosity, elasticity : bool
        Switched off by an Analysis whose scene switches the effect off.
    threads : int, optional
        Threads for the independent solves of one analysis — a cam cycle is cut into this many
        arcs, each warm-started angle by angle (the compiled kernels release the GIL, so two
        threads nearly halve a cycle on two cores). None: the CPU count, at most 4. The films
        of different thread counts agree within ``tolerance`` (each arc starts cold).
    thermal, non_newtonian : bool
        Solve the energy equation of the film and the surfaces / an Eyring film (switched on by a line-contact
        scene with the effects ``thermal`` / ``non_newtonian``): the thermal and non-Newtonian solver
        :func:`camcontact.ehl.line_thermal.solve_thermal`, whose films replace the isothermal ones (no formula
        factor on top) and whose traction the scene's friction takes. Needs the surface speeds u1, u2 > 0 and,
        thermal, the lubricant's conductivity, density, specific heat and temperature–viscosity coefficient and
        the surfaces' effusivities.
    eyring_stress, limiting_shear_stress, limiting_shear_slope : float
        The film's Eyring stress tau0 [Pa] (non-Newtonian) and limiting shear stress tau_L0 [Pa] + Lambda_L p
        (slope None: none); the scene takes them from its traction model.
    cavitation : str
        ``"reynolds"`` (default: cavitation by clipping, a full film everywhere) or ``"mass_conserving"``
        (Jakobsson–Floberg–Olsson film fraction, :mod:`camcontact.ehl.line_multigrid`): steady films are the
        same; in the transient march of the ``squeeze`` effect the lubricant left behind the contact is what
        it meets after an entrainment reversal (starvation at reversal).

    References
    ----------
    Venner, C.H. & Lubrecht, A.A. (2000) Multilevel Methods in Lubrication, Elsevier;
    discretisation of Tsuha (2015) §5.3, validated against its Table 5.1.
    """

    name = "multigrid"
    reference = "Venner & Lubrecht (2000) Multilevel Methods in Lubrication; Tsuha (2015) §5.3, Table 5.1"
    geometry = "line"
    requires = (*LINE_INPUTS, "lubricant_state", "density_law")
    #: a starved inlet's lubricant layer [m] (``LineContact.oil_layer``), when the scene gives one; the surface
    #: speeds [m/s] and effusivities of the thermal and non-Newtonian solve
    optional_requires = ("oil_layer", "u1", "u2", "effusivity")
    provides = ("h_c", "h_min")
    can_disable = ("piezoviscosity", "elasticity")
    #: effects a line-contact scene switches on in this model (:func:`camcontact.steps.film.resolve_film_model`)
    can_enable = ("thermal", "non_newtonian")

    levels: int = 9
    tolerance: float = 1e-7
    domain: tuple | None = None
    strict: bool = False
    piezoviscosity: bool = True
    elasticity: bool = True
    threads: int | None = attrs.field(default=None)
    cavitation: str = attrs.field(default="reynolds")
    thermal: bool = False
    non_newtonian: bool = False
    eyring_stress: float | None = None
    limiting_shear_stress: float = 0.0
    limiting_shear_slope: float | None = None

    @cavitation.validator
    def _check_cavitation(self, attribute, value):
        from ..ehl.line_problem import CAVITATION_MODELS

        if value not in CAVITATION_MODELS:
            raise InputError(f"film model 'multigrid': cavitation = {value!r}; allowed: {', '.join(CAVITATION_MODELS)}")

    @threads.validator
    def _check_threads(self, attribute, value):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or value < 1):
            raise InputError(f"film model 'multigrid': threads = {value!r}; allowed: None or an integer >= 1")

    def problem(self, R, w, E_reduced, u_m, eta0, alpha, lubricant_state=None, density_law="dowson_higginson"):
        """The dimensionless :class:`~camcontact.ehl.line_problem.LineEHLProblem` of the contact: R [m],
        w [N/m], E' [Pa], u_m [m/s], eta0 [Pa s], alpha [1/Pa]."""
        from ..ehl.line_problem import LineEHLProblem

        law = getattr(lubricant_state, "pressure_law", None)
        viscosity, density = solver_laws(self.name, lubricant_state, density_law)
        if density == "dowson_higginson" and law is not None:
            constants = getattr(lubricant_state.density_law, "a", 5.9e8), getattr(lubricant_state.density_law, "b", 1.34)
            if constants != (5.9e8, 1.34):
                raise InputError("film model 'multigrid' uses the Dowson–Higginson constants 5.9e8 Pa and 1.34")
        alpha = alpha if self.piezoviscosity else 0.0
        z = getattr(lubricant_state, "roelands_z", None) if viscosity == "roelands" else None
        p0 = getattr(law, "p0", 1.96e8)
        first = LineEHLProblem.from_contact(R=R, w=w, E_reduced=E_reduced, u_m=u_m, eta0=eta0, alpha=alpha, z=z,
                                            viscosity=viscosity, density=density, p0=p0, elastic=self.elasticity)
        domain = self.domain if self.domain is not None else automatic_domain(first.M, first.L, self.elasticity)
        return attrs.evolve(first, domain=tuple(domain), cavitation=self.cavitation)

    def check_validity(self, values) -> list[str]:
        """The range messages of :class:`FilmModel`; where the thermal solver's film viscosity profile reached its
        bound (:attr:`camcontact.ehl.line_thermal.ThermalLineSolution.profile_bounded`: shear bands the film points
        do not resolve, so that film and traction depend on the bound); and where it returned the uniform-viscosity
        solution because the cross-film one did not converge (``cross_film`` False)."""
        messages = super().check_validity(values)
        solution = values.get("ehl_solution")
        bounded = getattr(solution, "profile_bounded", None)
        count = 0 if bounded is None else int(np.count_nonzero(bounded & solution.wet))
        if count or getattr(solution, "cross_film", True) is False:
            from ..ehl.line_thermal import UNIFORM_FALLBACK, profile_bound_note

            if count:
                messages.append(profile_bound_note(count))
            if solution.cross_film is False:
                messages.append(UNIFORM_FALLBACK)
        return messages

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha, lubricant_state=None, density_law="dowson_higginson",
                 initial=None, oil_layer=None, u1=None, u2=None, effusivity=None, before=None):
        """Films [m] from the numerical solution, with the solution and its convergence record.

        ``initial`` (a previous :class:`~camcontact.ehl.line_solution.LineEHLSolution`, e.g. of the
        neighbouring cam angle) warm-starts the solver instead of its full-multigrid start; its
        pressures are interpolated onto this problem's grid (the automatic domain may differ: a longer
        inlet takes the start's inlet stretched, a shorter one compressed,
        :func:`camcontact.ehl.line_multigrid.inlet_mapped`); ``before``, the solution before ``initial`` (the
        angle before the neighbour), makes the start their linear extrapolation where both lie on this problem's
        grid (:func:`camcontact.ehl.line_multigrid.extrapolated_start`).
        ``oil_layer`` [m]: a starved inlet's lubricant layer (both surfaces), solved with mass-conserving
        cavitation by :func:`camcontact.ehl.line_starved.solve_starved` (its content h_oil R/b^2 is the
        problem's ``supply``); a layer that the flooded contact could not pass leaves it flooded. With ``thermal`` /
        ``non_newtonian``: the thermal and non-Newtonian solve (class docstring) from the surface speeds u1, u2
        [m/s] and the surfaces' ``effusivity`` (a pair [W s^0.5/(m^2 K)]), also giving the isothermal films
        ``h_c_isothermal``, ``h_min_isothermal``; ``initial`` is not used there; with ``oil_layer`` the starved
        thermal solve (:func:`camcontact.ehl.line_thermal.solve_thermal`), its isothermal films those of the isothermal
        starved contact with the same layer.
        """
        from ..ehl.line_multigrid import solve_multigrid

        problem = self.problem(R, w, E_reduced, u_m, eta0, alpha, lubricant_state, density_law)
        if oil_layer is not None and not (math.isfinite(oil_layer) and oil_layer > 0):
            raise InputError(f"film model 'multigrid': oil_layer = {oil_layer!r} m must be finite and > 0")
        if self.thermal or self.non_newtonian:
            return self._thermal_films(problem, R, w, E_reduced, eta0, alpha, lubricant_state, u1, u2, effusivity,
                                       oil_layer)
        if oil_layer is not None:
            from ..ehl.line_starved import solve_starved

            supply = float(oil_layer) / problem.scales(R, w, E_reduced)["h_scale"]  # H_oil = h_oil R/b^2
            starved = attrs.evolve(problem, cavitation="mass_conserving", supply=supply)
            solution = solve_starved(starved, self.levels, tolerance=self.tolerance, strict=self.strict)
        else:
            solution = solve_multigrid(problem, self.levels, tolerance=self.tolerance, strict=self.strict,
                                       initial=initial, before=before)
        values = solution.dimensional(R, w, E_reduced)
        return {"h_c": values["h_c"], "h_min": values["h_min"], "ehl_solution": solution,
                "convergence": solution.record, "M": problem.M, "L": problem.L}

    def thermal_contact(self, problem, R, w, E_reduced, u1, u2, eta0, alpha, lubricant_state, effusivity,
                        oil_layer=None):
        """The :class:`~camcontact.ehl.line_thermal.ThermalLineContact` of the thermal and/or non-Newtonian solve:
        ``problem`` (:meth:`problem`) gives the laws and domain; R [m], w [N/m], E' [Pa], surface speeds u1, u2
        [m/s], eta0 [Pa s], alpha [1/Pa], a starved inlet's ``oil_layer`` [m] (None: flooded); the lubricant's
        conductivity, density, specific heat and thermoviscous coefficient and the surfaces' ``effusivity`` (a pair
        [W s^0.5/(m^2 K)]) are needed with ``thermal`` (InputError naming the missing ones), the Eyring stress with
        ``non_newtonian``; with ``thermal`` a lubricant's thermal expansivity (with its temperature) gives the film's
        compression work and thermal expansion."""
        from ..ehl.line_thermal import ThermalLineContact

        data = {"thermal_conductivity": getattr(lubricant_state, "thermal_conductivity", None),
                "thermoviscous_coefficient": getattr(lubricant_state, "thermoviscous_coefficient", None),
                "density": getattr(lubricant_state, "density", None),
                "specific_heat": getattr(lubricant_state, "specific_heat", None), "effusivity": effusivity}
        if self.thermal:
            missing = [name for name, value in data.items() if value is None]
            if missing:
                raise InputError("film model 'multigrid' with the thermal effect needs the lubricant's "
                                 "thermal_conductivity, density, specific_heat and temperature-dependent viscosity "
                                 "(thermoviscous_coefficient) and both materials' thermal data (effusivity); "
                                 f"missing: {', '.join(missing)}")
        else:  # not used without the energy equation
            data = {"thermal_conductivity": 1.0, "thermoviscous_coefficient": 0.0, "density": 1.0,
                    "specific_heat": 1.0, "effusivity": (1.0, 1.0)}
        if self.non_newtonian and self.eyring_stress is None:
            raise InputError("film model 'multigrid' with the non_newtonian effect needs the Eyring stress "
                             "(the lubricant's eyring_stress, or an Eyring traction model)")
        # the compression work alpha_T T u dp/dx of a lubricant with a thermal expansivity needs its temperature
        expansivity = float(getattr(lubricant_state, "thermal_expansivity", 0.0) or 0.0) if self.thermal else 0.0
        temperature = getattr(lubricant_state, "temperature", None) if expansivity > 0.0 else None
        if expansivity > 0.0 and temperature is None:
            raise InputError(f"film model 'multigrid' with the thermal effect: the lubricant's thermal_expansivity = "
                             f"{expansivity:g} 1/K needs its temperature (the contact's temperature) for the "
                             "compression work alpha_T T u dp/dx; give one, or drop thermal_expansivity")
        return ThermalLineContact(
            R=R, w=w, E_reduced=E_reduced, u1=float(u1), u2=float(u2), eta0=eta0, alpha=float(alpha),
            beta=float(data["thermoviscous_coefficient"]), conductivity=float(data["thermal_conductivity"]),
            heat_capacity=float(data["density"]) * float(data["specific_heat"]),
            effusivity_1=float(data["effusivity"][0]), effusivity_2=float(data["effusivity"][1]),
            eyring_stress=self.eyring_stress if self.non_newtonian else None,
            limiting_shear_stress=self.limiting_shear_stress, limiting_shear_slope=self.limiting_shear_slope,
            viscosity=problem.viscosity, density=problem.density, z=problem.z, p0=problem.p0, domain=problem.domain,
            elastic=problem.elastic, oil_layer=None if oil_layer is None else float(oil_layer),
            thermal_expansivity=expansivity, temperature=None if temperature is None else float(temperature))

    def _thermal_films(self, problem, R, w, E_reduced, eta0, alpha, lubricant_state, u1, u2, effusivity,
                       oil_layer=None) -> dict:
        """Films [m] of the thermal and/or non-Newtonian solve (:func:`camcontact.ehl.line_thermal.solve_thermal`;
        starved with ``oil_layer`` [m]) with its isothermal Newtonian films and the solution."""
        from ..ehl.line_thermal import solve_thermal

        if u1 is None or u2 is None or not (u1 > 0 and u2 > 0):
            raise InputError(f"film model 'multigrid' with the thermal / non-Newtonian solver needs both surface "
                             f"speeds > 0 (u1 = {u1!r}, u2 = {u2!r} m/s): the surfaces must move through the contact "
                             "in the same direction")
        contact = self.thermal_contact(problem, R, w, E_reduced, u1, u2, eta0, alpha, lubricant_state, effusivity,
                                       oil_layer)
        solution = solve_thermal(contact, self.levels, thermal=self.thermal, non_newtonian=self.non_newtonian,
                                 tolerance=self.tolerance, strict=self.strict)
        scale = solution.scales["h_scale"]
        return {"h_c": solution.h_c, "h_min": solution.h_min, "h_c_isothermal": solution.isothermal.H_c * scale,
                "h_min_isothermal": solution.isothermal.H_min * scale, "ehl_solution": solution,
                "convergence": solution.record, "M": problem.M, "L": problem.L}
