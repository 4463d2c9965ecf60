"""Thermal and non-Newtonian (Eyring) steady line-contact EHL: the multigrid solver with an energy equation.

The isothermal Newtonian solver (:func:`camcontact.ehl.line_multigrid.solve_multigrid`) solves the Reynolds
equation with a flow factor per node on its Poiseuille coefficient, xi = F rho H^3/(eta lambda),
F = a sqrt(1 + (k eta-bar(P))^2) (a = 1, k = 0: isothermal Newtonian; :func:`camcontact.ehl._kernels.flow_factor`).
This module supplies a (the Poiseuille coefficient of the film's viscosity profile against the isothermal film's;
exp(beta dT) for a viscosity uniform at the film's temperature rise dT), k (the Eyring coefficient,
eta0 |u2 - u1|/(tau0 h) at the film's Couette viscosity) and, in sliding, the Couette factor c on the wedge (the
entrainment flux u_e h = c u_m h of a film whose viscosity varies across it) from the film's rheology and
temperature, in a fixed-point iteration around that solver:

1. solve the Reynolds and film equations with phi (warm-started from the previous solution);
2. from the pressure and film, solve the energy equation in the film and the surfaces
   (:func:`camcontact.ehl._thermal_kernels.layer_sweep`: the temperature at nine points across the film along
   x, with the film's velocity profile and its reverse flow in the inlet; the surfaces as moving half-spaces),
   with the viscosity eta(p, T) = eta(p, T0) exp(-beta (T - T0)) at each film point's temperature T (Yang & Wen's
   generalised Reynolds equation; ``cross_film=False``: uniform at the film's mean temperature Tm);
3. the new (ln a, ln k, ln c) from the temperatures and the film; the next ones by Anderson mixing (Walker & Ni
   2011) of the iterates; stop when the mean of |ln F_new - ln F| + |ln c_new - ln c| (F = a Phi, Phi the Eyring
   film's Poiseuille flow factor, at the current pressure) over the wet nodes (inlet to the last pressurised node)
   is below ``flow_tolerance`` and the films and the traction have settled (or its largest value is below the
   tolerance too). The Eyring factor's dependence on the pressure (through eta-bar) stays in the kernels: frozen
   per node, it turned the Hertz zone of a heavily loaded contact into one of 1000 times its load parameter M
   and the multigrid diverged (measured: M = 28, L = 14, S = 0.1).

A starved inlet (``ThermalLineContact.oil_layer``) is solved as the isothermal one
(:mod:`camcontact.ehl.line_starved`): the meniscus where the thermal film of the shorter inlet carries exactly the
supplied layer. Measured (steel rollers, 200 kN/m, u_m 5 m/s, S = 1, Eyring 5 MPa, level 6; layers 0.8, 0.5 and 0.2
of the flooded h_c): the film is the layer's (h_c/h_c,iso of the isothermal starved contact 0.975, 0.965, 0.961;
flooded 0.888), the film temperature peaks 97, 87, 77 K (flooded 113 K) and the traction rises to 0.037, 0.043, 0.053
(flooded 0.029): a starved inlet holds less lubricant to heat, and the thinner, cooler film shears harder; 6-10
thermal solves (8-16 with the bracket's fixed steps before 2026-11-29).

Levels above :data:`NESTED_FROM` iterate on coarser levels first (nested iteration). A multigrid solve that fails
with the mixed flow factors is retried with shorter plain steps; the record says what happened.
:func:`thermal_transient_cycle` couples the same energy equation to the transient march of
:mod:`camcontact.ehl.line_transient`, step by step.

Models (equations in :mod:`camcontact.ehl._thermal_kernels`):

* **Rheology**: Newtonian, or Eyring du/dz = (tau0/eta) sinh(tau/tau0), in the Reynolds–Eyring form of Conry, Wang &
  Cusano (1987): sinh(tau_c/tau0) = eta_c (u2 - u1)/(tau0 h) at the film's Couette (harmonic-mean) viscosity eta_c,
  Poiseuille flow factor cosh(tau_c/tau0) on the Poiseuille coefficient of the viscosity profile (Yang & Wen 1990 in
  that limit; :func:`camcontact.ehl._thermal_kernels.film_profile`). The same rheology as the lumped traction model
  :mod:`camcontact.contact.fluid_traction` (Johnson & Tevaarwerk 1977), of which this solver is the numerical top
  rung. A limiting shear stress is not modelled here.
* **Temperature**: the energy equation of the film at nine Chebyshev points across it (convection along x
  with the local velocity, conduction across, the local dissipation of the linear stress profile), coupled to
  the surfaces as half-spaces moving through the contact (Jaeger 1942; Carslaw & Jaeger 1959 §10.7) — the
  structure of the thermal line EHL analyses of Sadeghi & Sui (1990), which solve the same film energy
  equation by finite differences. The viscosity follows exp(-beta dT) with one temperature–viscosity
  coefficient beta (as the lumped traction model and the film-reduction formulas' thermal loading do), at each
  film point. Its profile about the film's mean is bounded, beta |T - Tm| <= PROFILE_BOUND = 2 (a film sheared into
  bands the nine points do not resolve: Newtonian heavy sliding, or an Eyring film far beyond its stress); the nodes
  where the bound holds the profile are reported (``profile_bounded``, the record's message), and their films depend
  on it (measured: a Newtonian film at S = 1.5, u_m 5 m/s, p_h 1.9 GPa, h_c/h_c,iso 0.69 with the bound 2 and not
  converged, 0.82 with the bound 0.5). Where the iteration with the viscosity varying across the film does not
  converge and the uniform one does (measured at level 7: 2 of 54 contacts, Newtonian films in heavy sliding),
  :func:`solve_thermal` returns the uniform one, with ``cross_film`` False and the record saying so.
* **Compression work and thermal expansion** (``ThermalLineContact.thermal_expansivity`` alpha_T > 0; default 0:
  neither): the density rho_DH(p) exp(-alpha_T (T - T0)), the Dowson–Higginson law with the constant expansivity of
  the thermal EHL analyses (6.5e-4 1/K since Sadeghi & Dow 1987; their linear factor 1 - alpha_T (T - T0), within
  0.2 % of the exponential to 100 K, whose exponential form keeps alpha_T constant). The energy equation gains the
  compression work alpha_T T u dp/dx at each film point (T absolute, p the pressure solution's; integrated over
  each cell of the energy equation's grid along the flow): the layers that
  run into the inlet's pressure heat, its reverse flow and the outlet's expanding film cool; the Reynolds equation
  takes the density at the film's mean temperature on its Poiseuille and Couette coefficients (a density wedge where
  the film heats). Measured (steel rollers, 200 kN/m, T0 = 353 K, level 6): pure rolling at u_m 5/10/20 m/s, h_c/h_c,iso
  0.947/0.864/0.723 against 0.959/0.892/0.771 without, the outlet's film mean 26-42 K below T0; sliding (S = 1,
  Eyring 5 MPa) 0.947 against 0.888, h_min 0.780 against 0.757, traction 0.0281 against 0.0291. A constant alpha_T
  overstates the expansion of a hot film at GPa pressures (real oils expand less there), which is why it is not on
  by default. The transient march (:func:`thermal_transient_cycle`) refuses it: with the lagged coupling a cam's
  outlet spike and its compression heating fed each other until no step converged (measured, LS-1 turn).
* **Simplifications (camcontact's, stated)**: the heat capacity does not depend on temperature or pressure, nor the
  density without ``thermal_expansivity``; no conduction along x; downstream of the film rupture
  the film is treated as full (it no longer affects the pressure); the inlet lubricant and both surfaces enter at T0.
  The energy equation runs on every 2^k-th node of the EHL grid (at most :data:`LAYER_NODES` nodes), its temperatures
  interpolated back.

Validation (tests): in the isothermal Newtonian limit phi = 1 and the solution is the isothermal solver's, node for
node. The film energy and viscosity profile reproduce Nahme's closed form of a heated Couette film (peak 4e-6, heat
4e-5 off; the uniform viscosity: 6 % and 4 %), and the sweeps conserve the energy of a converging inlet with reverse
flow (within 1 %) and match an independent conservative finite-volume solution of it on 160 layers (peak 0.25 %,
mean temperature along x 0.3 %; tests/unit/test_line_thermal_energy_reference.py). The thermal film reduction of
pure rolling lies 5-19 % above the inlet shear-heating factor of Murch & Wilson (1975) over thermal loadings
L_m = 0.2-3.4 (0.959, 0.892, 0.771 against 0.911, 0.812, 0.647: the reduction 1 - phi_T itself is 47-65 % of
theirs; with the viscosity uniform at the film's mean temperature 0.948,
0.866, 0.731: the cool walls carry the inlet's Poiseuille flow), and the rolling (Poiseuille) force falls with heating
by 35-45 % of what Goksem & Hargreaves' (1978) thermal inlet fit says (its isothermal fit within 8 % of this solver);
with sliding it falls less than Wilson & Sheu's (1983) and Gupta et al.'s (1992; Zhu & Cheng's) factors say (L_m =
0.21, S = 1: 0.876 here, 0.775 and 0.544 there, which disagree with each other by 1.4x), though its reduction grows
with sliding as Gupta's does (3.0x the rolling one at S = 1; Gupta: 2.3x). Until 2026-11-29 the energy equation left
out the flow across the film's layers and did not conserve the inlet's energy; its rolling films were 0.957, 0.879,
0.718. No published full TEHL line-contact solution with its complete input data was available to compare with
(searched: Sadeghi & Sui 1990, Kim & Sadeghi 1992, Ghosh & Hamrock 1985, Hsiao & Hamrock 1992, Conry, Wang & Cusano
1987 — abstracts or nothing). A first, cheaper
energy model — one mean temperature per node with a quadratic profile across the film, convected with the net flux —
gave 0.923 for pure rolling at L_m = 0.21 (layered, uniform viscosity: 0.946) and had no more sliding sensitivity; it
was dropped for the layered one, which resolves the inlet's reverse flow.

References: Conry, T.F., Wang, S. & Cusano, C. (1987) A Reynolds–Eyring equation for elastohydrodynamic
lubrication in line contacts, ASME J. Tribol. 109:648–658. Jaeger, J.C. (1942) Moving sources of heat and
the temperature at sliding contacts, Proc. R. Soc. N.S.W. 76:203–224. Sadeghi, F. & Sui, P.C. (1990)
Thermal elastohydrodynamic lubrication of rolling/sliding contacts, ASME J. Tribol. 112:189–195. Yang, P. &
Wen, S. (1990) A generalized Reynolds equation for non-Newtonian thermal elastohydrodynamic lubrication, ASME
J. Tribol. 112:631–636. Walker, H.F. & Ni, P. (2011) Anderson acceleration for fixed-point iterations, SIAM J.
Numer. Anal. 49:1715–1735. Goksem, P.G. & Hargreaves, R.A. (1978) The effect of viscous shear heating on both film
thickness and rolling traction in an EHL line contact, Part I, ASME J. Lubr. Technol. 100:346–358, as Aihara, S.
(1987) A new running torque formula for tapered roller bearings under axial load, ASME J. Tribol. 109:471–478,
Eqs. 19–21 print it. Murch & Wilson (1975), Wilson & Sheu (1983): :mod:`camcontact.models.film_thermal`.
"""

from __future__ import annotations

import functools
import math
import time
import warnings

import attrs
import numpy as np

from ..errors import ConvergenceError, ConvergenceWarning, InputError, not_converged
from ..units import non_negative, number_field, positive
from . import _thermal_kernels
from .line_domain import automatic_domain
from .line_multigrid import solve_multigrid
from .line_problem import ROELANDS_P0, LineEHLProblem
from .line_solution import ConvergenceRecord, LineEHLSolution

__all__ = ["ThermalLineContact", "ThermalLineSolution", "ThermalTransientResult", "profile_bound_note",
           "solve_thermal", "thermal_transient_cycle"]

#: levels above this one iterate first on the levels two, four... below (down to this one), then carry the flow
#: factors up (nested iteration): level 10 took 14 iterations at 0.43 s each from the isothermal start, measured;
#: the films agree to 1e-4 between levels 8 and 10
NESTED_FROM = 7
#: Anderson mixing of (ln a, ln k) over this many previous iterations (Walker & Ni 2011): with a plain relaxation of 0.8
#: a Newtonian film at S = 0.05 (level 8) oscillated at the outlet spike at 2e-3 for 40 iterations (0.4: 15
#: iterations), and Eyring films did not settle there at all, with a per-node relaxation either (measured)
ANDERSON_DEPTH = 5
#: smallest fraction of the flow factors' change per iteration tried before the iteration stops (halved from
#: ``relaxation`` each time the multigrid solve with the new factors fails)
MIN_STEP = 1.0 / 32.0
#: Illinois tolerance of a node's film temperature [K] and its iteration limit
NODE_TOLERANCE = 1e-9
NODE_ITERATIONS = 60
#: the traction coefficient below which the settling test of :func:`solve_thermal` takes the traction's changes as
#: absolute (output_tolerance times this): before 2026-11-29 a rolling film's traction, rounding noise about zero,
#: never settled, and rolling solves ran until their largest flow-factor change met the tolerance (measured: level
#: 10 with compression work 24 iterations, 13.2x the isothermal solve's time)
TRACTION_FLOOR = 1e-3


@attrs.frozen(kw_only=True)
class ThermalLineContact:
    """A line contact with the lubricant's and the surfaces' thermal data (SI floats).

    Parameters
    ----------
    R : float
        Reduced radius [m].
    w : float
        Load per unit length [N/m].
    E_reduced : float
        E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] [Pa].
    u1, u2 : float
        Surface speeds [m/s], both > 0 (moving through the contact in the same direction). Surface 1 is the
        one at z = 0; the sliding speed is u_s = u1 - u2.
    eta0 : float
        Viscosity at ambient pressure and the inlet temperature T0 [Pa s].
    alpha : float
        Pressure–viscosity coefficient [1/Pa] (0: isoviscous).
    beta : float
        Temperature–viscosity coefficient -d ln(eta)/dT [1/K] (0: the viscosity does not depend on temperature).
    conductivity : float
        Lubricant thermal conductivity k [W/(m K)].
    heat_capacity : float
        Lubricant heat capacity per volume rho c_p [J/(m^3 K)].
    effusivity_1, effusivity_2 : float
        sqrt(k rho c) of the two surfaces [W s^0.5/(m^2 K)] (:meth:`camcontact.Material.thermal_effusivity`).
    eyring_stress : float, optional
        Eyring stress tau0 [Pa] of the non-Newtonian film (None: Newtonian).
    limiting_shear_stress, limiting_shear_slope : float
        Limiting shear stress tau_L = tau_L0 + Lambda_L p of the film (Bair & Winer 1979) [Pa], [-]; the slope
        None (default): no limit. As the traction models of :mod:`camcontact.models.traction_fluid`.
    viscosity, density, z, p0, elastic
        As :meth:`camcontact.ehl.line_problem.LineEHLProblem.from_contact` (Roelands index z: from eta0 and
        alpha when None).
    domain : (float, float), optional
        [X_a, X_b] in units of b; None (default): :func:`camcontact.ehl.line_domain.automatic_domain` of the
        isothermal problem, an inlet long enough for a flooded film (with [-4, 1.5] the isothermal film is 2.2 %
        thin at 5 m/s and 7 % at 20 m/s for the steel rollers of tests/literature/test_thermal_ehl.py, and the
        inlet's heated back-flow leaves the domain).
    oil_layer : float, optional
        A starved inlet: the layer of lubricant [m] (both surfaces together, at ambient density) the surfaces
        bring to the contact (:func:`solve_thermal`'s starved solve; None: flooded).
    thermal_expansivity : float
        The lubricant's volumetric thermal expansivity alpha_T = -d ln(rho)/dT [1/K] (default 0: the density does
        not depend on temperature and the film does no compression work). With alpha_T > 0 the density is
        rho_DH(p) exp(-alpha_T (T - T0)) (module docstring): the film heats where its flow runs up the pressure and
        cools where it runs down it (alpha_T T u dp/dx), and the hot film's lower density enters the Reynolds
        equation. Mineral oils: 6-7e-4 1/K (6.5e-4 in the thermal EHL analyses since Sadeghi & Dow 1987).
    temperature : float, optional
        The inlet (absolute) temperature T0 [K], 150-800 K, of the lubricant and the surfaces, which the compression
        work alpha_T T u dp/dx needs (required with ``thermal_expansivity`` > 0).
    """

    R: float = number_field(validators=[positive("m")])
    w: float = number_field(validators=[positive("N/m")])
    E_reduced: float = number_field(validators=[positive("Pa")])
    u1: float = number_field(validators=[positive("m/s")])
    u2: float = number_field(validators=[positive("m/s")])
    eta0: float = number_field(validators=[positive("Pa s")])
    alpha: float = number_field(validators=[non_negative("1/Pa")])
    beta: float = number_field(validators=[non_negative("1/K")])
    conductivity: float = number_field(validators=[positive("W/(m K)")])
    heat_capacity: float = number_field(validators=[positive("J/(m^3 K)")])
    effusivity_1: float = number_field(validators=[positive("W s^0.5/(m^2 K)")])
    effusivity_2: float = number_field(validators=[positive("W s^0.5/(m^2 K)")])
    eyring_stress: float | None = number_field(optional=True, validators=[positive("Pa")])
    limiting_shear_stress: float = number_field(default=0.0, validators=[non_negative("Pa")])
    limiting_shear_slope: float | None = number_field(optional=True, validators=[positive()])
    viscosity: str = "roelands"
    density: str = "dowson_higginson"
    z: float | None = None
    p0: float = ROELANDS_P0
    domain: tuple | None = None
    elastic: bool = True
    oil_layer: float | None = number_field(optional=True, validators=[positive("m")])
    thermal_expansivity: float = number_field(default=0.0, validators=[non_negative("1/K")])
    temperature: float | None = number_field(optional=True, validators=[positive("K")])

    def __attrs_post_init__(self) -> None:
        if self.temperature is not None and not 150.0 <= self.temperature <= 800.0:
            raise InputError(f"ThermalLineContact.temperature = {self.temperature!r} K; allowed: an absolute inlet "
                             "temperature of 150-800 K (a value in degrees Celsius would cut the compression work)")
        if self.thermal_expansivity > 0.0 and self.temperature is None:
            raise InputError(f"ThermalLineContact.thermal_expansivity = {self.thermal_expansivity!r} 1/K needs the "
                             "inlet temperature (temperature [K]) for the compression work alpha_T T u dp/dx; give it, "
                             "or thermal_expansivity=0 to leave the compression work out")

    @property
    def u_m(self) -> float:
        """Entrainment (mean) speed (u1 + u2)/2 [m/s]."""
        return 0.5 * (self.u1 + self.u2)

    @property
    def sliding_speed(self) -> float:
        """u_s = u1 - u2 [m/s]."""
        return self.u1 - self.u2

    @property
    def slide_roll_ratio(self) -> float:
        """S = (u1 - u2)/u_m [-]."""
        return self.sliding_speed / self.u_m

    @property
    def supply(self) -> float | None:
        """The starved inlet's content H_oil = h_oil R/b^2 [-] (:attr:`LineEHLProblem.supply`; None: flooded),
        over the Hertz film scale b^2/R of :meth:`LineEHLProblem.scales`."""
        if self.oil_layer is None:
            return None
        return self.oil_layer / self.problem().scales(self.R, self.w, self.E_reduced)["h_scale"]

    def problem(self) -> LineEHLProblem:
        """The dimensionless isothermal problem of the contact (:meth:`LineEHLProblem.from_contact`) on
        :attr:`domain` or the automatic domain."""
        problem = LineEHLProblem.from_contact(R=self.R, w=self.w, E_reduced=self.E_reduced, u_m=self.u_m,
                                              eta0=self.eta0, alpha=self.alpha, z=self.z, viscosity=self.viscosity,
                                              density=self.density, p0=self.p0, elastic=self.elastic)
        domain = self.domain if self.domain is not None else automatic_domain(problem.M, problem.L, self.elastic)
        return attrs.evolve(problem, domain=tuple(domain))


@attrs.frozen
class ThermalLineSolution:
    """Result of :func:`solve_thermal`: the EHL solution with the flow factors it converged to, the isothermal
    Newtonian solution it started from, and the film's temperature and stress fields (SI, per node of
    ``ehl.X``)."""

    contact: ThermalLineContact
    thermal: bool  #: the energy equation was solved
    rheology: str  #: "newtonian" or "eyring"
    ehl: LineEHLSolution  #: final solution (its ``flow_factor`` the converged phi)
    #: isothermal Newtonian solution of the same problem and grid (starved: of the same supply, on its own grid)
    isothermal: LineEHLSolution
    x: np.ndarray = attrs.field(repr=False, eq=False)  #: [m]
    p: np.ndarray = attrs.field(repr=False, eq=False)  #: pressure [Pa]
    h: np.ndarray = attrs.field(repr=False, eq=False)  #: film [m]
    temperature_rise: np.ndarray = attrs.field(repr=False, eq=False)  #: film mean temperature - T0 [K]
    surface_temperature_rise_1: np.ndarray = attrs.field(repr=False, eq=False)  #: [K]
    surface_temperature_rise_2: np.ndarray = attrs.field(repr=False, eq=False)  #: [K]
    shear_stress: np.ndarray = attrs.field(repr=False, eq=False)  #: mid-plane tau_m, sign of u2 - u1 [Pa]
    heat: np.ndarray = attrs.field(repr=False, eq=False)  #: dissipation per unit area [W/m^2]
    #: phi of the last march [-] (with thermal expansion times the film's density factor exp(-alpha_T dT))
    flow_factor: np.ndarray = attrs.field(repr=False, eq=False)
    #: nodes whose viscosity profile across the film reached the bound beta |T - T_mean| = PROFILE_BOUND of
    #: :mod:`camcontact.ehl._thermal_kernels` (a film sheared into bands the nine film points do not resolve) [bool]
    profile_bounded: np.ndarray = attrs.field(repr=False, eq=False)
    wet: np.ndarray = attrs.field(repr=False, eq=False)  #: nodes inlet .. last pressurised + 1 [bool]
    record: ConvergenceRecord  #: the fixed-point iteration (residuals: mean |d ln phi| over the wet nodes)
    #: the viscosity varied across the film (False: uniform at its mean temperature, by request or where the
    #: cross-film iteration did not converge and this one did; the record's message says which)
    cross_film: bool = True
    #: a starved inlet's meniscus x [m] (where the supplied layer fills the gap; the solution's domain starts there;
    #: ``isothermal`` is then the isothermal starved solution of the same supply); None: flooded
    meniscus: float | None = None

    @property
    def scales(self) -> dict:
        c = self.contact
        return self.ehl.problem.scales(c.R, c.w, c.E_reduced)

    @property
    def h_c(self) -> float:
        """Central film h(0) [m]."""
        return self.ehl.H_c * self.scales["h_scale"]

    @property
    def h_min(self) -> float:
        """Minimum film [m]."""
        return self.ehl.H_min * self.scales["h_scale"]

    @property
    def film_reduction(self) -> float:
        """h_c / h_c of the isothermal Newtonian solution [-] (the numerical thermal/non-Newtonian factor)."""
        return self.ehl.H_c / self.isothermal.H_c

    @property
    def minimum_film_reduction(self) -> float:
        """h_min / h_min of the isothermal Newtonian solution [-]."""
        return self.ehl.H_min / self.isothermal.H_min

    def _integral(self, values: np.ndarray) -> float:
        return _trapezoid(values, self.x, self.wet)

    @property
    def traction_force(self) -> float:
        """Sliding traction per unit length int tau_m dx over the wet film [N/m], sign of u_s = u1 - u2."""
        return -self._integral(self.shear_stress)

    @property
    def traction_coefficient(self) -> float:
        """traction_force / w [-], sign of u_s (as :mod:`camcontact.contact.fluid_traction`)."""
        return self.traction_force / self.contact.w

    @property
    def rolling_force(self) -> float:
        """Rolling (Poiseuille) resistance per unit length int h/2 dp/dx dx over the wet film [N/m]: the part of
        each surface's shear force that the pressure gradient adds (> 0 opposes the rolling)."""
        dp = np.gradient(self.p, self.x)
        return self._integral(0.5 * self.h * dp)

    @property
    def max_temperature_rise(self) -> float:
        """Largest film mean temperature rise over the wet film [K]."""
        return float(self.temperature_rise[self.wet].max())

    @property
    def max_surface_temperature_rise(self) -> tuple[float, float]:
        """Largest surface temperature rises (surface 1, surface 2) over the wet film [K]."""
        return (float(self.surface_temperature_rise_1[self.wet].max()),
                float(self.surface_temperature_rise_2[self.wet].max()))

    def traction_profile(self):
        """The pressure and film of the solution for the lumped traction model
        (:meth:`camcontact.ehl.line_solution.LineEHLSolution.traction_profile`)."""
        return self.ehl.traction_profile()

    def summary(self) -> dict:
        """The decision values with units in their names."""
        return {
            "h_c [m]": self.h_c, "h_min [m]": self.h_min, "h_c isothermal [m]": self.isothermal.H_c * self.scales[
                "h_scale"], "film reduction [-]": self.film_reduction,
            "minimum film reduction [-]": self.minimum_film_reduction,
            "traction coefficient [-]": self.traction_coefficient, "traction force [N/m]": self.traction_force,
            "rolling force [N/m]": self.rolling_force, "max film temperature rise [K]": self.max_temperature_rise,
            "max surface temperature rise 1 [K]": self.max_surface_temperature_rise[0],
            "max surface temperature rise 2 [K]": self.max_surface_temperature_rise[1],
            "profile bounded nodes [-]": int(np.count_nonzero(self.profile_bounded & self.wet)),
            "iterations [-]": self.record.cycles, "converged": self.record.converged,
            "wall time [s]": self.record.wall_time,
        }

    def plot(self, axes=None):
        """Pressure and film (top), temperatures and mid-plane shear stress (bottom) over x/b (matplotlib)."""
        import matplotlib.pyplot as plt

        if axes is None:
            _, axes = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
        b = self.scales["b"]
        X = self.x / b
        top, bottom = axes
        top.plot(X, self.p / 1e9, label="p [GPa]")
        top.plot(self.isothermal.X, self.isothermal.P * self.scales["p_h"] / 1e9, color="0.6", linestyle=":",
                 label="p isothermal Newtonian")
        top.set(ylabel="p [GPa]", title=(f"{self.rheology}, {'thermal' if self.thermal else 'isothermal'}: "
                                         f"h_c {1e9 * self.h_c:.0f} nm ({self.film_reduction:.3f} of isothermal), "
                                         f"µ {self.traction_coefficient:.4f}"))
        film = top.twinx()
        film.plot(X, 1e9 * self.h, color="tab:orange", label="h [nm]")
        film.plot(self.isothermal.X, 1e9 * self.isothermal.H * self.scales["h_scale"], color="tab:orange",
                  linestyle=":", label="h isothermal Newtonian")
        film.set_ylim(0, 4 * 1e9 * self.h_min)
        film.set_ylabel("h [nm]")
        lines = top.get_legend_handles_labels()[0] + film.get_legend_handles_labels()[0]
        top.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
        bottom.plot(X, self.temperature_rise, label="film mean")
        bottom.plot(X, self.surface_temperature_rise_1, label=f"surface 1 ({self.contact.u1:g} m/s)")
        bottom.plot(X, self.surface_temperature_rise_2, label=f"surface 2 ({self.contact.u2:g} m/s)")
        bottom.set(xlabel="x/b", ylabel="temperature rise [K]")
        stress = bottom.twinx()
        stress.plot(X, np.abs(self.shear_stress) / 1e6, color="tab:red", linestyle="--", label="|τ_m| [MPa]")
        stress.set_ylabel("|τ_m| [MPa]")
        lines = bottom.get_legend_handles_labels()[0] + stress.get_legend_handles_labels()[0]
        bottom.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
        bottom.set_xlim(X[0], X[-1])
        return axes


#: film points across the film of the layered energy model (Chebyshev–Lobatto, surfaces included) and the
#: most nodes along x it uses (every 2^k-th node of the EHL grid)
LAYER_POINTS = 9
LAYER_NODES = 900
#: sweep pairs (downstream + upstream) of the layered energy equation per fixed-point iteration at most, and the
#: temperature change [K] below which they stop
LAYER_SWEEPS = 12
LAYER_TOLERANCE = 1e-4
#: while the fixed point is far from its own: the sweeps stop at a temperature change of SWEEP_SHARE x the last
#: iteration's mean |d ln phi| / beta (the temperature error that moves ln phi by that share of the iteration's own
#: change), between LAYER_TOLERANCE and LOOSEST_SWEEPS [K]; the iteration that meets the flow tolerance is redone
#: with the sweeps to LAYER_TOLERANCE before it counts as converged
SWEEP_SHARE = 0.1
LOOSEST_SWEEPS = 1.0


def _collocation(points: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(zeta, D, D2, weights): Chebyshev–Lobatto points on [0, 1], the derivative matrices d/dzeta and
    d^2/dzeta^2 (Trefethen 2000, Spectral Methods in MATLAB, cheb.m, mapped) and Clenshaw–Curtis weights of
    the mean over [0, 1]."""
    N = points - 1
    k = np.arange(N + 1)
    x = np.cos(np.pi * k / N)
    c = np.where((k == 0) | (k == N), 2.0, 1.0) * (-1.0) ** k
    dX = x[:, None] - x[None, :]
    D = np.outer(c, 1.0 / c) / (dX + np.eye(N + 1))
    D -= np.diag(D.sum(axis=1))
    zeta = 0.5 * (1.0 - x)
    Dz = -2.0 * D
    weights = np.zeros(N + 1)  # Clenshaw-Curtis on [-1, 1], halved for the mean over [0, 1]
    theta = np.pi * k / N
    for j in range(N + 1):
        total = 1.0
        for m in range(1, N // 2 + 1):
            b = 1.0 if 2 * m == N else 2.0
            total -= b * np.cos(2 * m * theta[j]) / (4 * m * m - 1)
        weights[j] = total * (1.0 if j in (0, N) else 2.0) / N
    return zeta, Dz, Dz @ Dz, 0.5 * weights


@functools.lru_cache(maxsize=4)
def _film_points(points: int) -> tuple[np.ndarray, ...]:
    """(zeta, D, D2, weights, integral) of :func:`_collocation` and :func:`_antiderivative_matrix` (read-only)."""
    collocation = _collocation(points)
    arrays = (*collocation, _antiderivative_matrix(collocation[0]))
    for array in arrays:
        array.flags.writeable = False
    return arrays


def _antiderivative_matrix(zeta: np.ndarray) -> np.ndarray:
    """Q with (Q f)_j = int_0^zeta_j p_f: the antiderivative, at the film points ``zeta`` on [0, 1], of the polynomial
    p_f interpolating f there (exact for polynomials of degree < len(zeta))."""
    N = zeta.size - 1
    Q = np.empty((N + 1, N + 1))
    for c in range(N + 1):
        unit = np.zeros(N + 1)
        unit[c] = 1.0
        p = np.polynomial.Chebyshev.fit(zeta, unit, N, domain=[0.0, 1.0])
        Q[:, c] = p.integ(lbnd=0.0)(zeta)
    return Q


def _layers(contact: ThermalLineContact, solution: LineEHLSolution, thermal: bool, tau0: float, state: dict,
            kernels: dict, scales: dict | None = None, cross_film: bool = True,
            sweep_tolerance: float = LAYER_TOLERANCE) -> dict:
    """Temperature, stress and flow-factor fields of ``solution`` from the layered energy model (sweeps warm-started
    from ``state``, which keeps the temperatures between iterations); ``scales`` (b, p_h, h_scale of the solution's
    X, P, H; default: the contact's Hertz scales); ``cross_film``: the viscosity varies across the film with its
    temperature (Yang & Wen's generalised Reynolds terms), else uniform at the film's mean temperature;
    ``sweep_tolerance`` [K]: the sweeps stop at that change of the temperatures (:data:`SWEEP_SHARE`)."""
    problem = solution.problem
    scales = scales or problem.scales(contact.R, contact.w, contact.E_reduced)
    b, p_h, h_scale = scales["b"], scales["p_h"], scales["h_scale"]
    X, P = solution.X, solution.P
    n = X.size
    h = np.maximum(solution.H, 0.0) * h_scale
    dp = np.gradient(P, X) * (p_h / b)
    eta_iso = contact.eta0 * np.exp(problem.log_viscosity(P))
    limit = (np.full(n, np.inf) if contact.limiting_shear_slope is None
             else contact.limiting_shear_stress + contact.limiting_shear_slope * P * p_h)
    used = solution.poiseuille_factor  # the flow factor the solution was solved with, at its pressure
    zeta, D, D2, weights, integral = _film_points(LAYER_POINTS)
    expansivity = contact.thermal_expansivity if thermal else 0.0
    stride = 1  # the energy equation's nodes: every stride-th node of the EHL grid
    while (n - 1) // stride > LAYER_NODES and (n - 1) % (2 * stride) == 0:
        stride *= 2
    coarse = slice(None, None, stride)
    Xe = X[coarse]
    # with thermal expansion the solution's factors carry the density exp(-alpha_T Tm) of the temperatures they came
    # from (those the sweeps start from): its volume flux is the mass flux over that density
    density = np.ones(n)
    if expansivity > 0.0 and state.get("T") is not None and state["T"].shape[0] == Xe.size:
        density = np.exp(-expansivity * np.interp(X, Xe, state["T"] @ weights))
    flux = -used / density * h**3 * dp / (12.0 * eta_iso)  # Poiseuille (volume) flux in +x the solver carries
    pressurised = np.flatnonzero(P > 0.0)
    last = int(pressurised[-1]) + 1 if pressurised.size else n - 1
    wet = np.arange(n) <= min(last, n - 1)
    du = contact.u2 - contact.u1
    profile = np.zeros((n, LAYER_POINTS))
    failed = 0
    unsettled = False
    sweep_change = 0.0  # the temperature change [K] of the last sweep pair (0: no energy equation)
    if thermal:
        if state.get("T") is None or state["T"].shape[0] != Xe.size:
            state.update(T=np.zeros((Xe.size, LAYER_POINTS)), q1=np.zeros(Xe.size), q2=np.zeros(Xe.size))
        T, q1, q2 = state["T"], state["q1"], state["q2"]
        dx = float(Xe[1] - Xe[0]) * b
        C1 = 1.0 / (contact.effusivity_1 * math.sqrt(math.pi * contact.u1))
        C2 = 1.0 / (contact.effusivity_2 * math.sqrt(math.pi * contact.u2))
        # the compression work takes the pressure change between the energy grid's nodes (the EHL grid's gradient
        # sampled at every stride-th node missed or caught the outlet spike by chance: the outlet film's
        # temperature swung from -3 to -63 K with the grid level, measured)
        args = (dx, np.ascontiguousarray(h[coarse]), np.ascontiguousarray(eta_iso[coarse]),
                np.ascontiguousarray(flux[coarse]), np.ascontiguousarray(limit[coarse]), contact.u1, du, tau0,
                contact.beta, contact.conductivity,
                contact.heat_capacity, C1, C2, zeta, D, D2, weights, integral, T, q1, q2, NODE_TOLERANCE,
                NODE_ITERATIONS, bool(cross_film), expansivity, np.ascontiguousarray(P[coarse] * p_h),
                contact.temperature or 0.0)
        for _ in range(LAYER_SWEEPS):
            down, bad_down = kernels["layer_sweep"](1, *args)
            up, bad_up = kernels["layer_sweep"](-1, *args)
            change = max(down, up)
            if change <= sweep_tolerance:
                break
        sweep_change = change
        if bad_down or bad_up:
            failed = 1
            failure = (f"energy sweeps: no film temperature within {_thermal_kernels.MAX_RISE:g} K at "
                       f"{max(bad_down, bad_up)} nodes")
        elif change > sweep_tolerance:
            unsettled = True
            failure = f"energy sweeps: {LAYER_SWEEPS} sweep pairs left a change of {change:.3g} K"
        profile = np.column_stack([np.interp(X, Xe, T[:, j]) for j in range(LAYER_POINTS)])
    beta = contact.beta if thermal else 0.0
    tau, phi, Q, a, total, m = (np.empty(n) for _ in range(6))
    kernels["film_fields"](eta_iso, h, flux, limit, du, tau0, beta, profile, bool(cross_film), zeta, integral, weights,
                           tau, phi, Q, a, total, m)
    # the solver's factors: F = a sqrt(1 + (k eta-bar)^2) on the Poiseuille coefficient, a = -12 C_P of the viscosity
    # profile (exp(beta dT) for a uniform one), the Eyring coefficient k = eta0 |u2 - u1|/(tau0 h F0(1)) of
    # Lambda = k eta-bar at the Couette (harmonic-mean) viscosity (0: Newtonian), and the Couette factor
    # c = (u1 + (u2 - u1) m)/u_m on the wedge (1 in pure rolling and for a uniform viscosity)
    k = (contact.eta0 * abs(du) / (tau0 * total * np.maximum(h, 1e-300)) if tau0 > 0.0 and du != 0.0
         else np.zeros(n))
    c = (contact.u1 + du * m) / contact.u_m if cross_film else np.ones(n)
    Tm = profile @ weights
    # the film's density rho_DH(p) exp(-alpha_T Tm) at its mean temperature rise, on both the Poiseuille and the
    # Couette coefficient of the Reynolds equation (1 without thermal expansion)
    expansion = np.exp(-expansivity * Tm)
    a = a * expansion
    c = c * expansion
    spread = beta * np.abs(profile - Tm[:, None]).max(axis=1)
    bounded = spread > _thermal_kernels.PROFILE_BOUND if cross_film else np.zeros(n, dtype=bool)
    return {"Tm": Tm, "T1": profile[:, 0], "T2": profile[:, -1], "tau": tau, "phi": phi * a,
            "used": used, "a": a, "k": k, "c": c, "Q": Q, "x": X * b, "p": P * p_h, "h": h, "wet": wet,
            "bounded": bounded, "failed": failed, "unsettled": unsettled, "sweep_change": sweep_change,
            "failure": failure if failed or unsettled else ""}


def solve_thermal(
    contact: ThermalLineContact,
    levels: int = 10,
    *,
    thermal: bool = True,
    non_newtonian: bool | None = None,
    tolerance: float = 1e-7,
    flow_tolerance: float = 1e-3,
    output_tolerance: float = 1e-4,
    relaxation: float = 0.8,
    max_iterations: int = 40,
    cross_film: bool = True,
    strict: bool = False,
    compiled: bool = True,
) -> ThermalLineSolution:
    """Solve the thermal and/or non-Newtonian line contact ``contact`` on ``levels`` grid levels (module
    docstring).

    Parameters
    ----------
    contact : ThermalLineContact
    levels : int
        Finest multigrid level (10: 7169 nodes).
    thermal : bool
        Solve the energy equation (False: isothermal at T0).
    non_newtonian : bool, optional
        Eyring film (needs ``contact.eyring_stress``); None: Eyring when the contact has an Eyring stress.
    tolerance : float
        Tolerance of each multigrid solve (:func:`solve_multigrid`).
    flow_tolerance, output_tolerance : float
        Stop when the mean of |ln F_new - ln F| + |ln c_new - ln c| over the wet nodes (F the flow factors at the
        current pressure, c the Couette factors) is below ``flow_tolerance`` and either its largest value is too, or
        H_c, H_min and the traction force changed by less than ``output_tolerance`` (relative; the traction's against
        at least :data:`TRACTION_FLOOR` of the load) from the previous iteration. (The largest change stays at a few
        nodes of the outlet constriction, where the film moves from iteration to iteration: measured 0.003-0.04 when
        the films and the traction have settled to 1e-4.)
    relaxation : float
        Mixing parameter of the Anderson iteration on (ln a, ln k, ln c) (the plain relaxation of its first step and
        of the shortened steps after a failed solve), in (0, 1].
    max_iterations : int
        Fixed-point iterations at most per level (each one multigrid solve and one energy solve).
    cross_film : bool
        The viscosity varies across the film with its temperature, and the Reynolds equation is Yang & Wen's
        generalised one (default). False: the viscosity is uniform across the film at its mean temperature (the
        model of camcontact before 2026-11-28, kept to show what the cross-film terms change). Where the cross-film
        iteration does not converge (heavy sliding: the profile's feedback on the entrainment stalls it) and the
        uniform one does, the uniform solution is returned, ``cross_film`` False on it and the record's message
        saying so (:data:`UNIFORM_FALLBACK`).
    strict : bool
        Raise ConvergenceError instead of warning when not converged.
    compiled : bool
        Numba kernels (False: the plain-Python twins, slow; for tests).

    A starved inlet (``contact.oil_layer``) is solved as :func:`camcontact.ehl.line_starved.solve_starved` solves the
    isothermal one, each trial meniscus X_m a thermal solve of the domain [X_m, X_b]: the meniscus where the
    thermal film's mass flux (:func:`~camcontact.ehl.line_starved.wet_flux`, with its flow and Couette factors)
    equals the supply to max(``output_tolerance``, 10 ``tolerance``) (the flux of one thermal solve is settled to
    about ``output_tolerance``), by :func:`~camcontact.ehl.line_starved.find_meniscus`. The lubricant and the
    surfaces enter the meniscus at T0 (the unpressurised layer ahead of it is not heated here). A supply of at least
    the thermal flooded film's flux leaves the contact flooded. The solution's domain starts at the meniscus
    (:attr:`ThermalLineSolution.meniscus`), its ``isothermal`` is the isothermal starved solution of the same supply
    and its record's message gives the meniscus, the flux error and the number of thermal solves.
    """
    if not isinstance(contact, ThermalLineContact):
        raise InputError(f"solve_thermal: contact = {contact!r}; allowed: a ThermalLineContact")
    if non_newtonian is None:
        non_newtonian = contact.eyring_stress is not None
    if non_newtonian and contact.eyring_stress is None:
        raise InputError("solve_thermal: non_newtonian=True needs the contact's eyring_stress [Pa] (the Eyring "
                         "stress tau0 of the lubricant, e.g. 2-10 MPa for mineral oils)")
    if not (isinstance(relaxation, (int, float)) and 0.0 < relaxation <= 1.0):
        raise InputError(f"solve_thermal: relaxation = {relaxation!r}; allowed: 0 < relaxation <= 1")
    for name, value in (("flow_tolerance", flow_tolerance), ("output_tolerance", output_tolerance)):
        if not (isinstance(value, (int, float)) and value > 0.0):
            raise InputError(f"solve_thermal: {name} = {value!r}; allowed: > 0")
    if not (isinstance(max_iterations, int) and max_iterations >= 1):
        raise InputError(f"solve_thermal: max_iterations = {max_iterations!r}; allowed: an integer >= 1")
    options = dict(thermal=thermal, non_newtonian=non_newtonian, tolerance=tolerance, flow_tolerance=flow_tolerance,
                   output_tolerance=output_tolerance, relaxation=relaxation, max_iterations=max_iterations,
                   cross_film=cross_film, strict=strict, compiled=compiled)
    if contact.oil_layer is not None:
        result = _starved(contact, levels, options)
    else:
        result = _flooded(contact, levels, options)
    if not result.record.converged:
        not_converged(f"thermal line EHL did not converge: {result.record.message}", result.record, strict=strict)
    return result


def profile_bound_note(count: int) -> str:
    """The reason a film is not valid where its viscosity profile reached its bound at ``count`` nodes
    (:attr:`ThermalLineSolution.profile_bounded`, :attr:`ThermalTransientResult.profile_bounded`)."""
    return (f"the film's viscosity profile reached its bound at {count} nodes (a film sheared into bands the solver's "
            "nine film points do not resolve; its film and traction depend on "
            "camcontact.ehl._thermal_kernels.PROFILE_BOUND)")


#: the record's message where :func:`solve_thermal` returns the uniform-viscosity solution
UNIFORM_FALLBACK = ("the viscosity uniform across the film at its mean temperature (cross_film=False): the iteration "
                    "with the viscosity varying across it did not converge")


def _flooded(contact: ThermalLineContact, levels: int, options: dict) -> ThermalLineSolution:
    """The flooded solve of :func:`solve_thermal` (``options`` its checked keywords), with the uniform-viscosity
    fallback; not converged: the record says so (no warning here)."""
    start = time.perf_counter()
    cross_film, thermal = options["cross_film"], options["thermal"]
    try:
        result, failure = _iterate(contact, levels, **options), None
    except ConvergenceError as exc:  # a non-finite flow factor
        if not (cross_film and thermal):
            raise
        result, failure = None, exc
    if cross_film and thermal and (result is None or not result.record.converged):
        # the viscosity profile's feedback stalled (heavy sliding): the uniform-viscosity model, if it converges
        uniform = _iterate(contact, levels, **(options | {"cross_film": False}))
        if uniform.record.converged or result is None:
            text = result.record.message if result is not None else str(failure)
            record = attrs.evolve(uniform.record, wall_time=time.perf_counter() - start,
                                  message=f"{UNIFORM_FALLBACK} ({text}); {uniform.record.message}")
            result = attrs.evolve(uniform, record=record)
    return result


def _starved(contact: ThermalLineContact, levels: int, options: dict) -> ThermalLineSolution:
    """The starved solve of :func:`solve_thermal` (its docstring): the meniscus by
    :func:`~camcontact.ehl.line_starved.find_meniscus` over flooded thermal solves of the reduced domains."""
    from .line_starved import find_meniscus, solve_starved, wet_flux

    start = time.perf_counter()
    fed = attrs.evolve(contact, oil_layer=None)
    supply = float(contact.supply)
    X_a, X_b = contact.problem().domain
    solutions: dict[float, ThermalLineSolution] = {}

    def flux_error(x_m: float) -> float:
        solutions[x_m] = _flooded(attrs.evolve(fed, domain=(x_m, X_b)), levels, options)
        return wet_flux(solutions[x_m].ehl) / supply - 1.0

    flooded = _flooded(fed, levels, options)
    F_ff = wet_flux(flooded.ehl)
    if supply >= F_ff:
        chosen, x_m, converged = flooded, None, flooded.record.converged
        message = f"flooded: supply {supply:.6g} >= the thermal flooded flux {F_ff:.6g}"
    else:
        target = max(options["output_tolerance"], 10.0 * options["tolerance"])
        x_m, error = find_meniscus(flux_error, X_a, F_ff / supply - 1.0, target=target, supply=supply,
                                   record=flooded.record, caller="solve_thermal (starved inlet)")
        chosen = solutions[x_m]
        converged = chosen.record.converged and abs(error) <= target
        message = (f"meniscus at X = {x_m:.6g}; flux/supply - 1 = {error:.3g} (target {target:g}); "
                   f"{len(solutions) + 1} thermal solves")
    starved_problem = attrs.evolve(contact.problem(), cavitation="mass_conserving", supply=supply)
    isothermal = solve_starved(starved_problem, levels, tolerance=options["tolerance"], strict=options["strict"],
                               compiled=options["compiled"])
    record = attrs.evolve(chosen.record, method=f"starved inlet: meniscus by regula falsi over {chosen.record.method}",
                          wall_time=time.perf_counter() - start, converged=bool(converged),
                          message=f"{message}; last solve: {chosen.record.message}")
    meniscus = None if x_m is None else x_m * chosen.scales["b"]
    return attrs.evolve(chosen, contact=contact, isothermal=isothermal, record=record, meniscus=meniscus)


def _iterate(contact: ThermalLineContact, levels: int, *, thermal: bool, non_newtonian: bool, tolerance: float,
             flow_tolerance: float, output_tolerance: float, relaxation: float, max_iterations: int,
             cross_film: bool, strict: bool, compiled: bool) -> ThermalLineSolution:
    """The fixed point of :func:`solve_thermal` with one viscosity model (``cross_film``), its inputs checked; the
    solution carries its record, converged or not (no warning here)."""
    start = time.perf_counter()
    kernels = {name: _thermal_kernels.compiled(name) if compiled else _thermal_kernels.PY[name]
               for name in ("layer_sweep", "film_fields")}
    state: dict = {}
    tau0 = float(contact.eyring_stress) if non_newtonian else 0.0
    problem = contact.problem()
    isothermal = solve_multigrid(problem, levels, tolerance=tolerance, strict=strict, compiled=compiled)
    stages = list(range(levels, NESTED_FROM - 1, -2))[::-1] if levels > NESTED_FROM else [levels]
    if stages[0] == levels:
        solution = isothermal
    else:
        solution = solve_multigrid(problem, stages[0], tolerance=tolerance, strict=strict, compiled=compiled)
    eyring = non_newtonian and contact.u1 != contact.u2  # a sheared Eyring film: its flow factor has k > 0
    # a heated film in sliding: its viscosity profile shifts the entrainment flux (Couette factor c != 1); a film
    # that expands as it heats carries less mass at the entrainment speed (c the density factor)
    couette = bool(thermal and ((cross_film and contact.beta > 0.0 and contact.u1 != contact.u2)
                                or contact.thermal_expansivity > 0.0))
    x = None  # the iteration's variables: ln a (, ln k) (, ln c) per node
    changes: list[float] = []
    loads: list[float] = []
    works: list[float] = []
    per_stage: list[str] = []
    work = isothermal.record.work_units[-1] if isothermal.record.work_units else 0.0
    halvings = 0
    stalled = None

    def variables(fields) -> np.ndarray:
        """ln a (, ln k) (, ln c) per node of the fields' flow and Couette factors."""
        parts = ([np.log(fields["a"])] + ([np.log(np.maximum(fields["k"], 1e-300))] if eyring else [])
                 + ([np.log(fields["c"])] if couette else []))
        return np.concatenate(parts)

    def solve(level, x, initial):
        """(solution, work, failure) of the multigrid solve with the flow and Couette factors of ``x``."""
        n = problem.grid(level).size
        parts = iter(np.exp(np.split(x, len(x) // n)))
        factors = {"flow_factor": next(parts), "eyring": next(parts) if eyring else None,
                   "couette": next(parts) if couette else None}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ConvergenceWarning)
                attempt = solve_multigrid(problem, level, tolerance=tolerance, initial=initial, compiled=compiled,
                                          **factors)
        except ConvergenceError as exc:
            return None, 0.0, str(exc)
        cost = attempt.record.work_units[-1] if attempt.record.work_units else 0.0
        return attempt, cost, None if attempt.record.converged else attempt.record.message

    for stage, level in enumerate(stages):
        if stage:  # nested iteration: the flow factors of the level below, interpolated, and a warm start
            below = solution.X.size
            x = np.concatenate([np.interp(problem.grid(level), solution.X, part)
                                for part in np.split(x, len(x) // below)])
            attempt, cost, failure = solve(level, x, solution)
            work += cost
            if failure is not None:
                stalled = f"the solve on level {level} from level {stages[stage - 1]} failed: {failure[:200]}"
                break
            solution = attempt
        converged = False
        previous = None
        history: list = []
        first = len(changes)
        tight = False  # this pass's sweeps must reach LAYER_TOLERANCE (the flow factors looked settled)
        for _ in range(max_iterations):
            sweep_tolerance = LAYER_TOLERANCE
            if len(changes) > first and not tight and thermal and contact.beta > 0.0:
                sweep_tolerance = min(LOOSEST_SWEEPS, max(LAYER_TOLERANCE,
                                                          SWEEP_SHARE * changes[-1] / contact.beta))
            tight = False
            fields = _layers(contact, solution, thermal, tau0, state, kernels, cross_film=cross_film,
                             sweep_tolerance=sweep_tolerance)
            target = variables(fields)
            if x is None:  # the isothermal start: the Eyring coefficients of its film to begin with
                x = target.copy()
                x[:solution.X.size] = 0.0
                if couette:
                    x[-solution.X.size:] = 0.0
            wet = fields["wet"]
            # the flow and Couette factors the film wants against those its solution was solved with, at its pressure
            difference = (np.abs(np.log(fields["phi"][wet]) - np.log(fields["used"][wet]))
                          + np.abs(np.log(fields["c"][wet]) - np.log(solution.couette_factor[wet])))
            change, largest = float(np.mean(difference)), float(np.max(difference))
            changes.append(change)
            # the traction force against at least TRACTION_FLOOR of the load: a rolling film's traction is rounding
            # noise (1e-18 w), whose relative changes never settle
            watched = np.array([solution.H_c, solution.H_min,
                                abs(_trapezoid(fields["tau"], fields["x"], wet)) + TRACTION_FLOOR * contact.w])
            settled = previous is not None and bool(np.all(np.abs(watched / previous - 1.0) <= output_tolerance))
            previous = watched
            loads.append(solution.record.load_errors[-1] if solution.record.load_errors else float("nan"))
            works.append(work)
            if not math.isfinite(change):
                raise ConvergenceError(f"thermal line EHL: non-finite flow factor (iteration {len(changes)})",
                                       _record(changes, loads, works, start, False, "non-finite flow factor", levels,
                                               solution))
            if change <= flow_tolerance and (settled or largest <= flow_tolerance):
                if fields["sweep_change"] <= LAYER_TOLERANCE:
                    converged = True
                    break
                # the flow factors have settled, the temperatures not yet to LAYER_TOLERANCE (loose sweeps, or
                # LAYER_SWEEPS pairs did not reach it): the same solution again, with tight sweeps
                tight = True
                continue
            residual = target - x
            proposal = _anderson(history, x, residual, relaxation)
            step = 1.0
            while True:  # a step whose multigrid solve fails is halved (down to MIN_STEP), without the mixing
                trial = proposal if step == 1.0 else x + step * relaxation * residual
                attempt, cost, failure = solve(level, trial, solution)
                work += cost
                if failure is None:
                    break
                step *= 0.5
                if step < MIN_STEP:
                    break
            if failure is not None:
                stalled = (f"the multigrid solve failed with every step down to {MIN_STEP:g} of the flow factors' "
                           f"change at iteration {len(changes)}: {failure.split(': ', 1)[-1][:200]}")
                break
            if step < 1.0:
                halvings += 1
                history.clear()
            x, solution = trial, attempt
        per_stage.append(f"{len(changes) - first} on level {level}")
        if stalled:
            break
    message = (f"mean |d ln phi| {changes[-1]:.3g} (largest {largest:.3g}) after {len(changes)} iterations "
               f"({', '.join(per_stage)}) "
               f"(tolerance {flow_tolerance:g}; films and traction settled to {output_tolerance:g}: {settled})"
               + (f"; {halvings} steps halved" if halvings else "")
               + (f"; stopped: {stalled}" if stalled else "")
               + (f"; {fields['failure']}" if fields["failure"] else "")
               + (f"; viscosity profile bounded at {np.count_nonzero(fields['bounded'] & fields['wet'])} wet nodes"
                  if np.any(fields["bounded"] & fields["wet"]) else ""))
    converged = converged and not fields["failed"] and solution.record.converged
    record = _record(changes, loads, works, start, converged, message, levels, solution)
    return ThermalLineSolution(
        contact=contact, thermal=bool(thermal), rheology="eyring" if non_newtonian else "newtonian", ehl=solution,
        isothermal=isothermal, x=fields["x"], p=fields["p"], h=fields["h"], temperature_rise=fields["Tm"],
        surface_temperature_rise_1=fields["T1"], surface_temperature_rise_2=fields["T2"],
        shear_stress=fields["tau"], heat=fields["Q"], flow_factor=fields["phi"], wet=fields["wet"],
        profile_bounded=fields["bounded"], record=record, cross_film=bool(cross_film))


def _anderson(history: list, x: np.ndarray, residual: np.ndarray, mixing: float) -> np.ndarray:
    """Next iterate of the fixed point x = g(x) by Anderson mixing (Walker & Ni 2011, Anderson 1965): from the
    iterate x, its residual g(x) - x and the ``history`` of previous (x, residual) pairs (updated in place, at most
    :data:`ANDERSON_DEPTH`), x + mixing residual - (dX + mixing dF) gamma with gamma the least-squares
    coefficients of the residual on the residual differences dF."""
    history.append((x.copy(), residual.copy()))
    del history[:-ANDERSON_DEPTH - 1]
    if len(history) < 2:
        return x + mixing * residual
    dX = np.stack([b[0] - a[0] for a, b in zip(history[:-1], history[1:])], axis=1)
    dF = np.stack([b[1] - a[1] for a, b in zip(history[:-1], history[1:])], axis=1)
    gamma = np.linalg.lstsq(dF, residual, rcond=None)[0]
    return x + mixing * residual - (dX + mixing * dF) @ gamma


def _trapezoid(values: np.ndarray, x: np.ndarray, mask: np.ndarray) -> float:
    return float(np.trapezoid(values[mask], x[mask]))


def _record(changes, loads, works, start, converged, message, levels, solution) -> ConvergenceRecord:
    return ConvergenceRecord(method="thermal/non-Newtonian fixed point on FAS multigrid", levels=int(levels),
                             nodes=int(solution.X.size), residuals=tuple(changes), load_errors=tuple(loads),
                             work_units=tuple(works), wall_time=time.perf_counter() - start, converged=converged,
                             message=message, tolerance=float("nan"))


@attrs.frozen
class ThermalTransientResult:
    """Result of :func:`thermal_transient_cycle`: the transient films and, per instant, the film's thermal state."""

    films: object  #: the :class:`camcontact.ehl.line_transient.TransientLineResult` of the march
    temperature_rise: np.ndarray = attrs.field(repr=False, eq=False)  #: largest film mean rise [K] per instant
    surface_temperature_rise: np.ndarray = attrs.field(repr=False, eq=False)  #: largest surface rise [K]
    traction_coefficient: np.ndarray = attrs.field(repr=False, eq=False)  #: int tau_m dx / w, sign of u1 - u2
    thermal: np.ndarray = attrs.field(repr=False, eq=False)  #: the energy equation ran at the instant [bool]
    energy_time: float  #: wall time spent on the energy equation [s]
    #: wet nodes whose film viscosity profile reached its bound in the energy solve after the instant (its flow
    #: factors are the next step's; :attr:`ThermalLineSolution.profile_bounded`) [-]
    profile_bounded: np.ndarray = attrs.field(factory=lambda: np.zeros(0, dtype=int), repr=False, eq=False)

    def to_frame(self):
        """The march's frame (:meth:`TransientLineResult.to_frame`) with the thermal columns."""
        frame = self.films.to_frame()
        frame["max film temperature rise [K]"] = self.temperature_rise
        frame["max surface temperature rise [K]"] = self.surface_temperature_rise
        frame["traction coefficient [-]"] = self.traction_coefficient
        frame["thermal"] = self.thermal
        frame["profile bounded nodes [-]"] = self.profile_bounded
        return frame


def thermal_transient_cycle(times, w, R, u1, u2, *, contact: ThermalLineContact, levels: int = 8,
                            thermal: bool = True, non_newtonian: bool | None = None, tolerance: float = 1e-6,
                            cross_film: bool = True, strict: bool = False, compiled: bool = True,
                            **options) -> ThermalTransientResult:
    """The transient line contact (:func:`camcontact.ehl.line_transient.transient_cycle`, squeeze term, BDF2) with
    the thermal and non-Newtonian film of this module, coupled step by step.

    After each instant the energy equation (:func:`camcontact.ehl._thermal_kernels.layer_sweep`, warm-started from
    the previous instant) runs on the instant's pressure and film with its surface speeds, and its flow-factor
    parameters (a, k) are the next step's: a lagged coupling, quasi-steady in the energy (the film crosses the
    contact in b/u_m, tens of microseconds, against steps of a degree of cam, a hundred microseconds or more at
    1000 rpm). The first instant starts isothermal (the steady start of the march). Instants where a surface does
    not move through the contact in the direction of the entrainment (u1 or u2 <= 0: a flat follower near its
    reversal) have no energy solution here: the next step runs isothermal and ``thermal`` is False there.

    Parameters
    ----------
    times, w, R : arrays
        As :func:`transient_cycle` [s], [N/m], [m].
    u1, u2 : arrays [m/s]
        The surface speeds (u_m = (u1 + u2)/2).
    contact : ThermalLineContact
        The lubricant's, the surfaces' and the rheology's data (its own R, w, u1, u2 are not used).
    levels, tolerance, strict, compiled, options
        As :func:`transient_cycle` (``options``: its further keywords).
    thermal, non_newtonian, cross_film : bool
        As :func:`solve_thermal`: with ``cross_film`` the march takes the Poiseuille and Couette factors of the film's
        viscosity profile (the squeeze term keeps the film's content, the wedge the Couette factor's).

    The compression work (``contact.thermal_expansivity`` > 0) is refused (InputError): with the lagged coupling it
    fed a cam's outlet pressure spike, which grew from step to step (measured: LS-1 roller turn, level 8, 1.6, 1.7,
    2.2, 4.3 GPa over four steps, the film there 80, 107, 180, 728 K above T0, its flow factor 2.5e9, then no
    solution), where the steady iteration converges.
    """
    from .line_transient import transient_cycle

    if not isinstance(contact, ThermalLineContact):
        raise InputError(f"thermal_transient_cycle: contact = {contact!r}; allowed: a ThermalLineContact")
    if thermal and contact.thermal_expansivity > 0.0:
        raise InputError(f"thermal_transient_cycle: contact.thermal_expansivity = {contact.thermal_expansivity!r} 1/K; "
                         "allowed: 0 (the transient march does not take the compression work: with its lagged "
                         "coupling a cam's outlet pressure spike ran away; the steady solve_thermal takes it)")
    if non_newtonian is None:
        non_newtonian = contact.eyring_stress is not None
    if non_newtonian and contact.eyring_stress is None:
        raise InputError("thermal_transient_cycle: non_newtonian=True needs the contact's eyring_stress [Pa]")
    times = np.asarray(times, dtype=float)
    n = times.size
    series = {name: np.broadcast_to(np.asarray(value, dtype=float), (n,)).copy()
              for name, value in (("w", w), ("R", R), ("u1", u1), ("u2", u2))}
    tau0 = float(contact.eyring_stress) if non_newtonian else 0.0
    kernels = {name: _thermal_kernels.compiled(name) if compiled else _thermal_kernels.PY[name]
               for name in ("layer_sweep", "film_fields")}
    state: dict = {}
    out = {name: np.full(n, np.nan) for name in ("rise", "surface", "traction")}
    ran = np.zeros(n, dtype=bool)
    bounded = np.zeros(n, dtype=int)
    clock = [0.0]

    def after_step(i, solver):
        start = time.perf_counter()
        u1_i, u2_i = series["u1"][i], series["u2"][i]
        if not (u1_i > 0.0 and u2_i > 0.0):
            solver.flow = None
            state.clear()
            clock[0] += time.perf_counter() - start
            return
        here = attrs.evolve(contact, R=series["R"][i], w=series["w"][i], u1=u1_i, u2=u2_i)
        sc = solver.scaling
        H = solver.film(solver.P, solver.H0, series["R"][i])
        flow = None if solver.flow is None else np.column_stack(
            [solver.flow[0], np.zeros(solver.n) if solver.flow[1] is None else solver.flow[1], solver.flow[2]])
        snapshot = LineEHLSolution(problem=solver.problem, level=solver.levels, X=solver.X, P=solver.P, H=H,
                                   H0=solver.H0, record=None, flow_factor=flow)
        fields = _layers(here, snapshot, thermal, tau0, state, kernels,
                         scales={"b": sc.b, "p_h": sc.p_h, "h_scale": sc.h_scale}, cross_film=cross_film)
        wet = fields["wet"]
        out["rise"][i] = float(fields["Tm"][wet].max())
        bounded[i] = int(np.count_nonzero(fields["bounded"] & wet))
        out["surface"][i] = float(max(fields["T1"][wet].max(), fields["T2"][wet].max()))
        out["traction"][i] = -_trapezoid(fields["tau"], fields["x"], wet) / series["w"][i]
        ran[i] = True
        solver.flow = (fields["a"], fields["k"] if non_newtonian else None, fields["c"])
        clock[0] += time.perf_counter() - start

    u_m = 0.5 * (series["u1"] + series["u2"])
    opts = dict(E_reduced=contact.E_reduced, eta0=contact.eta0, alpha=contact.alpha, z=contact.z,
                viscosity=contact.viscosity, density=contact.density, p0=contact.p0, elastic=contact.elastic)
    films = transient_cycle(times, series["w"], series["R"], u_m, levels=levels, tolerance=tolerance, strict=strict,
                            compiled=compiled, after_step=after_step, **(opts | options))
    return ThermalTransientResult(films=films, temperature_rise=out["rise"], surface_temperature_rise=out["surface"],
                                  traction_coefficient=out["traction"], thermal=ran, energy_time=clock[0],
                                  profile_bounded=bounded)
